"""Mixed lubrication: a film model plus Greenwood–Tripp asperity contact and boundary friction."""

from __future__ import annotations

import dataclasses
import math
import tomllib

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.contact.asperity import AsperityParameters, asperity_force, kernel_parameters
from conrod.contact.mixed import MixedLubricationFilm
from conrod.film.base import BearingGeometry, FilmModel, FilmState
from conrod.film.short.film import ShortBearingFilm

GEOMETRY = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6)
PARAMS = AsperityParameters(0.5e-6, 4e9, 25e-6, 5.9e10).kernel_parameters(0.025, 0.02)


def _mixed(mu: float = 0.1) -> MixedLubricationFilm:
    return MixedLubricationFilm(ShortBearingFilm(GEOMETRY), PARAMS, mu)


def test_is_a_film_model_and_equals_the_film_away_from_contact():
    film = _mixed()
    assert isinstance(film, FilmModel)
    state = FilmState(eccentricity_x=10e-6, eccentricity_y=5e-6, velocity_x=1e-3, velocity_y=-2e-3,
                      journal_speed=300.0, shell_speed=0.0, viscosity=0.01)
    assert film.force(state) == pytest.approx(film.base.force(state), rel=1e-15)
    assert film.solve(state).extra["asperity_force_N"] == 0.0


def test_force_adds_radial_asperity_force_and_opposing_friction():
    angle = 0.7
    e = 25e-6 - 0.5e-6  # gap of one σ
    state = FilmState(eccentricity_x=e * math.cos(angle), eccentricity_y=e * math.sin(angle),
                      velocity_x=0.0, velocity_y=0.0, journal_speed=300.0, shell_speed=0.0,
                      viscosity=0.01)
    film, frictionless = _mixed(0.1), _mixed(0.0)
    base = np.array(film.base.force(state))
    asperity = np.array(asperity_force(state.eccentricity_x, state.eccentricity_y,
                                       25e-6, PARAMS))
    np.testing.assert_allclose(np.array(frictionless.force(state)) - base, asperity, rtol=1e-12)
    tangent = np.array([-math.sin(angle), math.cos(angle)])
    friction = np.array(film.force(state)) - base - asperity
    # journal turning forward (+t̂) slides forward: friction −μ|F_a| t̂
    np.testing.assert_allclose(friction, -0.1 * np.linalg.norm(asperity) * tangent, rtol=1e-9)
    backwards = FilmState(eccentricity_x=state.eccentricity_x, eccentricity_y=state.eccentricity_y,
                          velocity_x=0.0, velocity_y=0.0, journal_speed=-300.0, shell_speed=0.0,
                          viscosity=0.01)
    friction_back = np.array(film.force(backwards)) - np.array(film.base.force(backwards)) - (
        asperity)
    np.testing.assert_allclose(friction_back, -friction, rtol=1e-9)
    extra = film.solve(state).extra
    assert extra["asperity_force_N"] == pytest.approx(np.linalg.norm(asperity))
    assert extra["boundary_friction_N"] == pytest.approx(0.1 * np.linalg.norm(asperity))


@pytest.mark.slow
def test_mixed_lubrication_orbit_shares_the_load_smoothly(repo):
    """1000 rpm example with Greenwood–Tripp (σ = 1 µm, ηβσ = 0.04, σ/β = 0.02) inside the
    orbit (the orbit solver adds the asperity force when model = "greenwood_tripp"): the
    asperities carry part of the combustion load, the asperity force rises and falls
    smoothly, and contact (asperity force > 1 % of the peak load) sits around combustion.
    The same surfaces inside a MixedLubricationFilm (with boundary friction) agree."""
    from conrod.results.summary import headline
    from conrod.simulation.simulation import Simulation

    class MixedSimulation(Simulation):
        """Asperity force + boundary friction from the film wrapper instead of the solver."""

        def problem(self, viscosity=None):
            problem = super().problem(viscosity)
            film = MixedLubricationFilm(problem.film, kernel_parameters(self.case),
                                        self.case.contact.dry_friction_coefficient)
            return dataclasses.replace(problem, film=film, asperity=None)

    path = repo / "examples" / "passenger_car_diesel_1000rpm.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    sigma = 1.0e-6
    data["contact"].update(model="greenwood_tripp", roughness=sigma, asperity_radius=sigma / 0.02,
                           asperity_density=0.04 / (sigma * sigma / 0.02))
    data["solver"]["contact_film_thickness"] = 0.0  # no hard-contact circle inside the film
    case = Case.from_dict(data, base_dir=path.parent)
    results = Simulation(case).run()
    contact = results.contact
    force = contact.contact_force
    peak_load = float(np.max(np.hypot(results.cycle.load_x, results.cycle.load_y)))
    assert 0.01 * peak_load < np.max(force) < 0.5 * peak_load
    assert np.max(np.abs(np.diff(force))) < 0.2 * np.max(force)  # smooth, no switch
    (start, end), = contact.asperity_intervals  # the hard-contact intervals are empty
    assert 0.0 < math.degrees(start) < 40.0 and 40.0 < math.degrees(end) < 100.0
    assert float(np.max(results.cycle.contact_force)) == 0.0 and contact.intervals == []
    line = headline(results)["contact"]  # the engineer is told the asperities carry load
    assert line.startswith("asperities (Greenwood–Tripp) carry up to ")
    assert f"{np.max(force):.3g} N" in line
    wrapped = MixedSimulation(case).run().contact
    assert np.max(wrapped.contact_force) == pytest.approx(np.max(force), rel=0.05)
