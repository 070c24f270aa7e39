"""Compiled building blocks of the massless (quasi-static) orbit that film kernels run.

A massless journal moves with the velocity that balances film force and load,
F(e, ė) + W = 0, and only its position is integrated (Heun, fixed step). The journal centre
may not leave the contact circle of radius r_c (hard contact, eqs 4.1.1–4.1.8 of the
contact model of [D4]): a position outside is projected back onto it and an
outward normal velocity is removed.

* :func:`project_onto_circle`, :func:`remove_normal_velocity`, :func:`constrain_and_record`
  — the contact-circle rules shared by every compiled loop;
* :func:`newton_cycle` — the generic compiled Heun loop for any film that declares a
  compiled force (:class:`~conrod.film.capabilities.CompiledKernel`): a damped Newton
  solve of F + W = 0 with a finite-difference Jacobian at every stage;
* :func:`table_cycle` — the loop of the tabulated and mobility films, whose velocity is the
  table's exact inverse.

[D4] Contact of the surfaces, dry friction (ch. 4); see ``docs/references.md``.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.film.table.kernel import mobility_velocity

NEWTON_ITERATIONS = 60
"""Most iterations of one Newton velocity solve [-]."""

NEWTON_TOLERANCE = 1.0e-10
"""Stop when |F + W| ≤ this × (|W| + 1 N) [-]."""


@nb.njit(cache=True)
def project_onto_circle(x: float, y: float, radius: float) -> tuple[float, float, bool]:
    """[D4] eqs 4.1.1–4.1.3: (x, y)/Z if Z = |e|/radius > 1; returns (x, y, projected)."""
    z = math.hypot(x, y) / radius
    if z > 1.0:
        return x / z, y / z, True
    return x, y, False


@nb.njit(cache=True)
def constrain_and_record(
    x: float, y: float, vx: float, vy: float, contact_radius: float,
    step: int, record_every: int, out: np.ndarray,
) -> tuple[float, float]:
    """Shared step of the compiled massless Heun loops: on the contact circle drop an outward
    normal velocity (eqs 4.1.5–4.1.8); every ``record_every`` steps store the row
    (x, y, v_x, v_y, ·, ·, contact) in ``out``. Returns the admissible (v_x, v_y) [m/s]."""
    contact = math.hypot(x, y) >= contact_radius * (1.0 - 1e-9)
    if contact and x * vx + y * vy > 0.0:
        vx, vy = remove_normal_velocity(x, y, vx, vy)
    if step % record_every == 0 and step // record_every < out.shape[0]:
        row = step // record_every
        out[row, 0], out[row, 1], out[row, 2], out[row, 3] = x, y, vx, vy
        out[row, 6] = 1.0 if contact else 0.0
    return vx, vy


@nb.njit(cache=True)
def remove_normal_velocity(x: float, y: float, vx: float, vy: float) -> tuple[float, float]:
    """[D4] eqs 4.1.5–4.1.8: keep only the tangential velocity V_k t̂ [m/s]."""
    e = math.hypot(x, y)
    if e == 0.0:
        return vx, vy
    nx = x / e
    ny = y / e
    v_k = vy * nx - vx * ny
    return -v_k * ny, v_k * nx


@nb.njit  # function-typed argument: specialised per process, not cached
def newton_velocity(force, params, x, y, load_x, load_y, omega_sum, viscosity, vx, vy,
                    speed_scale):
    """Damped Newton with a finite-difference Jacobian on F(x, y, v) + W = 0 from (v_x, v_y)
    for the compiled ``force(x, y, v_x, v_y, ω_j + ω_b, μ, params)`` [N]. Returns
    (v_x, v_y, |F + W| relative to |W| + 1 N [-], force evaluations)."""
    load = math.hypot(load_x, load_y) + 1.0
    fx, fy = force(x, y, vx, vy, omega_sum, viscosity, params)
    rx, ry = fx + load_x, fy + load_y
    res = math.hypot(rx, ry)
    delta = 1e-7 * speed_scale
    count = 1
    for _ in range(NEWTON_ITERATIONS):
        if res <= NEWTON_TOLERANCE * load:
            break
        f1x, f1y = force(x, y, vx + delta, vy, omega_sum, viscosity, params)
        f2x, f2y = force(x, y, vx, vy + delta, omega_sum, viscosity, params)
        count += 2
        j11, j21 = (f1x - fx) / delta, (f1y - fy) / delta
        j12, j22 = (f2x - fx) / delta, (f2y - fy) / delta
        det = j11 * j22 - j12 * j21
        if det == 0.0:
            break
        dvx = -(j22 * rx - j12 * ry) / det
        dvy = -(-j21 * rx + j11 * ry) / det
        lam = 1.0
        nvx, nvy, gx, gy, new_res = vx, vy, fx, fy, res
        for _ in range(30):
            nvx, nvy = vx + lam * dvx, vy + lam * dvy
            gx, gy = force(x, y, nvx, nvy, omega_sum, viscosity, params)
            count += 1
            new_res = math.hypot(gx + load_x, gy + load_y)
            if new_res < res or lam < 1e-6:
                break
            lam *= 0.5
        vx, vy, fx, fy = nvx, nvy, gx, gy
        rx, ry, res = gx + load_x, gy + load_y, new_res
    return vx, vy, res / load, count


@nb.njit  # function-typed argument: specialised per process, not cached
def newton_cycle(force, params, x, y, vx, vy, dt, load_x, load_y, journal_speed,
                 shell_speed, record_every, viscosity, contact_radius, speed_scale):
    """Compiled Heun loop of the massless orbit with :func:`newton_velocity`: rows
    (x, y, v_x, v_y, 0, 0, contact) every ``record_every`` steps, end state (x, y, v_x, v_y)
    and the worst relative residual [-]."""
    n_steps = load_x.size - 1
    out = np.zeros((n_steps // record_every, 7))
    worst = 0.0
    for k in range(n_steps):
        vx, vy, r1, _ = newton_velocity(force, params, x, y, load_x[k], load_y[k],
                                        journal_speed[k] + shell_speed[k], viscosity, vx, vy,
                                        speed_scale)
        vx, vy = constrain_and_record(x, y, vx, vy, contact_radius, k, record_every, out)
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, contact_radius)
        vx2, vy2, r2, _ = newton_velocity(
            force, params, xp, yp, load_x[k + 1], load_y[k + 1],
            journal_speed[k + 1] + shell_speed[k + 1], viscosity, vx, vy, speed_scale)
        x, y, _ = project_onto_circle(
            x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), contact_radius)
        vx, vy = vx2, vy2
        worst = max(worst, r1, r2)
    return out, np.array([x, y, vx, vy]), worst


def force(x, y, vx, vy, omega_sum, viscosity, params):
    """Film force (F_x, F_y) [N]: a placeholder of :func:`contact_forces`, bound per film
    force by the orbit (``conrod.orbit.quasi_static.bound_contact_forces``)."""
    raise RuntimeError("contact_forces runs only with a film force bound in its place")


def contact_forces(params, table, load_x, load_y, omega_sum, viscosity, dry_friction):
    """P_c = (W + F)·n̂ ≥ 0 [N] (column 4) and μ_dry P_c (column 5) of the recorded rows
    where the massless journal sits on the contact circle (column 6), F the bound film
    ``force``. Compiled per film force with the force bound as a global, so that numba
    keeps it on disk: with the force as an argument it was compiled in every process
    (0.3–0.4 s of a warm 2.3 s quasi-static run)."""
    for i in range(table.shape[0]):
        if table[i, 6] > 0.5:
            x, y = table[i, 0], table[i, 1]
            fx, fy = force(x, y, table[i, 2], table[i, 3], omega_sum[i], viscosity, params)
            e = math.hypot(x, y)
            p_c = max(((load_x[i] + fx) * x + (load_y[i] + fy) * y) / e, 0.0)
            table[i, 4], table[i, 5] = p_c, dry_friction * p_c


@nb.njit(cache=True)
def table_cycle(x, y, dt, load_x, load_y, journal_speed, shell_speed, record_every,
                viscosity, force_scale, clearance, s_step, log_magnitude, turning,
                contact_radius):
    """Compiled Heun loop of the massless orbit for the tabulated film: the velocity is
    the table's exact inverse :func:`~conrod.film.table.kernel.mobility_velocity`."""
    n_steps = load_x.size - 1
    out = np.zeros((n_steps // record_every, 7))
    vx2, vy2 = 0.0, 0.0
    for k in range(n_steps):
        vx, vy = mobility_velocity(x, y, load_x[k], load_y[k], journal_speed[k] + shell_speed[k],
                                   viscosity, force_scale, clearance, s_step, log_magnitude,
                                   turning)
        vx, vy = constrain_and_record(x, y, vx, vy, contact_radius, k, record_every, out)
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, contact_radius)
        vx2, vy2 = mobility_velocity(
            xp, yp, load_x[k + 1], load_y[k + 1], journal_speed[k + 1] + shell_speed[k + 1],
            viscosity, force_scale, clearance, s_step, log_magnitude, turning)
        x, y, _ = project_onto_circle(
            x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), contact_radius)
    return out, np.array([x, y, vx2, vy2]), 0.0
