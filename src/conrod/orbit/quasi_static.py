"""Massless quasi-static orbit (Booker's mobility idea): the journal centre velocity solves
the force balance F_film(e, ė) + W = 0 at every instant, and only the position is
integrated (Heun, fixed step ``[solver] quasi_static_step_deg``).

A film that declares :class:`~conrod.film.capabilities.HasCompiledKernel` runs a compiled
Heun loop: its own (Booker's exact inversion for the short bearing and for a rigid Reynolds
film without supply/cavitation pressure, the table's inverse for the table and mobility
films) or, with only a compiled force, the generic compiled Newton loop of
:mod:`conrod.film.massless`. Other films run a Python loop over the film's
``journal_velocity`` or a damped Newton solve on ``force``, with the film memory held in a
:class:`~conrod.orbit.memory.FilmSession`.
On the contact circle the outward normal velocity is removed (eqs 4.1.5–4.1.8 of the
contact model) and the unbalanced normal force is reported as the contact force.
"""

from __future__ import annotations

import math

import numpy as np

from conrod.errors import ConvergenceError
from conrod.film.base import FilmState
from conrod.film.capabilities import (
    CompiledKernel,
    HasContentStep,
    HasDeformedGap,
    QuasiStaticRequest,
)
from conrod.film.massless import (
    NEWTON_ITERATIONS,
    contact_forces,
    newton_cycle,
    newton_velocity,
)
from conrod.orbit.contact import project_onto_circle, remove_normal_velocity
from conrod.orbit.implicit_step import implicit_step_cycle as content_cycle
from conrod.orbit.memory import FilmSession
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.progress import AngleReports
from conrod.orbit.trajectory import CycleTrajectory


def _velocity_solver(problem: OrbitProblem, session: FilmSession):
    """(x, y, W_x, W_y, ω_j, ω_b, guess, φ) → (v_x, v_y, relative residual)."""
    mu = problem.viscosity
    film = problem.film
    if hasattr(film, "balance_velocity"):  # film solving its own force balance with memory
        def balanced(x, y, wx, wy, wj, wb, guess, angle=0.0):
            state = FilmState(eccentricity_x=x, eccentricity_y=y, velocity_x=guess[0],
                              velocity_y=guess[1], journal_speed=wj, shell_speed=wb, viscosity=mu)
            vx, vy, residual, session.memory = film.balance_velocity(
                state, (wx, wy), session.memory, angle)
            return vx, vy, residual
        return balanced
    if hasattr(film, "journal_velocity"):
        def mobility(x, y, wx, wy, wj, wb, guess, angle=0.0):
            vx, vy = film.journal_velocity(x, y, wx, wy, wj, wb, mu)
            return float(vx), float(vy), 0.0
        return mobility
    scale = film.geometry.radial_clearance * max(problem.crank_speed, 1e-3)
    kernel = problem.compiled_force
    if kernel is not None:
        def compiled(x, y, wx, wy, wj, wb, guess, angle=0.0):  # reference path (compiled)
            return newton_velocity(kernel.force, kernel.params, x, y, wx, wy, wj + wb, mu,
                                    guess[0], guess[1], scale)[:3]
        return compiled
    return _generic_newton(problem, scale, session)


def _generic_newton(problem: OrbitProblem, scale: float, session: FilmSession | None = None):
    """Damped Newton (backtracking, step ≤ 10 c ω) with a finite-difference Jacobian; the
    film memory of the Jacobian's trial solves is restored before the Newton step."""
    session = session if session is not None else problem.session()
    force = problem.force_function(session)

    def residual(x, y, v, wx, wy, wj, wb):
        fx, fy = force(x, y, v[0], v[1], wj, wb)
        return np.array([fx + wx, fy + wy])

    def solve(x, y, wx, wy, wj, wb, guess, angle=0.0):
        v = np.array(guess, dtype=float)
        load = math.hypot(wx, wy) + 1.0
        r = residual(x, y, v, wx, wy, wj, wb)
        norm = float(np.hypot(*r))
        for _ in range(NEWTON_ITERATIONS):
            if norm <= 1e-8 * load:
                break
            delta = 1e-4 * scale
            jac = np.empty((2, 2))
            base = session.snapshot()
            for i in range(2):
                dv = v.copy()
                dv[i] += delta
                jac[:, i] = (residual(x, y, dv, wx, wy, wj, wb) - r) / delta
                session.restore(base)
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
    from conrod.orbit.rk2 import step_grid

    if isinstance(problem.film, HasContentStep):
        return content_cycle(problem, state, step_deg, output_step_deg, with_mass=False)
    phi, record_every, n_out = step_grid(problem, step_deg, output_step_deg)
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    dt = (phi[1] - phi[0]) / problem.crank_speed
    rc = problem.contact_radius * (1.0 - 1e-9)
    kernel = compiled_kernel(problem)
    if kernel is not None:
        request = QuasiStaticRequest(state.x, state.y, state.vx, state.vy, dt, load_x, load_y,
                                     wj, wb, record_every, problem.viscosity, rc,
                                     problem.crank_speed)
        return _compiled(problem, kernel, request, phi, n_out)
    session = problem.session(state.film_memory)
    velocity = _velocity_solver(problem, session)
    x, y, guess = state.x, state.y, (state.vx, state.vy)
    table = np.zeros((n_out, 7))
    memory = [None] * n_out if session.has_memory else None
    worst, worst_k, reports = 0.0, 0, AngleReports()
    for k in range(len(phi) - 1):
        reports.reached(phi[k])
        vx, vy, r1 = velocity(x, y, load_x[k], load_y[k], wj[k], wb[k], guess, phi[k])
        contact = math.hypot(x, y) >= _radius(problem, session, x, y, rc) * (1.0 - 1e-9)
        if contact:
            vx, vy = _inward_only(x, y, vx, vy)
        if k % record_every == 0:
            table[k // record_every] = (x, y, vx, vy, 0.0, 0.0, float(contact))
            if memory is not None:
                memory[k // record_every] = session.snapshot()
        xp, yp = _project(problem, session, x + dt * vx, y + dt * vy, rc)
        k1 = k + 1
        vx2, vy2, r2 = velocity(xp, yp, load_x[k1], load_y[k1], wj[k1], wb[k1], (vx, vy),
                                phi[k1])
        x, y = _project(problem, session, x + 0.5 * dt * (vx + vx2),
                        y + 0.5 * dt * (vy + vy2), rc)
        guess = (vx2, vy2)
        if max(r1, r2) > worst:
            worst, worst_k = max(r1, r2), k
        session.advance(FilmState(eccentricity_x=xp, eccentricity_y=yp, velocity_x=vx,
                                  velocity_y=vy, journal_speed=wj[k], shell_speed=wb[k],
                                  viscosity=problem.viscosity), dt)
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError(
            "quasi-static velocity solve failed (relative force residual; try a smaller "
            "solver.quasi_static_step_deg or the integrator 'implicit')",
            where=f"crank angle {math.degrees(float(phi[worst_k])):.1f} deg", residual=worst)
    sampled = [a[::record_every][:n_out] for a in (load_x, load_y, wj, wb)]
    _contact_forces(problem, table, *sampled)
    end = OrbitState(x, y, guess[0], guess[1], False, session.snapshot())
    traj = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, 2 * (len(phi) - 1))
    traj.film_memory = memory
    return traj


def compiled_kernel(problem: OrbitProblem) -> CompiledKernel | None:
    """The kernel whose compiled loop runs the cycle: the film's own massless loop, or the
    generic Newton loop on its compiled force; None: the Python loop."""
    kernel = problem.kernel
    if kernel is None or (kernel.quasi_static_cycle is None and kernel.force is None):
        return None
    return kernel


def compiled_applies(problem: OrbitProblem) -> bool:
    """True when a compiled Heun loop covers the problem (see :func:`compiled_kernel`)."""
    return compiled_kernel(problem) is not None


def _compiled(problem: OrbitProblem, kernel: CompiledKernel, request: QuasiStaticRequest,
              phi: np.ndarray, n_out: int) -> CycleTrajectory:
    """Compiled Heun loop of ``kernel`` over ``request``, then the contact forces."""
    if kernel.quasi_static_cycle is not None:
        table, end, worst = kernel.quasi_static_cycle(request)
    else:
        r = request
        scale = problem.clearance * max(problem.crank_speed, 1e-3)
        table, end, worst = newton_cycle(
            kernel.force, kernel.params, r.x, r.y, r.vx, r.vy, r.dt, r.load_x, r.load_y,
            r.journal_speed, r.shell_speed, r.record_every, r.viscosity, r.contact_radius,
            scale)
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError(
            "quasi-static velocity solve failed (relative force residual, worst over the cycle; "
            "try a smaller solver.quasi_static_step_deg or the integrator 'implicit')",
            residual=worst)
    every = request.record_every
    sampled = [a[::every][:n_out] for a in (request.load_x, request.load_y,
                                            request.journal_speed, request.shell_speed)]
    if kernel.force is not None:
        contact_forces(kernel.force, kernel.params, table, sampled[0], sampled[1],
                                 sampled[2] + sampled[3], problem.viscosity,
                                 problem.dry_friction)
    else:
        _contact_forces(problem, table, *sampled)
    end_state = OrbitState(end[0], end[1], end[2], end[3], False)
    return CycleTrajectory.from_table(phi[::every][:n_out], table, end_state,
                                      2 * (len(phi) - 1))


def _radius(problem: OrbitProblem, session: FilmSession, x: float, y: float,
            rc: float) -> float:
    """Radius of the contact circle along (x, y) [m]: r_c, or less where the film on a
    deformed bore closes first (a film with :class:`HasDeformedGap`, the elastic big end: the
    contact circle is not rigid there)."""
    film = problem.film
    if isinstance(film, HasDeformedGap) and session.memory is not None:
        return min(rc, film.open_radius(x, y, session.memory) * (1.0 - 1e-9))
    return rc


def _project(problem: OrbitProblem, session: FilmSession, x: float, y: float,
             rc: float) -> tuple[float, float]:
    """(x, y) [m] projected onto the contact circle along its direction when outside."""
    px, py, _ = project_onto_circle(x, y, _radius(problem, session, x, y, rc))
    return px, py


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
