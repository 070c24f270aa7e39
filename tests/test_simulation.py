"""Simulation API, characteristics, heat balance, load tables and shipped cases (issue 4)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.short.film import ShortBearingFilm
from conrod.orbit.heat_balance import effective_temperature

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def table_case(tmp_path: Path, rows: str, **sections) -> Case:
    """A [load]-table case with a small bearing; ``sections`` override TOML sections."""
    (tmp_path / "load.csv").write_text(rows, encoding="utf-8")
    text = {
        "bearing": "diameter = 0.05\nwidth = 0.02\nradial_clearance = 30e-6\n",
        "lubricant": "viscosity = 0.01\n",
        "load": 'table = "load.csv"\nspeed = 3000\ncycle_deg = 360\n',
        "solver": 'film = "short"\nmax_cycles = 4\n',
    }
    text.update(sections)
    body = "".join(f"[{name}]\n{content}\n" for name, content in text.items())
    (tmp_path / "case.toml").write_text(body, encoding="utf-8")
    return Case.from_toml(tmp_path / "case.toml")


def sinus_rows(n: int = 36, mean: float = 3000.0, amplitude: float = 2000.0) -> str:
    angles = np.arange(n) * 360.0 / n
    lines = ["# provenance comment", "crank_angle_deg,load_x_N,load_y_N"]
    for a in angles:
        lines.append(f"{a},{mean + amplitude * math.cos(math.radians(a))},"
                     f"{amplitude * math.sin(math.radians(a))}")
    return "\n".join(lines) + "\n"


@pytest.fixture(scope="module")
def table_run(tmp_path_factory):
    case = table_case(tmp_path_factory.mktemp("table"), sinus_rows())
    return case, Simulation(case).run()


def test_run_returns_typed_periodic_results(table_run):
    _, results = table_run
    s, cycle = results.summary, results.cycle
    assert s.periodic and s.periodicity_error <= 1e-3 and s.cycles >= 2
    assert len(cycle) == 360 and cycle.crank_angle_deg[1] == pytest.approx(1.0)
    assert s.h_min == pytest.approx(cycle.h_min.min())
    assert math.degrees(s.p_max_crank_angle) == pytest.approx(
        cycle.crank_angle_deg[np.argmax(cycle.p_max)])
    assert np.all(cycle.h_min > 0) and np.all(cycle.eccentricity_ratio < 1)


def test_friction_power_is_torque_times_relative_speed(table_run):
    _, results = table_run
    c = results.cycle
    relative = c.journal_speed - c.shell_speed
    assert np.allclose(c.friction_power, np.abs(c.friction_torque * relative), rtol=1e-12)


def test_friction_torque_matches_raimondi_boyd_friction_variable():
    """Steady short bearing: (R/c) f = 2π² S/√(1−ε²) + ε sin φ/2 (Raimondi & Boyd)."""
    radius, width, c, mu, omega = 0.025, 0.02, 30e-6, 0.01, 300.0
    film = ShortBearingFilm(BearingGeometry(diameter=2 * radius, width=width, radial_clearance=c))
    eps, psi = 0.6, 0.3
    state = FilmState(eccentricity_x=eps * c * math.cos(psi),
                      eccentricity_y=eps * c * math.sin(psi), velocity_x=0, velocity_y=0,
                      journal_speed=omega, shell_speed=0, viscosity=mu)
    r = film.solve(state)
    load = math.hypot(r.force_x, r.force_y)
    radial = r.force_x * math.cos(psi) + r.force_y * math.sin(psi)  # on the line of centres
    tangential = -r.force_x * math.sin(psi) + r.force_y * math.cos(psi)
    attitude = math.atan2(abs(tangential), -radial)
    sommerfeld = (radius / c) ** 2 * mu * (omega / (2 * math.pi)) / (load / (2 * radius * width))
    friction_variable = 2 * math.pi**2 * sommerfeld / math.sqrt(1 - eps**2) + eps * math.sin(
        attitude) / 2
    assert abs(r.friction_torque_journal) / (radius * load) * radius / c == pytest.approx(
        friction_variable, rel=1e-9)


def test_side_flow_equals_edge_flux_of_the_pressure_field():
    """Flow balance: the reported side flow is the Poiseuille flux through both edges."""
    geometry = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=30e-6)
    film = ShortBearingFilm(geometry, n_theta=2000, n_z=201)
    state = FilmState(eccentricity_x=12e-6, eccentricity_y=-9e-6, velocity_x=4e-3, velocity_y=2e-3,
                      journal_speed=300.0, shell_speed=0.0, viscosity=0.01)
    result = film.solve(state, with_pressure=True)
    theta, z = film.grid()
    h = 30e-6 - 12e-6 * np.cos(theta) + 9e-6 * np.sin(theta)
    dz = z[1] - z[0]
    gradient = (3 * result.pressure[:, -1] - 4 * result.pressure[:, -2]
                + result.pressure[:, -3]) / (2 * dz)
    edge_flux = 2 * np.sum(h**3 / (12 * 0.01) * -gradient) * 0.025 * (theta[1] - theta[0])
    assert edge_flux == pytest.approx(result.side_flow, rel=2e-3)


def test_heat_balance_closes_with_reported_means(table_run):
    case, results = table_run
    s, lub = results.summary, case.lubricant
    rise = s.mean_friction_power / (lub.density * lub.specific_heat * s.mean_side_flow)
    assert s.effective_temperature == pytest.approx(lub.supply_temperature + rise, rel=1e-12)
    assert effective_temperature(10.0, 0.0, 80.0, 860.0, 2000.0) is None


def test_vogel_viscosity_is_iterated_to_the_effective_temperature(tmp_path):
    lub = "vogel_a = 6.0e-5\nvogel_b = 900.0\nvogel_c = 95.0\nsupply_temperature = 80.0\n"
    solver = 'film = "short"\nintegrator = "quasi_static"\nthermal_tolerance = 0.05\n'
    case = table_case(tmp_path, sinus_rows(), lubricant=lub,
                      solver=solver + "thermal_iterations = 30\n")
    results = Simulation(case).run()
    s = results.summary
    assert s.thermal_iterations >= 1
    temperature_of_viscosity = case.lubricant.vogel_b / math.log(s.viscosity / 6.0e-5) - 95.0
    assert temperature_of_viscosity == pytest.approx(s.effective_temperature, abs=0.1)


def test_load_table_errors_name_the_problem(tmp_path):
    with pytest.raises(CaseError, match="missing column"):
        Simulation(table_case(tmp_path, "crank_angle_deg,load_x_N\n0,1\n1,2\n2,3\n3,4\n"))
    with pytest.raises(CaseError, match="strictly increasing"):
        Simulation(table_case(tmp_path, "crank_angle_deg,load_x_N,load_y_N\n0,1,0\n2,1,0\n"
                                        "1,1,0\n3,1,0\n"))
    case = table_case(tmp_path, sinus_rows())
    (tmp_path / "load.csv").unlink()
    with pytest.raises(CaseError, match="cannot be read"):
        Simulation(case)


def test_closing_row_of_a_table_is_dropped(tmp_path):
    rows = sinus_rows(n=36) + "360,5000,0\n"
    cycle = Simulation(table_case(tmp_path, rows)).load_cycle()
    assert cycle.crank_angle.size == 36 and cycle.journal_speed[0] == pytest.approx(
        3000 * math.pi / 30)


def test_lubricant_needs_exactly_one_viscosity_source(tmp_path):
    with pytest.raises(CaseError, match="exactly one"):
        table_case(tmp_path, sinus_rows(), lubricant="density = 850.0\n")


def test_solver_overrides_are_validated(tmp_path):
    case = table_case(tmp_path, sinus_rows())
    with pytest.raises(CaseError, match="solver.integrator"):
        Simulation(case, integrator="euler")
    with pytest.raises(CaseError, match="solver.film = .nonexistent.: Input should be .short."):
        Simulation(case, film="nonexistent")


def _quick(case: Case, **overrides):
    return Simulation(case, **overrides).run()


def test_passenger_car_2000rpm_runs_with_default_solver_without_contact():
    results = _quick(Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml"))
    assert results.summary.periodic
    assert results.summary.max_contact_force == 0.0
    assert results.summary.film_model == "short"


@pytest.mark.parametrize("name", [
    "flores2006_table_load.toml", "ruston_hornsby_6vebx_mk3.toml",
    "passenger_car_diesel_1000rpm.toml", "kamaz_740_truck_diesel.toml",
])
def test_shipped_cases_run(name):
    case = Case.from_toml(EXAMPLES / name)
    results = _quick(case, film="short", integrator="quasi_static", max_cycles=2,
                     quasi_static_step_deg=1.0, output_step_deg=2.0)
    assert np.all(np.isfinite(results.cycle.h_min)) and results.summary.h_min >= 0.0
    assert results.summary.cycles >= 1
