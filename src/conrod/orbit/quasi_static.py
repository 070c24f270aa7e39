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

import dataclasses
import functools
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
from conrod.orbit.compiled_flight import bound_to_force
from conrod.orbit.contact import project_onto_circle, remove_normal_velocity
from conrod.orbit.implicit_step import implicit_step_cycle as content_cycle
from conrod.orbit.memory import FilmSession
from conrod.orbit.problem import OrbitProblem, OrbitState, step_grid
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


JACOBIAN_STEPS = (1.0e-6, 1.0e-8)
"""Steps of the finite-difference velocity Jacobian of the generic massless solve, in
units of c ω: forward differences at the first, central differences at the second after a
Newton step that found no decrease [-]. (A step of 1e-4 c ω left the iteration at a
relative residual of 2e-4 on a fed Reynolds film at ε = 0.998, where one central step of
1e-6 c ω converges in one iteration.)"""


def _generic_newton(problem: OrbitProblem, scale: float, session: FilmSession | None = None):
    """Damped Newton (backtracking, step ≤ max(10 c ω, 2|v|)) with a finite-difference Jacobian
    (:data:`JACOBIAN_STEPS`); the film memory of the Jacobian's trial solves is restored
    before the Newton step; a step that lowers the residual by no backtracking gets a
    central-difference Jacobian at the finer step, and the iteration stops where neither
    lowers it (never accepting a larger residual)."""
    session = session if session is not None else problem.session()
    force = problem.force_function(session)

    def residual(x, y, v, wx, wy, wj, wb, phi=None):
        fx, fy = force(x, y, v[0], v[1], wj, wb, phi)
        return np.array([fx + wx, fy + wy])

    def jacobian(x, y, v, r, wx, wy, wj, wb, central: bool, phi=None):
        delta = (JACOBIAN_STEPS[1] if central else JACOBIAN_STEPS[0]) * scale
        jac = np.empty((2, 2))
        base = session.snapshot()
        for i in range(2):
            dv = v.copy()
            dv[i] += delta
            plus = residual(x, y, dv, wx, wy, wj, wb, phi)
            session.restore(base)
            if central:
                dv[i] -= 2.0 * delta
                jac[:, i] = (plus - residual(x, y, dv, wx, wy, wj, wb, phi)) / (2.0 * delta)
                session.restore(base)
            else:
                jac[:, i] = (plus - r) / delta
        return jac

    def solve(x, y, wx, wy, wj, wb, guess, angle=0.0):
        v = np.array(guess, dtype=float)
        load = math.hypot(wx, wy) + 1.0
        r = residual(x, y, v, wx, wy, wj, wb, angle)
        norm = float(np.hypot(*r))
        central = False
        for _ in range(NEWTON_ITERATIONS):
            if norm <= 1e-8 * load:
                break
            jac = jacobian(x, y, v, r, wx, wy, wj, wb, central, angle)
            step = -np.linalg.lstsq(jac, r, rcond=None)[0]
            length = float(np.hypot(*step))
            limit = max(10.0 * scale, 2.0 * float(np.hypot(*v)))  # grows geometrically
            if length > limit:
                step *= limit / length
            lam, found = 1.0, None
            while lam >= 1e-4:
                trial = v + lam * step
                r_trial = residual(x, y, trial, wx, wy, wj, wb, angle)
                if np.hypot(*r_trial) < norm:
                    found = trial, r_trial
                    break
                lam *= 0.5
            if found is None:
                if central:
                    break  # no decrease with the finest Jacobian: as good as it gets
                central = True
                continue
            v, r = found
            norm = float(np.hypot(*r))
        return float(v[0]), float(v[1]), norm / load

    return solve


def quasi_static_cycle(
    problem: OrbitProblem, state: OrbitState, step_deg: float, output_step_deg: float
) -> CycleTrajectory:
    """One cycle of the massless orbit from ``state`` (only its position is used)."""
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
    stepper = _HeunSteps(problem, session, rc)
    x, y, guess = state.x, state.y, (state.vx, state.vy)
    table = np.zeros((n_out, 7))
    memory = [None] * n_out if session.has_memory else None
    worst, worst_k, reports = 0.0, 0, AngleReports()
    for k in range(len(phi) - 1):
        reports.reached(phi[k])
        vx, vy, r1 = stepper.velocity(x, y, phi[k], guess)
        contact = stepper.on_circle(x, y)
        if contact:
            vx, vy = _inward_only(x, y, vx, vy)
        if k % record_every == 0:
            table[k // record_every] = (x, y, vx, vy, 0.0, 0.0, float(contact))
            if memory is not None:
                memory[k // record_every] = session.snapshot()
        if k == 0:
            settle = _moves_far(problem, dt, vx, vy)
        count = MAX_SUBSTEPS if settle and k < record_every else 1
        x, y, guess, r2 = stepper.step(x, y, (vx, vy), phi[k], phi[k + 1], count)
        if max(r1, r2) > worst:
            worst, worst_k = max(r1, r2), k
    if worst > 1e-4 or not np.all(np.isfinite(table)):
        raise ConvergenceError(
            "quasi-static velocity solve failed (relative force residual; try a smaller "
            "solver.quasi_static_step_deg or the integrator 'implicit')",
            where=f"crank angle {math.degrees(float(phi[worst_k])):.1f} deg", residual=worst)
    sampled = [a[::record_every][:n_out] for a in (load_x, load_y, wj, wb, phi)]
    _contact_forces(problem, table, *sampled)
    end = OrbitState(x, y, guess[0], guess[1], False, session.snapshot())
    traj = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end,
                                      2 * (len(phi) - 1) + stepper.extra_steps)
    traj.film_memory = memory
    return traj


MAX_MOVE = 0.05
"""Largest journal-centre move of the first Heun step of a cycle, share of the radial
clearance [-]: a cycle whose first step would move the journal more takes its first output
interval in :data:`MAX_SUBSTEPS` × as many steps. From the concentric start the massless
journal crosses much of the clearance within a fraction of a degree; one Heun step of
``quasi_static_step_deg`` there put the predictor far outside the film (onto the shell),
where no velocity balances the load."""
MAX_SUBSTEPS = 64
"""Sub-steps of each Heun step of a settled first output interval [-]."""


def _moves_far(problem: OrbitProblem, dt: float, vx: float, vy: float) -> bool:
    """True when a step ``dt`` [s] at (v_x, v_y) [m/s] moves the journal more than
    :data:`MAX_MOVE` of the clearance [-]."""
    return dt * math.hypot(vx, vy) > MAX_MOVE * problem.clearance


class _HeunSteps:
    """Heun steps of the massless orbit in Python with the film's velocity solve and the
    contact circle, in sub-steps on request, the film memory advanced after each."""

    def __init__(self, problem: OrbitProblem, session: FilmSession, rc: float):
        self.problem, self.session, self.rc = problem, session, rc
        self.solve = _velocity_solver(problem, session)
        self.extra_steps = 0

    def velocity(self, x, y, angle, guess):
        """(v_x, v_y, relative residual) balancing the load at φ = ``angle`` [rad]."""
        wx, wy = (float(a[0]) for a in self.problem.loads.load(np.array([angle])))
        wj, wb = (float(a[0]) for a in self.problem.loads.speeds(np.array([angle])))
        return self.solve(x, y, wx, wy, wj, wb, guess, angle)

    def on_circle(self, x, y) -> bool:
        """On the contact circle (of the deformed bore where it closes first) [-]."""
        return math.hypot(x, y) >= _radius(self.problem, self.session, x, y,
                                           self.rc) * (1.0 - 1e-9)

    def step(self, x, y, v, phi0, phi1, count: int = 1):
        """(x, y, velocity at φ1, worst relative residual) of the Heun step φ0 → φ1 from
        (x, y) with the start velocity ``v`` [m, m/s], in ``count`` sub-steps."""
        self.extra_steps += 2 * (count - 1)
        worst, angles = 0.0, np.linspace(phi0, phi1, count + 1)
        for i in range(count):
            if i > 0:
                vx, vy, r = self.velocity(x, y, angles[i], v)
                v, worst = (vx, vy), max(worst, r)
                if self.on_circle(x, y):
                    v = _inward_only(x, y, *v)
            x, y, v, r = self._heun(x, y, v, angles[i], angles[i + 1])
            worst = max(worst, r)
        return x, y, v, worst

    def _heun(self, x, y, v, phi0, phi1):
        problem, session = self.problem, self.session
        dt = (phi1 - phi0) / problem.crank_speed
        xp, yp = _project(problem, session, x + dt * v[0], y + dt * v[1], self.rc)
        vx2, vy2, r2 = self.velocity(xp, yp, phi1, v)
        wj, wb = (float(a[0]) for a in problem.loads.speeds(np.array([phi0])))
        x1, y1 = _project(problem, session, x + 0.5 * dt * (v[0] + vx2),
                          y + 0.5 * dt * (v[1] + vy2), self.rc)
        session.advance(FilmState(eccentricity_x=xp, eccentricity_y=yp, velocity_x=v[0],
                                  velocity_y=v[1], journal_speed=wj, shell_speed=wb,
                                  viscosity=problem.viscosity,
                                  journal_feed=problem.journal_feed(phi0)), dt)
        return x1, y1, (vx2, vy2), r2


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
    """Compiled Heun loop of ``kernel`` over ``request``, then the contact forces. Where
    the first step moves the journal far (:data:`MAX_MOVE`) or the velocity solve fails,
    the cycle is run again with the first output interval in :data:`MAX_SUBSTEPS` ×
    as many steps (:func:`_settled_start`), as the Python loop takes it; a failure that
    remains names its crank angle (:func:`_failure_angle`)."""
    if _moves_far(problem, request.dt, *_first_row(problem, kernel, request)[2:4]):
        table, end, worst = _settled_start(problem, kernel, request, phi)
    else:
        table, end, worst = _run_compiled(problem, kernel, request)
        if _failed(table, worst):
            table, end, worst = _settled_start(problem, kernel, request, phi)
    if _failed(table, worst):
        raise ConvergenceError(
            "quasi-static velocity solve failed (relative force residual; try a smaller "
            "solver.quasi_static_step_deg or the integrator 'implicit')",
            where=f"crank angle {_failure_angle(problem, kernel, request, phi):.1f} deg",
            residual=worst)
    every = request.record_every
    sampled = [a[::every][:n_out] for a in (request.load_x, request.load_y,
                                            request.journal_speed, request.shell_speed)]
    if kernel.force is not None:
        load_x, load_y = (np.ascontiguousarray(a) for a in sampled[:2])  # one signature
        bound_contact_forces(kernel.force)(kernel.params, table, load_x, load_y,
                                           sampled[2] + sampled[3], problem.viscosity,
                                           problem.dry_friction)
    else:
        _contact_forces(problem, table, *sampled)
    end_state = OrbitState(end[0], end[1], end[2], end[3], False)
    return CycleTrajectory.from_table(phi[::every][:n_out], table, end_state,
                                      2 * (len(phi) - 1))


def _first_row(problem: OrbitProblem, kernel: CompiledKernel, r: QuasiStaticRequest
               ) -> np.ndarray:
    """The first row (x, y, v_x, v_y, ...) of the compiled cycle over ``r``, from its first
    output interval alone: whether the first step moves far is known before the whole
    cycle is run (a massless orbit from the concentric start: 1.2 s of a 144 × 16 cycle
    that the settled start would replace)."""
    every = r.record_every
    head = dataclasses.replace(r, load_x=r.load_x[:every + 1], load_y=r.load_y[:every + 1],
                               journal_speed=r.journal_speed[:every + 1],
                               shell_speed=r.shell_speed[:every + 1])
    return _run_compiled(problem, kernel, head)[0][0]


def _failed(table: np.ndarray, worst: float) -> bool:
    return worst > 1e-4 or not np.all(np.isfinite(table))


def _run_compiled(problem: OrbitProblem, kernel: CompiledKernel, r: QuasiStaticRequest):
    """(rows, end state array, worst relative residual) of the kernel's compiled loop."""
    if kernel.quasi_static_cycle is not None:
        return kernel.quasi_static_cycle(r)
    scale = problem.clearance * max(problem.crank_speed, 1e-3)
    return newton_cycle(
        kernel.force, kernel.params, r.x, r.y, r.vx, r.vy, r.dt, r.load_x, r.load_y,
        r.journal_speed, r.shell_speed, r.record_every, r.viscosity, r.contact_radius,
        scale)


def _settled_start(problem: OrbitProblem, kernel: CompiledKernel, r: QuasiStaticRequest,
                   phi: np.ndarray):
    """The compiled cycle with its first output interval in :data:`MAX_SUBSTEPS` × as many
    steps, then the rest from where they end: (rows, end state array, worst residual)."""
    every = r.record_every
    angles = np.linspace(phi[0], phi[every], MAX_SUBSTEPS * every + 1)
    load_x, load_y = problem.loads.load(angles)
    wj, wb = problem.loads.speeds(angles)
    first = dataclasses.replace(r, dt=r.dt / MAX_SUBSTEPS, load_x=load_x, load_y=load_y,
                                journal_speed=wj, shell_speed=wb,
                                record_every=MAX_SUBSTEPS * every)
    rows, start, worst = _run_compiled(problem, kernel, first)
    rest = dataclasses.replace(
        r, x=float(start[0]), y=float(start[1]), vx=float(start[2]), vy=float(start[3]),
        load_x=r.load_x[every:], load_y=r.load_y[every:],
        journal_speed=r.journal_speed[every:], shell_speed=r.shell_speed[every:])
    table, end, later = _run_compiled(problem, kernel, rest)
    return np.vstack([rows[:1], table]), end, max(worst, later)


def _failure_angle(problem: OrbitProblem, kernel: CompiledKernel, r: QuasiStaticRequest,
                   phi: np.ndarray) -> float:
    """Crank angle [deg] of the first step whose velocity solve fails in the compiled loop
    over ``r`` (bisection on the number of steps: the loop is deterministic)."""
    low, high = 0, r.load_x.size - 1  # steps known to pass / to fail
    while high - low > 1:
        middle = (low + high) // 2
        cut = dataclasses.replace(r, load_x=r.load_x[:middle + 1],
                                  load_y=r.load_y[:middle + 1],
                                  journal_speed=r.journal_speed[:middle + 1],
                                  shell_speed=r.shell_speed[:middle + 1])
        if _failed(*_run_compiled(problem, kernel, cut)[::2]):
            high = middle
        else:
            low = middle
    return math.degrees(float(phi[high]))


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


@functools.cache
def bound_contact_forces(film_force):
    """:func:`conrod.film.massless.contact_forces` compiled with ``film_force`` bound as its
    global ``force`` (:func:`conrod.orbit.compiled_flight.bound_to_force`)."""
    return bound_to_force(contact_forces, film_force, "contact_forces")


def _contact_forces(problem, table, load_x, load_y, wj, wb, angles=None) -> None:
    """P_c = (W + F)·n̂ ≥ 0 where the massless journal sits on the contact circle."""
    force = problem.force_function()
    for i in np.flatnonzero(table[:, 6] > 0.5):
        x, y, vx, vy = table[i, :4]
        fx, fy = force(x, y, vx, vy, wj[i], wb[i],
                       None if angles is None else float(angles[i]))
        e = math.hypot(x, y)
        p_c = max(((load_x[i] + fx) * x + (load_y[i] + fy) * y) / e, 0.0)
        table[i, 4], table[i, 5] = p_c, problem.dry_friction * p_c
