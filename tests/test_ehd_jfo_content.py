"""Mass-conserving (JFO) film on a deforming bore stepped implicitly in its film content
(:mod:`conrod.ehd.mass_conserving_ehd`): the stiff-bore limit is the rigid orbit of the
same integrator, and the deforming bore conserves oil over the periodic cycle."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.ehd.film import ElasticSettings
from conrod.ehd.mass_conserving_ehd import ElasticMassConservingFilm, elastic_film
from conrod.film.capabilities import HasContentStep
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from elastic_helpers import WINKLER_SETTINGS, winkler_housing
from test_orbit_jfo import OMEGA, fed_bearing, orbit

N_THETA = 24
BEDDING = 2e-9  # [m/N] Winkler bore: node j moves out by BEDDING × its nodal force


def _film(bedding: float) -> ElasticMassConservingFilm:
    geometry = fed_bearing()
    base = MassConservingFilm(geometry, n_theta=N_THETA, n_z=4)
    housing = winkler_housing(geometry, N_THETA, bedding)
    settings = ElasticSettings(cycle=2 * math.pi, **WINKLER_SETTINGS)
    return elastic_film(base, housing, OMEGA, settings)


def _defect(cycle) -> float:
    """|∮(supply − side flow) dt| / ∮ supply dt over the periodic cycle [-]."""
    return abs(float(np.mean(cycle.supply_flow - cycle.side_flow))) / float(
        np.mean(cycle.supply_flow))


def test_only_the_isoviscous_mass_conserving_film_gets_the_content_step():
    film = _film(BEDDING)
    assert isinstance(film, ElasticMassConservingFilm) and isinstance(film, HasContentStep)
    reynolds = elastic_film(ReynoldsFilm(fed_bearing(), n_theta=N_THETA, n_z=4),
                            film.housing, OMEGA, film.settings)
    assert not isinstance(reynolds, HasContentStep)


@pytest.fixture(scope="module")
def rigid():
    result, cycle, _ = orbit(MassConservingFilm(fed_bearing(), n_theta=N_THETA, n_z=4))
    assert result.periodic
    return cycle


def test_stiff_bore_reproduces_the_rigid_jfo_orbit(rigid):
    """Bedding / 1e4 (modulus × 1e4): h_min and p_max of the rigid JFO orbit within 0.2 %
    (the rigid run takes the same implicit content steps)."""
    result, cycle, _ = orbit(_film(BEDDING / 1e4))
    assert result.periodic
    assert cycle.h_min.min() == pytest.approx(rigid.h_min.min(), rel=2e-3)
    assert cycle.p_max.max() == pytest.approx(rigid.p_max.max(), rel=2e-3)


def test_deforming_bore_conserves_oil_like_the_rigid_film(rigid):
    """The content step holds the deformed film of both ends of the step, so the bore's own
    rate is in the content balance: the conservation defect over the periodic cycle is of
    the rigid film's order, while the bore visibly changes the orbit."""
    film = _film(BEDDING)
    result, cycle, _ = orbit(film)
    assert result.periodic
    assert _defect(cycle) < max(2.0 * _defect(rigid), 2e-3)
    assert abs(cycle.h_min.min() / rigid.h_min.min() - 1.0) > 0.05


def test_jfo_and_reynolds_agree_on_the_same_deforming_bore(rigid):
    """Two different films on the same Winkler bore (the Reynolds one massless with the
    bore's rate in its squeeze term, :mod:`conrod.film.rated_state`): h_min within 5 % as on
    the rigid bore, and both lower p_max below their rigid value. Measured (24 × 4, 2°):
    JFO 4.06 µm / 8.25 MPa, Reynolds 4.11 µm / 7.59 MPa; rigid 3.85 / 10.67 and
    4.02 / 9.96."""
    from conrod.ehd.film import ElasticFilm

    jfo_film = _film(BEDDING)
    _, jfo, _ = orbit(jfo_film)
    reynolds_rigid = ReynoldsFilm(fed_bearing(), n_theta=N_THETA, n_z=4)
    _, reynolds, _ = orbit(ElasticFilm(reynolds_rigid, jfo_film.housing, OMEGA,
                                       jfo_film.settings))
    _, reynolds_on_rigid, _ = orbit(reynolds_rigid)
    assert jfo.h_min.min() == pytest.approx(reynolds.h_min.min(), rel=0.05)
    assert jfo.p_max.max() < rigid.p_max.max()
    assert reynolds.p_max.max() < reynolds_on_rigid.p_max.max()
