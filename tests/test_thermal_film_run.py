"""The thermal film over the cycle (conrod.simulation.thermal_film_run): one coarse run of
the shipped thermal example checked for conservation and plausibility, the isothermal limit
against the run at the supply temperature, and the one-line refusals."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.errors import CaseError

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
COARSE = {"n_theta": 24, "n_z": 8, "output_step_deg": 4.0}


def _case(**solver) -> Case:
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel_thermal.toml").read_text())
    data["solver"].update(solver)
    return Case.from_dict(data, base_dir=EXAMPLES)


@pytest.fixture(scope="module")
def thermal_run():
    return Simulation(_case(**COARSE)).run()


def test_thermal_run_conserves_energy_and_is_plausible(thermal_run):
    t = thermal_run.thermal_film
    assert t.converged
    assert abs(t.generated - (t.to_oil + t.to_journal + t.to_shell)) < 1e-9 * t.generated
    assert abs(t.to_journal) < 1e-9 * t.generated  # adiabatic journal
    assert t.to_shell == pytest.approx(1000.0 * 2 * np.pi * 0.04 * 0.03
                                       * (t.shell_temperature - 95.0), rel=1e-6)
    supply = 90.0
    assert supply < t.mean_temperature < t.hottest[0]
    assert t.temperature.min() >= supply - 1e-9  # nothing colder than the coolest source
    # dissipation = friction + squeeze + pumping power to the grid's error
    assert t.generated == pytest.approx(t.friction_power + t.squeeze_power + t.pumping_power,
                                        rel=0.15)
    assert thermal_run.summary.effective_temperature == pytest.approx(t.mean_temperature)


def test_thermal_run_writes_its_table_and_summary(thermal_run):
    from conrod.output.tables import summary_items

    items = summary_items(thermal_run)["thermal_film"]
    assert items["max_film_temperature_C"] == pytest.approx(thermal_run.thermal_film.hottest[0])
    table = thermal_run.thermal_film.table()
    assert table["temperature_C"].size == 24 * 9


def test_isothermal_limit_reproduces_the_run_at_the_supply_temperature():
    walls = {"thermal_wall_coefficient": 1.0e7, "thermal_housing_coefficient": 1.0e6,
             "thermal_housing_temperature": 90.0, "thermal_journal_temperature": 90.0}
    hot = Simulation(_case(**COARSE, **walls)).run()
    assert np.max(np.abs(hot.thermal_film.temperature - 90.0)) < 0.2
    cold = Simulation(_case(**COARSE, thermal="heat_balance", thermal_iterations=0)).run()
    assert hot.summary.h_min == pytest.approx(cold.summary.h_min, rel=2e-3)
    assert hot.summary.p_max == pytest.approx(cold.summary.p_max, rel=2e-3)


def test_films_without_a_viscosity_field_are_refused_in_one_line():
    with pytest.raises(CaseError, match=r"\[solver\] thermal = 'film'.*'short'.*reynolds"):
        Simulation(_case(**COARSE), film="short").run()


def test_bad_thermal_settings_are_refused():
    with pytest.raises(CaseError, match="thermal"):
        _case(thermal="hot")
    with pytest.raises(CaseError, match="thermal_wall_coefficient"):
        _case(thermal_wall_coefficient=-1.0)
