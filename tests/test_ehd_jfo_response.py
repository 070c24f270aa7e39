"""Exact response of the mass-conserving film's content step to the bore deformation
(:mod:`conrod.film.mass_conserving.response`) against central differences of the film."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from conrod.ehd.bore_system import nodal_force_weights
from conrod.film.base import FilmState
from conrod.film.mass_conserving.film import MassConservingFilm
from test_orbit_jfo import OMEGA, fed_bearing

N_THETA, N_Z = 24, 4
STEP = 2e-5  # [s] content step


def _ruptured_memory(film: MassConservingFilm, state: FilmState):
    """Film content after a few steps of a journal moving away from the load line (the
    film breaks on the diverging side)."""
    memory = film.initial_memory()
    for k in range(40):
        moving = dataclasses.replace(state, eccentricity_x=state.eccentricity_x
                                     - (40 - k) * STEP * state.velocity_x)
        memory = film.content_step(moving, memory, STEP)[2]
    return memory


def test_content_step_response_matches_central_differences():
    """∂f/∂u on a film with full and broken-film cells: within 1e-5 of the largest entry
    of the central differences (step 1e-11 m)."""
    geometry = fed_bearing()
    film = MassConservingFilm(geometry, n_theta=N_THETA, n_z=N_Z)
    c = geometry.radial_clearance
    state = FilmState(eccentricity_x=0.6 * c, eccentricity_y=0.2 * c, velocity_x=0.05 * c
                      * OMEGA, velocity_y=-0.1 * c * OMEGA, journal_speed=OMEGA,
                      shell_speed=0.0, viscosity=0.02)
    memory = _ruptured_memory(film, state)
    theta, _ = film.grid()
    u = 0.05 * c * np.cos(2.0 * theta)
    nodal = nodal_force_weights(film, theta, geometry.radius)

    def solve(bore: np.ndarray):
        deformed = dataclasses.replace(state, deformation=np.repeat(bore[:, None], N_Z + 1,
                                                                    axis=1))
        _, _, after = film.content_step(deformed, memory, STEP)
        forces = np.sum(nodal * film.gauge_pressure(after.pressure, deformed), axis=1)
        return forces, after, deformed

    forces, after, deformed = solve(u)
    assert 0.05 < float(np.mean(after.fraction < 1.0 - 1e-9)) < 0.95  # both kinds of cell
    exact = film.thickness_response(deformed, after, nodal, STEP).nodal_by_bore
    h = 1e-11
    differences = np.empty_like(exact)
    for r in range(N_THETA):
        shift = np.zeros(N_THETA)
        shift[r] = h
        differences[:, r] = (solve(u + shift)[0] - solve(u - shift)[0]) / (2.0 * h)
    scale = float(np.max(np.abs(differences)))
    assert scale > 0.0 and math.isfinite(scale)
    assert float(np.max(np.abs(exact - differences))) < 1e-5 * scale
