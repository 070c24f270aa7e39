"""Compiled look-up of a tabulated squeeze-force map (used by the table and mobility films).

Reduction (Booker [1]): in a frame turning at ω̄ = (ω_j + ω_b)/2 the two surfaces move at
±(ω_j − ω_b)/2, so the wedge term of the Reynolds equation (∝ ω_j + ω_b) vanishes and the
film is a pure squeeze film driven by the journal-centre velocity relative to that frame,

.. math:: \\mathbf v_s = \\dot{\\mathbf e} - \\bar ω \\times \\mathbf e,
          \\qquad (v_r, v_t) = (\\dot e,\\; e(\\dot ψ - \\bar ω)).

The squeeze force is positively homogeneous of degree one in v_s (cavitation at p = 0
scales with p), so in the line-of-centres frame

.. math:: \\mathbf F = \\frac{μ R^3 L}{c^3} |v_s|\\, \\bar f(ε, β) \\,
          (\\cos φ, \\sin φ), \\qquad φ = β + π + A(ε, β), β = atan2(v_t, v_r).

The table stores G = ln|f̄| + WEIGHT_POWER·ln(1 − ε²) (smooth; the weight removes the
squeeze singularity at ε → 1) and the turning angle A (≈ 0 when the force opposes the
velocity) on direction nodes uniform in u, β = u + (κ/2) sin 2u (:data:`CLUSTERING`), and
on ε nodes uniform in s = −ln(1 − ε). Both are interpolated by three-point Lagrange
polynomials in s and in u: quadratic in the
displacement as [D0] §3.3. In the velocity the interpolation is log-polar rather than
linear: the force magnitude changes by orders of magnitude with the velocity direction
near the wall (separating vs approaching motion), where a linear blend errs by ~20 %.

[1] J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution",
    J. Basic Eng. 87 (1965) 537–546.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

WEIGHT_POWER = 2.5
"""G = ln|f̄| + WEIGHT_POWER·ln(1 − ε²) is what is tabulated [-]."""


@nb.njit(cache=True)
def stretched(eps: float) -> float:
    """s = −ln(1 − ε) [-]."""
    return -math.log(1.0 - eps)


@nb.njit(cache=True)
def lagrange3(x: float, n: int, periodic: bool) -> tuple[int, float, float, float]:
    """Middle node j and weights for nodes j−1, j, j+1 at grid coordinate x (spacing 1)."""
    j = int(math.floor(x + 0.5))
    if not periodic:
        j = min(max(j, 1), n - 2)
    t = x - j
    return j, 0.5 * t * (t - 1.0), 1.0 - t * t, 0.5 * t * (t + 1.0)


CLUSTERING = 0.6
"""Direction clustering κ: β = u + (κ/2) sin 2u packs nodes 1/(1 − κ) times closer around
the pure-wedge directions β = ±π/2, where the rupture line sweeps over the minimum gap
and the force turns fastest with the velocity direction [-]."""


@nb.njit(cache=True)
def direction_of(u: float) -> float:
    """Velocity direction β(u) = u + (κ/2) sin 2u [rad]."""
    return u + 0.5 * CLUSTERING * math.sin(2.0 * u)


@nb.njit(cache=True)
def uniform_coordinate(beta: float) -> float:
    """Inverse of :func:`direction_of` (Newton from the first-order inverse; β ↦ u is
    smooth and monotone) [rad]."""
    u = beta - 0.5 * CLUSTERING * math.sin(2.0 * beta)
    for _ in range(30):
        step = (direction_of(u) - beta) / (1.0 + CLUSTERING * math.cos(2.0 * u))
        u -= step
        if abs(step) < 1e-14:
            break
    return u


@nb.njit(cache=True)
def interpolate(table: np.ndarray, eps: float, beta: float, s_step: float) -> float:
    """Value of a (n_eps, n_dir) table at (ε, β); nodes β(u_k), u_k = −π + 2πk/n_dir."""
    return interpolate_at(table, eps, uniform_coordinate(
        (beta + math.pi) % (2.0 * math.pi) - math.pi), s_step)


@nb.njit(cache=True)
def interpolate_at(table: np.ndarray, eps: float, u: float, s_step: float) -> float:
    """Value of a (n_eps, n_dir) table at ε and the uniform direction coordinate u."""
    n_eps, n_dir = table.shape
    j, a0, a1, a2 = lagrange3(stretched(eps) / s_step, n_eps, False)
    k, b0, b1, b2 = lagrange3((u + math.pi) * n_dir / (2.0 * math.pi), n_dir, True)
    total = 0.0
    for dk, wb in ((-1, b0), (0, b1), (1, b2)):
        col = (k + dk) % n_dir
        total += wb * (a0 * table[j - 1, col] + a1 * table[j, col] + a2 * table[j + 1, col])
    return total


@nb.njit(cache=True)
def squeeze_velocity(
    ex: float, ey: float, vx: float, vy: float, omega_sum: float, clearance: float
) -> tuple[float, float, float, float, float]:
    """(ε, cos ψ, sin ψ, v_r, v_t): squeeze velocity relative to the ω̄ frame, LOC components."""
    e = math.hypot(ex, ey)
    if e > 1.0e-12 * clearance:
        cos_psi, sin_psi = ex / e, ey / e
    else:
        cos_psi, sin_psi = 1.0, 0.0
    mean = 0.5 * omega_sum
    wx = vx + mean * ey
    wy = vy - mean * ex
    return e / clearance, cos_psi, sin_psi, wx * cos_psi + wy * sin_psi, wy * cos_psi - wx * sin_psi


@nb.njit(cache=True)
def unit_force(
    eps: float, beta: float, s_step: float, log_magnitude: np.ndarray, turning: np.ndarray
) -> tuple[float, float]:
    """Dimensionless squeeze force f̄ (radial, tangential) for a unit velocity at angle β."""
    u = uniform_coordinate((beta + math.pi) % (2.0 * math.pi) - math.pi)
    return unit_force_at(eps, u, s_step, log_magnitude, turning)


@nb.njit(cache=True)
def unit_force_at(
    eps: float, u: float, s_step: float, log_magnitude: np.ndarray, turning: np.ndarray
) -> tuple[float, float]:
    """:func:`unit_force` at the uniform direction coordinate u."""
    magnitude = math.exp(interpolate_at(log_magnitude, eps, u, s_step)) / (
        (1.0 - eps * eps) ** WEIGHT_POWER)
    phi = direction_of(u) + math.pi + interpolate_at(turning, eps, u, s_step)
    return magnitude * math.cos(phi), magnitude * math.sin(phi)


@nb.njit(cache=True)
def table_force(
    ex: float, ey: float, vx: float, vy: float, omega_sum: float, viscosity: float,
    force_scale: float, clearance: float, s_step: float,
    log_magnitude: np.ndarray, turning: np.ndarray,
) -> tuple[float, float]:
    """Film force on the journal (F_x, F_y) [N]; force_scale = R³L/c³ [m]."""
    eps, c_psi, s_psi, v_r, v_t = squeeze_velocity(ex, ey, vx, vy, omega_sum, clearance)
    speed = math.hypot(v_r, v_t)
    if speed == 0.0:
        return 0.0, 0.0
    f_r, f_t = unit_force(eps, math.atan2(v_t, v_r), s_step, log_magnitude, turning)
    unit = viscosity * force_scale * speed
    return unit * (f_r * c_psi - f_t * s_psi), unit * (f_r * s_psi + f_t * c_psi)


@nb.njit(cache=True)
def _turning_at_nodes(eps: float, s_step: float, turning: np.ndarray) -> np.ndarray:
    """A(ε, β_k) at every direction node (Lagrange in s only) [rad]."""
    n_eps, n_dir = turning.shape
    j, a0, a1, a2 = lagrange3(stretched(eps) / s_step, n_eps, False)
    column = np.empty(n_dir)
    for k in range(n_dir):
        column[k] = a0 * turning[j - 1, k] + a1 * turning[j, k] + a2 * turning[j + 1, k]
    return column


@nb.njit(cache=True)
def _force_angle(u: float, column: np.ndarray) -> float:
    """Unwrapped force angle g = β(u) + π + A(ε, β(u)), increasing by 2π over a turn [rad]."""
    n_dir = column.size
    k, b0, b1, b2 = lagrange3((u + math.pi) * n_dir / (2.0 * math.pi), n_dir, True)
    turning = (b0 * column[(k - 1) % n_dir] + b1 * column[k % n_dir]
               + b2 * column[(k + 1) % n_dir])
    return direction_of(u) + math.pi + turning


@nb.njit(cache=True)
def inverse_direction(eps: float, target: float, s_step: float, turning: np.ndarray) -> float:
    """Velocity direction β [rad] whose squeeze force points at angle ``target`` [rad]."""
    return direction_of(inverse_coordinate(eps, target, s_step, turning))


@nb.njit(cache=True)
def inverse_coordinate(eps: float, target: float, s_step: float, turning: np.ndarray) -> float:
    """Uniform direction coordinate u whose squeeze force points at ``target`` [rad].

    Brackets the target between direction nodes, then Illinois regula falsi in u on the
    same interpolant as the forward look-up (so force(inverse) reproduces the target).
    """
    column = _turning_at_nodes(eps, s_step, turning)
    n_dir = column.size
    step = 2.0 * math.pi / n_dir
    u_lo = -math.pi
    g_lo = _force_angle(u_lo, column)
    goal = g_lo + (target - g_lo) % (2.0 * math.pi)
    u_hi, g_hi = math.pi, g_lo + 2.0 * math.pi
    for k in range(1, n_dir + 1):
        u = -math.pi + k * step
        g = _force_angle(u, column)
        if g >= goal:
            u_hi, g_hi = u, g
            break
        u_lo, g_lo = u, g
    f_lo, f_hi = g_lo - goal, g_hi - goal
    u = u_lo if f_lo == 0.0 else u_hi
    side = 0
    for _ in range(100):
        if f_hi == f_lo or f_lo == 0.0 or f_hi == 0.0:
            break
        u = (u_lo * f_hi - u_hi * f_lo) / (f_hi - f_lo)
        f = _force_angle(u, column) - goal
        if abs(f) < 1e-13 or u_hi - u_lo < 1e-13:
            break
        if f * f_hi > 0.0:
            u_hi, f_hi = u, f
            if side == -1:
                f_lo *= 0.5
            side = -1
        else:
            u_lo, f_lo = u, f
            if side == 1:
                f_hi *= 0.5
            side = 1
    return u


@nb.njit(cache=True)
def mobility_velocity(
    ex: float, ey: float, load_x: float, load_y: float, omega_sum: float, viscosity: float,
    force_scale: float, clearance: float, s_step: float,
    log_magnitude: np.ndarray, turning: np.ndarray,
) -> tuple[float, float]:
    """Quasi-static journal velocity (v_x, v_y) [m/s] under the load W [N]: the squeeze
    velocity whose tabulated force is −W, plus ω̄ × e; force_scale = R³L/c³ [m]."""
    e = math.hypot(ex, ey)
    if e > 1.0e-12 * clearance:
        cos_psi, sin_psi = ex / e, ey / e
    else:
        cos_psi, sin_psi = 1.0, 0.0
    mean = 0.5 * omega_sum
    load = math.hypot(load_x, load_y)
    if load == 0.0:
        return -mean * ey, mean * ex
    eps = e / clearance
    film_r = -(load_x * cos_psi + load_y * sin_psi)
    film_t = -(load_y * cos_psi - load_x * sin_psi)
    u = inverse_coordinate(eps, math.atan2(film_t, film_r), s_step, turning)
    beta = direction_of(u)
    f_r, f_t = unit_force_at(eps, u, s_step, log_magnitude, turning)
    speed = load / (viscosity * force_scale * math.hypot(f_r, f_t))
    v_r, v_t = speed * math.cos(beta), speed * math.sin(beta)
    return (v_r * cos_psi - v_t * sin_psi - mean * ey,
            v_r * sin_psi + v_t * cos_psi + mean * ex)
