"""The multigrid pressure equals a direct sparse solve of the same discrete problem.

Independent answer: the finite-volume balance of :mod:`conrod.film.reynolds.kernel`
assembled here as a full-grid sparse matrix (θ periodic, both edge rows at ambient) and
solved by SuperLU (``scipy.sparse.linalg.spsolve``) on the multigrid's pressurised set,
with the cavitated nodes at p_cav. The multigrid solves only z ≤ 0 (mid-plane mirror),
warm or cold, so this also checks the mirror and the warm start.
"""

from __future__ import annotations

import numpy as np
import pytest
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import spsolve

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds.film import ReynoldsFilm

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)


def _state(step: int) -> FilmState:
    """Journal at ε ≈ 0.6, squeezing and creeping by 0.002 rad per step."""
    angle = 0.002 * step
    c = GEOMETRY.radial_clearance
    return FilmState(eccentricity_x=0.6 * c * np.cos(angle), eccentricity_y=0.6 * c * np.sin(angle),
                     velocity_x=2e-4, velocity_y=-1e-4, journal_speed=200.0, viscosity=0.02)


def _direct_pressure(film: ReynoldsFilm, state: FilmState, active: np.ndarray) -> np.ndarray:
    """Pressure [Pa] solving K p = b on ``active`` with p = 0 elsewhere (sparse LU)."""
    problem = film._problem(state)
    g = film.film_grid
    a_east, a_north, source = kernel.assemble_coefficients(
        problem.h, problem.h_rate, g.radius, g.d_theta, g.d_z,
        state.journal_speed + state.shell_speed, state.viscosity)
    n_theta, n_nodes = active.shape
    index = -np.ones(active.shape, dtype=np.int64)
    rows_i, rows_j = np.nonzero(active)
    index[rows_i, rows_j] = np.arange(rows_i.size)
    east, west = (rows_i + 1) % n_theta, (rows_i - 1) % n_theta
    links = ((east, rows_j, a_east[rows_i, rows_j]), (west, rows_j, a_east[west, rows_j]),
             (rows_i, rows_j + 1, a_north[rows_i, rows_j]),
             (rows_i, rows_j - 1, a_north[rows_i, rows_j - 1]))
    own = np.arange(rows_i.size)
    rows, cols, data = [own], [own], [sum(link[2] for link in links)]
    for ni, nj, conductance in links:
        neighbour = index[ni, nj]
        keep = neighbour >= 0  # inactive neighbours hold p = 0 (edges, cavitated)
        rows.append(own[keep])
        cols.append(neighbour[keep])
        data.append(-conductance[keep])
    matrix = coo_matrix((np.concatenate(data), (np.concatenate(rows), np.concatenate(cols))),
                        shape=(own.size, own.size)).tocsc()
    pressure = np.zeros(active.shape)
    pressure[rows_i, rows_j] = spsolve(matrix, source[rows_i, rows_j])
    return pressure


@pytest.mark.parametrize("grid", [(72, 16), (144, 32), (288, 64)])
@pytest.mark.parametrize("warm", [False, True])
@pytest.mark.parametrize("tolerance", [5e-7, 1e-9, 1e-10, 1e-12])
def test_multigrid_pressure_equals_sparse_direct_solve(grid, warm, tolerance):
    """max|p_multigrid − p_direct| ≤ tolerance·max p (the tolerance bounds the error), at
    the tolerances the orbit solves the film at (5e-7 in Newton of the implicit orbit, 1e-9
    quasi-static, 1e-12 adaptive) and on the grids whose coarse cycles cut the coarse
    faces at the rupture line."""
    film = ReynoldsFilm(GEOMETRY, n_theta=grid[0], n_z=grid[1], tolerance=tolerance)
    memory = film.initial_memory()
    if warm:
        _, memory = film.solve_with_memory(_state(0), memory)
    state = _state(5)
    result, _ = film.solve_with_memory(state, memory, with_pressure=True)
    pressure = result.pressure
    assert result.extra["warm_start"] == float(warm)
    active = ~film._problem(state).fixed & (pressure > 0.0)
    direct = _direct_pressure(film, state, active)
    assert direct[active].min() > 0.0  # the same set is pressurised in the direct answer
    error = np.abs(pressure - direct).max() / direct.max()
    assert error <= tolerance


@pytest.mark.parametrize("grid", [(72, 16), (288, 64)])
@pytest.mark.parametrize("tolerance", [5e-7, 1e-12])
def test_secant_predicted_start_equals_sparse_direct_solve(grid, tolerance):
    """A solve started from the secant predictor of two earlier solves (states 0 and 3,
    solved at 5: α = 2/3) meets the direct answer within the tolerance."""
    film = ReynoldsFilm(GEOMETRY, n_theta=grid[0], n_z=grid[1], tolerance=tolerance)
    _, memory = film.solve_with_memory(_state(0), film.initial_memory())
    _, memory = film.solve_with_memory(_state(3), memory)
    assert memory.previous is not None
    state = _state(5)
    pressure = film.solve_with_memory(state, memory, with_pressure=True)[0].pressure
    active = ~film._problem(state).fixed & (pressure > 0.0)
    direct = _direct_pressure(film, state, active)
    assert direct[active].min() > 0.0
    assert np.abs(pressure - direct).max() / direct.max() <= tolerance
