"""Friction work (seed 004 eq. 4.5.1) and its distribution; wear per element; worn profile."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.contact.friction_work import (
    deposit_along_arc,
    friction_work_distribution,
    seed_friction_work,
)
from conrod.contact.wear import (
    SEED_WEAR_UNIT_TO_SI,
    element_area,
    wear_distribution,
    worn_profile_deformation,
)

RADIUS, WIDTH = 0.03, 0.025
CYCLE = 4.0 * math.pi
PHI = np.arange(720) * CYCLE / 720


def _combustion_contact(phi):
    """A contact pulse over 370–452° crank angle and one across the cycle seam (700–20°)."""
    deg = np.degrees(phi)
    pulse = np.where((deg > 370) & (deg < 452), 2.0e4 * np.sin(np.pi * (deg - 370) / 82), 0.0)
    seam = np.where((deg > 700) | (deg < 20), 3.0e3, 0.0)
    return pulse + seam


def test_distributions_each_sum_to_the_total():
    force = 0.1 * _combustion_contact(PHI)
    contact_angle = math.pi / 2 + 0.4 * np.sin(PHI) + 3.0 * (PHI > 2.0)  # jumps and wanders
    rotation = PHI - 0.3 * np.sin(PHI)  # rod swing, λ = 0.3
    work = friction_work_distribution(PHI, force, contact_angle, rotation, RADIUS, 360)
    assert work.total > 0.0
    assert np.sum(work.journal) == pytest.approx(work.total, rel=1e-12)
    assert np.sum(work.shell) == pytest.approx(work.total, rel=1e-12)
    assert np.all(work.journal >= 0.0) and np.all(work.shell >= 0.0)
    assert work.cumulative[0] == 0.0 and np.all(np.diff(work.cumulative) >= 0.0)


def test_equals_seed_formula_when_relative_rotation_is_crank_angle():
    """ψ = φ and P_f = μ P_c: the periodic trapezoidal sum is the seed's μ R Σ P_c Δφ."""
    contact = _combustion_contact(PHI)
    work = friction_work_distribution(PHI, 0.1 * contact, np.zeros_like(PHI), PHI, RADIUS, 360)
    assert work.total == pytest.approx(
        seed_friction_work(contact, PHI[1] - PHI[0], 0.1, RADIUS), rel=1e-12
    )


def test_constant_friction_over_the_cycle():
    """F = 100 N sliding over 2 journal turns: A = F·R·4π; spread evenly over the journal,
    all on the one shell element holding the fixed contact point."""
    force = np.full(PHI.size, 100.0)
    contact_angle = np.full(PHI.size, math.radians(90.3))
    work = friction_work_distribution(PHI, force, contact_angle, PHI, RADIUS, 72)
    assert work.total == pytest.approx(100.0 * RADIUS * CYCLE, rel=1e-12)
    np.testing.assert_allclose(work.journal, work.total / 72, rtol=1e-9)
    assert work.shell[18] == pytest.approx(work.total, rel=1e-12)  # 90–95° element


def test_rod_swing_changes_sliding_distance_but_not_its_cycle_mean():
    """ψ = φ − λ sin φ: the sliding distance of a full cycle is still R·4π (swing averages out).
    The closing step's ψ is extrapolated (error O(Δφ³) ≈ 1e-7 here, hence rel=1e-6)."""
    force = np.full(PHI.size, 50.0)
    work = friction_work_distribution(
        PHI, force, np.zeros_like(PHI), PHI - 0.3 * np.sin(PHI), RADIUS, 36
    )
    assert work.total == pytest.approx(50.0 * RADIUS * CYCLE, rel=1e-6)


def test_deposit_along_arc_wraps_and_conserves():
    bins = np.zeros(12)
    deposit_along_arc(bins, math.radians(-15.0), math.radians(45.0), 6.0)  # over 0°
    assert np.sum(bins) == pytest.approx(6.0)
    assert bins[11] == pytest.approx(1.5) and bins[0] == pytest.approx(3.0)
    assert bins[1] == pytest.approx(1.5)
    deposit_along_arc(bins, 10 * math.pi + 0.1, 10 * math.pi + 0.1, 2.0)  # point, many turns
    assert bins[0] == pytest.approx(5.0)


def test_wear_scales_linearly_with_its_coefficient():
    force = 0.1 * _combustion_contact(PHI)
    work = friction_work_distribution(PHI, force, np.full(PHI.size, 1.0), PHI, RADIUS, 360)
    single = wear_distribution(work, RADIUS, WIDTH, 1e-15, 1e-16)
    double = wear_distribution(work, RADIUS, WIDTH, 2e-15, 3e-16)
    np.testing.assert_allclose(double.journal_wear, 2.0 * single.journal_wear, rtol=1e-14)
    np.testing.assert_allclose(double.shell_wear, 3.0 * single.shell_wear, rtol=1e-14)
    area = WIDTH * RADIUS * 2 * math.pi / 360
    assert element_area(RADIUS, WIDTH, 360) == pytest.approx(area)
    np.testing.assert_allclose(single.shell_wear, 1e-16 * work.shell / area, rtol=1e-14)
    zero = wear_distribution(work, RADIUS, WIDTH, 0.0, 0.0)
    assert not np.any(zero.journal_wear) and not np.any(zero.shell_wear)


def test_seed_wear_unit_conversion():
    """1 µm/(kgf·mm/mm²) = 1e-6 m / (9.80665e-3 J / 1e-6 m²) = 1.0197e-10 m³/J."""
    assert pytest.approx(1e-6 / (9.80665e-3 / 1e-6), rel=1e-12) == SEED_WEAR_UNIT_TO_SI


def test_worn_profile_deformation_on_a_film_grid():
    elements = (np.arange(36) + 0.5) * 2 * math.pi / 36
    wear = np.zeros(36)
    wear[9] = 2e-9  # element centred on 95°
    theta = np.linspace(0.0, 2 * math.pi, 72, endpoint=False)
    z = np.linspace(-0.01, 0.01, 5)
    delta = worn_profile_deformation(theta, z, elements, wear, cycles=1000)
    assert delta.shape == (72, 5)
    assert delta[19, 2] == pytest.approx(2e-6)  # θ = 95° after 1000 cycles, uniform in z
    assert np.all(delta[:, 0] == delta[:, 4]) and np.all(delta >= 0.0)
    assert delta[0, 0] == 0.0


def test_element_maximum_follows_the_contact_point():
    """Seed Fig. 4.4.1: a stress pulse at a fixed shell point marks one shell element, and the
    journal elements that pass under it (journal-fixed angle θ − ψ)."""
    from conrod.contact.friction_work import element_maximum

    deg = np.degrees(PHI)
    stress = np.where((deg > 10.0) & (deg < 50.0), 3.0e7, 0.0)
    contact_angle = np.full(PHI.size, math.radians(180.5))
    journal, shell = element_maximum(stress, contact_angle, PHI, PHI, 360)
    assert shell[180] == 3.0e7 and np.count_nonzero(shell) == 1
    touched = np.flatnonzero(journal)  # 180.5° − ψ for ψ from ~10° to ~50°
    assert touched.min() >= 129 and touched.max() <= 171
    assert np.max(journal) == 3.0e7


def test_worn_shell_film_opens_the_gap_of_a_reynolds_film():
    """δ = 0 leaves the Reynolds force unchanged; wear where the film is thinnest lowers it."""
    from conrod.contact.running_in import WornShellFilm
    from conrod.film.base import BearingGeometry, FilmState
    from conrod.film.reynolds.film import ReynoldsFilm

    film = ReynoldsFilm(BearingGeometry(diameter=0.05, width=0.02,
                                        radial_clearance=25e-6), n_theta=36, n_z=8)
    state = FilmState(eccentricity_x=20e-6, eccentricity_y=0.0, velocity_x=0.0, velocity_y=0.0,
                      journal_speed=300.0, shell_speed=0.0, viscosity=0.01)
    unworn = WornShellFilm(film, lambda theta, z: np.zeros((theta.size, z.size)))
    assert unworn.force(state) == pytest.approx(film.force(state), rel=1e-9)

    def pocket(theta, z):  # 2 µm deep wear around θ = 0, where h is smallest
        return np.repeat((2e-6 * np.cos(theta / 2.0) ** 8)[:, None], z.size, axis=1)

    worn = WornShellFilm(film, pocket)
    assert np.hypot(*worn.force(state)) < 0.9 * np.hypot(*film.force(state))
    assert worn.solve(state).min_film_thickness > film.solve(state).min_film_thickness


def test_run_in_refuses_films_that_ignore_the_worn_profile():
    from conrod.cases.case import Case
    from conrod.errors import CaseError
    from conrod.simulation.running_in import run_in

    case = Case.from_dict({"bearing": {"diameter": 0.05, "width": 0.02,
                                       "radial_clearance": 25e-6}})
    with pytest.raises(CaseError, match="solver.film = 'short'.*reynolds"):
        run_in(case, cycles=100)
    with pytest.raises(CaseError, match="cycles"):
        run_in(case, cycles=0)
