"""The step systems of a journal whose tilt is solved (k = 4 degrees of freedom): their
Jacobian blocks — the tilt's velocity columns and the moments' rows — against central
differences of the step's residual, for the elastic Reynolds film on a Winkler bore and the
rigid Reynolds film (the fed bearing of the JFO orbit tests, 24 × 4)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.step_system import StepRequest, TiltRequest
from conrod.orbit.tilt_systems import FilmTiltSystems
from elastic_helpers import assert_jacobian_columns, solved_step, step_jacobian_and_residual
from test_orbit_jfo import OMEGA, fed_bearing
from test_step_systems import FILMS, N_THETA, VISCOSITY, _memory

INERTIA = 0.02  # [kg m^2]


def _request(film, memory, lever: float) -> StepRequest:
    c = film.geometry.radial_clearance
    dt = np.radians(1.0) / OMEGA
    edge = 0.3 * c  # the edge displacements ℓγ of the reference [m]
    return StepRequest(np.array([0.6 * c, 0.2 * c, edge, -0.5 * edge]),
                       np.array([0.05, -0.1, 0.02, 0.01]) * c * OMEGA, 2.0 * dt / 3.0, dt,
                       np.array([0.8, 1.1, INERTIA / lever**2, INERTIA / lever**2]),
                       np.array([-1200.0, -300.0, 4.0 / lever, -2.0 / lever]), OMEGA, 0.0,
                       VISCOSITY, 0.3, True, (memory, memory), TiltRequest(lever))


def test_elastic_film_with_free_tilt_blocks_match_central_differences():
    """Bore nodes 0, 5, 12 and all four journal velocities (two of them the edges') within
    1e-5 of each column's largest entry; the moments' rows are in the residual."""
    film = FILMS["reynolds"]()
    c = film.geometry.radial_clearance
    memory = _memory(film, c)
    request = _request(film, memory, 0.5 * film.geometry.width)
    scale = c * OMEGA
    done = solved_step(film, request, request.velocity_reference, scale)
    assert done is not None and done.newton.converged
    jac, residual, z0, _ = step_jacobian_and_residual(film, request, done.newton.own,
                                                      done.velocity, scale)
    assert jac.shape == (N_THETA + 4, N_THETA + 4)
    assert_jacobian_columns(jac, residual, z0, (0, 5, 12, *range(N_THETA, N_THETA + 4)))


def test_rigid_film_with_free_tilt_blocks_match_central_differences():
    """The rigid Reynolds film's system (no own unknowns): the four velocity columns of
    forces and moments from its 4 × 4 linearisation within 1e-5 (adjoints at 1e-9)."""
    film = ReynoldsFilm(fed_bearing(), n_theta=N_THETA, n_z=4)
    provider = FilmTiltSystems(film)
    c = film.geometry.radial_clearance
    request = dataclasses.replace(_request(film, film.initial_memory(),
                                           0.5 * film.geometry.width),
                                  memories=(film.initial_memory(),))
    scale = c * OMEGA
    done = solved_step(provider, request, request.velocity_reference, scale)
    assert done is not None and done.newton.converged
    jac, residual, z0, _ = step_jacobian_and_residual(provider, request, done.newton.own,
                                                      done.velocity, scale)
    assert_jacobian_columns(jac, residual, z0, range(4), tolerance=1e-5)
    assert math.isfinite(float(np.abs(jac).max()))
