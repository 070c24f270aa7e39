"""The step system of the mass-conserving film on the deforming bore
(:func:`conrod.ehd.bore_system.content_step_system`): its exact Jacobian against central
differences of the step, and the orbit it gives against the orbit's own iteration around
separate bore couplings."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import conrod.orbit.content_steps as content_steps
from conrod.ehd.film import ElasticMemory
from conrod.film.base import FilmState
from conrod.film.capabilities import HasStepSystem
from conrod.film.step_system import StepRequest
from elastic_helpers import step_jacobian_and_residual
from test_ehd_jfo_content import BEDDING, N_THETA, _film
from test_ehd_jfo_response import STEP, _ruptured_memory
from test_orbit_jfo import OMEGA, orbit

MASS = np.array([0.8, 1.1])  # [kg] moving mass, so that the inertia column is checked too


def test_step_system_jacobian_matches_central_differences():
    """∂(G, F − m a)/∂(u, v) of one content step on a film with full and broken-film cells
    (backward Euler, the journal moving with mass): every block within 1e-5 of its largest
    central difference (1e-11 m of film thickness, a velocity step that moves the end
    position by as much)."""
    film = _film(BEDDING)
    base = film.base
    c = base.geometry.radial_clearance
    state = FilmState(eccentricity_x=0.6 * c, eccentricity_y=0.2 * c, velocity_x=0.05 * c
                      * OMEGA, velocity_y=-0.1 * c * OMEGA, journal_speed=OMEGA,
                      shell_speed=0.0, viscosity=0.02)
    inner = _ruptured_memory(base, state)
    assert inner.thickness is not None
    theta, _ = base.grid()
    memory = ElasticMemory(inner=inner, deformation=np.zeros(N_THETA), crank_angle=0.0,
                           elapsed=10.0)
    v0 = np.array([state.velocity_x, state.velocity_y])
    reference = np.array([state.eccentricity_x, state.eccentricity_y]) - STEP * v0
    request = StepRequest(reference, 0.3 * v0, STEP, STEP, MASS, np.zeros(2), OMEGA, 0.0,
                          state.viscosity, 0.0, False, (memory,))
    u = 0.05 * c * np.cos(2.0 * theta)
    scale = c * OMEGA
    jac, residual, z0, payload = step_jacobian_and_residual(film, request, u, v0, scale)
    assert 0.05 < float(np.mean(payload[1].fraction < 1.0 - 1e-9)) < 0.95
    h = 1e-11 / c  # of the scaled unknowns: 1e-11 m of bore, τ δv moving the journal as far
    numeric = np.empty_like(jac)
    for column in range(len(z0)):
        delta = np.zeros(len(z0))
        delta[column] = h if column < N_THETA else h * c / (STEP * scale)
        plus, minus = residual(z0 + delta), residual(z0 - delta)
        numeric[:, column] = (plus - minus) / (2.0 * delta[column])
    n = N_THETA
    blocks = [(jac[:n, :n], numeric[:n, :n]), (jac[n:, :n], numeric[n:, :n]),
              (jac[:n, n:], numeric[:n, n:]), (jac[n:, n:], numeric[n:, n:])]
    for analytic, differences in blocks:
        scale_of = float(np.max(np.abs(differences)))
        assert scale_of > 0.0 and math.isfinite(scale_of)
        assert float(np.max(np.abs(analytic - differences))) < 1e-5 * scale_of


class _NoJointStep:
    """Stands in for the capability so that no film offers the joint step."""


def test_joint_orbit_equals_the_orbit_of_separate_couplings(monkeypatch):
    """The periodic JFO orbit on a Winkler bore by the step system and by the orbit's
    own velocity iteration around full bore couplings: the same h_min and p_max at every
    output angle (both converge each step to 1e-8 of the load), with under half the film
    steps. Measured (24 × 4, 2°): 4739 vs 19 935 film steps, h_min equal to 1e-9."""
    joint_film = _film(BEDDING)
    assert isinstance(joint_film, HasStepSystem)
    joint, joint_cycle, _ = orbit(joint_film)
    monkeypatch.setattr(content_steps, "HasStepSystem", _NoJointStep)
    separate_film = _film(BEDDING)
    separate, separate_cycle, _ = orbit(separate_film)
    assert joint.periodic and separate.periodic
    assert joint_film.joint_calls > 0 and joint_film.content_calls == 0  # no fallback
    assert separate_film.joint_calls == 0
    assert joint_film.joint_solves < 0.5 * separate_film.content_solves
    assert np.max(np.abs(joint_cycle.h_min / separate_cycle.h_min - 1.0)) < 1e-4
    assert np.max(np.abs(joint_cycle.p_max / separate_cycle.p_max - 1.0)) < 1e-4
    assert joint_cycle.h_min.min() == pytest.approx(separate_cycle.h_min.min(), rel=1e-5)


def test_joint_step_is_not_offered_by_plain_films():
    """Only the elastic mass-conserving film offers the step system; the rigid JFO film
    keeps the orbit's own iteration."""
    film = _film(BEDDING)
    assert not isinstance(film.base, HasStepSystem)
    assert dataclasses.is_dataclass(film.base)
