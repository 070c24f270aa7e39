"""The step system of every film that declares one
(:class:`~conrod.film.capabilities.HasStepSystem`): its exact Jacobian blocks, with the
journal's inertia, against central differences of the step's residual at the converged end
of one BDF2 step, on a Winkler bore (the fed bearing of the JFO orbit tests, 24 × 4)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from conrod.ehd.film import ElasticSettings
from conrod.ehd.mass_conserving_ehd import elastic_film
from conrod.film.base import FilmState
from conrod.film.capabilities import HasStepSystem
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.step_system import StepRequest
from elastic_helpers import (
    WINKLER_SETTINGS,
    assert_jacobian_columns,
    solved_step,
    step_jacobian_and_residual,
    winkler_housing,
)
from test_ehd_jfo_response import _ruptured_memory
from test_orbit_jfo import OMEGA, fed_bearing

N_THETA = 24
BEDDING = 2e-9  # [m/N]
MASS = np.array([0.8, 1.1])  # [kg]
VISCOSITY = 0.02  # [Pa s]


def _film(base):
    settings = ElasticSettings(cycle=2 * math.pi, **WINKLER_SETTINGS)
    return elastic_film(base, winkler_housing(fed_bearing(), N_THETA, BEDDING), OMEGA,
                        settings)


def _memory(film, c: float):
    """The film's memory past its rigid start (for the content film: a film content with
    broken-film cells after a few content steps)."""
    memory = dataclasses.replace(film.initial_memory(), elapsed=10.0)
    if memory.inner is None or not hasattr(memory.inner, "fraction"):
        return memory
    state = FilmState(eccentricity_x=0.6 * c, eccentricity_y=0.2 * c,
                      velocity_x=0.05 * c * OMEGA, velocity_y=-0.1 * c * OMEGA,
                      journal_speed=OMEGA, viscosity=VISCOSITY)
    return dataclasses.replace(memory, inner=_ruptured_memory(film.base, state))


def _request(c: float, memory):
    """One BDF2 step of 1° from the journal at (0.6, 0.2) c, the step's memory ``memory``."""
    dt = np.radians(1.0) / OMEGA
    return StepRequest(np.array([0.6 * c, 0.2 * c]), np.array([0.05, -0.1]) * c * OMEGA,
                       2.0 * dt / 3.0, dt, MASS, np.array([-1200.0, -300.0]), OMEGA, 0.0,
                       VISCOSITY, 0.3, True, (memory, memory))


FILMS = {
    "reynolds": lambda: _film(ReynoldsFilm(fed_bearing(), n_theta=N_THETA, n_z=4)),
    "mass_conserving": lambda: _film(MassConservingFilm(fed_bearing(), n_theta=N_THETA,
                                                        n_z=4)),
}


@pytest.mark.parametrize("name", sorted(FILMS))
def test_step_system_blocks_match_central_differences(name):
    """Every column of the scaled Jacobian (bore nodes 0, 5, 12 and both velocity
    components) within 1e-5 of its largest entry of the central differences."""
    film = FILMS[name]()
    assert isinstance(film, HasStepSystem) and film.supports_step_system()
    c = film.geometry.radial_clearance
    memory = _memory(film, c)
    request = _request(c, memory)
    scale = c * OMEGA
    done = solved_step(film, request, request.velocity_reference, scale)
    assert done is not None and done.newton.converged
    jac, residual, z0, _ = step_jacobian_and_residual(film, request, done.newton.own,
                                                      done.velocity, scale)
    assert_jacobian_columns(jac, residual, z0, (0, 5, 12, N_THETA, N_THETA + 1))


def test_each_film_solve_of_a_step_starts_from_the_steps_last_solve(monkeypatch):
    """The Reynolds film on the elastic bore: the first solve of a step starts from the
    step's memory (the last step's answer), each later one from the solve before it; the
    answer does not depend on where it started beyond the film's tolerance."""
    film = FILMS["reynolds"]()
    c = film.geometry.radial_clearance
    memory = _memory(film, c)
    request = _request(c, memory)
    starts = []
    evaluator = type(film).evaluator

    def recording(self, state, at, accuracy=None, start=None):
        starts.append(at.inner if start is None else start)
        return evaluator(self, state, at, accuracy, start)

    monkeypatch.setattr(type(film), "evaluator", recording)
    system = film.step_system(request)
    velocity = np.array([0.05, -0.1]) * c * OMEGA
    own = np.linspace(-1.0, 1.0, N_THETA) * 1e-3 * c
    payloads = [system.evaluate(u, velocity)[3] for u in (own, 2.0 * own, own)]
    assert starts[0] is memory.inner
    assert starts[1].pressure is payloads[0].pressure
    assert starts[2].pressure is payloads[1].pressure
    # the same state solved from two starts: the same pressure within the tolerance
    scale = float(np.max(np.abs(payloads[0].pressure)))
    assert np.max(np.abs(payloads[2].pressure - payloads[0].pressure)) <= 1e-9 * scale
    assert not np.array_equal(payloads[2].pressure, payloads[1].pressure)


def test_an_inexact_step_gives_the_exact_steps_answer_with_fewer_multigrid_cycles(monkeypatch):
    """The Reynolds film's implicit step with its film solved only as accurately as the
    Newton iteration needs (inexact Newton, :data:`conrod.numerics.newton.FORCING`): the
    first solve is asked for :data:`~conrod.numerics.newton.FIRST_ACCURACY`, none looser;
    the answer is the step solved with every film to its tolerance, within the coupling
    tolerance (bore) and 1e-7 (velocity, relative), with fewer multigrid cycles."""
    from conrod.numerics import newton

    solve_pressure = ReynoldsFilm.solve_pressure

    def solved(first_accuracy: float):
        asked, sweeps = [], []

        def recording(self, problem, state, memory, accuracy=None):
            pressure, info = solve_pressure(self, problem, state, memory, accuracy)
            asked.append(accuracy)
            sweeps.append(info["sweeps"])
            return pressure, info

        monkeypatch.setattr(ReynoldsFilm, "solve_pressure", recording)
        monkeypatch.setattr(newton, "FIRST_ACCURACY", first_accuracy)
        film = FILMS["reynolds"]()
        c = film.geometry.radial_clearance
        request = _request(c, _memory(film, c))
        done = solved_step(film, request, request.velocity_reference, c * OMEGA)
        assert done is not None and done.newton.converged
        return done, film, asked, sum(sweeps)

    first = newton.FIRST_ACCURACY
    inexact, film, asked, inexact_sweeps = solved(first)
    exact, _, exact_asked, exact_sweeps = solved(0.0)  # every solve to the film's tolerance
    assert asked[0] == first
    assert all(a is not None and a <= first for a in asked)
    assert max(a for a in exact_asked) == 0.0  # max(tolerance, 0): the tolerance
    assert inexact_sweeps < exact_sweeps
    tolerance = film.coupling.tolerance
    assert np.max(np.abs(inexact.newton.own - exact.newton.own)) <= 0.1 * tolerance
    v = exact.velocity
    assert np.max(np.abs(inexact.velocity - v)) <= 1e-7 * np.max(np.abs(v))
