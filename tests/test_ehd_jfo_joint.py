"""Joint Newton step of the journal and the deforming bore for the mass-conserving film
(:mod:`conrod.ehd.mass_conserving_joint`): its exact Jacobian against central
differences of the step, and the orbit it gives against the content orbit's own
iteration around separate bore couplings."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

import conrod.orbit.content_orbit as content_orbit
from conrod.ehd.film import ElasticMemory
from conrod.ehd.mass_conserving_joint import _evaluator, _responder
from conrod.film.base import FilmState
from conrod.film.capabilities import HasJointContentStep
from test_ehd_jfo_content import BEDDING, N_THETA, _film
from test_ehd_jfo_response import STEP, _ruptured_memory
from test_orbit_jfo import OMEGA, orbit

MASS = np.array([0.8, 1.1])  # [kg] moving mass, so that the inertia column is checked too


def test_joint_jacobian_matches_central_differences():
    """∂(f, F − m a)/∂(u, v) of one content step on a film with full and broken-film cells:
    every block within 1e-5 of its largest central difference (1e-11 m of film thickness,
    a velocity step that moves the end position by as much)."""
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
    tau = STEP
    v0 = np.array([state.velocity_x, state.velocity_y])
    reference = np.array([state.eccentricity_x, state.eccentricity_y]) - tau * v0
    speeds = (state.journal_speed, state.shell_speed)

    def step(u, v):  # a fresh evaluator: every solve starts from the same memory
        evaluate = _evaluator(film, memory, None, STEP, reference, 0.3 * v0, tau, MASS,
                              speeds, state.viscosity)
        return evaluate(u, v)

    u = 0.05 * c * np.cos(2.0 * theta)
    _, _, _, payload = step(u, v0)
    assert 0.05 < float(np.mean(payload.step[2].fraction < 1.0 - 1e-9)) < 0.95
    exact = _responder(film, tau, MASS, STEP)(payload)
    h = 1e-11
    by_bore = np.empty((N_THETA + 2, N_THETA))
    for r in range(N_THETA):
        shift = np.zeros(N_THETA)
        shift[r] = h
        plus, minus = step(u + shift, v0), step(u - shift, v0)
        by_bore[:N_THETA, r] = (plus[0] - minus[0]) / (2.0 * h)
        by_bore[N_THETA:, r] = (plus[1] - minus[1]) / (2.0 * h)
    by_velocity = np.empty((N_THETA + 2, 2))
    dv = h / tau
    for i in range(2):
        shift = np.zeros(2)
        shift[i] = dv
        plus, minus = step(u, v0 + shift), step(u, v0 - shift)
        by_velocity[:N_THETA, i] = (plus[0] - minus[0]) / (2.0 * dv)
        by_velocity[N_THETA:, i] = (plus[1] - minus[1]) / (2.0 * dv)
    blocks = [(exact.nodal_by_bore, by_bore[:N_THETA]),
              (exact.force_by_bore, by_bore[N_THETA:]),
              (exact.nodal_by_velocity, by_velocity[:N_THETA]),
              (exact.force_by_velocity, by_velocity[N_THETA:])]
    for analytic, differences in blocks:
        scale = float(np.max(np.abs(differences)))
        assert scale > 0.0 and math.isfinite(scale)
        assert float(np.max(np.abs(analytic - differences))) < 1e-5 * scale


class _NoJointStep:
    """Stands in for the capability so that no film offers the joint step."""


def test_joint_orbit_equals_the_orbit_of_separate_couplings(monkeypatch):
    """The periodic JFO orbit on a Winkler bore by joint Newton steps and by the orbit's
    own velocity iteration around full bore couplings: the same h_min and p_max at every
    output angle (both converge each step to 1e-8 of the load), with under half the film
    steps. Measured (24 × 4, 2°): 4739 vs 19 935 film steps, h_min equal to 1e-9."""
    joint_film = _film(BEDDING)
    assert isinstance(joint_film, HasJointContentStep)
    joint, joint_cycle, _ = orbit(joint_film)
    monkeypatch.setattr(content_orbit, "HasJointContentStep", _NoJointStep)
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
    """Only the elastic mass-conserving film offers the joint step; the rigid JFO film
    keeps the orbit's own iteration."""
    film = _film(BEDDING)
    assert not isinstance(film.base, HasJointContentStep)
    assert dataclasses.is_dataclass(film.base)
