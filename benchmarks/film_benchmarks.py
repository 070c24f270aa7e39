"""Film-model benchmarks (issue 3): time per solve, cold and warm, and sweeps, per model and
grid; short-bearing call time; table build time; the same bearing in ROSS as a ratio.

Run:  python benchmarks/film_benchmarks.py   (writes benchmarks/film_benchmarks.md)

Bearing: D = 50 mm, L = 25 mm, c = 25 µm, μ = 0.02 Pa s, ω_j = 200 rad/s, ε = 0.6 along +x.
"Cold" = median of 5 fresh models (numba already compiled); "warm" = median of the next 30
solves of a slowly moving journal (Δe = 0.2 % c per call, as in an orbit step), starting
from the last field. The mass-conserving model is timed with a full film history.
"""

from __future__ import annotations

import dataclasses
import math
import sys
import time
import warnings
from pathlib import Path

import numba as nb
import numpy as np

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.mass_conserving import MassConservingFilm
from conrod.film.mobility import MobilityFilm
from conrod.film.reynolds import ReynoldsFilm
from conrod.film.short_bearing import ShortBearingFilm
from conrod.film.short_bearing_kernel import short_bearing_force
from conrod.film.table import TabulatedFilm
from conrod.film.table_kernel import mobility_velocity, table_force
from conrod.io.atomic import write_text

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
VISCOSITY, SPEED, ECCENTRICITY = 0.02, 200.0, 0.6
GRIDS = ((72, 16), (144, 32), (288, 64))
TOLERANCE = 1.0e-7
"""Pressure-iteration tolerance of both grid models in the table (max|Δp|/max|p|) [-]; the orbit
uses ReynoldsFilm's tighter default 1e-12 (timed separately below)."""
OUTPUT = Path(__file__).with_suffix(".md")


def state_at(k: int, history: np.ndarray | None = None) -> FilmState:
    """Journal creeping around at ε ≈ 0.6 (k-th orbit step)."""
    c = GEOMETRY.radial_clearance
    angle = 0.002 * k
    return FilmState(ECCENTRICITY * c * math.cos(angle), ECCENTRICITY * c * math.sin(angle),
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
        start = time.perf_counter()
        cold = model.solve(state_at(0, history))
        cold_times.append(time.perf_counter() - start)
    cold_time = float(np.median(cold_times))
    times, sweeps = [], []
    _, memory = model.solve_with_memory(state_at(0, history), model.initial_memory())
    for k in range(1, n_warm + 1):
        start = time.perf_counter()
        result, memory = model.solve_with_memory(state_at(k, history), memory)  # warm start
        times.append(time.perf_counter() - start)
        sweeps.append(sweeps_of(model, result))
    return {"cold": cold_time, "cold_sweeps": sweeps_of(model, cold),
            "warm": float(np.median(times)), "warm_sweeps": float(np.median(sweeps)),
            "force": math.hypot(cold.force_x, cold.force_y)}


def whirling_state(t: float, history: np.ndarray | None) -> FilmState:
    """Journal whirling and squeezing (ε 0.3–0.7) — a film that ruptures and re-forms."""
    c, w = GEOMETRY.radial_clearance, 2.0 * math.pi / 0.1
    return FilmState(c * (0.3 + 0.4 * math.sin(w * t)), 0.3 * c * math.cos(w * t),
                     0.4 * c * w * math.cos(w * t), -0.3 * c * w * math.sin(w * t),
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
        start = time.perf_counter()
        jfo_memory = dataclasses.replace(jfo_memory, fraction=history)
        result, jfo_memory = jfo.solve_with_memory(state, jfo_memory)  # warm starts held here
        if k >= 360:
            times["jfo"].append(time.perf_counter() - start)
            start = time.perf_counter()
            _, reynolds_memory = reynolds.solve_with_memory(state, reynolds_memory)
            times["reynolds"].append(time.perf_counter() - start)
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
    start = time.perf_counter()
    _short_loop(n, c)
    kernel = (time.perf_counter() - start) / n
    model = ShortBearingFilm(GEOMETRY)
    state = state_at(1)
    model.force(state)
    start = time.perf_counter()
    for _ in range(20000):
        model.force(state)
    return {"kernel": kernel, "python": (time.perf_counter() - start) / 20000}


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
    start = time.perf_counter()
    _table_only_loop(n, *args)
    force_time = (time.perf_counter() - start) / n
    start = time.perf_counter()
    _table_loop(n, *args)
    return force_time, (time.perf_counter() - start) / n - force_time


def time_table() -> dict[str, float]:
    """Table build over ReynoldsFilm 144×32 (no cache) and per-call look-up [s]."""
    ReynoldsFilm(GEOMETRY, n_theta=72, n_z=16).solve(state_at(0))
    table = TabulatedFilm(ReynoldsFilm(GEOMETRY, n_theta=144, n_z=32), use_cache=False)
    state = FilmState(1.2e-5, 0.4e-5, 1e-4, -2e-4, journal_speed=SPEED, viscosity=VISCOSITY)
    table.force(state)
    start = time.perf_counter()
    for _ in range(20000):
        table.force(state)
    lookup = (time.perf_counter() - start) / 20000
    error = table.interpolation_error(20, eccentricity_max=0.9)
    mobility = MobilityFilm(GEOMETRY, base=table.base, use_cache=False)
    mobility.table = table
    mobility.journal_velocity(1e-5, 0.0, 1e3, 2e3, SPEED, 0.0, VISCOSITY)
    start = time.perf_counter()
    for _ in range(5000):
        mobility.journal_velocity(1e-5, 0.0, 1e3, 2e3, SPEED, 0.0, VISCOSITY)
    mobility_time = (time.perf_counter() - start) / 5000
    compiled_force, compiled_mobility = time_compiled_lookups(table)
    return {"build": table.build_seconds, "lookup": lookup, "error_max": error["max_relative"],
            "mobility": mobility_time,
            "compiled_force": compiled_force, "compiled_mobility": compiled_mobility}


def time_ross(n_theta: int, n_z: int) -> tuple[float, float] | str:
    """Time [s] and load [N] of ROSS's FluidFlow at the same grid (its θ count must be odd:
    n_theta + 1 nodes, the closing node repeating θ = 0; n_z + 1 axial nodes), or why not."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            from ross.bearings.fluid_flow import FluidFlow
            from ross.bearings.fluid_flow_coefficients import calculate_oil_film_force
    except Exception as error:  # ROSS missing or its import fails: report and carry on
        return f"ROSS not importable ({type(error).__name__}: {error})"
    c = GEOMETRY.radial_clearance
    try:
        start = time.perf_counter()
        flow = FluidFlow(
            nz=n_z + 1, ntheta=n_theta + 1, length=GEOMETRY.width, omega=SPEED, p_in=0.0,
            p_out=0.0, radius_rotor=GEOMETRY.radius, radius_stator=GEOMETRY.radius + c,
            viscosity=VISCOSITY, density=860.0, eccentricity=ECCENTRICITY * c,
            attitude_angle=0.0,
        )
        elapsed = time.perf_counter() - start
        radial, tangential, _, _ = calculate_oil_film_force(flow, force_type="numerical")
    except Exception as error:
        return f"ROSS could not solve the case ({type(error).__name__}: {error})"
    return elapsed, math.hypot(radial, tangential)


def markdown(rows: list[str], notes: list[str]) -> str:
    head = ["# Film benchmarks", "", f"Machine: {sys.platform}, Python {sys.version.split()[0]}; "
            "bearing D = 50 mm, L/D = 0.5, c = 25 µm, ε = 0.6, 200 rad/s; pressure tolerance "
            f"{TOLERANCE:g} unless stated.", "",
            "| model | grid | cold [ms] | cold sweeps | warm [ms] | warm sweeps | note |",
            "| --- | --- | ---: | ---: | ---: | ---: | --- |"]
    return "\n".join(head + rows + [""] + notes) + "\n"


def main() -> None:
    rows, notes = [], []
    reynolds_cold, reynolds_warm = {}, {}
    for n_theta, n_z in GRIDS:
        for name, cls in (("reynolds", ReynoldsFilm), ("mass_conserving", MassConservingFilm)):
            r = time_grid_model(lambda cls=cls, a=n_theta, b=n_z: cls(
                GEOMETRY, n_theta=a, n_z=b, tolerance=TOLERANCE))
            if name == "reynolds":
                reynolds_cold[(n_theta, n_z)] = r["cold"]
                reynolds_warm[(n_theta, n_z)] = r["warm"]
            rows.append(f"| {name} | {n_theta}×{n_z} | {1e3 * r['cold']:.2f} | "
                        f"{r['cold_sweeps']:.0f} | {1e3 * r['warm']:.3f} | "
                        f"{r['warm_sweeps']:.0f} | W = {r['force']:.0f} N |")
            print(rows[-1], flush=True)
    tight = time_grid_model(lambda: ReynoldsFilm(GEOMETRY, n_theta=144, n_z=32, tolerance=1e-12))
    rows.append(f"| reynolds, tolerance 1e-12 (orbit default) | 144×32 | {1e3 * tight['cold']:.2f} "
                f"| {tight['cold_sweeps']:.0f} | {1e3 * tight['warm']:.3f} | "
                f"{tight['warm_sweeps']:.0f} | W = {tight['force']:.0f} N |")
    print(rows[-1], flush=True)
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
    for n_theta, n_z in GRIDS:
        ross = time_ross(n_theta, n_z)
        if isinstance(ross, str):
            notes.append(f"- ROSS at {n_theta}×{n_z}: {ross}")
            print(notes[-1], flush=True)
            continue
        cold_ratio = ross[0] / reynolds_cold[(n_theta, n_z)]
        warm_ratio = ross[0] / reynolds_warm[(n_theta, n_z)]
        rows.append(f"| ROSS FluidFlow | {n_theta}×{n_z} | {1e3 * ross[0]:.1f} | – | – | – | "
                    f"W = {ross[1]:.0f} N; ROSS time / conrod reynolds: {cold_ratio:.0f}× cold, "
                    f"{warm_ratio:.0f}× warm |")
        print(rows[-1], flush=True)
    write_text(OUTPUT, markdown(rows, notes))
    print(f"written {OUTPUT}")


if __name__ == "__main__":
    main()
