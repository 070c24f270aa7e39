"""Massless journal velocity of the short bearing by Booker's exact inversion.

In the frame turning at ω̄ = (ω_j + ω_b)/2 the short-bearing film of
:mod:`conrod.film.short.kernel` is a pure squeeze film driven by
v_s = ė − ω̄ × e: with the line-of-centres components (v_r, v_t) = (ė, e(ψ̇ − ω̄)) its
wedge and squeeze rates are ε(ω_j + ω_b − 2ψ̇) = −2v_t/c and 2ε̇ = 2v_r/c, so the squeeze
wedge speed is V = 2|v_s|/c and the active-arc angle α = atan2(v_r, −v_t), i.e. v_s points
at β = α − π/2 from the line of centres. The force is then positively homogeneous of degree
one in v_s,

.. math:: \\mathbf F = \\frac{μ R L^3 V}{2 c^2}\\, \\mathbf g(ε, α), \\qquad
          \\mathbf g = \\begin{pmatrix} J_{sc} & -J_{cc} \\\\ J_{ss} & -J_{sc}\\end{pmatrix}
          \\begin{pmatrix}\\cos α \\\\ \\sin α\\end{pmatrix},

with the active-arc integrals J(α, ε) of the kernel. Because the pressure vanishes at the
arc ends, dJ/dα contributes nothing and
dg/dα = −[[J_cc, J_sc], [J_sc, J_ss]] (cos α, sin α) exactly. The force angle
φ(α) = atan2(g_t, g_r) increases monotonically by 2π per turn of α and stays within π/2 of
α + π/2 (checked over ε ≤ 1 − 10⁻⁶), so the balance F = −W reduces to one angle: a
safeguarded Newton iteration (rtsafe) on φ(α) = χ, χ the angle of −W, bracketed in
[χ_u − π, χ_u] and warm-started from the previous solve. The speed follows from |W|:
|v_s| = c|W|/(2 S |g|), S = μRL³/(2c²), and ė = v_s + ω̄ × e (Booker [1]).

[1] J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution",
    J. Basic Eng. 87 (1965) 537–546.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.film.massless import constrain_and_record, project_onto_circle
from conrod.film.short.kernel import (
    ECCENTRICITY_LIMIT,
    active_arc_integrals,
    short_bearing_force,
)

ANGLE_ITERATIONS = 60
"""Most Newton/bisection steps of one direction solve [-]."""

ANGLE_TOLERANCE = 1.0e-12
"""Stop when the force angle is within this of −W [rad]: the relative force residual
|F + W|/|W| (the former Newton solve stopped at 1e-10) [-]."""

ANGLE_STEP_TOLERANCE = 1.0e-9
"""After a Newton step in α below this [rad] the force is evaluated once more and the
solve ends (quadratic convergence: the remaining error is ~ the step squared; reached
only where rounding of the force integrals keeps the miss above ANGLE_TOLERANCE)."""

NEWTON_ITERATIONS = 60
"""Most iterations of the reference 2-D Newton solve [-]."""


@nb.njit(cache=True)
def unit_force_direction(alpha: float, eps: float) -> tuple[float, float, float, float]:
    """(g_r, g_t, dg_r/dα, dg_t/dα): dimensionless short-bearing force per unit wedge
    speed V at active-arc angle α [rad], line-of-centres frame (module docstring)."""
    j_cc, j_ss, j_sc = active_arc_integrals(alpha, eps)
    ca, sa = math.cos(alpha), math.sin(alpha)
    return (ca * j_sc - sa * j_cc, ca * j_ss - sa * j_sc,
            -ca * j_cc - sa * j_sc, -ca * j_sc - sa * j_ss)


@nb.njit(cache=True)
def _wrap(angle: float) -> float:
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


@nb.njit(cache=True)
def active_arc_angle(eps: float, target: float, alpha: float) -> tuple[float, float, float, int]:
    """α [rad] with force angle φ(α) = ``target`` [rad] (line-of-centres frame) from the
    guess ``alpha``; returns (α, |g(α)|, final angle miss [rad], evaluations)."""
    # continuous force angle: φ_u(α) = α + π/2 + wrap(φ − α − π/2), |φ_u − α − π/2| < π/2
    goal = alpha + 0.5 * math.pi + _wrap(target - alpha - 0.5 * math.pi)
    lo, hi = goal - math.pi, goal
    if not lo < alpha < hi:
        alpha = 0.5 * (lo + hi)
    miss, size = 0.0, 0.0
    count = 0
    last = False
    for _ in range(ANGLE_ITERATIONS):
        g_r, g_t, d_r, d_t = unit_force_direction(alpha, eps)
        count += 1
        size2 = g_r * g_r + g_t * g_t
        size = math.sqrt(size2)
        miss = alpha + 0.5 * math.pi + _wrap(math.atan2(g_t, g_r) - alpha - 0.5 * math.pi) - goal
        if last or abs(miss) <= ANGLE_TOLERANCE:
            break
        if miss > 0.0:
            hi = alpha
        else:
            lo = alpha
        slope = (g_r * d_t - g_t * d_r) / size2
        nxt = alpha - miss / slope if slope > 0.0 else 0.5 * (lo + hi)
        last = abs(nxt - alpha) < ANGLE_STEP_TOLERANCE
        if not (last or lo < nxt < hi):
            nxt = 0.5 * (lo + hi)
            last = hi - lo < ANGLE_STEP_TOLERANCE
        alpha = nxt
    return alpha, size, abs(miss), count


@nb.njit(cache=True)
def short_velocity(
    x, y, load_x, load_y, journal_speed, shell_speed, viscosity, radius, width, clearance,
    alpha_abs,
):
    """Velocity (v_x, v_y) [m/s] with F_short(x, y, v) + W = 0 by Booker's inversion
    (module docstring), from the guess ``alpha_abs`` = α + ψ of the active-arc angle in the
    fixed frame [rad]. Returns (v_x, v_y, α + ψ, relative residual |F + W|/|W| [-],
    direction evaluations)."""
    mean = 0.5 * (journal_speed + shell_speed)
    whirl_x, whirl_y = -mean * y, mean * x
    load = math.hypot(load_x, load_y)
    if load == 0.0:
        return whirl_x, whirl_y, alpha_abs, 0.0, 0
    e = math.hypot(x, y)
    if e > 1.0e-12 * clearance:
        cos_psi, sin_psi = x / e, y / e
    else:
        cos_psi, sin_psi = 1.0, 0.0
    psi = math.atan2(sin_psi, cos_psi)
    eps = min(e / clearance, ECCENTRICITY_LIMIT)
    target = math.atan2(-(load_y * cos_psi - load_x * sin_psi),
                        -(load_x * cos_psi + load_y * sin_psi))
    alpha, size, miss, count = active_arc_angle(eps, target, _wrap(alpha_abs - psi))
    scale = viscosity * radius * width**3 / (2.0 * clearance * clearance)
    speed = clearance * load / (2.0 * scale * size)
    v_r, v_t = speed * math.sin(alpha), -speed * math.cos(alpha)
    return (v_r * cos_psi - v_t * sin_psi + whirl_x, v_r * sin_psi + v_t * cos_psi + whirl_y,
            _wrap(alpha + psi), 2.0 * abs(math.sin(0.5 * miss)), count)


@nb.njit(cache=True)
def short_bearing_cycle(
    x, y, alpha, dt, load_x, load_y, journal_speed, shell_speed, record_every,
    viscosity, radius, width, clearance, contact_radius,
):
    """Compiled Heun loop of the massless orbit with :func:`short_velocity`: rows
    (x, y, vx, vy, 0, 0, contact) every ``record_every`` steps, end state
    (x, y, vx, vy, α + ψ, direction evaluations) and the worst relative residual."""
    n_steps = load_x.size - 1
    out = np.zeros((n_steps // record_every, 7))
    worst, evaluations = 0.0, 0
    vx2, vy2 = 0.0, 0.0
    turn = 0.0  # α(corrector) − α(predictor) of the last step: predicts the next one
    for k in range(n_steps):
        vx, vy, alpha, r1, n1 = short_velocity(
            x, y, load_x[k], load_y[k], journal_speed[k], shell_speed[k], viscosity,
            radius, width, clearance, alpha)
        vx, vy = constrain_and_record(x, y, vx, vy, contact_radius, k, record_every, out)
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, contact_radius)
        vx2, vy2, alpha2, r2, n2 = short_velocity(
            xp, yp, load_x[k + 1], load_y[k + 1], journal_speed[k + 1], shell_speed[k + 1],
            viscosity, radius, width, clearance, alpha + turn)
        turn, alpha = _wrap(alpha2 - alpha), alpha2
        x, y, _ = project_onto_circle(
            x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), contact_radius)
        worst = max(worst, r1, r2)
        evaluations += n1 + n2
    return out, np.array([x, y, vx2, vy2, alpha, float(evaluations)]), worst


@nb.njit(cache=True)
def newton_short_velocity(
    x, y, load_x, load_y, journal_speed, shell_speed, viscosity, radius, width, clearance,
    vx, vy, speed_scale,
):
    """Reference solve (the former orbit path): damped Newton with a finite-difference
    Jacobian on F_short(x, y, v) + W = 0 from (vx, vy). Returns (v_x, v_y, |F + W| relative
    to |W| + 1 N [-], force evaluations)."""
    omega_sum = journal_speed + shell_speed
    load = math.hypot(load_x, load_y) + 1.0
    fx, fy = short_bearing_force(x, y, vx, vy, omega_sum, viscosity, radius, width, clearance)
    rx, ry = fx + load_x, fy + load_y
    res = math.hypot(rx, ry)
    delta = 1e-7 * speed_scale
    count = 1
    for _ in range(NEWTON_ITERATIONS):
        if res <= 1e-10 * load:
            break
        f1x, f1y = short_bearing_force(
            x, y, vx + delta, vy, omega_sum, viscosity, radius, width, clearance)
        f2x, f2y = short_bearing_force(
            x, y, vx, vy + delta, omega_sum, viscosity, radius, width, clearance)
        count += 2
        j11, j21 = (f1x - fx) / delta, (f1y - fy) / delta
        j12, j22 = (f2x - fx) / delta, (f2y - fy) / delta
        det = j11 * j22 - j12 * j21
        if det == 0.0:
            break
        dvx = -(j22 * rx - j12 * ry) / det
        dvy = -(-j21 * rx + j11 * ry) / det
        lam = 1.0
        for _ in range(30):
            nvx, nvy = vx + lam * dvx, vy + lam * dvy
            gx, gy = short_bearing_force(
                x, y, nvx, nvy, omega_sum, viscosity, radius, width, clearance)
            count += 1
            new_res = math.hypot(gx + load_x, gy + load_y)
            if new_res < res or lam < 1e-6:
                break
            lam *= 0.5
        vx, vy, fx, fy = nvx, nvy, gx, gy
        rx, ry, res = gx + load_x, gy + load_y, new_res
    return vx, vy, res / load, count
