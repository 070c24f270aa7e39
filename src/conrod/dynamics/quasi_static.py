"""Massless quasi-static orbit (Booker's mobility idea, SPEC S3): the journal centre velocity
solves the force balance F_film(e, ė) + W = 0 at every instant, and only the position is
integrated (Heun, fixed step ``[solver] quasi_static_step_deg``).

The velocity comes from the film model's ``journal_velocity`` when it has one (mobility
film); for a rigid Reynolds film without supply/cavitation pressure from Booker's reduction
to a 1-D direction solve (:mod:`conrod.dynamics.squeeze_velocity`, compiled); for the table
film from its compiled inverse; otherwise from a damped Newton solve on ``force``
(compiled for the short bearing).
On the contact circle the outward normal velocity is removed (seed 004 eqs 4.1.5–4.1.8) and
the unbalanced normal force is reported as the contact force.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.dynamics.contact import project_onto_circle, remove_normal_velocity
from conrod.dynamics.problem import FilmHistory, OrbitProblem, OrbitState
from conrod.dynamics.squeeze_velocity import (
    squeeze_applies,
    squeeze_cycle,
    table_applies,
    table_cycle,
)
from conrod.dynamics.trajectory import CycleTrajectory
from conrod.errors import ConvergenceError
from conrod.film.base import FilmState
from conrod.film.short_bearing_kernel import short_bearing_force

NEWTON_ITERATIONS = 60
"""Most Newton iterations of the velocity solve [-]."""


@nb.njit(cache=True)
def short_bearing_velocity(
    x, y, load_x, load_y, journal_speed, shell_speed, viscosity, radius, width, clearance,
    vx, vy, speed_scale,
):
    """Velocity (v_x, v_y) [m/s] with F_short(x, y, v) + W = 0 by damped Newton from (vx, vy);
    third value: final residual |F + W| relative to |W| + 1 N [-]."""
    omega_sum = journal_speed + shell_speed
    load = math.hypot(load_x, load_y) + 1.0
    fx, fy = short_bearing_force(x, y, vx, vy, omega_sum, viscosity, radius, width, clearance)
    rx, ry = fx + load_x, fy + load_y
    res = math.hypot(rx, ry)
    delta = 1e-7 * speed_scale
    for _ in range(NEWTON_ITERATIONS):
        if res <= 1e-10 * load:
            break
        f1x, f1y = short_bearing_force(
            x, y, vx + delta, vy, omega_sum, viscosity, radius, width, clearance
        )
        f2x, f2y = short_bearing_force(
            x, y, vx, vy + delta, omega_sum, viscosity, radius, width, clearance
        )
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
                x, y, nvx, nvy, omega_sum, viscosity, radius, width, clearance
            )
            new_res = math.hypot(gx + load_x, gy + load_y)
            if new_res < res or lam < 1e-6:
                break
            lam *= 0.5
        vx, vy, fx, fy = nvx, nvy, gx, gy
        rx, ry, res = gx + load_x, gy + load_y, new_res
    return vx, vy, res / load


@nb.njit(cache=True)
def quasi_static_short_bearing_cycle(
    x, y, vx, vy, dt, load_x, load_y, journal_speed, shell_speed, record_every,
    viscosity, radius, width, clearance, contact_radius, speed_scale,
):
    """Compiled Heun loop of :func:`quasi_static_cycle` for the short bearing: rows
    (x, y, vx, vy, 0, 0, contact) every ``record_every`` steps, end state, worst residual."""
    n_steps = load_x.size - 1
    out = np.zeros((n_steps // record_every, 7))
    worst = 0.0
    for k in range(n_steps):
        vx, vy, r1 = short_bearing_velocity(
            x, y, load_x[k], load_y[k], journal_speed[k], shell_speed[k], viscosity,
            radius, width, clearance, vx, vy, speed_scale,
        )
        contact = math.hypot(x, y) >= contact_radius * (1.0 - 1e-9)
        if contact and x * vx + y * vy > 0.0:
            vx, vy = remove_normal_velocity(x, y, vx, vy)
        if k % record_every == 0 and k // record_every < out.shape[0]:
            row = k // record_every
            out[row, 0], out[row, 1], out[row, 2], out[row, 3] = x, y, vx, vy
            out[row, 6] = 1.0 if contact else 0.0
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, contact_radius)
        vx2, vy2, r2 = short_bearing_velocity(
            xp, yp, load_x[k + 1], load_y[k + 1], journal_speed[k + 1], shell_speed[k + 1],
            viscosity, radius, width, clearance, vx, vy, speed_scale,
        )
        x, y, _ = project_onto_circle(
            x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), contact_radius
        )
        vx, vy = vx2, vy2
        worst = max(worst, r1, r2)
    return out, np.array([x, y, vx, vy]), worst


def _velocity_solver(problem: OrbitProblem, history=None):
    """(x, y, W_x, W_y, ω_j, ω_b, guess) → (v_x, v_y, relative residual)."""
    mu = problem.viscosity
    film = problem.film
    if hasattr(film, "journal_velocity"):
        def mobility(x, y, wx, wy, wj, wb, guess):
            vx, vy = film.journal_velocity(x, y, wx, wy, wj, wb, mu)
            return float(vx), float(vy), 0.0
        return mobility
    g = film.geometry
    scale = g.radial_clearance * max(problem.crank_speed, 1e-3)
    if problem.is_short_bearing:
        def short(x, y, wx, wy, wj, wb, guess):
            return short_bearing_velocity(
                x, y, wx, wy, wj, wb, mu, g.radius, g.width, g.radial_clearance,
                guess[0], guess[1], scale,
            )
        return short
    return _generic_newton(problem, scale, history)


def _generic_newton(problem: OrbitProblem, scale: float, history=None):
    """Damped Newton (backtracking, step ≤ 10 c ω) with a finite-difference Jacobian."""
    force = problem.force_function(history)

    def residual(x, y, v, wx, wy, wj, wb):
        fx, fy = force(x, y, v[0], v[1], wj, wb)
        return np.array([fx + wx, fy + wy])

    def solve(x, y, wx, wy, wj, wb, guess):
        v = np.array(guess, dtype=float)
        load = math.hypot(wx, wy) + 1.0
        r = residual(x, y, v, wx, wy, wj, wb)
        norm = float(np.hypot(*r))
        for _ in range(NEWTON_ITERATIONS):
            if norm <= 1e-8 * load:
                break
            delta = 1e-4 * scale
            jac = np.empty((2, 2))
            for i in range(2):
                dv = v.copy()
                dv[i] += delta
                jac[:, i] = (residual(x, y, dv, wx, wy, wj, wb) - r) / delta
            step = -np.linalg.lstsq(jac, r, rcond=None)[0]
            length = float(np.hypot(*step))
            if length > 10.0 * scale:
                step *= 10.0 * scale / length
            lam = 1.0
            while True:
                trial = v + lam * step
                r_trial = residual(x, y, trial, wx, wy, wj, wb)
                if np.hypot(*r_trial) < norm or lam < 1e-4:
                    break
                lam *= 0.5
            v, r, norm = trial, r_trial, float(np.hypot(*r_trial))
        return float(v[0]), float(v[1]), norm / load

    return solve


def quasi_static_cycle(
    problem: OrbitProblem, state: OrbitState, step_deg: float, output_step_deg: float
) -> CycleTrajectory:
    """One cycle of the massless orbit from ``state`` (only its position is used)."""
    from conrod.dynamics.rk2 import _step_grid

    phi, record_every, n_out = _step_grid(problem, step_deg, output_step_deg)
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    dt = (phi[1] - phi[0]) / problem.crank_speed
    rc = problem.contact_radius * (1.0 - 1e-9)
    if problem.is_short_bearing or squeeze_applies(problem) or table_applies(problem):
        return _compiled(problem, state, phi, record_every, n_out, rc)
    history = FilmHistory(problem.film, state.film_history) if problem.has_history else None
    velocity = _velocity_solver(problem, history)
    x, y, guess = state.x, state.y, (state.vx, state.vy)
    table = np.zeros((n_out, 7))
    worst = 0.0
    for k in range(len(phi) - 1):
        vx, vy, r1 = velocity(x, y, load_x[k], load_y[k], wj[k], wb[k], guess)
        contact = math.hypot(x, y) >= rc * (1.0 - 1e-9)
        if contact:
            vx, vy = _inward_only(x, y, vx, vy)
        if k % record_every == 0:
            table[k // record_every] = (x, y, vx, vy, 0.0, 0.0, float(contact))
        xp, yp, _ = project_onto_circle(x + dt * vx, y + dt * vy, rc)
        k1 = k + 1
        vx2, vy2, r2 = velocity(xp, yp, load_x[k1], load_y[k1], wj[k1], wb[k1], (vx, vy))
        x, y, _ = project_onto_circle(x + 0.5 * dt * (vx + vx2), y + 0.5 * dt * (vy + vy2), rc)
        guess = (vx2, vy2)
        worst = max(worst, r1, r2)
        if history is not None:
            history.advance(FilmState(xp, yp, vx, vy, wj[k], wb[k], problem.viscosity), dt)
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError("quasi-static velocity solve failed", residual=worst)
    sampled = [a[::record_every][:n_out] for a in (load_x, load_y, wj, wb)]
    _contact_forces(problem, table, *sampled)
    end = OrbitState(x, y, guess[0], guess[1], False,
                     history.field if history is not None else None)
    return CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, 2 * (len(phi) - 1))


def _compiled(problem, state, phi, record_every, n_out, rc) -> CycleTrajectory:
    """Compiled Heun loop: short bearing, Reynolds by Booker's reduction, or table."""
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    dt = (phi[1] - phi[0]) / problem.crank_speed
    film, mu = problem.film, problem.viscosity
    g = film.geometry
    if squeeze_applies(problem):
        table, end, worst = squeeze_cycle(problem, state, dt, (load_x, load_y, wj, wb),
                                          record_every, rc)
    elif table_applies(problem):
        table, end, worst = table_cycle(
            state.x, state.y, dt, load_x, load_y, wj, wb, record_every, mu,
            film.force_scale, g.radial_clearance, film.s_step, film.tables["log_magnitude"],
            film.tables["turning"], rc)
    else:
        table, end, worst = quasi_static_short_bearing_cycle(
            state.x, state.y, state.vx, state.vy, dt, load_x, load_y, wj, wb, record_every,
            mu, g.radius, g.width, g.radial_clearance, rc,
            g.radial_clearance * max(problem.crank_speed, 1e-3),
        )
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError("quasi-static velocity solve failed", residual=worst)
    sampled = [a[::record_every][:n_out] for a in (load_x, load_y, wj, wb)]
    _contact_forces(problem, table, *sampled)
    end_state = OrbitState(end[0], end[1], end[2], end[3], False)
    return CycleTrajectory.from_table(phi[::record_every][:n_out], table, end_state,
                                      2 * (len(phi) - 1))


def _inward_only(x: float, y: float, vx: float, vy: float) -> tuple[float, float]:
    if x * vx + y * vy > 0.0:
        return remove_normal_velocity(x, y, vx, vy)
    return vx, vy


def _contact_forces(problem, table, load_x, load_y, wj, wb) -> None:
    """P_c = (W + F)·n̂ ≥ 0 where the massless journal sits on the contact circle."""
    force = problem.force_function()
    for i in np.flatnonzero(table[:, 6] > 0.5):
        x, y, vx, vy = table[i, :4]
        fx, fy = force(x, y, vx, vy, wj[i], wb[i])
        e = math.hypot(x, y)
        p_c = max(((load_x[i] + fx) * x + (load_y[i] + fy) * y) / e, 0.0)
        table[i, 4], table[i, 5] = p_c, problem.dry_friction * p_c
