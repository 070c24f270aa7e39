"""The bore warm from the thermal film (TEHD, conrod.simulation.warm_film_run): the shell-side
temperature's balance, the film-driven warm bore against the given-temperature path with
the same numbers, a free ring's growth, the refusal, and a coarse run of the TEHD example;
the thermal film on the elastic bore against its isothermal limit."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.errors import CaseError
from conrod.simulation.warm_film_run import WarmFilmBore, bore_temperatures

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
COARSE = {"n_theta": 36, "n_z": 8, "output_step_deg": 4.0}
ALPHA = 11.5e-6


def _data(**solver) -> dict:
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel_tehd.toml").read_text())
    data["solver"].update({**COARSE, **solver})
    return data


def _case(data: dict) -> Case:
    return Case.from_dict(data, base_dir=EXAMPLES)


def test_the_shell_side_temperature_averages_to_the_shell_temperature():
    """T_b(θ) = (H T̄(θ) + H_h T_h)/(H + H_h) summed over θ is the energy equation's shell
    balance: its mean is T_s of the solution, to round-off."""
    from conrod.film.base import BearingGeometry, FilmState
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.film.thermal.energy import ThermalWalls, solve_energy

    geometry = BearingGeometry(diameter=0.08, width=0.03, radial_clearance=5e-5,
                               supply_pressure=3e5)
    film = ReynoldsFilm(geometry, n_theta=36, n_z=8)
    state = FilmState(eccentricity_x=3.5e-5, eccentricity_y=1e-5, velocity_x=0.0,
                      velocity_y=0.0, journal_speed=272.0, viscosity=0.01)
    flows, _ = film.film_flows(state, film.initial_memory())
    walls = ThermalWalls(2000.0, 1000.0, 95.0)
    answer = solve_energy(flows, 860.0 * 2000.0, 90.0, walls)
    journal, shell = bore_temperatures(answer, flows.area, walls)
    assert journal == answer.journal_temperature
    assert shell.mean() == pytest.approx(answer.shell_temperature, abs=1e-9)
    assert np.ptp(shell) > 0.1  # the film's angular variation reaches the bore
    adiabatic = ThermalWalls(0.0, 1000.0, 95.0)
    flat = bore_temperatures(solve_energy(flows, 860.0 * 2000.0, 90.0, adiabatic), flows.area,
                             adiabatic)[1]
    assert np.ptp(flat) == 0.0


def _given_path_case(data: dict, journal: float, shell: np.ndarray, ambient: float) -> Case:
    """The case with [housing.thermal] written out by hand with the same temperatures."""
    given = {**data}
    angles = [360.0 * j / shell.size for j in range(shell.size)]
    given["housing"] = {**data["housing"], "thermal": {
        "journal_temperature": journal, "shell_temperature_angles": angles,
        "shell_temperatures": [float(t) for t in shell], "ambient_temperature": ambient}}
    return _case(given)


def test_the_film_driven_bore_is_the_given_temperature_path_with_the_same_numbers():
    from conrod.film.thermal.energy import ThermalWalls

    data = _data()
    sim = Simulation(_case(data), rigid_companion=False)
    warm = WarmFilmBore.start(sim, ThermalWalls(2000.0, 1000.0, 95.0))
    theta = 2.0 * np.pi * np.arange(36) / 36
    warm.journal, warm.shell = 104.0, 100.0 + 6.0 * np.cos(theta - 0.4)
    film_driven = warm.current = warm.simulation()
    given = Simulation(_given_path_case(data, 104.0, warm.shell, 95.0), rigid_companion=False)
    assert film_driven.geometry().radial_clearance == given.geometry().radial_clearance
    driven_housing, given_housing = film_driven.housing(), given.housing()
    assert np.array_equal(driven_housing.warm.bore, given_housing.warm.bore)
    result = warm.results()
    assert result.clearance_change == pytest.approx(
        given.geometry().radial_clearance - data["bearing"]["radial_clearance"], rel=1e-12)
    assert result.out_of_round == pytest.approx(float(np.ptp(given_housing.warm.profile(
        given_housing.projector))), rel=1e-12)
    assert result.out_of_round > 1e-7  # a hot side distorts the bore


def test_a_free_ring_warm_from_the_film_grows_by_alpha_delta_t_r():
    """No FE housing: the housing is a free ring at the mean shell-side temperature T_s;
    Δc = α (T_s − T_ref) R_b − α (T_s − T_ref) t_s − α (T_j − T_ref) R."""
    from conrod.film.thermal.energy import ThermalWalls

    data = _data()
    data["housing"] = {"model": "rigid", "thermal": {}}
    sim = Simulation(_case(data))
    warm = WarmFilmBore.start(sim, ThermalWalls(2000.0, 1000.0, 95.0))
    warm.journal, warm.shell = 110.0, np.linspace(95.0, 105.0, 36)
    geometry = warm.simulation().geometry()
    radius = 0.04  # the ring's growth ε_h R_b less the shell's ε_h t_s: ε_h R
    expected = ALPHA * (100.0 - 20.0) * radius - ALPHA * (110.0 - 20.0) * radius
    assert geometry.radial_clearance - 5e-5 == pytest.approx(expected, rel=1e-9)
    assert warm.results().out_of_round is None


def test_a_bore_without_temperatures_needs_the_thermal_film():
    data = _data(thermal="heat_balance")
    with pytest.raises(CaseError, match=r"housing.thermal: no journal_temperature.*"
                                        r"thermal = 'film'"):
        Simulation(_case(data)).geometry()
    bad = _data()
    bad["housing"]["thermal"] = {"housing_temperature": 100.0}
    with pytest.raises(CaseError, match="journal_temperature is required"):
        _case(bad)


@pytest.fixture(scope="module")
def tehd_run():
    return Simulation(_case(_data()), rigid_companion=False).run()


def test_the_tehd_run_converges_conserves_energy_and_reports_its_bore(tehd_run):
    from conrod.output.ehd_tables import elastic_summary_items

    film = tehd_run.elastic.thermal_film
    assert film.converged
    assert abs(film.generated - (film.to_oil + film.to_journal + film.to_shell)) < (
        1e-9 * film.generated)
    warm = film.warm_bore
    # the last orbit's bore is at the relaxed temperatures, within the tolerance of the film's
    assert warm.journal_temperature == pytest.approx(film.journal_temperature, abs=0.5)
    assert warm.shell_side_temperature.mean() == pytest.approx(film.shell_temperature,
                                                               abs=0.5)
    # one truth: the clearance the elastic orbit ran with is the cold one + Δc
    assert tehd_run.elastic.clearance == pytest.approx(5e-5 + warm.clearance_change,
                                                       rel=1e-12)
    assert tehd_run.info["thermal_clearance_change_um"] == pytest.approx(
        warm.clearance_change * 1e6, rel=1e-12)
    items = elastic_summary_items(tehd_run)["thermal_film"]
    assert items["warm_bore_out_of_round_um"] == pytest.approx(warm.out_of_round * 1e6)
    assert "bore warm from the film" in film.headline_text()
    from conrod.results.summary import headline

    # one truth: the headline printed for the elastic run is summary.json's
    assert headline(tehd_run)["temperature"] == film.headline_text()
    assert headline(tehd_run) == headline(tehd_run.elastic) | dict(tehd_run.headline_extra)
    from conrod.output.registry import figures
    from conrod.output.thermal_tables import thermal_outputs

    spec = {spec.file: spec for spec in thermal_outputs(tehd_run.elastic, figures)}[
        "warm_bore.png"]
    assert spec.build().axes  # T_b(θ) and the thermal profile drawn
    assert warm.profile is not None and np.ptp(warm.profile) == pytest.approx(warm.out_of_round)


def _elastic_thermal_data(**solver) -> dict:
    data = _data(n_theta=24, **solver)
    data["housing"].pop("assembly")
    data["housing"].pop("thermal")
    return data


def test_isothermal_limit_of_the_elastic_thermal_film_is_the_elastic_run_at_supply():
    walls = {"thermal_wall_coefficient": 1.0e7, "thermal_housing_coefficient": 1.0e6,
             "thermal_housing_temperature": 90.0, "thermal_journal_temperature": 90.0}
    hot = Simulation(_case(_elastic_thermal_data(**walls)), rigid_companion=False).run()
    film = hot.elastic.thermal_film
    assert np.max(np.abs(film.temperature - 90.0)) < 0.2
    assert abs(film.generated - (film.to_oil + film.to_journal + film.to_shell)) < (
        1e-9 * film.generated)
    cold = Simulation(_case(_elastic_thermal_data(thermal="heat_balance",
                                                  thermal_iterations=0)),
                      rigid_companion=False).run()
    assert hot.elastic.summary.h_min == pytest.approx(cold.elastic.summary.h_min, rel=2e-3)
    assert hot.elastic.summary.p_max == pytest.approx(cold.elastic.summary.p_max, rel=2e-3)


def test_the_rigid_companion_runs_its_own_warm_bore_from_its_film():
    """The rigid bore of the TEHD example (the elastic run's companion): the thermal film
    on the rigid bore, its clearance that of the FE housing conducting from the film's
    shell-side temperatures (the given-temperature path with the same numbers), round."""
    from conrod.housing.housing import Housing

    data = _data(thermal_iterations=3, thermal_tolerance=5.0)
    rigid = Simulation(_case(data), housing="rigid").run()
    film = rigid.thermal_film
    warm = film.warm_bore
    assert warm.out_of_round is None and warm.profile is None
    assert abs(film.generated - (film.to_oil + film.to_journal + film.to_shell)) < (
        1e-9 * film.generated)
    given = _given_path_case(data, warm.journal_temperature, warm.shell_side_temperature,
                             95.0)
    housing = Housing.from_case(given)
    assert rigid.clearance - 5e-5 == pytest.approx(
        housing.warm.clearance_change(housing.projector), rel=1e-9)
    assert warm.housing_temperature == pytest.approx(housing.warm.housing_temperature,
                                                     rel=1e-12)
