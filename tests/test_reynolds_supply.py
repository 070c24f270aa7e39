"""Oil-supply features of the Reynolds film: grooves, feed holes, flows."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.base import validate_section
from conrod.cases.bearing import BearingSection
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FeedHole, FilmState, Groove
from conrod.film.characteristics import FilmGrid
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.supply import groove_mask, hole_mask, supply_mask

MU, D, C = 0.02, 0.1, 1.0e-4
R = 0.5 * D
OMEGA = 200.0


def test_central_groove_splits_bearing_into_two_lands():
    """A full central groove at ambient pressure: force = 2 × bearing of one land width."""
    step = D / 34
    groove = Groove(width=2.0 * step)  # covers the 3 central axial nodes
    grooved = ReynoldsFilm(BearingGeometry(diameter=D, width=D, radial_clearance=C,
                                           grooves=(groove,)), n_theta=72, n_z=34)
    land = ReynoldsFilm(BearingGeometry(diameter=D, width=16 * step,
                                        radial_clearance=C), n_theta=72, n_z=16)
    state = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.2 * C, velocity_x=1e-3,
                      journal_speed=OMEGA, viscosity=MU)
    whole, half = grooved.solve(state), land.solve(state)
    assert whole.force_x == pytest.approx(2 * half.force_x, rel=1e-5)
    assert whole.force_y == pytest.approx(2 * half.force_y, rel=1e-5)


def test_pressurised_groove_without_motion_has_closed_form_flow():
    """Concentric, no rotation, central groove at p_s: linear pressure in each land,
    Q = 2 · 2πR c³ p_s / (12 μ l), l = land width — exact for the scheme."""
    supply = 3.0e5
    step = D / 32
    groove = Groove(width=2.0 * step)
    film = ReynoldsFilm(BearingGeometry(diameter=D, width=D, radial_clearance=C, grooves=(groove,),
                                        supply_pressure=supply),
                        n_theta=36, n_z=32)
    result = film.solve(FilmState(eccentricity_x=0.0, eccentricity_y=0.0, viscosity=MU))
    land = 15 * step
    exact = 2 * 2 * math.pi * R * C**3 * supply / (12 * MU * land)
    assert result.supply_flow == pytest.approx(exact, rel=1e-6)
    assert result.side_flow == pytest.approx(exact, rel=1e-6)
    assert math.hypot(result.force_x, result.force_y) < 1e-6 * supply * D * D


def test_supply_flow_equals_side_flow_without_cavitation():
    g = BearingGeometry(diameter=D, width=0.8 * D, radial_clearance=C,
                        grooves=(Groove(width=0.01),), supply_pressure=5.0e6)
    result = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-12).solve(
        FilmState(eccentricity_x=0.3 * C, eccentricity_y=0.0, journal_speed=0.1 * OMEGA,
                  viscosity=MU))
    assert result.cavitated_fraction == 0.0
    assert result.supply_flow > 0.0
    assert result.supply_flow == pytest.approx(result.side_flow, rel=1e-9)


def test_flow_balance_with_cavitation_and_squeeze():
    """Σ boundary flows = ∫∂h/∂t dA: supply − side + cavitation term − squeeze = 0."""
    hole = FeedHole(angle=2.0, diameter=0.008)
    g = BearingGeometry(diameter=D, width=0.6 * D, radial_clearance=C, feed_holes=(hole,),
                        supply_pressure=2.0e5)
    film = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-12)
    result = film.solve(FilmState(eccentricity_x=0.7 * C, eccentricity_y=0.1 * C, velocity_x=2e-3,
                                  velocity_y=-1e-3,
                                  journal_speed=OMEGA, viscosity=MU))
    assert result.cavitated_fraction > 0.1
    balance = (result.supply_flow - result.side_flow
               + result.extra["cavitation_flow_m3_per_s"])
    # ∫∂h/∂t dA vanishes for a rigid-body translation of the journal
    assert abs(balance) < 1e-9 * result.supply_flow


def test_supply_masks_rasterise_features():
    grid = FilmGrid(R, D, 72, 16)
    partial = Groove(start_angle=math.radians(90), extent=math.radians(90), width=D)
    mask = groove_mask(partial, grid)
    covered = np.flatnonzero(mask.any(axis=1))
    assert np.degrees(grid.theta[covered]).tolist() == pytest.approx(
        np.arange(90.0, 180.1, 5.0).tolist())
    tiny = hole_mask(FeedHole(angle=1.0, diameter=1e-6), grid)
    assert tiny.sum() == 1
    both = supply_mask(BearingGeometry(diameter=D, width=D, radial_clearance=C,
                                       grooves=(partial,)), grid)
    assert not both[:, [0, -1]].any()


def test_bearing_section_builds_geometry_with_supply_features():
    section = validate_section(BearingSection, {
        "diameter": 0.085, "width": 0.028, "radial_clearance": 4e-5, "supply_pressure": 3e5,
        "grooves": [{"start_angle": 90.0, "extent": 180.0, "width": 0.004}],
        "feed_holes": [{"angle": 30.0, "diameter": 0.005}],
    }, "bearing")
    geometry = section.geometry()
    assert geometry.grooves[0].extent == pytest.approx(math.pi)
    assert geometry.feed_holes[0].angle == pytest.approx(math.radians(30.0))
    assert geometry.supply_pressure == 3e5
    with pytest.raises(CaseError, match="did you mean 'extent'"):
        validate_section(BearingSection, {"diameter": 0.085, "width": 0.028,
                                          "grooves": [{"width": 0.004, "extnt": 90}]}, "bearing")
    outside = validate_section(BearingSection, {
        "diameter": 0.085, "width": 0.028, "radial_clearance": 4e-5,
        "feed_holes": [{"angle": 0.0, "diameter": 0.005, "axial_position": 0.02}]}, "bearing")
    with pytest.raises(CaseError, match=r"feed_holes\[0\].axial_position"):
        outside.geometry()
