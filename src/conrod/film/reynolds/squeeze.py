"""Massless journal velocity of a grid Reynolds film by Booker's reduction.

In the frame turning at ω̄ = (ω_j + ω_b)/2 the Reynolds right-hand side of
:mod:`conrod.film.base` becomes a pure squeeze term,

.. math:: 6μ(ω_j + ω_b)∂_θ h + 12μ ∂_t h = -12μ\\,(v_{s,x}\\cos θ + v_{s,y}\\sin θ),
          \\qquad \\mathbf v_s = \\dot{\\mathbf e} - \\bar ω(-e_y, e_x),

and with p = 0 on the edges, grooves and cavitated region (no supply pressure, p_cav = 0)
the force is positively homogeneous of degree one in v_s: F(e, v_s) = |v_s| F(e, v̂_s).
So the 2-D force balance F + W = 0 reduces to one angle: find the squeeze direction β
whose unit-speed force points along −W (safeguarded secant on the wrapped angle mismatch,
warm-started from the previous solve), then |v_s| = s_0|W|/|F(s_0 v̂(β))| and
ė = v_s + ω̄ × e (Booker [1]; docs/film_advanced.md §2).

The film solve is the compiled projected multigrid of :mod:`conrod.film.reynolds.multigrid`
on the same grid, masks and mid-plane symmetry as :class:`~conrod.film.reynolds.film.ReynoldsFilm`,
warm-started from the last field; the Heun loop of :mod:`conrod.orbit.quasi_static`
runs compiled around it.

[1] J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution",
    J. Basic Eng. 87 (1965) 537–546.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.film.massless import constrain_and_record, project_onto_circle
from conrod.film.reynolds.multigrid import coarse_levels, multigrid_solve, read_only
from conrod.film.reynolds.multigrid_operators import copy_into

ANGLE_TOLERANCE = 1.0e-8
"""Stop when the film force is within this angle of −W [rad]: the relative residual
|F + W|/|W| (the Newton path stops at 1e-8)."""

FIRST_FILM_TOLERANCE = 1.0e-6
"""Multigrid tolerance of the first solve of a velocity solve. Later solves use
0.1·miss² (the secant's next miss is ~miss²), down to max(film tolerance,
0.1·ANGLE_TOLERANCE) at which a miss ≤ ANGLE_TOLERANCE is accepted; a loose solve that
already meets the angle is continued to that tolerance (inexact secant) [-]."""

ANGLE_ITERATIONS = 40
"""Most film solves of one velocity solve [-]."""


class SqueezeGrid:
    """Arrays of the compiled squeeze solve for a :class:`ReynoldsFilm` (half grid plus a
    padding row when the film is solved on z ≤ 0, like ``reynolds_multigrid.solve_on_grid``).

    cos_t, sin_t : cos θ, sin θ at the nodes [-]; fixed : Dirichlet nodes (p = 0) [-];
    source_x, source_y : multigrid source per unit v_s,x, v_s,y [Pa m^4 s/m];
    weight_x, weight_y : force quadrature F = −Σ p w [m^2]; pressure : warm-start field [Pa];
    stats : [film solves, multigrid cycles] counted by the compiled solve [-].
    """

    def __init__(self, film, viscosity: float):
        from conrod.film.supply import edge_mask, supply_mask

        grid = film.film_grid
        fixed = edge_mask(grid) | supply_mask(film.geometry, grid)
        cos_t = np.repeat(np.cos(grid.theta)[:, None], grid.n_z + 1, axis=1)
        sin_t = np.repeat(np.sin(grid.theta)[:, None], grid.n_z + 1, axis=1)
        width = np.full(grid.n_z + 1, grid.d_z)
        width[[0, -1]] *= 0.5
        source_unit = 12.0 * viscosity * width[None, :] * grid.radius * grid.d_theta
        area = grid.area_weights
        weight_x, weight_y = cos_t * area, sin_t * area
        self.symmetric = bool(film.symmetric and grid.n_z % 4 == 0
                              and np.array_equal(fixed, fixed[:, ::-1]))
        n_z = grid.n_z
        if self.symmetric:
            mid = n_z // 2
            n_z = mid
            fixed, cos_t, sin_t = (half_rows(a, pad) for a, pad in
                                   ((fixed, True), (cos_t, None), (sin_t, None)))
            weight_x = half_rows(weight_x * _doubling(mid), 0.0)
            weight_y = half_rows(weight_y * _doubling(mid), 0.0)
            source_unit = half_rows(np.broadcast_to(source_unit,
                                                    cos_t.shape[:1] + (grid.n_z + 1,)),
                                0.0)
        self.fixed = read_only(fixed)  # one signature of multigrid_solve on every path
        self.cos_t, self.sin_t = cos_t, sin_t
        self.source_x = np.ascontiguousarray(source_unit * cos_t * ~fixed)
        self.source_y = np.ascontiguousarray(source_unit * sin_t * ~fixed)
        self.weight_x, self.weight_y = weight_x, weight_y
        self.geometry = (grid.radius, grid.d_theta, grid.d_z, film.geometry.radial_clearance)
        self.n_coarse = coarse_levels(grid.n_theta, n_z)
        self.pressure = np.zeros(fixed.shape)
        self.stats = np.zeros(2)


def half_rows(field: np.ndarray, padding) -> np.ndarray:
    """Rows z ≤ 0 (mid-plane included) plus a padding row (None: the mirror row)."""
    mid = (field.shape[1] - 1) // 2
    half = np.empty((field.shape[0], mid + 2), dtype=field.dtype)
    half[:, : mid + 1] = field[:, : mid + 1]
    half[:, -1] = field[:, mid + 1] if padding is None else padding
    return half


def _doubling(mid: int) -> np.ndarray:
    """Axial factors folding the mirrored half onto z ≤ 0: 2 below the mid-plane, 1 on it."""
    factor = np.full(2 * mid + 1, 2.0)
    factor[mid:] = 0.0
    factor[mid] = 1.0
    return factor[None, :]


@nb.njit(cache=True, inline="always")
def _unit_force(beta, pressure, h, g, speed, tolerance, max_cycles):
    """Film force (F_x, F_y) [N] at the unit squeeze speed ``speed`` in direction β and
    whether the multigrid converged; ``g`` = (fixed, source_x, source_y, w_x, w_y, dims...,
    stats), stats = [film solves, multigrid cycles] accumulated."""
    fixed, src_x, src_y, w_x, w_y, radius, d_theta, d_z, n_coarse, symmetric, stats = g
    source = speed * (math.cos(beta) * src_x + math.sin(beta) * src_y)
    cycles, change = multigrid_solve(pressure, h, source, fixed, radius, d_theta, d_z, 0.0,
                                     tolerance, max_cycles, n_coarse, symmetric)
    stats[0] += 1.0
    stats[1] += cycles
    return -np.sum(pressure * w_x), -np.sum(pressure * w_y), change <= tolerance


@nb.njit(cache=True)
def _wrap(angle):
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@nb.njit(cache=True, inline="always")
def squeeze_velocity(x, y, load_x, load_y, omega_mean, beta, slope, pressure, cos_t, sin_t,
                     g, clearance, speed, tolerance, max_cycles, tangent, scratch):
    """Quasi-static velocity (v_x, v_y) [m/s] with F(e, ė) + W = 0 by Booker's reduction
    (module docstring), from the squeeze direction guess β [rad] and the slope dφ/dβ of
    the force angle [-]. Returns (v_x, v_y, β, slope, angle residual [rad]); the residual
    is ∞ when the film solve failed. ``tangent`` ≈ ∂p/∂β [Pa/rad] (kept between calls,
    updated from successive iterates) moves the warm-start field along with β; ``scratch``
    is work space of the field's shape."""
    whirl_x, whirl_y = -omega_mean * y, omega_mean * x
    load = math.hypot(load_x, load_y)
    if load == 0.0:
        return whirl_x, whirl_y, beta, slope, 0.0
    h = clearance - x * cos_t - y * sin_t
    target = math.atan2(-load_y, -load_x)
    lo, hi = -np.inf, np.inf
    prev_beta, prev_miss = np.nan, np.nan
    miss = np.inf
    fx, fy = 0.0, 0.0
    accept = max(tolerance, 0.1 * ANGLE_TOLERANCE)
    film_tolerance = max(accept, FIRST_FILM_TOLERANCE)
    solved_at = np.nan
    for _ in range(ANGLE_ITERATIONS):
        if not np.isnan(solved_at):
            copy_into(scratch, pressure)
            pressure += (beta - solved_at) * tangent
            np.maximum(pressure, 0.0, pressure)
        fx, fy, ok = _unit_force(beta, pressure, h, g, speed, film_tolerance, max_cycles)
        if not np.isnan(solved_at) and abs(beta - solved_at) > 1e-6:
            moved = beta - solved_at
            for i in range(pressure.shape[0]):
                for j in range(pressure.shape[1]):
                    tangent[i, j] = (pressure[i, j] - scratch[i, j]) / moved
        solved_at = beta
        if not ok:
            return whirl_x, whirl_y, beta, slope, np.inf
        miss = _wrap(target - math.atan2(fy, fx))
        if abs(miss) <= ANGLE_TOLERANCE:
            if film_tolerance <= accept:
                break
            film_tolerance = accept
            continue
        if 0.0 < miss < 1.0:
            lo = max(lo, beta)
        elif -1.0 < miss < 0.0:
            hi = min(hi, beta)
        if not np.isnan(prev_miss) and miss != prev_miss and beta != prev_beta:
            secant = (prev_miss - miss) / (beta - prev_beta)
            if 0.05 < secant < 50.0:
                slope = secant
        prev_beta, prev_miss = beta, miss
        step = miss / slope
        step = max(-0.5, min(0.5, step))
        nxt = beta + step
        if not lo < nxt < hi and -np.inf < lo < hi < np.inf:
            nxt = 0.5 * (lo + hi)
        beta = nxt
        film_tolerance = max(accept, min(FIRST_FILM_TOLERANCE, 0.1 * miss * miss))
    magnitude = math.hypot(fx, fy)
    if magnitude == 0.0:
        return whirl_x, whirl_y, beta, slope, np.inf
    scale = speed * load / magnitude
    return (scale * math.cos(beta) + whirl_x, scale * math.sin(beta) + whirl_y,
            _wrap(beta), slope, abs(miss))


@nb.njit(cache=True)
def squeeze_reynolds_cycle(x, y, dt, load_x, load_y, journal_speed, shell_speed,
                           record_every, pressure, cos_t, sin_t, g, clearance, contact_radius,
                           speed, tolerance, max_cycles, beta, slope, whirl_factor):
    """Compiled Heun loop of :func:`conrod.orbit.quasi_static.quasi_static_cycle` with
    :func:`squeeze_velocity`: rows (x, y, vx, vy, 0, 0, contact) every ``record_every``
    steps, end state (x, y, vx, vy, β, slope) and the worst angle residual [rad].
    ``whirl_factor`` κ = sin Δθ/Δθ: the discrete wedge term of ``ReynoldsFilm`` (central
    difference of h) equals the squeeze term of v_s = ė − κ ω̄ × e exactly [-]."""
    n_steps = load_x.size - 1
    out = np.zeros((n_steps // record_every, 7))
    worst = 0.0
    vx2, vy2 = 0.0, 0.0
    turn = 0.0  # β(corrector) − β(predictor) of the last step: predicts the next one
    field_2, last_1 = pressure.copy(), pressure.copy()  # predictor/corrector fields
    tangent, scratch = np.zeros_like(pressure), np.zeros_like(pressure)
    for k in range(n_steps):
        mean = 0.5 * whirl_factor * (journal_speed[k] + shell_speed[k])
        vx, vy, beta, slope, r1 = squeeze_velocity(
            x, y, load_x[k], load_y[k], mean, beta, slope, pressure, cos_t, sin_t, g,
            clearance, speed, tolerance, max_cycles, tangent, scratch)
        vx, vy = constrain_and_record(x, y, vx, vy, contact_radius, k, record_every, out)
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, contact_radius)
        copy_into(scratch, pressure)
        if k > 0:  # p(corrector) ≈ p(predictor) + last step's difference
            pressure += field_2 - last_1
            np.maximum(pressure, 0.0, pressure)
        copy_into(last_1, scratch)
        mean = 0.5 * whirl_factor * (journal_speed[k + 1] + shell_speed[k + 1])
        vx2, vy2, beta2, slope, r2 = squeeze_velocity(
            xp, yp, load_x[k + 1], load_y[k + 1], mean, beta + turn, slope, pressure, cos_t,
            sin_t, g, clearance, speed, tolerance, max_cycles, tangent, scratch)
        turn, beta = _wrap(beta2 - beta), beta2
        copy_into(field_2, pressure)
        x, y, _ = project_onto_circle(
            x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), contact_radius)
        worst = max(worst, r1, r2)
        if worst == np.inf:
            break
    return out, np.array([x, y, vx2, vy2, beta, slope]), worst


def squeeze_cycle(film, request):
    """Run :func:`squeeze_reynolds_cycle` for the Reynolds ``film`` over the
    :class:`~conrod.film.capabilities.QuasiStaticRequest` ``request``. Returns (rows, end
    state array (x, y, v_x, v_y, β, slope, film solves, multigrid cycles), worst residual)."""
    r = request
    grid = SqueezeGrid(film, r.viscosity)
    radius, d_theta, d_z, clearance = grid.geometry
    g = (grid.fixed, grid.source_x, grid.source_y, grid.weight_x, grid.weight_y,
         radius, d_theta, d_z, grid.n_coarse, grid.symmetric, grid.stats)
    kappa = math.sin(d_theta) / d_theta
    mean = 0.5 * kappa * (r.journal_speed[0] + r.shell_speed[0])
    sx, sy = r.vx + mean * r.y, r.vy - mean * r.x
    beta = math.atan2(sy, sx) if sx or sy else math.atan2(r.load_y[0], r.load_x[0])
    speed = clearance * max(r.crank_speed, 1e-3)
    rows, end, worst = squeeze_reynolds_cycle(
        r.x, r.y, r.dt, r.load_x, r.load_y, r.journal_speed, r.shell_speed, r.record_every,
        grid.pressure, grid.cos_t, grid.sin_t, g, clearance, r.contact_radius, speed,
        film.tolerance, film.max_iterations, beta, 1.0, kappa)
    return rows, np.concatenate((end, grid.stats)), worst
