"""Film-model benchmarks: time per solve, cold and warm, and sweeps, per model, grid and
tolerance; short-bearing call time; table build time; ROSS 3.1 on the same bearing.

Run:  python benchmarks/film_benchmarks.py   (writes benchmarks/film_benchmarks.md)

ROSS 3.1 (``ross-rotordynamics`` 3.1.x) needs Python ≥ 3.13. When ``python3.13`` is found
(on PATH or under pyenv) the script creates ``benchmarks/.venv-ross`` once, installs ROSS
there with pip, and times ROSS's finite-element pressure solve in that interpreter
(``ross_press_timing.py``) grid by grid, interleaved with conrod's solves of the same grid.
All times are CPU time of the timing process (``time.process_time``), which a loaded shared
machine disturbs less than wall time; ROSS is timed the same way.

Bearing: D = 50 mm, L = 25 mm, c = 25 µm, μ = 0.02 Pa s, ω_j = 200 rad/s, ε = 0.6 along +x.
"Cold" = median of 5 fresh models (numba already compiled); "warm" = median of the next 30
solves of a slowly moving journal (Δe = 0.2 % c per call, as in an orbit step), starting
from the last field. The mass-conserving model is timed with a full film history.
"""

from __future__ import annotations

import dataclasses
import json
import math
import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import numba as nb
import numpy as np

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.film.short.kernel import short_bearing_force
from conrod.film.table.film import TabulatedFilm
from conrod.film.table.kernel import mobility_velocity, table_force
from conrod.film.table.mobility import MobilityFilm
from conrod.io.atomic import write_text

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
VISCOSITY, SPEED, ECCENTRICITY = 0.02, 200.0, 0.6
GRIDS = ((72, 16), (144, 32), (288, 64))
TOLERANCE = 1.0e-7
"""Pressure-iteration tolerance of the rows of the second table (max|Δp|/max|p|) [-]."""
REYNOLDS_TOLERANCES = {
    5.0e-7: "implicit orbit with mass: force in Newton (0.5 × relative_tolerance 1e-6)",
    1.0e-7: "implicit orbit with mass: Jacobian solves",
    1.0e-9: "quasi-static orbit: accepted velocity solve",
    1.0e-12: "adaptive orbit, EHD coupling (film_tolerance)",
}
"""Multigrid tolerances of the Reynolds-versus-ROSS table [-] and the orbit path that solves
the film at each with the default ``[solver]`` settings (``docs/film.md``, Speed)."""
ROSS_REPEATS = 7
ROUNDS = 3
"""Interleaved rounds of the Reynolds-versus-ROSS table [-]."""
ROSS_VENV = Path(__file__).with_name(".venv-ross")
ROSS_SCRIPT = Path(__file__).with_name("ross_press_timing.py")
ROSS_REQUIREMENT = "ross-rotordynamics>=3.1,<3.2"
OUTPUT = Path(__file__).with_suffix(".md")


def state_at(k: int, history: np.ndarray | None = None) -> FilmState:
    """Journal creeping around at ε ≈ 0.6 (k-th orbit step)."""
    c = GEOMETRY.radial_clearance
    angle = 0.002 * k
    return FilmState(eccentricity_x=ECCENTRICITY * c * math.cos(angle),
                     eccentricity_y=ECCENTRICITY * c * math.sin(angle),
                     journal_speed=SPEED, viscosity=VISCOSITY, history=history)


def sweeps_of(model: object, result: object) -> float:
    extra = getattr(result, "extra", {})
    return extra.get("sweeps", extra.get("iterations", float("nan")))


def time_grid_model(factory, n_warm: int = 30, n_cold: int = 5) -> dict[str, float]:
    """Median cold (fresh model) and warm solve time [s] and sweeps of a grid model."""
    factory().solve(state_at(0))  # JIT compile outside the timing
    cold_times = []
    for _ in range(n_cold):
        model = factory()
        history = model.initial_history()
        start = time.process_time()
        cold = model.solve(state_at(0, history))
        cold_times.append(time.process_time() - start)
    cold_time = float(np.median(cold_times))
    times, sweeps = [], []
    _, memory = model.solve_with_memory(state_at(0, history), model.initial_memory())
    for k in range(1, n_warm + 1):
        start = time.process_time()
        result, memory = model.solve_with_memory(state_at(k, history), memory)  # warm start
        times.append(time.process_time() - start)
        sweeps.append(sweeps_of(model, result))
    return {"cold": cold_time, "cold_sweeps": sweeps_of(model, cold),
            "warm": float(np.median(times)), "warm_sweeps": float(np.median(sweeps)),
            "force": math.hypot(cold.force_x, cold.force_y)}


def whirling_state(t: float, history: np.ndarray | None) -> FilmState:
    """Journal whirling and squeezing (ε 0.3–0.7) — a film that ruptures and re-forms."""
    c, w = GEOMETRY.radial_clearance, 2.0 * math.pi / 0.1
    return FilmState(eccentricity_x=c * (0.3 + 0.4 * math.sin(w * t)),
                     eccentricity_y=0.3 * c * math.cos(w * t),
                     velocity_x=0.4 * c * w * math.cos(w * t),
                     velocity_y=-0.3 * c * w * math.sin(w * t),
                     journal_speed=SPEED, viscosity=VISCOSITY, history=history)


def time_broken_film(n_theta: int = 144, n_z: int = 32) -> dict[str, float]:
    """Warm solves along a transient with a broken film (ϑ < 1), JFO vs Reynolds [s]."""
    jfo = MassConservingFilm(GEOMETRY, n_theta=n_theta, n_z=n_z, tolerance=TOLERANCE)
    reynolds = ReynoldsFilm(GEOMETRY, n_theta=n_theta, n_z=n_z, tolerance=TOLERANCE)
    history, dt = jfo.initial_history(), 0.1 / 720  # 0.5° of whirl per step
    times: dict[str, list[float]] = {"jfo": [], "reynolds": []}
    jfo_memory, reynolds_memory = jfo.initial_memory(), reynolds.initial_memory()
    for k in range(400):
        state = whirling_state(k * dt, history)
        start = time.process_time()
        jfo_memory = dataclasses.replace(jfo_memory, fraction=history)
        result, jfo_memory = jfo.solve_with_memory(state, jfo_memory)  # warm starts held here
        if k >= 360:
            times["jfo"].append(time.process_time() - start)
            start = time.process_time()
            _, reynolds_memory = reynolds.solve_with_memory(state, reynolds_memory)
            times["reynolds"].append(time.process_time() - start)
        history = np.clip(history + dt * result.history_rate, 0.0, 1.0)
    return {"jfo": float(np.median(times["jfo"])), "reynolds": float(np.median(times["reynolds"])),
            "min_fraction": float(history.min()), "sweeps": result.extra["iterations"]}


@nb.njit(cache=True)
def _short_loop(n: int, c: float) -> float:
    total = 0.0
    for k in range(n):
        fx, fy = short_bearing_force(0.6 * c, 1e-3 * c * (k % 7), 1e-4, 0.0, 200.0,
                                     0.02, 0.025, 0.025, c)
        total += fx + fy
    return total


def time_short() -> dict[str, float]:
    """Per-call time of the compiled kernel (in a compiled loop) and of ``force()`` [s]."""
    c = GEOMETRY.radial_clearance
    _short_loop(10, c)
    n = 1_000_000
    start = time.process_time()
    _short_loop(n, c)
    kernel = (time.process_time() - start) / n
    model = ShortBearingFilm(GEOMETRY)
    state = state_at(1)
    model.force(state)
    start = time.process_time()
    for _ in range(20000):
        model.force(state)
    return {"kernel": kernel, "python": (time.process_time() - start) / 20000}


@nb.njit(cache=True)
def _table_loop(n: int, force_scale: float, c: float, s_step: float,
                log_magnitude: np.ndarray, turning: np.ndarray) -> float:
    total = 0.0
    for k in range(n):
        fx, fy = table_force(0.5 * c, 1e-2 * c * (k % 7), 1e-4, -2e-4, 200.0, 0.02,
                             force_scale, c, s_step, log_magnitude, turning)
        vx, vy = mobility_velocity(0.5 * c, 1e-2 * c * (k % 7), 1e3, 2e3, 200.0, 0.02,
                                   force_scale, c, s_step, log_magnitude, turning)
        total += fx + vx
    return total


@nb.njit(cache=True)
def _table_only_loop(n: int, force_scale: float, c: float, s_step: float,
                     log_magnitude: np.ndarray, turning: np.ndarray) -> float:
    total = 0.0
    for k in range(n):
        fx, fy = table_force(0.5 * c, 1e-2 * c * (k % 7), 1e-4, -2e-4, 200.0, 0.02,
                             force_scale, c, s_step, log_magnitude, turning)
        total += fx
    return total


def time_compiled_lookups(table: TabulatedFilm) -> tuple[float, float]:
    """Per-call time of table_force and mobility_velocity inside compiled loops [s]."""
    args = (table.force_scale, GEOMETRY.radial_clearance, table.s_step,
            table.tables["log_magnitude"], table.tables["turning"])
    _table_loop(10, *args)
    _table_only_loop(10, *args)
    n = 100_000
    start = time.process_time()
    _table_only_loop(n, *args)
    force_time = (time.process_time() - start) / n
    start = time.process_time()
    _table_loop(n, *args)
    return force_time, (time.process_time() - start) / n - force_time


def time_table() -> dict[str, float]:
    """Table build over ReynoldsFilm 144×32 (no cache) and per-call look-up [s]."""
    ReynoldsFilm(GEOMETRY, n_theta=72, n_z=16).solve(state_at(0))
    table = TabulatedFilm(ReynoldsFilm(GEOMETRY, n_theta=144, n_z=32), use_cache=False)
    state = FilmState(eccentricity_x=1.2e-5, eccentricity_y=0.4e-5, velocity_x=1e-4,
                      velocity_y=-2e-4, journal_speed=SPEED, viscosity=VISCOSITY)
    table.force(state)
    start = time.process_time()
    for _ in range(20000):
        table.force(state)
    lookup = (time.process_time() - start) / 20000
    error = table.interpolation_error(20, eccentricity_max=0.9)
    mobility = MobilityFilm(GEOMETRY, base=table.base, use_cache=False)
    mobility.table = table
    mobility.journal_velocity(1e-5, 0.0, 1e3, 2e3, SPEED, 0.0, VISCOSITY)
    start = time.process_time()
    for _ in range(5000):
        mobility.journal_velocity(1e-5, 0.0, 1e3, 2e3, SPEED, 0.0, VISCOSITY)
    mobility_time = (time.process_time() - start) / 5000
    compiled_force, compiled_mobility = time_compiled_lookups(table)
    return {"build": table.build_seconds, "lookup": lookup, "error_max": error["max_relative"],
            "mobility": mobility_time,
            "compiled_force": compiled_force, "compiled_mobility": compiled_mobility}


def python313() -> str | None:
    """A Python ≥ 3.13 interpreter for ROSS 3.1, or None."""
    found = shutil.which("python3.13")
    candidates = [found] if found else []
    pyenv = Path(os.environ.get("PYENV_ROOT", Path.home() / ".pyenv")) / "versions"
    candidates += sorted(str(p) for p in pyenv.glob("3.1[3-9]*/bin/python3.1[3-9]"))
    for candidate in candidates:
        try:
            subprocess.run([candidate, "--version"], check=True, capture_output=True)
        except (OSError, subprocess.CalledProcessError):
            continue
        return candidate
    return None


def ross_python() -> str:
    """Interpreter of the ROSS 3.1 environment (created on first use); raises OSError."""
    venv_python = ROSS_VENV / "bin" / "python"
    if not venv_python.exists():
        base = python313()
        if base is None:
            raise OSError("no Python >= 3.13 on this machine (ROSS 3.1 needs it)")
        subprocess.run([base, "-m", "venv", str(ROSS_VENV)], check=True)
        subprocess.run([str(venv_python), "-m", "pip", "install", "-q", ROSS_REQUIREMENT],
                       check=True)
    return str(venv_python)


def time_ross(n_theta: int, n_z: int) -> dict | str:
    """ROSS 3.1 pressure-solve CPU time [s] (median of ROSS_REPEATS) and load [N], or why not."""
    try:
        python = ross_python()
        done = subprocess.run([python, str(ROSS_SCRIPT), str(n_theta), str(n_z),
                               str(ROSS_REPEATS)], check=True, capture_output=True, text=True)
        return json.loads(done.stdout.strip().splitlines()[-1])
    except (OSError, subprocess.CalledProcessError, ValueError, IndexError) as error:
        return f"ROSS 3.1 not run ({type(error).__name__}: {error})"


def _call_with_memory(film: ReynoldsFilm, call: str, state: FilmState, memory):
    """``solve`` or ``force`` warm-started from ``memory`` (``solve()``/``force()`` alone
    are cold); returns the memory after the call."""
    if call == "solve":
        return film.solve_with_memory(state, memory)[1]
    return film.force_with_memory(state, memory)[2]


def time_reynolds(n_theta: int, n_z: int, tolerance: float, n_cold: int = 7,
                  n_warm: int = 30) -> dict[str, float]:
    """Median CPU time [s] of cold and warm ReynoldsFilm solve() and force() calls."""
    def model() -> ReynoldsFilm:
        return ReynoldsFilm(GEOMETRY, n_theta=n_theta, n_z=n_z, tolerance=tolerance)

    model().solve(state_at(0))
    out: dict[str, float] = {}
    for call in ("solve", "force"):
        cold = []
        for _ in range(n_cold):
            film = model()
            start = time.process_time()
            memory = _call_with_memory(film, call, state_at(0), film.initial_memory())
            cold.append(time.process_time() - start)
        warm = []
        for k in range(1, n_warm + 1):  # warm: each solve starts from the last field
            start = time.process_time()
            memory = _call_with_memory(film, call, state_at(k), memory)
            warm.append(time.process_time() - start)
        out[f"{call}_cold"], out[f"{call}_warm"] = float(np.median(cold)), float(np.median(warm))
    result = model().solve(state_at(0))
    out["force"] = math.hypot(result.force_x, result.force_y)
    return out


def time_sensitivities() -> list[str]:
    """Markdown rows: CPU time of ReynoldsFilm.sensitivities (solve + 2 adjoint solves)."""
    rows = []
    for n_theta, n_z in GRIDS:
        film = ReynoldsFilm(GEOMETRY, n_theta=n_theta, n_z=n_z, tolerance=1e-10)
        film.sensitivities(state_at(0))
        times = []
        for k in range(1, 8):
            start = time.process_time()
            film.sensitivities(state_at(k))
            times.append(time.process_time() - start)
        rows.append(f"| reynolds `sensitivities()` (K, C: solve + 2 adjoint solves, 1e-10) | "
                    f"{n_theta}×{n_z} | – | – | {1e3 * float(np.median(times)):.3f} | – | "
                    "warm |")
        print(rows[-1], flush=True)
    return rows


def reynolds_versus_ross() -> list[str]:
    """Markdown rows: conrod Reynolds at three tolerances and ROSS 3.1, grid by grid,
    ROUNDS interleaved rounds (each cell: median over the rounds of the round medians)."""
    rows = ["| grid | tolerance | conrod solve() cold / warm [ms] | conrod force() cold / warm "
            "[ms] | ROSS 3.1 press [ms] | ROSS ÷ conrod solve(), cold / warm | W conrod / "
            "ROSS [N] |", "| --- | --- | ---: | ---: | ---: | ---: | --- |"]
    ross: dict = {}
    conrod: dict = {}
    for _ in range(ROUNDS):
        for grid in GRIDS:
            answer = time_ross(*grid)
            ross.setdefault(grid, []).append(answer)
            for tolerance in REYNOLDS_TOLERANCES:
                conrod.setdefault((grid, tolerance), []).append(time_reynolds(*grid, tolerance))
    differences = []
    for grid in GRIDS:
        runs = [r for r in ross[grid] if not isinstance(r, str)]
        for tolerance in REYNOLDS_TOLERANCES:
            r = {key: float(np.median([run[key] for run in conrod[(grid, tolerance)]]))
                 for key in conrod[(grid, tolerance)][0]}
            if not runs:
                ross_text, ratio, load = ross[grid][0], "–", f"{r['force']:.0f} / –"
            else:
                median = float(np.median([run["median"] for run in runs]))
                ross_text = f"{1e3 * median:.2f}"
                ratio = f"{median / r['solve_cold']:.1f}× / {median / r['solve_warm']:.1f}×"
                load = f"{r['force']:.0f} / {runs[0]['load']:.0f}"
                differences.append(abs(runs[0]["load"] / r["force"] - 1.0))
            rows.append(f"| {grid[0]}×{grid[1]} | {tolerance:g} ({REYNOLDS_TOLERANCES[tolerance]}) "
                        f"| {1e3 * r['solve_cold']:.3f} / "
                        f"{1e3 * r['solve_warm']:.3f} | {1e3 * r['force_cold']:.3f} / "
                        f"{1e3 * r['force_warm']:.3f} | {ross_text} | {ratio} | {load} |")
            print(rows[-1], flush=True)
    spread = (f"{100 * min(differences):.1f}–{100 * max(differences):.1f} %" if differences
              else "– (ROSS not run)")
    c = GEOMETRY.radial_clearance
    ocvirk = math.hypot(*short_bearing_force(ECCENTRICITY * c, 0.0, 0.0, 0.0, SPEED, VISCOSITY,
                                             GEOMETRY.radius, GEOMETRY.width, c))
    rows += ["", f"Load check: ROSS and conrod differ by {spread} (finite elements with the "
             "cavitation clamp in the back substitution against the projected complementarity "
             "solve); Raimondi & Boyd's S = 0.319 gives 2489 N (conrod's finite-bearing load is "
             "validated against it, docs/film.md); the Ocvirk short-bearing closed form gives "
             f"{ocvirk:.0f} N."]
    return rows


def markdown(rows: list[str], notes: list[str], versus: list[str]) -> str:
    head = ["# Film benchmarks", "", f"Machine: {sys.platform}, Python {sys.version.split()[0]}; "
            "bearing D = 50 mm, L/D = 0.5, c = 25 µm, ε = 0.6, 200 rad/s, isoviscous; CPU time "
            "per call (medians).", "", "## Reynolds (Swift–Stieber) film and ROSS 3.1", "",
            "Cold = fresh model (nested-grid start), warm = the next 30 calls of a journal "
            "creeping by 0.002 rad per call, each started from the last field "
            "(`solve_with_memory` / `force_with_memory`, as the orbit calls the film). The "
            "tolerances are those the orbit solves the film at with the default `[solver]` "
            "settings (docs/film.md, Speed). ROSS 3.1: `ross.bearings.fluid_film.pressure.press` "
            f"(finite elements, banded LU), median of {ROSS_REPEATS} solves at the same grid "
            "(n_theta × n_z elements), ε = 0.6 held, one land of 2π − 1e-5 rad whose edge lies "
            "in the cavitated zone (for a land of exactly 360° ROSS drops the circumferential "
            "pressure flow and solves the short-bearing equation; `ross_press_timing.py`). "
            "Grid by grid, ROSS then "
            f"conrod, {ROUNDS} rounds; each cell is the median over the rounds.", ""] + versus + [
            "", f"## All film models (pressure tolerance {TOLERANCE:g})", "",
            "| model | grid | cold [ms] | cold sweeps | warm [ms] | warm sweeps | note |",
            "| --- | --- | ---: | ---: | ---: | ---: | --- |"]
    return "\n".join(head + rows + [""] + notes) + "\n"


def main() -> None:
    rows, notes = [], []
    versus = reynolds_versus_ross()
    for n_theta, n_z in GRIDS:
        for name, cls in (("reynolds", ReynoldsFilm), ("mass_conserving", MassConservingFilm)):
            r = time_grid_model(lambda cls=cls, a=n_theta, b=n_z: cls(
                GEOMETRY, n_theta=a, n_z=b, tolerance=TOLERANCE))
            rows.append(f"| {name} | {n_theta}×{n_z} | {1e3 * r['cold']:.2f} | "
                        f"{r['cold_sweeps']:.0f} | {1e3 * r['warm']:.3f} | "
                        f"{r['warm_sweeps']:.0f} | W = {r['force']:.0f} N |")
            print(rows[-1], flush=True)
    rows += time_sensitivities()
    broken = time_broken_film()
    rows.append(f"| mass_conserving, broken film (transient, min ϑ = {broken['min_fraction']:.2f}) "
                f"| 144×32 | – | – | {1e3 * broken['jfo']:.3f} | {broken['sweeps']:.0f} | "
                f"reynolds on the same states: {1e3 * broken['reynolds']:.3f} ms |")
    short = time_short()
    rows.append(f"| short (kernel, compiled loop) | – | – | – | {1e3 * short['kernel']:.5f} | – | "
                f"{1e9 * short['kernel']:.0f} ns/call |")
    rows.append(f"| short (`force()`, Python call) | – | – | – | {1e3 * short['python']:.4f} "
                "| – | |")
    table = time_table()
    rows.append(f"| table build (28 ε × 48 dir over reynolds 144×32) | – | "
                f"{1e3 * table['build']:.0f} | – | {1e3 * table['lookup']:.4f} | – | "
                f"look-up per call; max error {100 * table['error_max']:.2f} % (ε ≤ 0.9) |")
    rows.append(f"| mobility `journal_velocity` | – | – | – | {1e3 * table['mobility']:.4f} "
                "| – | |")
    rows.append(f"| compiled `table_force` / `mobility_velocity` (in a numba loop) | – | – | – | "
                f"{1e3 * table['compiled_force']:.5f} / {1e3 * table['compiled_mobility']:.5f} "
                "| – | for an orbit compiled end to end |")
    write_text(OUTPUT, markdown(rows, notes, versus))
    print(f"written {OUTPUT}")


if __name__ == "__main__":
    main()
