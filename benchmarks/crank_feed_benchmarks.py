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
from conrod.orbit.memory import FilmSession  # noqa: E402
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


def cycle_time(problem, integrator: str, settings) -> float:
    """Wall time of the second cycle from the end of a warm-up cycle [s]."""
    first = integrate_cycle(problem, OrbitState(), settings, integrator)
    start = time.perf_counter()
    integrate_cycle(problem, first.end_state, settings, integrator)
    return time.perf_counter() - start


def solve_time(problem, trajectory) -> float:
    """Wall time per film force along ``trajectory`` with the orbit's warm memory [s]."""
    session = FilmSession(problem.film)
    wj, wb = problem.loads.speeds(trajectory.crank_angle)
    states = [FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                        velocity_x=float(vx), velocity_y=float(vy), journal_speed=float(a),
                        shell_speed=float(b), viscosity=problem.viscosity,
                        journal_feed=problem.journal_feed(float(phi)))
              for x, y, vx, vy, a, b, phi in zip(trajectory.x, trajectory.y, trajectory.vx,
                                                  trajectory.vy, wj, wb,
                                                  trajectory.crank_angle, strict=True)]
    for state in states[:5]:
        session.force(state)
    start = time.perf_counter()
    for _ in range(3):
        for state in states:
            session.force(state)
    return (time.perf_counter() - start) / (3 * len(states))


def main() -> None:
    rotating, fixed = problems()
    case = Case.from_toml(CASE)
    settings = Simulation(case, **GRID).solver.model_copy(update={"output_step_deg": 1.0})
    rows = []
    trajectory = integrate_cycle(rotating, OrbitState(), settings, "quasi_static")
    t_rot, t_fix = solve_time(rotating, trajectory), solve_time(fixed, trajectory)
    rows.append(("film force along the orbit (72×16, warm)", t_fix * 1e3, t_rot * 1e3, "ms"))
    for name in ("quasi_static", "implicit"):
        slow_fixed = fixed
        if name == "implicit":
            slow_fixed = dataclasses.replace(fixed, film=_NoFlight(
                fixed.film.geometry, **GRID, tolerance=fixed.film.tolerance))
        a = cycle_time(slow_fixed, name, settings)
        b = cycle_time(rotating, name, settings)
        rows.append((f"orbit cycle, {name} (same Python film path)", a, b, "s"))
    a = cycle_time(fixed, "auto", settings)
    b = cycle_time(rotating, "auto", settings)
    rows.append(("orbit cycle, auto as shipped (fixed hole: compiled flight)", a, b, "s"))
    lines = ["# Crank-pin oil hole: turning vs fixed in the shell", "",
             f"`python benchmarks/crank_feed_benchmarks.py` — {platform.processor() or 'cpu'}, "
             f"Python {platform.python_version()}; case "
             "`examples/passenger_car_diesel_2000rpm_crank_fed.toml`, grid 72×16. Target: "
             "turning ≤ 1.2× fixed.", "",
             "| what | fixed hole | turning hole | ratio |", "| --- | ---: | ---: | ---: |"]
    for what, a, b, unit in rows:
        lines.append(f"| {what} | {a:.3g} {unit} | {b:.3g} {unit} | {b / a:.2f} |")
    out = ROOT / "benchmarks" / "crank_feed_benchmarks.md"
    out.write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
