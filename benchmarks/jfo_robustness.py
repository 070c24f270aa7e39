"""Robustness of the mass-conserving (JFO) orbit on random but plausible fed bearings.

Run from the repository root:  python benchmarks/jfo_robustness.py [refine]
Writes benchmarks/jfo_robustness.md (``refine``: only its step-and-grid section).
Fifteen bearings drawn with a fixed seed: bore 60–150 mm, L/D 0.3–0.6, 600–4000 rpm, radial
clearance 10–60 µm, a central circumferential groove (10 % of the width) fed at 0.1–0.5 MPa,
viscosity 5–20 mPa s, a four-stroke big-end-like load (firing pulse on a rotating inertia
load) whose peak is a specific load of 5–40 MPa on L·D. Each bearing runs the Reynolds and
the mass-conserving film, massless (``quasi_static``) and with mass (the integrator ``auto``
chooses), to a periodic orbit; a run longer than :data:`TIME_LIMIT_S` is reported as not
finished.
"""

from __future__ import annotations

import math
import signal
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SEED = 20261122
CASES = 15
TIME_LIMIT_S = 120
"""A run still going after this is reported as '> limit' [s]."""
GRID = (36, 8)
"""Film grid n_theta × n_z of the table (coarse, as the property test)."""


def draw_bearings(seed: int = SEED, count: int = CASES) -> list[dict]:
    """``count`` random plausible fed bearings (SI units)."""
    rng = np.random.default_rng(seed)
    return [{
        "bore": rng.uniform(0.06, 0.15),
        "width_ratio": rng.uniform(0.3, 0.6),
        "rpm": rng.uniform(600.0, 4000.0),
        "clearance": rng.uniform(10e-6, 60e-6),
        "supply": rng.uniform(0.1e6, 0.5e6),
        "viscosity": rng.uniform(0.005, 0.02),
        "unit_load": rng.uniform(5e6, 40e6),
    } for _ in range(count)]


def problem(bearing: dict, film: str, settings, mass: float = 1.0):
    """OrbitProblem of one bearing with the film ``film`` on the grid of ``settings``."""
    from conrod.film.base import BearingGeometry, Groove
    from conrod.film.mass_conserving.film import MassConservingFilm
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.loads.cycle import LoadCycle
    from conrod.orbit import OrbitProblem

    width = bearing["width_ratio"] * bearing["bore"]
    geometry = BearingGeometry(diameter=bearing["bore"], width=width,
                               radial_clearance=bearing["clearance"],
                               grooves=(Groove(width=0.1 * width),),
                               supply_pressure=bearing["supply"])
    model = {"reynolds": ReynoldsFilm, "mass_conserving": MassConservingFilm}[film]
    omega = bearing["rpm"] * math.pi / 30.0
    count = 144
    phi = np.linspace(0.0, 4 * math.pi, count, endpoint=False)
    peak = bearing["unit_load"] * bearing["bore"] * width
    firing = np.exp(-(((phi + math.pi) % (4 * math.pi) - math.pi) / 0.3) ** 2)
    inertia = 0.3 * peak
    load_x = peak * firing - inertia * np.cos(phi)
    load_y = -inertia * 0.4 * np.sin(phi)
    loads = LoadCycle(phi, load_x, load_y, np.full(count, omega), np.zeros(count), omega,
                      4 * math.pi)
    return OrbitProblem(model.from_settings(geometry, settings), loads,
                        bearing["viscosity"], mass, mass, 0.1, 0.05 * bearing["clearance"])


def run(bearing: dict, film: str, integrator: str, grid=GRID, step_deg: float = 1.0) -> dict:
    """Outcome of one periodic orbit: status, message, wall time, cycles, h_min."""
    from conrod.cases.solver import SolverSection
    from conrod.orbit.periodic import periodic_orbit

    settings = SolverSection(film=film, integrator=integrator, quasi_static_step_deg=step_deg,
                             max_step_deg=step_deg, output_step_deg=2.0, max_cycles=8,
                             n_theta=grid[0], n_z=grid[1])
    orbit_problem = problem(bearing, film, settings)
    signal.signal(signal.SIGALRM, _timeout)
    signal.alarm(TIME_LIMIT_S)
    start = time.perf_counter()
    try:
        result = periodic_orbit(orbit_problem, settings)
        h_min = orbit_problem.clearance - float(np.max(np.hypot(result.last.x,
                                                                result.last.y)))
        status = "periodic" if result.periodic else "not periodic"
        return {"status": status, "message": "", "time": time.perf_counter() - start,
                "cycles": result.cycles, "h_min": h_min}
    except TimeoutError:
        return {"status": "timeout", "message": f"> {TIME_LIMIT_S} s",
                "time": time.perf_counter() - start, "cycles": 0, "h_min": math.nan}
    except Exception as error:  # report, do not hide
        if isinstance(error.__cause__ or error.__context__, TimeoutError):
            return {"status": "timeout", "message": f"> {TIME_LIMIT_S} s",
                    "time": time.perf_counter() - start, "cycles": 0, "h_min": math.nan}
        return {"status": "failed", "message": f"{type(error).__name__}: {error}",
                "time": time.perf_counter() - start, "cycles": 0, "h_min": math.nan}
    finally:
        signal.alarm(0)


def _timeout(signum, frame):
    raise TimeoutError


REPEATS = 3
"""Cycles timed per speed row; the fastest counts (a shared machine) [-]."""
PASSENGER_CAR = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"
SPEED_ROWS = [("reynolds", "quasi_static"), ("mass_conserving", "quasi_static"),
              ("reynolds", "implicit"), ("mass_conserving", "implicit")]


def passenger_car_rows() -> list[str]:
    """Fastest of :data:`REPEATS` cycles (after a warm-up cycle) on the passenger-car case
    fed by a 2 mm central circumferential groove at 0.3 MPa, 72×16, Reynolds and
    mass-conserving, massless and with mass, all in this one run."""
    from conrod import Case, Simulation
    from conrod.cases.bearing import GrooveSection
    from conrod.orbit import initial_state, integrate_cycle

    case = Case.from_toml(PASSENGER_CAR)
    bearing = case.bearing.model_copy(update={"supply_pressure": 3.0e5,
                                              "grooves": [GrooveSection(width=0.002)]})
    case = case.model_copy(update={"bearing": bearing})
    rows, reference = [], {}
    for film, integrator in SPEED_ROWS:
        sim = Simulation(case, film=film, integrator=integrator, n_theta=72, n_z=16)
        problem = sim.problem()
        cycle = integrate_cycle(problem, initial_state(), sim.solver)
        seconds = math.inf
        for _ in range(REPEATS):
            start = time.perf_counter()
            cycle = integrate_cycle(problem, cycle.end_state, sim.solver)
            seconds = min(seconds, time.perf_counter() - start)
        h_min = problem.clearance - float(np.max(np.hypot(cycle.x, cycle.y)))
        reference.setdefault(integrator, seconds)
        ratio = seconds / reference[integrator]
        rows.append(f"| {film} | {integrator} | {seconds:.2f} s | {ratio:.2f}× | "
                    f"{h_min * 1e6:.2f} µm |")
        print(rows[-1], flush=True)
    return rows


REFINED_CASES = (1, 5, 6)
"""Bearings whose mass-conserving h_min lies farthest below the Reynolds film's."""
REFINEMENTS = [("mass_conserving", GRID, 1.0), ("mass_conserving", GRID, 0.5),
               ("mass_conserving", (72, 16), 1.0), ("reynolds", GRID, 1.0),
               ("reynolds", (72, 16), 1.0)]
REFINE_TITLE = "## Mass-conserving against Reynolds: step and grid"


def refinement_lines() -> list[str]:
    """Is the lower h_min of the mass-conserving film numerics or physics? The orbit with
    mass of :data:`REFINED_CASES` at the table's step and grid, at half the step and on a
    grid twice as fine, beside the Reynolds film."""
    bearings = draw_bearings()
    lines = [REFINE_TITLE, "",
             "Orbit with mass (`auto`) of the bearings where the two films differ most: "
             "the same h_min at half the step and on a grid twice as fine means the "
             "difference is the film model (film rupture and reformation with the content "
             "conserved), not the discretisation.", "",
             "| case | film | grid | step [deg] | outcome | cycles | h_min [µm] | time [s] |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for k in REFINED_CASES:
        for film, grid, step in REFINEMENTS:
            out = run(bearings[k], film, "auto", grid, step)
            lines.append(f"| {k} | {film} | {grid[0]}×{grid[1]} | {step:g} | "
                         f"{out['status']} | {out['cycles']} | {out['h_min'] * 1e6:.2f} | "
                         f"{out['time']:.1f} |")
            print(lines[-1], flush=True)
    return lines


def replace_refinement() -> None:
    """Re-measure only the step-and-grid section and put it at the end of the table."""
    path = ROOT / "benchmarks" / "jfo_robustness.md"
    text = path.read_text().split(REFINE_TITLE)[0].rstrip("\n")
    path.write_text(text + "\n\n" + "\n".join(refinement_lines()) + "\n")


def main() -> None:
    if sys.argv[1:] == ["refine"]:
        replace_refinement()
        return
    configurations = [("reynolds", "quasi_static"), ("mass_conserving", "quasi_static"),
                      ("reynolds", "auto"), ("mass_conserving", "auto")]
    only = sys.argv[1:]  # optional subset of configuration indices
    if only:
        configurations = [configurations[int(k)] for k in only]
    lines = [
        "# Mass-conserving orbit on random fed bearings",
        "",
        f"Seed {SEED}, {CASES} bearings (bore 60–150 mm, L/D 0.3–0.6, 600–4000 rpm, "
        "c 10–60 µm, central groove fed at 0.1–0.5 MPa, μ 5–20 mPa s, four-stroke load "
        f"peaking at 5–40 MPa on L·D), grid {GRID[0]}×{GRID[1]}, quasi-static step 1°, "
        f"up to 8 cycles, time limit {TIME_LIMIT_S} s per run. "
        "`auto` is the integrator chosen by default (with mass where the film allows it).",
        "",
        "| case | bore [mm] | rpm | c [µm] | p_s [MPa] | W/(LD) [MPa] | film | integrator "
        "| outcome | time [s] | cycles | h_min [µm] | message |",
        "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |",
    ]
    totals = {}
    for k, bearing in enumerate(draw_bearings()):
        for film, integrator in configurations:
            out = run(bearing, film, integrator)
            key = (film, integrator)
            done = totals.setdefault(key, [0, 0.0])
            done[0] += out["status"] == "periodic"
            done[1] += out["time"]
            row = (f"| {k} | {bearing['bore'] * 1e3:.0f} | {bearing['rpm']:.0f} | "
                   f"{bearing['clearance'] * 1e6:.1f} | {bearing['supply'] / 1e6:.2f} | "
                   f"{bearing['unit_load'] / 1e6:.1f} | {film} | {integrator} | "
                   f"{out['status']} | {out['time']:.1f} | {out['cycles']} | "
                   f"{out['h_min'] * 1e6:.2f} | {out['message'][:110]} |")
            print(row, flush=True)
            lines.append(row)
    lines += ["", "| film | integrator | periodic | total time [s] |", "| --- | --- | --- | --- |"]
    lines += [f"| {f} | {i} | {n}/{CASES} | {t:.1f} |" for (f, i), (n, t) in totals.items()]
    lines += ["", "## Speed on the passenger car with an oil feed", "",
              f"`{PASSENGER_CAR.relative_to(ROOT)}` with a 2 mm central groove at 0.3 MPa, "
              f"72×16, fastest of {REPEATS} cycles after a warm-up cycle; ratio to the "
              "Reynolds film with the same integrator in this run (target ≤ 2×).", "",
              "| film | integrator | time per cycle | × Reynolds | h_min |",
              "| --- | --- | --- | --- | --- |"]
    lines += passenger_car_rows()
    (ROOT / "benchmarks" / "jfo_robustness.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
