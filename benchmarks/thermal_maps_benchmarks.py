"""Cost and answers of the quasi-steady temperature maps at chosen crank angles
(``[solver] thermal_map_angles``, docs/thermal.md) on the KamAZ-740-like thermal example.

Run:  python benchmarks/thermal_maps_benchmarks.py   (writes benchmarks/thermal_maps_benchmarks.md)

One converged thermal film orbit of examples/kamaz_740_truck_diesel_thermal.toml (Reynolds
72 × 16, after a coarse warm-up), then the maps at every 60° and at the default angles (the
rows of the smallest h_min and the largest p_max): the time per map against the run's, and
per angle the hottest point, the heat flows, the squeezed share of the film, and — to show
how much the squeeze matters — the hottest point of the same energy solve with the squeezed
volume taken for supply oil (the cycle-mean equation applied as it is to one instant); last,
the run and its default maps with a ten times larger film-to-wall coefficient.
"""

from __future__ import annotations

import math
import os
import platform
import time
import tomllib
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.io.atomic import write_text
from conrod.simulation.simulation import Simulation
from conrod.simulation.thermal_film_run import thermal_film_orbit
from conrod.simulation.thermal_maps import default_map_angles, map_rows, solve_maps

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
OUTPUT = Path(__file__).with_suffix(".md")


def case(**solver) -> Case:
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel_thermal.toml").read_text())
    data["solver"].update(solver)
    return Case.from_dict(data, base_dir=EXAMPLES)


def naive_hottest(orbit, row: int, heat_capacity: float, supply: float, walls) -> float:
    """Hottest point [°C] of the instant's flows in the cycle-mean equation as it is (the
    squeezed volume fed at the supply temperature)."""
    problem = orbit.problem
    state = problem.row_state(orbit.cycle, row)
    flows, _ = problem.film.film_flows(state, problem.film.initial_memory())
    return float(solve_energy(flows, heat_capacity, supply, walls).temperature.max())


def stiff_walls(angles: np.ndarray, coefficient: float = 2.0e4) -> str:
    """The same run with a ten times larger film-to-wall coefficient: its cycle-mean peak
    and its maps' peaks at ``angles`` [deg] (one line)."""
    simulation = Simulation(case(thermal_wall_coefficient=coefficient))
    orbit = thermal_film_orbit(simulation)
    lubricant = simulation.case.lubricant
    supply = lubricant.supply_temperature
    maps = solve_maps(orbit, angles, lubricant.density_at(supply) * lubricant.specific_heat,
                      supply, coefficient)
    peaks = ", ".join(f"{maps.hottest(k)[0]:.1f} °C at {a:.0f}°" for k, a in enumerate(angles))
    return (f"With `thermal_wall_coefficient = {coefficient:g}` W/(m² K) (ten times the "
            f"example's): cycle-mean max {orbit.film.hottest[0]:.1f} °C, walls "
            f"{orbit.film.journal_temperature:.1f} / {orbit.film.shell_temperature:.1f} °C; "
            f"maps {peaks}.")


def main() -> None:
    thermal_film_orbit(Simulation(case(n_theta=24, n_z=8, output_step_deg=4.0)))  # compile
    simulation = Simulation(case())
    start = time.perf_counter()
    orbit = thermal_film_orbit(simulation)
    run_wall = time.perf_counter() - start
    lubricant = simulation.case.lubricant
    supply = lubricant.supply_temperature
    heat_capacity = lubricant.density_at(supply) * lubricant.specific_heat
    coefficient = simulation.solver.thermal_wall_coefficient
    defaults = default_map_angles(orbit.cycle)
    angles = np.concatenate([np.arange(0.0, 720.0, 60.0), defaults])
    start = time.perf_counter()
    maps = solve_maps(orbit, angles, heat_capacity, supply, coefficient)
    maps_wall = time.perf_counter() - start
    film = orbit.film
    walls = ThermalWalls(coefficient, 0.0, film.housing_temperature, film.journal_temperature,
                         film.shell_temperature)
    rows = map_rows(np.asarray(orbit.cycle.crank_angle_deg), angles,
                    float(np.degrees(orbit.problem.loads.cycle)))
    header = ("crank angle [deg]", "h_min [µm]", "p_max [MPa]", "map max [°C] (θ, z)",
              "generated [W] = oil + journal + shell + volume", "squeezed share [-]",
              "max, squeezed oil taken for supply oil [°C]")
    lines = ["# Temperature maps at chosen crank angles: cost and answers", "",
             f"`python benchmarks/thermal_maps_benchmarks.py` on "
             f"{platform.processor() or 'cpu'}, {os.cpu_count()} cores (shared), Python "
             f"{platform.python_version()}; the KamAZ-740-like thermal example, Reynolds "
             "72 × 16, rigid bore.", "",
             f"Thermal film run (orbit and energy iterated, {film.iterations} iterations): "
             f"**{run_wall:.1f} s**; {angles.size} maps: **{maps_wall:.2f} s** "
             f"({maps_wall / angles.size * 1e3:.0f} ms a map: one film solve, one energy "
             "solve). Cycle-mean field: max "
             f"{film.hottest[0]:.1f} °C at θ = {math.degrees(film.hottest[1]):.0f}°; walls "
             f"held at journal {film.journal_temperature:.1f} °C, shell "
             f"{film.shell_temperature:.1f} °C. Last two rows: the default angles (h_min, "
             "p_max).", "", "| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    cycle = orbit.cycle
    for k, row in enumerate(rows):
        t, theta, z = maps.hottest(k)
        heat = (f"{maps.generated[k]:.0f} = {maps.to_oil[k]:.0f} + {maps.to_journal[k]:.0f} + "
                f"{maps.to_shell[k]:.0f} + {maps.to_volume[k]:.0f}")
        naive = naive_hottest(orbit, int(row), heat_capacity, supply, walls)
        lines.append(f"| {maps.crank_angle_deg[k]:.0f} | {cycle.h_min[row] * 1e6:.2f} | "
                     f"{cycle.p_max[row] / 1e6:.1f} | {t:.1f} ({math.degrees(theta):.0f}°, "
                     f"{z * 1e3:.1f} mm) | {heat} | {maps.squeeze_share[k]:.2f} | "
                     f"{naive:.1f} |")
    lines += ["", stiff_walls(defaults)]
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
