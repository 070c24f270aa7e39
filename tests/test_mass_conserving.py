"""Mass-conserving (JFO) film: full-film closed form, conservation over a transient,
agreement with Swift–Stieber, steady Raimondi–Boyd conditions."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.errors import CaseError, FilmThicknessError
from conrod.film.base import BearingGeometry, FeedHole, FilmState, Groove
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm

RADIUS = 0.05
CLEARANCE = 5.0e-5


def linear_full_film_force(eps: float, mu: float, omega: float, width: float) -> float:
    """Tangential force of the full (uncavitated) finite bearing to first order in ε [N].

    p = A(z) sin θ with A'' − A/R² = 6μωε/c², A(±L/2) = 0  ⇒
    F_y = (6πμωεR³/c²)(L − 2R tanh(L/2R)).
    """
    return 6.0 * math.pi * mu * omega * eps * RADIUS**3 / CLEARANCE**2 * (
        width - 2.0 * RADIUS * math.tanh(width / (2.0 * RADIUS)))


def test_full_film_matches_closed_form_with_second_order_convergence():
    width = 0.05
    geometry = BearingGeometry(diameter=2 * RADIUS, width=width, radial_clearance=CLEARANCE,
                               cavitation_pressure=-1.0e6)
    exact = linear_full_film_force(1e-3, 0.01, 100.0, width)
    errors, sizes = [], []
    for n_theta, n_z in ((36, 8), (72, 16), (144, 32)):
        model = MassConservingFilm(geometry, n_theta=n_theta, n_z=n_z, tolerance=1e-10)
        result = model.solve(FilmState(eccentricity_x=1e-3 * CLEARANCE, eccentricity_y=0.0,
                                       journal_speed=100.0, viscosity=0.01))
        assert abs(result.force_x) < 1e-6 * exact
        errors.append(abs(result.force_y / exact - 1.0))
        sizes.append(1.0 / n_theta)
    order = np.polyfit(np.log(sizes), np.log(errors), 1)[0]
    assert errors[-1] < 2e-3
    assert order == pytest.approx(2.0, abs=0.15)


def test_full_history_equals_reynolds_swift_stieber():
    """With ϑ = 1 everywhere the JFO instant is the Swift–Stieber problem (ReynoldsFilm).

    Both are second-order discretisations that differ in the face coefficients and in the
    peak-pressure read-out, so they agree to the O(Δ²) grid error of 72×16 (measured:
    forces 0.1 %, p_max 0.4 %), not to round-off."""
    geometry = BearingGeometry(diameter=2 * RADIUS, width=0.05, radial_clearance=CLEARANCE)
    state = FilmState(eccentricity_x=0.6 * CLEARANCE, eccentricity_y=0.2 * CLEARANCE,
                      velocity_x=0.01, velocity_y=-0.005,
                      journal_speed=150.0, viscosity=0.02)
    jfo = MassConservingFilm(geometry, n_theta=72, n_z=16, tolerance=1e-9).solve(state)
    reynolds = ReynoldsFilm(geometry, n_theta=72, n_z=16, tolerance=1e-9).solve(state)
    assert jfo.force_x == pytest.approx(reynolds.force_x, rel=2e-3)
    assert jfo.force_y == pytest.approx(reynolds.force_y, rel=2e-3)
    assert jfo.max_pressure == pytest.approx(reynolds.max_pressure, rel=1e-2)


def test_steady_jfo_with_inlet_line_matches_raimondi_boyd_and_swift_stieber():
    """L/D = 1, ε = 0.8: published S = 0.0446 (Raimondi & Boyd 1958). With a full-film inlet
    line at the maximum gap the JFO rupture condition equals Swift–Stieber's, so the loads
    agree to solver tolerance (measured: |ΔW|/W < 1e-6); JFO inflow = side flow."""
    geometry = BearingGeometry(diameter=2 * RADIUS, width=2 * RADIUS, radial_clearance=CLEARANCE)
    model = MassConservingFilm(geometry, n_theta=144, n_z=32)
    state = FilmState(eccentricity_x=0.8 * CLEARANCE, eccentricity_y=0.0, journal_speed=100.0,
                      viscosity=0.01)
    jfo = model.solve_steady(state)
    stieber = model.solve_steady(state, cavitation="swift_stieber")
    load = math.hypot(jfo.force_x, jfo.force_y)
    sommerfeld = (RADIUS / CLEARANCE) ** 2 * 0.01 * (100.0 / (2 * math.pi)) / (
        load / (2 * RADIUS * 2 * RADIUS))
    assert sommerfeld == pytest.approx(0.0446, rel=0.015)
    assert math.hypot(stieber.force_x, stieber.force_y) == pytest.approx(load, rel=1e-5)
    assert jfo.supply_flow == pytest.approx(jfo.side_flow, rel=1e-4)
    assert 0.0 < jfo.cavitated_fraction < 0.6


def whirling_state(t: float, history: np.ndarray, period: float) -> FilmState:
    w = 2 * math.pi / period
    c = 2.5e-5
    return FilmState(
        eccentricity_x=c * (0.3 + 0.4 * math.sin(w * t)), eccentricity_y=0.3 * c * math.cos(w * t),
        velocity_x=0.4 * c * w * math.cos(w * t), velocity_y=-0.3 * c * w * math.sin(w * t),
        journal_speed=200.0, viscosity=0.02, history=history)


def conservation_defect(steps: int) -> tuple[float, float, float]:
    """Heun-integrate ϑ over one period; return (Δcontent, ∫(supply − side) dt, min ϑ)."""
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5,
                               supply_pressure=2e5, grooves=(
        Groove(start_angle=math.radians(170), extent=math.radians(20), width=0.005),))
    model = MassConservingFilm(geometry, n_theta=48, n_z=8)
    period = 0.1
    dt = period / steps
    history = model.initial_history()
    content0 = model.solve(whirling_state(0.0, history, period)).extra["film_content_m3"]
    net, lowest = 0.0, 1.0
    for k in range(steps):
        a = model.solve(whirling_state(k * dt, history, period))
        trial = np.clip(history + dt * a.history_rate, 0.0, 1.0)
        b = model.solve(whirling_state((k + 1) * dt, trial, period))
        history = np.clip(history + 0.5 * dt * (a.history_rate + b.history_rate), 0.0, 1.0)
        net += 0.5 * dt * (a.supply_flow - a.side_flow + b.supply_flow - b.side_flow)
        lowest = min(lowest, float(history.min()))
    content1 = model.solve(whirling_state(steps * dt, history, period)).extra["film_content_m3"]
    return content1 - content0, net, lowest


@pytest.mark.slow
def test_mass_conservation_over_a_transient_converges_with_step():
    """inflow − outflow − d(content)/dt → 0: defect < 1 % of the net flow, halving with Δt
    (first order: the film-fraction clip at ϑ = 1 on reformation)."""
    change_coarse, net_coarse, lowest = conservation_defect(200)
    change_fine, net_fine, _ = conservation_defect(400)
    assert lowest < 0.5  # the film really ruptured and re-formed
    defect_coarse = abs(change_coarse - net_coarse) / abs(net_coarse)
    defect_fine = abs(change_fine - net_fine) / abs(net_fine)
    assert defect_fine < 0.01
    assert defect_fine < 0.65 * defect_coarse


def test_history_rate_is_zero_in_the_pressurised_film_and_negative_at_rupture():
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
    model = MassConservingFilm(geometry, n_theta=48, n_z=8)
    state = FilmState(eccentricity_x=1.5e-5, eccentricity_y=0.0, journal_speed=200.0,
                      viscosity=0.02,
                      history=model.initial_history())
    result = model.solve(state, with_pressure=True)
    rate = result.history_rate
    assert np.all(rate[result.pressure > 0.0] == 0.0)
    assert rate.min() < 0.0
    assert np.all(rate <= 0.0)


def test_steady_feed_hole_jfo_differs_slightly_from_swift_stieber():
    """Oil only from a feed hole at the maximum gap (2 bar): the JFO film re-forms where the
    supplied oil allows, Swift–Stieber wherever its pressure turns positive. Measured load
    difference −1.7 % (−6.2 % at 0.5 bar, starved); JFO supply flow = side flow."""
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5,
                               supply_pressure=2e5,
                               feed_holes=(FeedHole(angle=math.pi, diameter=0.005),))
    model = MassConservingFilm(geometry, n_theta=72, n_z=16)
    state = FilmState(eccentricity_x=0.7 * 2.5e-5, eccentricity_y=0.0, journal_speed=200.0,
                      viscosity=0.02)
    jfo = model.solve_steady(state, inlet_line=False)
    ruptured = float(model.last_film_fraction.min())
    stieber = model.solve_steady(state, inlet_line=False, cavitation="swift_stieber")
    difference = math.hypot(jfo.force_x, jfo.force_y) / math.hypot(
        stieber.force_x, stieber.force_y) - 1.0
    assert ruptured < 0.9
    assert 0.002 < abs(difference) < 0.05
    assert jfo.supply_flow == pytest.approx(jfo.side_flow, rel=1e-4)


def test_steady_without_any_inlet_is_rejected():
    model = MassConservingFilm(BearingGeometry(diameter=0.05, width=0.025,
                                               radial_clearance=2.5e-5), n_theta=16, n_z=4)
    with pytest.raises(CaseError, match="no loaded steady"):
        model.solve_steady(FilmState(eccentricity_x=1e-5, eccentricity_y=0.0,
                                     journal_speed=100.0), inlet_line=False)


def test_sor_and_multigrid_instants_agree_with_a_broken_film():
    """Both full-film solvers give the same instant, rates included, on a ruptured film."""
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
    history = np.ones((48, 9))
    history[30:40, 1:-1] = 0.4
    state = FilmState(eccentricity_x=1.2e-5, eccentricity_y=0.3e-5, velocity_x=1e-4, velocity_y=0.0,
                      journal_speed=200.0, viscosity=0.02,
                      history=history)
    results = [MassConservingFilm(geometry, n_theta=48, n_z=8, method=method,
                                  tolerance=1e-10).solve(state) for method in ("sor", "multigrid")]
    assert results[0].force_x == pytest.approx(results[1].force_x, rel=1e-6)
    assert results[0].force_y == pytest.approx(results[1].force_y, rel=1e-6)
    scale = np.abs(results[1].history_rate).max()
    assert np.abs(results[0].history_rate - results[1].history_rate).max() < 1e-5 * scale


def test_bad_inputs_raise_case_errors():
    model = MassConservingFilm(BearingGeometry(diameter=0.05, width=0.025,
                                               radial_clearance=2.5e-5), n_theta=16, n_z=4)
    with pytest.raises(FilmThicknessError, match="touches the shell"):
        model.solve(FilmState(eccentricity_x=2.6e-5, eccentricity_y=0.0, journal_speed=100.0))
    with pytest.raises(CaseError, match="deformation shape"):
        model.solve(FilmState(eccentricity_x=1e-5, eccentricity_y=0.0, journal_speed=100.0,
                              deformation=np.zeros((16, 4))))
    with pytest.raises(CaseError, match="viscosity"):
        model.solve(FilmState(eccentricity_x=1e-5, eccentricity_y=0.0, journal_speed=100.0,
                              viscosity=0.0))


def test_deformation_field_is_additive():
    """A uniform δ is the same as a larger clearance (h = c − e·n + δ)."""
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
    wider = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=3.0e-5)
    state = FilmState(eccentricity_x=1.5e-5, eccentricity_y=0.0, journal_speed=200.0,
                      viscosity=0.02)
    model = MassConservingFilm(geometry, n_theta=32, n_z=8, tolerance=1e-10)
    deformed = model.solve(FilmState(**{**state.__dict__,
                                        "deformation": np.full((32, 9), 0.5e-5)}))
    reference = MassConservingFilm(wider, n_theta=32, n_z=8, tolerance=1e-10).solve(state)
    assert deformed.force_y == pytest.approx(reference.force_y, rel=1e-8)
