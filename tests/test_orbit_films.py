"""Film models as the orbit builds them (conrod.film.factory)."""

from __future__ import annotations

import math

import pytest

from conrod.cases.solver import SolverSection
from conrod.film.base import BearingGeometry, FilmState, Groove
from conrod.film.factory import GroovedShortBearingFilm, build_film_model
from conrod.film.short.film import ShortBearingFilm


def grooved(width: float) -> BearingGeometry:
    return BearingGeometry(diameter=0.1, width=width, radial_clearance=50e-6,
                           grooves=(Groove(0.0, 2 * math.pi, 0.004, 0.0),))


def test_short_film_with_a_central_groove_becomes_two_lands():
    film = build_film_model(SolverSection(film="short"), grooved(0.04))
    assert isinstance(film, GroovedShortBearingFilm)
    assert film.land.geometry.width == pytest.approx(0.018)
    plain = build_film_model(SolverSection(film="short"), BearingGeometry(diameter=0.1, width=0.04,
                                                                          radial_clearance=50e-6))
    assert isinstance(plain, ShortBearingFilm)


def test_two_land_short_bearing_agrees_with_grooved_finite_difference_film():
    """Short lands (L_land/D = 0.18): Ocvirk on each land vs Reynolds with the groove."""
    reynolds = pytest.importorskip("conrod.film.reynolds.film")
    geometry = grooved(0.04)
    state = FilmState(eccentricity_x=30e-6, eccentricity_y=10e-6, velocity_x=0.002,
                      velocity_y=-0.001, journal_speed=300.0, shell_speed=0.0, viscosity=0.01)
    short = GroovedShortBearingFilm.from_geometry(geometry).solve(state)
    fd = reynolds.ReynoldsFilm(geometry, n_theta=144, n_z=66, tolerance=1e-10).solve(state)
    # measured: forces within 2.1 %, side flow within 0.4 % (144 x 66 grid)
    assert math.hypot(short.force_x, short.force_y) == pytest.approx(
        math.hypot(fd.force_x, fd.force_y), rel=0.03)
    assert short.side_flow == pytest.approx(fd.side_flow, rel=0.01)
    # the groove at the (zero) supply pressure takes oil out of both lands: supply flow,
    # positive into the film, is minus the side flow, as the finite-difference film's
    # (measured 3.1 % apart)
    assert short.supply_flow == pytest.approx(-short.side_flow)
    assert short.supply_flow == pytest.approx(fd.supply_flow, rel=0.04)
