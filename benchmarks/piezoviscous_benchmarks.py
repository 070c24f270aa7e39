"""Piezoviscous film benchmarks: warm Reynolds solve with μ(p) against the isoviscous one,
short-bearing force call, and the shipped passenger-car orbit with piezoviscosity on.

Run:  python benchmarks/piezoviscous_benchmarks.py   (writes benchmarks/piezoviscous_benchmarks.md)

Solve timing: D = 50 mm, L = 20 mm, c = 25 µm, μ₀ = 6.5 mPa s, ω_j = 210 rad/s (2000 rpm),
ε = 0.9 (p_max ≈ 40 MPa isoviscous, Barus α p_max ≈ 0.6), journal creeping by 0.2 % c per
call as in an orbit step; median of 30 warm solves after one cold solve (numba compiled).
Orbit rows: ``examples/passenger_car_diesel_2000rpm.toml`` (rigid bearing, μ₀ = 6.5 mPa s as
shipped) and ``examples/ruston_hornsby_6vebx_mk3.toml`` (μ₀ = 15 mPa s), isoviscous and with
pressure–viscosity laws of typical engine oils.
"""

from __future__ import annotations

import math
import statistics
import sys
import time
import tomllib
from pathlib import Path

from conrod.cases.case import Case
from conrod.errors import ConvergenceError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.io.atomic import write_text
from conrod.simulation.simulation import Simulation

ROOT = Path(__file__).resolve().parents[1]
OUTPUT = Path(__file__).with_suffix(".md")
GEOMETRY = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=2.5e-5)
MU0, SPEED, ECCENTRICITY = 0.0065, 210.0, 0.9
BARUS = PressureViscosity("barus", coefficient=1.5e-8)
ROELANDS = PressureViscosity("roelands", roelands_index=0.6)
LAWS = {"isoviscous": None, "Barus α = 1.5e-8 1/Pa": BARUS, "Roelands z = 0.6": ROELANDS}


def state_at(k: int) -> FilmState:
    c, angle = GEOMETRY.radial_clearance, 0.002 * k
    return FilmState(eccentricity_x=ECCENTRICITY * c * math.cos(angle),
                     eccentricity_y=ECCENTRICITY * c * math.sin(angle),
                     journal_speed=SPEED, viscosity=MU0)


def warm_solve_time(law: PressureViscosity | None, grid=(144, 32), count: int = 30) -> tuple:
    """(median warm solve [ms], p_max [MPa]) of a Reynolds film."""
    film = ReynoldsFilm(GEOMETRY, *grid, pressure_viscosity=law)
    p_max = film.solve(state_at(0)).max_pressure
    times = []
    for k in range(1, count + 1):
        start = time.perf_counter()
        film.force(state_at(k))
        times.append(time.perf_counter() - start)
    return 1e3 * statistics.median(times), 1e-6 * p_max


def short_call_time(law: PressureViscosity | None, count: int = 2000) -> float:
    """Median short-bearing force call [µs]."""
    film = ShortBearingFilm(GEOMETRY, pressure_viscosity=law)
    state = state_at(0)
    film.force(state)
    start = time.perf_counter()
    for _ in range(count):
        film.force(state)
    return 1e6 * (time.perf_counter() - start) / count


def orbit_row(lubricant: dict, solver: dict,
              example: str = "passenger_car_diesel_2000rpm.toml") -> str:
    """Table cells h_min, p_max, friction, wall time of one periodic orbit (or the error)."""
    path = ROOT / "examples" / example
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["lubricant"].update(lubricant)
    data.setdefault("solver", {}).update(solver)
    case = Case.from_dict(data, base_dir=path.parent, path=path)
    start = time.perf_counter()
    try:
        s = Simulation(case).run().summary
    except ConvergenceError as error:
        return f"failed: {error} | – | – | {time.perf_counter() - start:.1f} |"
    return (f"{1e6 * s.h_min:.2f} | {1e-6 * s.p_max:.0f} | {s.mean_friction_power:.1f} | "
            f"{time.perf_counter() - start:.1f} |")


REYNOLDS = {"film": "reynolds", "integrator": "quasi_static"}
ORBIT_LAWS = {
    "isoviscous": {},
    "Barus α = 1.5e-8 1/Pa": {"pressure_viscosity": "barus",
                              "pressure_viscosity_coefficient": 1.5e-8},
    "Roelands z = 0.6": {"pressure_viscosity": "roelands", "roelands_index": 0.6},
    "Roelands z = 0.6, p_L = 0.5 GPa": {"pressure_viscosity": "roelands", "roelands_index": 0.6,
                                        "pressure_viscosity_limit": 5.0e8},
}


def main() -> None:
    lines = ["# Piezoviscous film benchmarks", "",
             f"`python benchmarks/piezoviscous_benchmarks.py` ({sys.platform}, 2-core machine).",
             "", "## Reynolds film, warm solve, 144×32, ε = 0.9, 2000 rpm", "",
             "| law | warm solve [ms] | ratio to isoviscous | p_max [MPa] |",
             "| --- | --- | --- | --- |"]
    iso_time = None
    for name, law in LAWS.items():
        warm, p_max = warm_solve_time(law)
        iso_time = iso_time or warm
        lines.append(f"| {name} | {warm:.2f} | {warm / iso_time:.2f} | {p_max:.1f} |")
    lines += ["", "## Short-bearing force call", "", "| law | call [µs] |", "| --- | --- |"]
    for name, law in LAWS.items():
        lines.append(f"| {name} | {short_call_time(law):.1f} |")
    lines += ["", "## Passenger-car diesel, 2000 rpm, rigid bearing, periodic orbit", "",
              "| film | law | h_min [µm] | p_max [MPa] | mean friction power [W] | wall [s] |",
              "| --- | --- | --- | --- | --- | --- |"]
    runs = [("short, adaptive", {"film": "short"}, name) for name in ORBIT_LAWS]
    runs += [("reynolds 72×16, quasi_static", REYNOLDS, name)
             for name in ("isoviscous", "Roelands z = 0.6")]
    for label, solver, name in runs:
        lines.append(f"| {label} | {name} | {orbit_row(ORBIT_LAWS[name], solver)}")
        print(lines[-1], flush=True)
    lines += ["", "## Ruston & Hornsby 6VEB-X Mk III (moderately loaded), rigid, periodic orbit",
              "", "| film | law | h_min [µm] | p_max [MPa] | mean friction power [W] | wall [s] |",
              "| --- | --- | --- | --- | --- | --- |"]
    for label, solver in (("short (two lands), adaptive", {}), ("reynolds 72×16, quasi_static",
                                                                 REYNOLDS)):
        for name in ("isoviscous", "Roelands z = 0.6"):
            row = orbit_row(ORBIT_LAWS[name], solver, "ruston_hornsby_6vebx_mk3.toml")
            lines.append(f"| {label} | {name} | {row}")
            print(lines[-1], flush=True)
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
