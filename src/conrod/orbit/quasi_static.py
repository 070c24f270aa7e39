"""Massless quasi-static orbit (Booker's mobility idea, SPEC S3): the journal centre velocity
solves the force balance F_film(e, ė) + W = 0 at every instant, and only the position is
integrated (Heun, fixed step ``[solver] quasi_static_step_deg``).

The velocity comes, in compiled Heun loops, from Booker's reduction to a 1-D direction
solve for the short bearing (:mod:`conrod.orbit.short_velocity`) and for a rigid
Reynolds film without supply/cavitation pressure (:mod:`conrod.orbit.squeeze_velocity`),
and from the table's exact inverse for the table and mobility films; otherwise from the
film model's ``journal_velocity`` or a damped Newton solve on ``force``.
On the contact circle the outward normal velocity is removed (seed 004 eqs 4.1.5–4.1.8) and
the unbalanced normal force is reported as the contact force.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.orbit.contact import project_onto_circle, remove_normal_velocity
from conrod.orbit.problem import FilmHistory, OrbitProblem, OrbitState
from conrod.orbit.short_velocity import (
    NEWTON_ITERATIONS,
    newton_short_velocity,
    short_bearing_cycle,
)
from conrod.orbit.squeeze_velocity import (
    squeeze_applies,
    squeeze_cycle,
    table_applies,
    table_cycle,
)
from conrod.orbit.trajectory import CycleTrajectory
from conrod.errors import ConvergenceError
from conrod.film.base import FilmState
from conrod.film.table_kernel import table_force


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
        def short(x, y, wx, wy, wj, wb, guess):  # reference path (tests)
            return newton_short_velocity(
                x, y, wx, wy, wj, wb, mu, g.radius, g.width, g.radial_clearance,
                guess[0], guess[1], scale,
            )[:3]
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
    from conrod.orbit.rk2 import _step_grid

    phi, record_every, n_out = _step_grid(problem, step_deg, output_step_deg)
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    dt = (phi[1] - phi[0]) / problem.crank_speed
    rc = problem.contact_radius * (1.0 - 1e-9)
    if compiled_applies(problem):
        return _compiled(problem, state, phi, (load_x, load_y, wj, wb), record_every, n_out, rc)
    history = FilmHistory(problem.film, state.film_history) if problem.has_history else None
    velocity = _velocity_solver(problem, history)
    x, y, guess = state.x, state.y, (state.vx, state.vy)
    table = np.zeros((n_out, 7))
    memory = [None] * n_out if history is not None else None
    worst = 0.0
    for k in range(len(phi) - 1):
        vx, vy, r1 = velocity(x, y, load_x[k], load_y[k], wj[k], wb[k], guess)
        contact = math.hypot(x, y) >= rc * (1.0 - 1e-9)
        if contact:
            vx, vy = _inward_only(x, y, vx, vy)
        if k % record_every == 0:
            table[k // record_every] = (x, y, vx, vy, 0.0, 0.0, float(contact))
            if memory is not None:
                memory[k // record_every] = history.field
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
    traj = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, 2 * (len(phi) - 1))
    traj.film_history = memory
    return traj


def mobility_applies(problem) -> bool:
    """True for the mobility film: its velocity is the table inverse of :func:`table_cycle`."""
    from conrod.film.mobility import MobilityFilm

    return type(problem.film) is MobilityFilm


def compiled_applies(problem) -> bool:
    """True when a compiled Heun loop covers the problem (see :func:`_compiled`)."""
    return (problem.is_short_bearing or squeeze_applies(problem) or table_applies(problem)
            or mobility_applies(problem))


def _compiled(problem, state, phi, loads, record_every, n_out, rc) -> CycleTrajectory:
    """Compiled Heun loop: short bearing and Reynolds by Booker's reduction, table and
    mobility films by the table's inverse; ``loads`` = (W_x, W_y, ω_j, ω_b) at ``phi``."""
    load_x, load_y, wj, wb = loads
    dt = (phi[1] - phi[0]) / problem.crank_speed
    film, mu = problem.film, problem.viscosity
    g = film.geometry
    tab = None
    if squeeze_applies(problem):
        table, end, worst = squeeze_cycle(problem, state, dt, (load_x, load_y, wj, wb),
                                          record_every, rc)
    elif table_applies(problem) or mobility_applies(problem):
        tab = film.table if mobility_applies(problem) else film
        table, end, worst = table_cycle(
            state.x, state.y, dt, load_x, load_y, wj, wb, record_every, mu,
            tab.force_scale, g.radial_clearance, tab.s_step, tab.tables["log_magnitude"],
            tab.tables["turning"], rc)
    else:
        table, end, worst = short_bearing_cycle(
            state.x, state.y, _start_angle(state, load_x[0], load_y[0], wj[0] + wb[0]), dt,
            load_x, load_y, wj, wb, record_every, mu, g.radius, g.width, g.radial_clearance,
            rc)
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError("quasi-static velocity solve failed", residual=worst)
    sampled = [a[::record_every][:n_out] for a in (load_x, load_y, wj, wb)]
    if tab is not None and problem.asperity is None:  # the same table_force, compiled
        _table_contact_forces(table, sampled[0], sampled[1], sampled[2] + sampled[3], mu,
                              tab.force_scale, g.radial_clearance, tab.s_step,
                              tab.tables["log_magnitude"], tab.tables["turning"])
        table[:, 5] = problem.dry_friction * table[:, 4]
    else:
        _contact_forces(problem, table, *sampled)
    end_state = OrbitState(end[0], end[1], end[2], end[3], False)
    return CycleTrajectory.from_table(phi[::record_every][:n_out], table, end_state,
                                      2 * (len(phi) - 1))


def _start_angle(state, load_x, load_y, omega_sum) -> float:
    """Guess of the short-bearing active-arc angle α + ψ = β + π/2 [rad] from the state's
    squeeze velocity v_s = ė − ω̄ × e, or from the load when the state is at rest."""
    mean = 0.5 * omega_sum
    sx, sy = state.vx + mean * state.y, state.vy - mean * state.x
    if sx or sy:
        return math.atan2(sy, sx) + 0.5 * math.pi
    return math.atan2(load_y, load_x) + 0.5 * math.pi


def _inward_only(x: float, y: float, vx: float, vy: float) -> tuple[float, float]:
    if x * vx + y * vy > 0.0:
        return remove_normal_velocity(x, y, vx, vy)
    return vx, vy


@nb.njit(cache=True)
def _table_contact_forces(table, load_x, load_y, omega_sum, viscosity, force_scale, clearance,
                          s_step, log_magnitude, turning):
    """:func:`_contact_forces` (column 4) for the table and mobility films, compiled."""
    for i in range(table.shape[0]):
        if table[i, 6] > 0.5:
            x, y = table[i, 0], table[i, 1]
            fx, fy = table_force(x, y, table[i, 2], table[i, 3], omega_sum[i], viscosity,
                                 force_scale, clearance, s_step, log_magnitude, turning)
            e = math.hypot(x, y)
            table[i, 4] = max(((load_x[i] + fx) * x + (load_y[i] + fy) * y) / e, 0.0)


def _contact_forces(problem, table, load_x, load_y, wj, wb) -> None:
    """P_c = (W + F)·n̂ ≥ 0 where the massless journal sits on the contact circle."""
    force = problem.force_function()
    for i in np.flatnonzero(table[:, 6] > 0.5):
        x, y, vx, vy = table[i, :4]
        fx, fy = force(x, y, vx, vy, wj[i], wb[i])
        e = math.hypot(x, y)
        p_c = max(((load_x[i] + fx) * x + (load_y[i] + fy) * y) / e, 0.0)
        table[i, 4], table[i, 5] = p_c, problem.dry_friction * p_c
