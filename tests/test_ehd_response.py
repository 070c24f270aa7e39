"""The film's exact response to the bore deformation and the journal velocity (one sparse
LU on the converged active set) against central differences of the Reynolds film."""

from __future__ import annotations

import dataclasses

import numpy as np

from conrod.ehd.bore_system import nodal_force_weights
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.rated_state import rated
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.memory import ReynoldsMemory
from conrod.housing.transfer import nodal_forces

RADIUS, CLEARANCE, STEP = 0.04, 5.0e-5, 1.0e-4  # [m], [m], rate time step [s]


def plain_film() -> ReynoldsFilm:
    """The isoviscous 36 × 8 film of these checks, with the bore's rate in its squeeze."""
    geometry = BearingGeometry(diameter=2 * RADIUS, width=0.03, radial_clearance=CLEARANCE)
    return ReynoldsFilm(geometry, n_theta=36, n_z=8).with_deformation_rate()


def setup(film: ReynoldsFilm | None = None):
    """(film, θ, a bore u, a journal velocity v, ``evaluate(u, v)`` → (state, pressure,
    nodal loads, force)) of ``film`` (default :func:`plain_film`) at a fixed journal
    position with a random bore and a bore rate over :data:`STEP`."""
    film = plain_film() if film is None else film
    theta, z = film.grid()
    rng = np.random.default_rng(1)
    bore = 3e-6 * np.cos(2 * theta) + 1e-6 * rng.standard_normal(len(theta))
    reference = bore - 2e-7 * np.sin(theta)
    state = FilmState(eccentricity_x=0.7 * CLEARANCE * np.cos(0.3),
                      eccentricity_y=0.7 * CLEARANCE * np.sin(0.3), velocity_x=0.01,
                      velocity_y=-0.02, journal_speed=272.0, viscosity=0.0095)

    def evaluate(u, velocity):
        moving = dataclasses.replace(state, velocity_x=velocity[0], velocity_y=velocity[1])
        field = np.repeat(u[:, None], len(z), axis=1)
        rate = np.repeat(((u - reference) / STEP)[:, None], len(z), axis=1)
        deformed = rated(moving, field, rate)
        result = film.solve(deformed, with_pressure=True)
        return (deformed, result.pressure, nodal_forces(result.pressure, z, theta, RADIUS),
                np.array([result.force_x, result.force_y]))

    return film, theta, bore, np.array([0.01, -0.02]), evaluate


def bore_differences(evaluate, bore: np.ndarray, velocity: np.ndarray
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Central differences (step 1e-10 m) of the nodal loads (n × n) [N/m per m] and the
    film force (2 × n) [N/m] by each bore displacement, ``evaluate(u, v)`` returning
    (state, pressure, nodal loads, force)."""
    nodal = np.empty((len(bore), len(bore)))
    force = np.empty((2, len(bore)))
    for j in range(len(bore)):
        step = np.zeros(len(bore))
        step[j] = 1e-10
        _, _, f_plus, force_plus = evaluate(bore + step, velocity)
        _, _, f_minus, force_minus = evaluate(bore - step, velocity)
        nodal[:, j] = (f_plus - f_minus) / 2e-10
        force[:, j] = (force_plus - force_minus) / 2e-10
    return nodal, force


def test_response_matches_central_differences():
    film, theta, bore, velocity, evaluate = setup()
    deformed, pressure, forces, _ = evaluate(bore, velocity)
    weights = nodal_force_weights(film, theta, RADIUS)
    assert np.allclose(np.sum(weights * pressure, axis=1), forces, rtol=1e-13, atol=0.0)
    response = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    nodal, force = bore_differences(evaluate, bore, velocity)
    assert np.max(np.abs(nodal - response.nodal_by_bore)) <= 1e-6 * np.max(np.abs(nodal))
    assert np.max(np.abs(force - response.force_by_bore)) <= 1e-6 * np.max(np.abs(force))
    # the check is not vacuous: a third of the rows carry pressure
    assert np.count_nonzero(np.max(np.abs(response.nodal_by_bore), axis=0)) >= len(theta) // 3
    for k in range(2):
        shift = np.zeros(2)
        shift[k] = 1e-6
        _, _, f_plus, force_plus = evaluate(bore, velocity + shift)
        _, _, f_minus, force_minus = evaluate(bore, velocity - shift)
        nodal = (f_plus - f_minus) / 2e-6
        force = (force_plus - force_minus) / 2e-6
        assert np.max(np.abs(nodal - response.nodal_by_velocity[:, k])) <= 1e-6 * np.max(
            np.abs(nodal))
        assert np.max(np.abs(force - response.force_by_velocity[:, k])) <= 1e-6 * np.max(
            np.abs(force))


def test_half_width_response_equals_the_full_width_one(monkeypatch):
    """The bore deformed alike over the width keeps the film mirror-symmetric: the
    response solved on z ≤ 0 (the mirrored couplings folded) equals the one on all active
    nodes (to round-off), and it is the one taken (the test above checks it against
    differences)."""
    from conrod.film.reynolds import response as response_module

    film, theta, bore, velocity, evaluate = setup()
    deformed, pressure, _, _ = evaluate(bore, velocity)
    weights = nodal_force_weights(film, theta, RADIUS)
    halves = []
    mirror_half = response_module._mirror_half

    def spied(*args):
        halves.append(mirror_half(*args))
        return halves[-1]

    monkeypatch.setattr(response_module, "_mirror_half", spied)
    half = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    assert halves[0] is not None and halves[0][0].size < 0.6 * halves[0][1].size
    monkeypatch.setattr(response_module, "MIRROR_HALF", False)
    full = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
    for name in ("nodal_by_bore", "nodal_by_velocity", "force_by_bore", "force_by_velocity"):
        a, b = getattr(half, name), getattr(full, name)
        assert np.max(np.abs(a - b)) <= 1e-10 * np.max(np.abs(b)), name
    # an uneven bore over the width is not mirror-symmetric: all active nodes
    uneven = dataclasses.replace(deformed, deformation=deformed.deformation
                                 + np.linspace(0.0, 1e-7, deformed.deformation.shape[1]))
    problem = film.discrete_problem(uneven)
    active = ~problem.fixed & (pressure > problem.cavitation)
    assert mirror_half(active, np.nonzero(active), pressure, problem) is None


def test_the_banded_solve_is_taken_and_equals_superlus(monkeypatch):
    """A film with a cavitated arc cuts the ring of active θ rows: its responses, half
    width and full width, are solved on the band (taken: spied) and equal SuperLU's (the
    banded solve turned off) to round-off."""
    from conrod.film.reynolds import response as response_module

    film, theta, bore, velocity, evaluate = setup()
    deformed, pressure, _, _ = evaluate(bore, velocity)
    weights = nodal_force_weights(film, theta, RADIUS)
    banded = response_module.banded_solve_rows
    answers: list[bool] = []

    def spied(*args):
        answers.append(banded(*args) is not None)
        return banded(*args)

    names = ("nodal_by_bore", "nodal_by_velocity", "force_by_bore", "force_by_velocity")
    for half in (True, False):
        monkeypatch.setattr(response_module, "MIRROR_HALF", half)
        monkeypatch.setattr(response_module, "banded_solve_rows", spied)
        band = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
        monkeypatch.setattr(response_module, "banded_solve_rows", lambda *args: None)
        lu = film.thickness_response(deformed, ReynoldsMemory(pressure), weights, STEP)
        for name in names:
            a, b = getattr(band, name), getattr(lu, name)
            assert np.max(np.abs(a - b)) <= 1e-12 * np.max(np.abs(b)), (half, name)
    assert answers == [True, True]


def test_the_compiled_rows_are_the_active_matrix_entry_for_entry():
    """The rows the band is built from (:func:`active_rows`) hold K_AA's entries as
    :func:`conrod.film.linearised.active_matrix` does, and on the half width the folded K_H,
    exactly (their sums in the same order)."""
    import scipy.sparse as sp

    from conrod.film.linearised import active_matrix
    from conrod.film.reynolds import kernel
    from conrod.film.reynolds.response import _folded, _mirror_half
    from conrod.film.reynolds.response_kernel import active_rows

    film, theta, bore, velocity, evaluate = setup()
    deformed, pressure, _, _ = evaluate(bore, velocity)
    problem, grid = film.discrete_problem(deformed), film.film_grid
    a_east, a_north, _ = kernel.assemble_coefficients(
        problem.h, problem.h_rate, grid.radius, grid.d_theta, grid.d_z,
        deformed.journal_speed + deformed.shell_speed, deformed.viscosity)
    active = ~problem.fixed & (pressure > problem.cavitation)
    matrix, nodes = active_matrix(a_east, a_north, active)
    n = nodes[0].size
    full = sp.csr_matrix(active_rows(a_east, a_north, active, False)[::-1], shape=(n, n))
    assert np.array_equal(full.toarray(), matrix.toarray())
    keep, representative = _mirror_half(active, nodes, pressure, problem)
    half = sp.csr_matrix(active_rows(a_east, a_north, active, True)[::-1],
                         shape=(keep.size, keep.size))
    assert np.array_equal(half.toarray(), _folded(matrix, keep, representative).toarray())
    assert 0 < keep.size < n
