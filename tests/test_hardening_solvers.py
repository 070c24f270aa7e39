"""Regression tests of solver defects on plausible input, each from its minimal reproduction:
right numbers or a clear refusal (benchmarks and measurements in docs/reliability.md)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.ehd.film import ElasticFilm, ElasticSettings
from conrod.errors import CaseError
from conrod.film.capabilities import HasAcceptedAnswer
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.flight import flight_kernel
from conrod.orbit.characteristics import cycle_characteristics
from conrod.orbit.periodic import periodic_orbit
from conrod.orbit.problem import OrbitState
from conrod.orbit.rk2 import rk2_cycle
from conrod.simulation.simulation import Simulation
from elastic_helpers import kamaz_case, winkler_housing
from hardening_helpers import EXAMPLES
from plausible_bearings import Bearing, assert_plausible, run

PASSENGER_CAR = EXAMPLES / "passenger_car_diesel_2000rpm.toml"
PERIODIC = {"max_cycles": 8, "min_cycles": 2}
"""Orbits compared with each other run to their periodic orbit [-]."""


# -- mass-conserving film: the rows are the accepted steps ------------------------------------
def _fed_passenger_car(**solver) -> Case:
    """The passenger car at 2000 rpm fed at 0.3 MPa through a 2 mm central groove, JFO film
    at 36 × 8, hard contact only at the clearance circle."""
    data = Case.from_toml(PASSENGER_CAR).model_dump(exclude_none=True)
    data["bearing"].update(supply_pressure=0.3e6, grooves=[{"width": 0.002}])
    data["solver"].update(film="mass_conserving", n_theta=36, n_z=8,
                          contact_film_thickness=0.0, thermal_iterations=0, **solver)
    return Case.from_dict(data, base_dir=EXAMPLES)


def _rows_and_answers(integrator: str, **solver):
    simulation = Simulation(_fed_passenger_car(integrator=integrator, **solver))
    problem = simulation.problem()
    orbit = periodic_orbit(problem, simulation.solver)
    cycle = cycle_characteristics(problem, orbit.last)
    film = problem.film
    accepted = np.array([float(np.max(film.gauge_pressure(m.pressure, None)))
                         if m.thickness is not None else np.nan for m in orbit.last.film_memory])
    return np.degrees(cycle.crank_angle), cycle.p_max, accepted


def _largest_spike(p_max: np.ndarray) -> float:
    """Largest ratio of a row's p_max to the larger of its (periodic) neighbours [-]."""
    return float(np.max(p_max / np.maximum(np.roll(p_max, 1), np.roll(p_max, -1))))


def test_mass_conserving_rows_are_the_pressure_of_the_accepted_steps():
    """Massless orbit of the fed passenger car: every row's p_max is the maximum pressure
    of the implicit content step the orbit accepted there (before: the film re-solved at
    the row with its film fraction frozen — 824 MPa at 282° between 28 and 45 MPa, where
    the accepted step's pressure is 22.8 MPa, and 0.30 MPa at 289°)."""
    assert isinstance(MassConservingFilm(Case.from_toml(PASSENGER_CAR).bearing.geometry()),
                      HasAcceptedAnswer)
    angle, p_max, accepted = _rows_and_answers("quasi_static")
    steps = np.isfinite(accepted)
    assert steps.all()
    np.testing.assert_allclose(p_max, accepted, rtol=1e-12)
    assert p_max[angle == 282.0][0] < 50e6
    # measured 2.6 (7.4 MPa between 6.8 and 5.8 MPa at 423°); before 29
    assert _largest_spike(p_max) < 3.0
    assert float(np.min(p_max / np.minimum(np.roll(p_max, 1), np.roll(p_max, -1)))) > 0.3


@pytest.mark.slow
def test_mass_conserving_rows_with_mass_are_the_accepted_steps():
    """The same with the journal's mass (BDF2 content steps, one cycle from the massless
    periodic orbit)."""
    _, p_max, accepted = _rows_and_answers("auto", max_cycles=1, min_cycles=1,
                                           massless_start=True)
    np.testing.assert_allclose(p_max, accepted, rtol=1e-12)
    assert _largest_spike(p_max) < 3.0


def test_elastic_mass_conserving_film_reports_the_accepted_step():
    """On the deforming bore too, the answer at a step's end is that step's pressure (on
    the deformation the step solved), not a new solve."""
    from conrod.ehd.mass_conserving_ehd import ElasticMassConservingFilm
    from conrod.film.base import FilmState

    geometry = _fed_passenger_car().bearing.geometry()
    base = MassConservingFilm(geometry, n_theta=36, n_z=8, tolerance=1e-10)
    film = ElasticMassConservingFilm(base, winkler_housing(geometry, 36, 1e-13), 209.0,
                                     ElasticSettings(rigid_start=0.0, ramp=0.0))
    assert isinstance(film, HasAcceptedAnswer)
    c = geometry.radial_clearance
    state = FilmState(eccentricity_x=0.8 * c, eccentricity_y=0.1 * c, velocity_x=2e-3,
                      velocity_y=-1e-3, journal_speed=209.0, shell_speed=0.0, viscosity=0.01)
    memory = film.initial_memory()
    fx, fy, after = film.content_step(state, memory, 1e-4)
    result = film.accepted_result(state, after)
    assert result.force_x == pytest.approx(fx, rel=1e-12)
    assert result.force_y == pytest.approx(fy, rel=1e-12)
    assert float(np.max(after.deformation)) > 0.0  # the bore gave way
    assert film.accepted_result(state, memory) is None  # not a step's answer


# -- Reynolds film with mass: the flight Jacobian next to the shell ------------------------
def test_reynolds_flight_jacobian_is_finite_next_to_the_shell():
    """A journal 1e-6 c from the shell (the default integrator of a fed two-land bearing
    that the film cannot carry, D 62 mm, 1981 rpm, 64 MPa: the orbit reaches ε = 1 − 1e-16):
    the forward-difference position step of 1e-5 c crossed the shell, the Jacobian was NaN
    and TR-BDF2's matrix inverse raised LinAlgError (exit 1). Now the step goes towards
    the centre and the Jacobian is finite."""
    geometry = Case.from_toml(PASSENGER_CAR).bearing.geometry()
    film = ReynoldsFilm(geometry, n_theta=36, n_z=8)
    kernel = flight_kernel(film, None, 1e-8)
    c = geometry.radial_clearance
    for angle in (0.0, math.radians(9.93), math.radians(190.0)):
        e = c * (1.0 - 1e-6)
        force, jacobian = kernel.jacobian(e * math.cos(angle), e * math.sin(angle), 0.0, 0.0,
                                          400.0, 0.01, kernel.params)
        assert np.all(np.isfinite(force)) and np.all(np.isfinite(jacobian)), angle


# -- the massless orbit on fed two-land bearings -------------------------------------------
GROOVED = Bearing(diameter=0.062, width_ratio=0.26, clearance_ratio=0.72e-3,
                  specific_load=69e6, viscosity=3.9e-3, speed=3105.0, grooved=True)
"""A fed two-land bearing on which both quasi-static orbits failed (short: residual 453,
no crank angle; Reynolds at 36 × 8: residual 2.3e-4 at ε = 0.998, 29.5°)."""


def test_two_land_short_film_quasi_static_runs_and_agrees_with_the_orbit_with_mass():
    """Booker's inversion of one land at twice the viscosity (the generic Newton loop on the
    two-land force failed with a relative residual of 453)."""
    massless = run(GROOVED, "short", "quasi_static", **PERIODIC)
    with_mass = run(GROOVED, "short", "auto", **PERIODIC)
    assert massless.kind == "ran" == with_mass.kind, massless.message
    assert_plausible(massless.results, GROOVED)
    assert massless.results.summary.p_max == pytest.approx(with_mass.results.summary.p_max,
                                                           rel=1e-3)


@pytest.mark.slow
def test_fed_reynolds_quasi_static_runs_and_agrees_with_the_orbit_with_mass():
    """The generic massless Newton (fed Reynolds film, 36 × 8): its 1e-4 c ω
    finite-difference Jacobian left a residual of 2.3e-4 at ε = 0.998; from the concentric
    start the first Heun step threw the journal onto the shell (residual 1.2e3 at 0°)."""
    grid = {"n_theta": 36, "n_z": 8, **PERIODIC}
    massless = run(GROOVED, "reynolds", "quasi_static", **grid)
    with_mass = run(GROOVED, "reynolds", "auto", **grid)
    assert massless.kind == "ran" == with_mass.kind, massless.message
    assert massless.results.summary.p_max == pytest.approx(with_mass.results.summary.p_max,
                                                           rel=2e-3)
    assert massless.results.summary.h_min == pytest.approx(with_mass.results.summary.h_min,
                                                           rel=0.05)


# -- rk2: the automatic step from the implicit orbit, or a refusal ----------------------------
def test_rk2_automatic_step_beyond_the_budget_is_refused_before_any_trial_cycle():
    """The passenger car's film needs steps below 1e-4° (7.3 million per cycle): refused
    with the working integrators, measured along the implicit orbit (the trial cycle at 1°
    diverged towards the shell and asked for a step of 1e-16°)."""
    simulation = Simulation(Case.from_toml(PASSENGER_CAR), integrator="rk2")
    with pytest.raises(CaseError, match=r"solver.integrator = 'rk2': .*too stiff.*allowed: "
                                        r"integrator = 'implicit' or 'auto'"):
        rk2_cycle(simulation.problem(), OrbitState(), None, 1.0, simulation.solver)


def test_rk2_automatic_step_runs_where_the_stable_step_fits():
    plain = Bearing(diameter=0.049, width_ratio=0.45, clearance_ratio=1.0e-3,
                    specific_load=39e6, viscosity=7.3e-3, speed=4484.0, grooved=False)
    explicit = run(plain, "short", "rk2", **PERIODIC)
    implicit = run(plain, "short", "implicit", **PERIODIC)
    assert explicit.kind == "ran", explicit.message
    assert explicit.results.summary.h_min == pytest.approx(implicit.results.summary.h_min,
                                                           rel=0.01)


# -- the elastic orbit: published choices run or are refused before the run ----------------
def _winkler_film(settings: ElasticSettings) -> ElasticFilm:
    """The KamAZ-740 Reynolds film (36 × 8) on a Winkler bore."""
    base = Simulation(kamaz_case(n_theta=36, n_z=8, film="reynolds"),
                      housing="rigid").film_model()
    return ElasticFilm(base, winkler_housing(base.geometry, 36, 1e-13), 270.0, settings)


def test_elastic_reynolds_film_without_the_bore_rate_is_refused_with_the_default():
    """Rodin's squeeze term without ∂u/∂t: both orbits stopped at 197° on the KamAZ-740
    rod (with mass: force residual 431 N, h_min 0.7 µm); refused with the alternative."""
    with pytest.raises(CaseError, match=r"deformation_rate = False.*allowed: "
                                        r"deformation_rate = True"):
        _winkler_film(ElasticSettings(deformation_rate=False))
    assert _winkler_film(ElasticSettings()).settings.deformation_rate


def test_elastic_orbit_with_mass_refuses_steps_below_a_quarter_degree():
    """0.125° steps stalled at 57° (Newton cycling between cavitation sets); refused at the
    first step, naming the shortest step and the massless orbit."""
    case = kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="implicit",
                      max_step_deg=0.125, thermal_iterations=0, max_cycles=1)
    base = Simulation(case, housing="rigid").film_model()
    simulation = Simulation(case, housing=winkler_housing(base.geometry, 36, 1e-13),
                            rigid_companion=False)
    with pytest.raises(CaseError, match=r"solver.max_step_deg: steps of 0.125 deg .*allowed: "
                                        r">= 0.25 deg"):
        simulation.run()


# -- worn shells ------------------------------------------------------------------------------
def _worn_example(joint: str, ratio: float):
    from conrod.mechanism.setup import mechanism_case

    raw = Case.from_toml(EXAMPLES / "kulayev_worn_rod_bearings.toml").model_dump(
        exclude_none=True)
    shell = raw["clearance"][joint]
    shell["clearance_min"] = ratio * shell["clearance_max"]
    return mechanism_case(Case.from_dict(raw, base_dir=EXAMPLES))


@pytest.mark.parametrize("joint", ["big_end", "small_end"])
def test_shipped_mechanism_with_a_shell_worn_to_a_third_runs(joint):
    """Δmin = 0.33 Δmax: the journal lies in the worn tip, narrower than itself, touching both
    flanks; the single contact normal flipped between them and the default (exact) geometry
    exhausted its 750 000 steps after 35–75 s. Now two contact points."""
    from conrod.mechanism.simulation import simulate

    base = _worn_example(joint, 0.33)
    results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
    summary = results.summary()
    assert summary["integrator_steps"] < 300_000  # measured 93 000–135 000 for 3 cycles
    assert summary["energy_residual_relative"] < 1e-3
    assert np.isfinite(summary["max_contact_force_big_end_N"])

