"""Cost of a crank-pin oil hole that turns with the journal against the same hole fixed
in the shell (target: ≤ 1.2×; a mask update per instant, no re-assembly of the film
operator beyond what a fixed hole needs).

Run from the repository root:  python benchmarks/crank_feed_benchmarks.py
Writes benchmarks/crank_feed_benchmarks.md. Case: examples/passenger_car_diesel_2000rpm_
crank_fed.toml (Reynolds film, pin hole at the wear-diagram angle, 3 bar gallery). The fixed
hole is the same hole held at its shell angle at φ = 0 with the same (constant) feed
pressure as ``[bearing] feed_holes`` + ``supply_pressure``. Rows:

* film solves: ``ReynoldsFilm.force`` at the states of the converged orbit (warm memory as in
  the orbit), the cost of one instant with the mask update;
* orbit cycles: one periodic-orbit cycle (the second, after a warm-up cycle), both holes
  through the same Python film path (quasi_static; implicit with the fixed hole's compiled
  flight kernel switched off), and the default integrator as a user gets it (the fixed
  hole's compiled flight kernel is exact only for a fixed supply mask).
Ratios are taken within one run, on one machine.
"""

from __future__ import annotations

import dataclasses
import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "src"))

from conrod.cases.case import Case  # noqa: E402
from conrod.film.base import FeedHole, FilmState  # noqa: E402
from conrod.film.reynolds.film import ReynoldsFilm  # noqa: E402
from conrod.orbit import OrbitState, integrate_cycle  # noqa: E402
from conrod.simulation import Simulation  # noqa: E402

CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm_crank_fed.toml"
GRID = {"n_theta": 72, "n_z": 16}


class _NoFlight(ReynoldsFilm):
    """The Reynolds film without its compiled flight kernel (the Python implicit path)."""

    def flight_kernel(self, memory, newton_tolerance):
        return None


def problems():
    """(rotating, fixed) orbit problems of the case on :data:`GRID`."""
    case = Case.from_toml(CASE)
    sim = Simulation(case, integrator="quasi_static", **GRID)
    rotating = sim.problem()
    pressure = rotating.feed.at(0.0).pressures[0]
    hole = rotating.film.geometry.journal_holes[0]
    geometry = dataclasses.replace(
        rotating.film.geometry, journal_holes=(),
        feed_holes=(FeedHole(hole.angle + rotating.feed.journal_angle(0.0), hole.diameter,
                             hole.axial_position),), supply_pressure=pressure)
    fixed_film = dataclasses.replace(rotating.film, geometry=geometry)
    fixed = dataclasses.replace(rotating, film=fixed_film, feed=None)
    return rotating, fixed


def cycle_time(problem, integrator: str, settings) -> tuple[float, int]:
    """(wall time [s], steps) of the second cycle from the end of a warm-up cycle."""
    first = integrate_cycle(problem, OrbitState(), settings, integrator)
    start = time.perf_counter()
    second = integrate_cycle(problem, first.end_state, settings, integrator)
    return time.perf_counter() - start, second.steps


def solve_time(problem, trajectory) -> float:
    """Wall time per film solve along ``trajectory`` (one pass, the warm memory carried
    from output angle to output angle as in the orbit) [s]."""
    film = problem.film
    wj, wb = problem.loads.speeds(trajectory.crank_angle)
    states = [FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                        velocity_x=float(vx), velocity_y=float(vy), journal_speed=float(a),
                        shell_speed=float(b), viscosity=problem.viscosity,
                        journal_feed=problem.journal_feed(float(phi)))
              for x, y, vx, vy, a, b, phi in zip(trajectory.x, trajectory.y, trajectory.vx,
                                                  trajectory.vy, wj, wb,
                                                  trajectory.crank_angle, strict=True)]
    memory = film.initial_memory()
    start = time.perf_counter()
    for state in states:
        _, memory = film.solve_with_memory(state, memory)
    return (time.perf_counter() - start) / len(states)


def best(measure, repeats: int = 3):
    """The fastest of ``repeats`` measurements (a shared machine: the others are noise)."""
    return min((measure() for _ in range(repeats)), key=lambda value: value
               if not isinstance(value, tuple) else value[0])


def main() -> None:
    rotating, fixed = problems()
    case = Case.from_toml(CASE)
    settings = Simulation(case, **GRID).solver.model_copy(update={"output_step_deg": 1.0})
    trajectory = integrate_cycle(rotating, OrbitState(), settings, "quasi_static")
    a = best(lambda: solve_time(fixed, trajectory), 5)
    b = best(lambda: solve_time(rotating, trajectory), 5)
    rows = [("film solve along the orbit, warm (the mask update)", a * 1e3, b * 1e3, "ms",
             "", "")]
    for name in ("quasi_static", "implicit"):
        slow_fixed = fixed
        if name == "implicit":
            slow_fixed = dataclasses.replace(fixed, film=_NoFlight(
                fixed.film.geometry, **GRID, tolerance=fixed.film.tolerance))
        (a, steps_a), (b, steps_b) = (best(lambda p=p, n=name: cycle_time(p, n, settings), 2)
                                      for p in (slow_fixed, rotating))
        rows.append((f"orbit cycle, {name} (the same Python film path)", a, b, "s",
                     steps_a, steps_b))
    lines = ["# Crank-pin oil hole: turning vs fixed in the shell", "",
             f"`python benchmarks/crank_feed_benchmarks.py` — Python "
             f"{platform.python_version()}, 2 shared cores (fastest of 5 or 2 repeats); "
             "case `examples/passenger_car_diesel_2000rpm_crank_fed.toml` (asperity "
             "contact: no compiled flight for either hole), grid 72×16, output every 1°. "
             "Target: turning ≤ 1.2× fixed.", "",
             "| what | fixed hole | turning hole | ratio | steps fixed / turning |",
             "| --- | ---: | ---: | ---: | ---: |"]
    for what, a, b, unit, steps_a, steps_b in rows:
        steps = f"{steps_a} / {steps_b}" if steps_a else "–"
        lines.append(f"| {what} | {a:.3g} {unit} | {b:.3g} {unit} | {b / a:.2f} | {steps} |")
    out = ROOT / "benchmarks" / "crank_feed_benchmarks.md"
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
