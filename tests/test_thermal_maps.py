"""Quasi-steady film temperature maps at chosen crank angles
(conrod.simulation.thermal_maps): at a constant load every map is the cycle-mean field with
the same walls, every map conserves energy with its walls held, huge wall coefficients at
the supply temperature hold the map there, the fixed-shell and volume-change extensions of
the energy solve leave the cycle-mean answer as it was, the outputs are written and bad
angles are refused in one line."""

from __future__ import annotations

import dataclasses
import json
import tomllib
from pathlib import Path

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.errors import CaseError
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.output.registry import write_results
from conrod.simulation.thermal_film_run import cycle_flows, thermal_film_orbit
from conrod.simulation.thermal_maps import map_rows, solve_maps

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
COARSE = {"n_theta": 24, "n_z": 8, "output_step_deg": 4.0}
SUPPLY = 90.0
TIGHT = {"periodicity_tolerance": 1e-6, "max_cycles": 40, "relative_tolerance": 1e-9,
         "absolute_tolerance": 1e-7}
"""A constant-load orbit settled to its equilibrium (ε steady to 1e-7) [-]."""


def _data(**solver) -> dict:
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel_thermal.toml").read_text())
    data["solver"].update(COARSE, **solver)
    return data


def _heat_capacity(case: Case) -> float:
    lubricant = case.lubricant
    return lubricant.density_at(lubricant.supply_temperature) * lubricant.specific_heat


@pytest.fixture(scope="module")
def engine():
    """The shipped thermal example, coarse: the simulation and its converged orbit."""
    simulation = Simulation(Case.from_dict(_data(), base_dir=EXAMPLES))
    return simulation, thermal_film_orbit(simulation)


@pytest.fixture(scope="module")
def steady(tmp_path_factory):
    """The example's bearing, oil and heat paths under a constant 8 kN [load] table: a
    steady bearing, its converged orbit."""
    folder = tmp_path_factory.mktemp("steady")
    rows = [f"{a},-8000.0,0.0" for a in np.arange(0.0, 361.0, 10.0)]
    (folder / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + "\n".join(rows))
    data = {key: value for key, value in _data(output_step_deg=10.0, **TIGHT).items()
            if key in ("title", "bearing", "lubricant", "solver")}
    data["load"] = {"table": "load.csv", "speed": 2600, "cycle_deg": 360}
    simulation = Simulation(Case.from_dict(data, base_dir=folder))
    return simulation, thermal_film_orbit(simulation)


def _maps(simulation, thermal, angles, coefficient=None, **film):
    """The maps of ``thermal`` at ``angles`` [deg], its walls replaced by ``film`` [°C] and
    the film-to-wall coefficient by ``coefficient`` [W/(m² K)] where given."""
    if film:
        thermal = dataclasses.replace(thermal, film=dataclasses.replace(thermal.film, **film))
    if coefficient is None:
        coefficient = simulation.solver.thermal_wall_coefficient
    return solve_maps(thermal, np.asarray(angles, float), _heat_capacity(simulation.case),
                      SUPPLY, coefficient)


def test_at_a_constant_load_every_map_is_the_cycle_mean_field(steady):
    """The same flows at every instant: a map with the walls held at the converged cycle-mean
    temperatures is the cycle-mean field, to the orbit's steadiness (measured 24 × 8 with the
    orbit settled to 1e-6: within 1.7e-5 K of a 32 K rise; with the default periodicity
    tolerance 1e-3, ε varies by 5e-4 over the cycle and the maps by up to 0.09 K)."""
    simulation, thermal = steady
    maps = _maps(simulation, thermal, [0.0, 120.0, 250.0])
    mean = thermal.film.temperature
    rise = float(mean.max() - SUPPLY)
    assert rise > 5.0  # a film that heats up
    for k in range(3):
        assert np.max(np.abs(maps.temperature[k] - mean)) < 1e-5 * rise
        assert abs(maps.to_volume[k]) < 1e-6 * maps.generated[k]  # the journal at rest


def test_every_map_conserves_energy_with_its_walls_held(engine):
    simulation, thermal = engine
    maps = _maps(simulation, thermal, [0.0, 30.0, 500.0])
    assert np.allclose(maps.crank_angle_deg, [0.0, 28.0, 500.0])  # nearest rows of a 4° output
    for k in range(3):
        assert abs(maps.imbalance(k)) < 1e-9 * maps.generated[k]
        assert maps.hottest(k)[0] > SUPPLY
    assert maps.generated.max() > 1.3 * maps.generated.min()  # the instants differ
    assert np.max(np.abs(maps.to_volume)) > 0.01 * maps.generated.max()  # the film squeezes
    assert maps.temperature.min() >= SUPPLY - 1e-6  # nothing colder than the coolest source


def test_huge_wall_coefficients_at_the_supply_temperature_hold_the_map_there(engine):
    simulation, thermal = engine
    maps = _maps(simulation, thermal, [30.0], journal_temperature=SUPPLY,
                 shell_temperature=SUPPLY, coefficient=1.0e9)
    assert np.max(np.abs(maps.temperature - SUPPLY)) < 0.05
    assert abs(maps.imbalance(0)) < 1e-9 * maps.generated[0]


def test_a_held_shell_at_its_own_temperature_and_zero_volume_change_change_nothing(engine):
    """The cycle-mean answer with the shell free; the same flows with the shell held at that
    answer's shell temperature give the same field (round-off), and a zero volume change the
    very same field as none."""
    simulation, thermal = engine
    s = simulation.solver
    flows = cycle_flows(thermal.problem, thermal.cycle)
    walls = ThermalWalls(s.thermal_wall_coefficient, s.thermal_housing_coefficient,
                         s.thermal_housing_temperature)
    capacity = _heat_capacity(simulation.case)
    free = solve_energy(flows, capacity, SUPPLY, walls)
    held = solve_energy(flows, capacity, SUPPLY, dataclasses.replace(
        walls, shell_temperature=free.shell_temperature))
    assert np.max(np.abs(held.temperature - free.temperature)) < 1e-9
    assert held.to_shell == pytest.approx(free.to_shell, rel=1e-9)
    zero = solve_energy(flows, capacity, SUPPLY, walls, np.zeros(flows.area.shape))
    assert np.array_equal(zero.temperature, free.temperature)
    assert zero.to_volume == 0.0
    assert zero.to_oil == pytest.approx(free.to_oil, rel=1e-12)  # counted above T_0


def test_the_run_writes_the_maps_table_summary_and_figure(tmp_path):
    """Through the Python API and the one writer, on a short grid: the default angles (h_min
    and p_max), the long table, summary.json 'thermal_film' 'maps', the figure."""
    case = Case.from_dict(_data(n_theta=16, n_z=4, output_step_deg=8.0, thermal_iterations=2),
                          base_dir=EXAMPLES)
    results = Simulation(case).run()
    maps = results.thermal_maps
    rows = [int(np.argmin(results.cycle.h_min)), int(np.argmax(results.cycle.p_max))]
    assert sorted(maps.crank_angle_deg) == sorted(set(results.cycle.crank_angle_deg[rows]))
    write_results(results, tmp_path / "out")
    summary = json.loads((tmp_path / "out" / "summary.json").read_text())
    items = summary["thermal_film"]["maps"]
    assert [item["crank_angle_deg"] for item in items] == maps.crank_angle_deg.tolist()
    assert items[0]["max_film_temperature_C"] == pytest.approx(maps.hottest(0)[0])
    heat = items[0]["heat_to_oil_W"] + items[0]["heat_to_journal_W"] + items[0]["heat_to_shell_W"]
    assert items[0]["generated_power_W"] == pytest.approx(heat, rel=1e-9)
    table = (tmp_path / "out" / "thermal_maps.csv").read_text().splitlines()
    assert table[0] == "crank_angle_deg,theta_deg,z_mm,temperature_C"
    assert len(table) == 1 + maps.crank_angle_deg.size * 16 * 5
    assert (tmp_path / "out" / "temperature_maps.png").stat().st_size > 10_000


def test_bad_map_angles_are_refused_in_one_line():
    with pytest.raises(CaseError, match=r"thermal_map_angles\[1\] = 800.*720 \[deg\]"):
        Case.from_dict(_data(thermal_map_angles=[10.0, 800.0]), base_dir=EXAMPLES)
    with pytest.raises(CaseError, match=r"thermal_map_angles = 400.0.*0 … 360 .*deg"):
        map_rows(np.arange(0.0, 360.0, 10.0), np.array([400.0]), 360.0)
    rows = map_rows(np.arange(0.0, 360.0, 10.0), np.array([358.0, 4.0, 6.0]), 360.0)
    assert rows.tolist() == [0, 0, 1]  # nearest around the cycle
