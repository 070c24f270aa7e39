"""Compiled Reynolds force and moments of a tilted journal with a warm start, for the
compiled free flight of a tilted journal (:mod:`conrod.orbit.tilt_flight`).

The discrete source of the Reynolds equation (:func:`conrod.film.reynolds.kernel.\
assemble_coefficients`) is linear in the squeeze velocity of the mean frame
(:mod:`conrod.film.reynolds.flight`); the tilt adds to h the field of an eccentricity that
grows along the width, e(z) = (zγ_y, −zγ_x) (:mod:`conrod.film.tilt`), whose wedge and squeeze
terms combine the same way:

.. math:: b = 12μ\\,w_z RΔθ\\,[v_{s,x}\\cos θ + v_{s,y}\\sin θ
              + z(t_c \\cos θ − t_s \\sin θ)],\\qquad
          t_s = \\dotγ_x + κ\\bar ωγ_y,\\; t_c = \\dotγ_y − κ\\bar ωγ_x,

so the pressure depends on the state only through q = (e, γ, v_s, t_s, t_c), and a force
evaluation (forces and moments) is one warm-started call of the compiled projected multigrid
on the full grid (a tilt breaks the mid-plane symmetry). The Jacobian is forward differences
in q from the converged field, each field difference kept as a tangent ∂p/∂q that moves the
warm start of the next solve to its own q (as the aligned kernel does).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.film.reynolds.flight import (
    JACOBIAN_STEP,
    JACOBIAN_TOLERANCE,
    FlightKernel,
    profile_arrays,
)
from conrod.film.reynolds.multigrid import coarse_levels, multigrid_solve, read_only
from conrod.film.reynolds.multigrid_operators import copy_into
from conrod.film.tilt import moment_weights, thickness_directions


class _FullGrid:
    """The full (unfolded) grid of a film for :func:`_profile_arrays` and the supply."""

    symmetric = False

    def __init__(self, fixed: np.ndarray):
        self.fixed = fixed


def tilt_flight_kernel(film, memory, newton_tolerance: float,
                       free: bool = True) -> FlightKernel | None:
    """The compiled force and moments of a tilted journal on a
    :class:`~conrod.film.reynolds.film.ReynoldsFilm` (rigid, isoviscous, multigrid, no inlet
    line; None otherwise), warm-started from ``memory`` (a ``ReynoldsMemory``), force
    evaluations solved to ``newton_tolerance`` [-]; ``free`` False (a prescribed tilt): the
    Jacobian differences the journal centre's columns only, four film solves fewer."""
    from conrod.film.supply import edge_mask, supply_mask

    if (film.method != "multigrid" or film.ambient_line_at_max_gap
            or film.pressure_viscosity is not None):
        return None
    grid, g = film.film_grid, film.geometry
    fixed = read_only(edge_mask(grid) | supply_mask(g, grid))
    cos_t = np.ascontiguousarray(np.repeat(np.cos(grid.theta)[:, None], grid.n_z + 1, axis=1))
    sin_t = np.ascontiguousarray(np.repeat(np.sin(grid.theta)[:, None], grid.n_z + 1, axis=1))
    width = np.full(grid.n_z + 1, grid.d_z)
    width[[0, -1]] *= 0.5
    unit = 12.0 * width[None, :] * grid.radius * grid.d_theta * ~fixed
    area = grid.area_weights
    by_gx, by_gy = thickness_directions(np.cos(grid.theta), np.sin(grid.theta), grid.z)
    zs, zc = np.ascontiguousarray(by_gx), np.ascontiguousarray(-by_gy)  # z sin θ, z cos θ
    w_mx, w_my = moment_weights(np.cos(grid.theta), np.sin(grid.theta), grid.z, area)
    field = np.zeros(fixed.shape)
    if memory is not None and getattr(memory, "pressure", None) is not None:
        field = np.array(memory.pressure, dtype=float)
    field[_supply_nodes_full(film)] = g.supply_pressure
    profile, profile_source = profile_arrays(film, _FullGrid(fixed))
    tolerances = np.array([max(float(newton_tolerance), film.tolerance),
                           min(JACOBIAN_TOLERANCE, max(float(newton_tolerance),
                                                       film.tolerance))])
    params = (field, fixed, np.ascontiguousarray(unit * cos_t),
              np.ascontiguousarray(unit * sin_t), cos_t * area, sin_t * area, cos_t, sin_t,
              grid.radius, grid.d_theta, grid.d_z, g.radial_clearance,
              coarse_levels(grid.n_theta, grid.n_z), False, float(g.cavitation_pressure),
              math.sin(grid.d_theta) / grid.d_theta, tolerances, int(film.max_iterations),
              np.zeros((8,) + field.shape), np.zeros(9), profile, profile_source, zc, zs,
              np.ascontiguousarray(unit * zc), np.ascontiguousarray(unit * zs),
              np.ascontiguousarray(w_mx), np.ascontiguousarray(w_my), np.ones(8),
              np.zeros(3))
    if not free:
        params[28][[2, 3, 6, 7]] = 0.0  # γ columns not asked for
    return FlightKernel(reynolds_tilt_force, reynolds_tilt_jacobian, params, film)


def _supply_nodes_full(film) -> np.ndarray:
    """Supply nodes of the full grid."""
    from conrod.film.supply import supply_mask

    return supply_mask(film.geometry, film.film_grid)


@nb.njit(cache=True, inline="always")
def _tilt_state(x, y, gx, gy, vx, vy, rx, ry, omega_sum, params):
    """q = (e_x, e_y, γ_x, γ_y, v_s,x, v_s,y, t_s, t_c) [m, rad, m/s, rad/s] (module
    docstring)."""
    k = 0.5 * params[15] * omega_sum
    return np.array([x, y, gx, gy, vx + k * y, vy - k * x, rx + k * gy, ry - k * gx])


@nb.njit(cache=True, inline="always")
def _tilt_predict(q, params):
    """Move the warm start along the tangents of the last Jacobian to ``q``."""
    pressure, fixed, cavitation, tangents, anchor = (params[0], params[1], params[14],
                                                     params[18], params[19])
    if anchor[8] == 0.0:
        return
    n, m = pressure.shape
    for i in range(n):
        for j in range(m):
            if fixed[i, j]:
                continue
            value = pressure[i, j]
            for k in range(8):
                value += tangents[k, i, j] * (q[k] - anchor[k])
            pressure[i, j] = value if value > cavitation else cavitation


@nb.njit(cache=True, inline="always")
def _tilt_solve(q, viscosity, params, tolerance, omega_sum):
    """(F_x, F_y, M_x, M_y) [N, N m] at q, solved in place on the warm-start field (NaN
    where the film closes or the solve fails)."""
    (pressure, fixed, src_x, src_y, w_x, w_y, cos_t, sin_t, radius, d_theta, d_z,
     clearance, n_coarse, symmetric, cavitation, _, _, max_cycles, _, anchor,
     profile, profile_source, zc, zs, src_zc, src_zs, w_mx, w_my, _, stats) = params
    out = np.full(4, np.nan)
    h = clearance - q[0] * cos_t - q[1] * sin_t + q[2] * zs - q[3] * zc
    source = viscosity * (q[4] * src_x + q[5] * src_y + q[7] * src_zc - q[6] * src_zs)
    if profile.shape[0] > 0:
        h = h + profile
        source = source + (viscosity * omega_sum) * profile_source
    if not np.min(h) > 0.0:
        return out
    cycles, change = multigrid_solve(pressure, h, source, fixed, radius, d_theta, d_z,
                                     cavitation, tolerance, max_cycles, n_coarse, symmetric)
    stats[0] += 1.0
    stats[1] += cycles
    if not change <= tolerance:
        stats[2] += 1.0
        return out
    for k in range(8):
        anchor[k] = q[k]
    out[0] = -np.sum(pressure * w_x)
    out[1] = -np.sum(pressure * w_y)
    out[2] = -np.sum(pressure * w_mx)
    out[3] = -np.sum(pressure * w_my)
    return out


@nb.njit(cache=True)
def reynolds_tilt_force(x, y, gx, gy, vx, vy, rx, ry, omega_sum, viscosity, params):
    """(F_x, F_y, M_x, M_y) [N, N m] of the tilted journal at the Newton tolerance,
    warm-started from the last field moved along the last Jacobian's tangents."""
    q = _tilt_state(x, y, gx, gy, vx, vy, rx, ry, omega_sum, params)
    _tilt_predict(q, params)
    return _tilt_solve(q, viscosity, params, params[16][0], omega_sum)


@nb.njit(cache=True)
def reynolds_tilt_jacobian(x, y, gx, gy, vx, vy, rx, ry, omega_sum, viscosity, params):
    """(Q (4,) [N, N m], ∂Q/∂(e_x, e_y, γ_x, γ_y, ė_x, ė_y, γ̇_x, γ̇_y) (4, 8)) by forward
    differences in q from the converged field (each solve at the Jacobian tolerance); the
    field differences are kept as the tangents ∂p/∂q."""
    pressure, clearance, tolerance = params[0], params[11], params[16][1]
    tangents, anchor = params[18], params[19]
    q = _tilt_state(x, y, gx, gy, vx, vy, rx, ry, omega_sum, params)
    _tilt_predict(q, params)
    by_q = np.full((4, 8), np.nan)
    force = _tilt_solve(q, viscosity, params, tolerance, omega_sum)
    if np.isnan(force[0]):
        return force, by_q
    base = pressure.copy()
    lever = 0.5 * params[10] * (pressure.shape[1] - 1)  # L/2 [m]
    speed = clearance * abs(omega_sum) + math.hypot(q[4], q[5])
    columns = params[28]
    for k in range(8):
        if columns[k] == 0.0:  # a column not asked for (a prescribed tilt)
            for row in range(4):
                by_q[row, k] = 0.0
            continue
        step = JACOBIAN_STEP * (clearance if k < 4 else max(speed, 1e-9 * clearance))
        if k in (2, 3, 6, 7):
            step /= lever  # an angle (rate) that moves the edge by the length (speed) step
        shifted = q.copy()
        shifted[k] += step
        moved = _tilt_solve(shifted, viscosity, params, tolerance, omega_sum)
        for row in range(4):
            by_q[row, k] = (moved[row] - force[row]) / step
        tangent = tangents[k]
        for i in range(pressure.shape[0]):
            for j in range(pressure.shape[1]):
                tangent[i, j] = (pressure[i, j] - base[i, j]) / step
        copy_into(pressure, base)
    for k in range(8):
        anchor[k] = q[k]
        if columns[k] == 0.0:  # no tangent: the predictor holds those components
            tangents[k].fill(0.0)
    anchor[8] = 1.0
    return force, _tilt_in_rates(by_q, 0.5 * params[15] * omega_sum)


@nb.njit(cache=True, inline="always")
def _tilt_in_rates(by_q, k):
    """∂Q/∂(e, γ, ė, γ̇) from ∂Q/∂q, q = (e, γ, v_s, t_s, t_c) with v_s = ė + k(e_y, −e_x),
    t_s = γ̇_x + kγ_y, t_c = γ̇_y − kγ_x (k = κω̄)."""
    out = by_q.copy()
    for row in range(4):
        out[row, 0] = by_q[row, 0] - k * by_q[row, 5]
        out[row, 1] = by_q[row, 1] + k * by_q[row, 4]
        out[row, 2] = by_q[row, 2] - k * by_q[row, 7]
        out[row, 3] = by_q[row, 3] + k * by_q[row, 6]
    return out
