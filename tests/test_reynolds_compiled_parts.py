"""The compiled pieces of the Reynolds solve equal the plain NumPy expressions they replace
(film thickness, warm-start field, symmetric fold, force and extrema, Gauss–Seidel sweep)."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.film import characteristics as chars
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds import multigrid as multigrid
from conrod.film.reynolds import multigrid_operators as ops
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.memory import ReynoldsMemory, scaled_state

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
C = GEOMETRY.radial_clearance


def _state(angle: float, velocity: float = 0.0) -> FilmState:
    return FilmState(eccentricity_x=0.6 * C * np.cos(angle),
                     eccentricity_y=0.6 * C * np.sin(angle), velocity_x=velocity,
                     velocity_y=-0.5 * velocity, journal_speed=200.0, viscosity=0.02)


def test_film_gap_is_the_rigid_thickness_and_its_rate():
    """h = c − e·(cos θ, sin θ) and ∂h/∂t = −ė·(cos θ, sin θ), bit for bit."""
    film = ReynoldsFilm(GEOMETRY, n_theta=36, n_z=8)
    state = _state(0.7, velocity=3e-3)
    theta = film.film_grid.theta[:, None]
    h, h_rate = kernel.film_gap(C, state.eccentricity_x, state.eccentricity_y,
                                state.velocity_x, state.velocity_y, np.cos(theta[:, 0]),
                                np.sin(theta[:, 0]), 9)
    expected = C - state.eccentricity_x * np.cos(theta) - state.eccentricity_y * np.sin(theta)
    expected_rate = -state.velocity_x * np.cos(theta) - state.velocity_y * np.sin(theta)
    assert np.array_equal(h, np.repeat(expected, 9, axis=1))
    assert np.array_equal(h_rate, np.repeat(expected_rate, 9, axis=1))


def test_warm_field_is_the_projected_secant_start_with_the_dirichlet_values():
    """max(memory.start(q), p_cav) with the fixed values on the Dirichlet nodes."""
    film = ReynoldsFilm(GEOMETRY, n_theta=36, n_z=8)
    memory = film.initial_memory()
    for angle in (0.0, 0.05):
        _, memory = film.solve_with_memory(_state(angle), memory)
    assert isinstance(memory, ReynoldsMemory)
    q = scaled_state(_state(0.09), C)
    problem = film._problem(_state(0.09))
    previous, step = memory.secant(q)
    assert 0.0 < step <= 2.0
    expected = np.maximum(memory.start(q), 1.0e4)
    expected[problem.fixed] = problem.fixed_values[problem.fixed]
    field = kernel.warm_field(memory.pressure, previous, step, 1.0e4, problem.fixed,
                              problem.fixed_values)
    assert np.array_equal(field, expected)


def test_fold_and_unfold_are_the_symmetric_half_layout():
    """Rows z ≤ 0 plus the padding row (p, b: 0; h: mirror row; fixed: True), and back."""
    rng = np.random.default_rng(3)
    n, m = 12, 9
    p, h, b = rng.random((n, m)), rng.random((n, m)), rng.random((n, m))
    fixed = rng.random((n, m)) < 0.3
    p_half, h_half, b_half, f_half = multigrid._fold(p, h, b, fixed)
    assert np.array_equal(p_half[:, :5], p[:, :5]) and not p_half[:, 5].any()
    assert np.array_equal(h_half[:, :6], h[:, :6])
    assert np.array_equal(b_half[:, :5], b[:, :5]) and not b_half[:, 5].any()
    assert np.array_equal(f_half[:, :5], fixed[:, :5]) and f_half[:, 5].all()
    out = np.empty((n, m))
    multigrid._unfold(p_half, out)
    assert np.array_equal(out[:, :5], p[:, :5])
    assert np.array_equal(out[:, 5:], p[:, 3::-1])


def test_force_and_extremes_match_the_numpy_quadrature_and_argmax():
    """Force sums to round-off of numpy's; the extreme nodes are numpy's first ones."""
    film = ReynoldsFilm(GEOMETRY, n_theta=72, n_z=16)
    result = film.solve(_state(0.4), with_pressure=True)
    h = film._problem(_state(0.4)).h
    w_x, w_y = film._force_weights
    sum_x, sum_y, i_p, j_p, i_h, j_h = kernel.force_and_extremes(result.pressure, w_x, w_y, h)
    assert sum_x == pytest.approx(np.sum(result.pressure * w_x), rel=1e-13)
    assert sum_y == pytest.approx(np.sum(result.pressure * w_y), rel=1e-13)
    assert (i_p, j_p) == np.unravel_index(np.argmax(result.pressure), h.shape)
    assert (i_h, j_h) == np.unravel_index(np.argmin(h), h.shape)
    assert (result.max_pressure, result.max_pressure_angle) == chars.peak_pressure(
        result.pressure, film.film_grid)
    assert (result.min_film_thickness, result.min_film_angle) == chars.minimum_film(
        h, film.film_grid)


def test_gauss_seidel_sweep_is_the_unrelaxed_sor_sweep():
    """gauss_seidel equals relax with ω = 1 to round-off, projection included."""
    rng = np.random.default_rng(5)
    h = 1e-5 * (1.0 + 0.5 * rng.random((16, 9)))
    fixed = np.zeros(h.shape, dtype=np.bool_)
    fixed[:, [0, -1]] = True
    a_east, a_north = ops.conductances(h, 0.025, 2 * np.pi / 16, 0.003)
    weights = ops.stencil(a_east, a_north, fixed, False)
    source = rng.normal(size=h.shape)
    start = rng.normal(size=h.shape)
    sor, gauss = start.copy(), start.copy()
    ops.relax(sor, *weights[:4], source, 1.0, 0.0, 3)
    multigrid.gauss_seidel(gauss, *weights[:4], source, 0.0, 3)
    assert (gauss[:, 1:-1] >= 0.0).all()  # edge rows are never relaxed
    np.testing.assert_allclose(gauss, sor, rtol=1e-13, atol=1e-13 * np.abs(sor).max())
