"""Orbit of a film with a transported content (mass-conserving, JFO) by implicit steps.

One step from φ_n to φ_{n+1} = φ_n + Δφ (Δt = Δφ/ω) solves, for the end velocity v,

.. math:: e^{n+1} = e^n + Δt\\,v,\\qquad
          F(e^{n+1}, v;\\ ϑ^n h^n, Δt) + W(φ_{n+1}) − m\\,\\frac{v − v^n}{Δt} = 0

(backward Euler, the first step of a cycle and after a contact event), then BDF2,
e^{n+1} = (4e^n − e^{n−1} + 2Δt v)/3 with the same formula for the velocity and the film
content (second order). F is the film force at the end of the implicit step of the film
content (:mod:`conrod.film.mass_conserving_step`), m the moving mass (0: the massless
orbit). Unlike the instantaneous force balance at a frozen film fraction, this balance has
an answer for any motion of the journal towards a ruptured region (the squeezed content
refills the gap and carries the load), so the step is well posed; both formulas are
L-stable. The 2 × 2 balance is solved by a damped Newton iteration with a finite-difference
Jacobian, each film solve warm-started from the previous trial; where it stalls because
the film force cannot turn with the load (a pressurised strip one row wide: the massless
journal jumps), a bracketed search for the end position finishes it
(:mod:`conrod.orbit.content_bracket`); a step that does not converge is split in halves
(backward Euler, down to 1/2^:data:`MAX_HALVINGS` of the step) before the orbit stops
with the crank angle, the force residual [N] and what to change.

On the contact circle r_c the centre moves along the circle (one unknown, the angle) and
the normal force that the film and load leave unbalanced is the contact force P_c ≥ 0
(eqs 4.1.5–4.1.8 of the contact model, [D0]); the centre leaves the circle when P_c < 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import FilmState
from conrod.film.capabilities import HasJointContentStep
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.progress import AngleReports
from conrod.orbit.trajectory import CycleTrajectory

NEWTON_ITERATIONS = 40
"""Most Newton iterations per step [-]."""
RELATIVE_RESIDUAL = 1.0e-8
"""Force residual, relative to the load plus 1 N, that ends the Newton iteration [-]."""
ACCEPTED_RESIDUAL = 1.0e-5
"""Largest relative residual accepted when the iteration limit is reached [-]."""
MAX_HALVINGS = 6
"""Most halvings of a step that does not converge [-]."""
CHORD_CONTRACTION = 0.25
"""Least reduction of the force residual per iteration with a reused Jacobian before it is
recomputed [-]."""
SUBSTEP_BUDGET = 4
"""Most steps per cycle, halved ones included, as a multiple of the nominal count: a cycle
that needs more stops instead of grinding on [-]."""


@dataclass
class _Step:
    """Outcome of one step: end position, velocity, memory, contact force, residual."""

    x: float
    y: float
    vx: float
    vy: float
    memory: Any
    contact_force: float
    in_contact: bool
    residual: float
    converged: bool


@dataclass(frozen=True)
class _Start:
    """Where a step starts: position [m], velocity [m/s], film memory, and the same one step
    earlier (``before``; None: a backward Euler step)."""

    x: float
    y: float
    vx: float
    vy: float
    memory: Any
    before: _Start | None = None

    def position(self, v, dt: float) -> tuple[float, float]:
        """End position of the step at end velocity ``v`` [m]."""
        b = self.before
        if b is None:
            return self.x + dt * v[0], self.y + dt * v[1]
        return ((dt * v[0] + 2.0 * self.x - 0.5 * b.x) / 1.5,
                (dt * v[1] + 2.0 * self.y - 0.5 * b.y) / 1.5)

    def velocity(self, x1: float, y1: float, dt: float) -> np.ndarray:
        """End velocity of the step that ends at (x1, y1) [m/s]."""
        b = self.before
        if b is None:
            return np.array([(x1 - self.x) / dt, (y1 - self.y) / dt])
        return np.array([(1.5 * x1 - 2.0 * self.x + 0.5 * b.x) / dt,
                         (1.5 * y1 - 2.0 * self.y + 0.5 * b.y) / dt])

    def predicted_velocity(self) -> np.ndarray:
        """Start of the iteration for the end velocity [m/s]: linear extrapolation over two
        equal steps (BDF2), else the velocity at the start."""
        b = self.before
        if b is None:
            return np.array([self.vx, self.vy])
        return np.array([2.0 * self.vx - b.vx, 2.0 * self.vy - b.vy])

    def acceleration(self, v, dt: float) -> np.ndarray:
        """dv/dt at the end of the step [m/s²]."""
        b = self.before
        if b is None:
            return np.array([(v[0] - self.vx) / dt, (v[1] - self.vy) / dt])
        return np.array([(1.5 * v[0] - 2.0 * self.vx + 0.5 * b.vx) / dt,
                         (1.5 * v[1] - 2.0 * self.vy + 0.5 * b.vy) / dt])


class _Balance:
    """Force balance of one implicit step (film, load, mass, contact circle)."""

    def __init__(self, problem: OrbitProblem, with_mass: bool):
        self.problem = problem
        self.film = problem.film
        self.mass = np.array([problem.mass_x, problem.mass_y]) if with_mass else np.zeros(2)
        self.radius = problem.contact_radius * (1.0 - 1e-9)
        self.scale = problem.clearance * max(problem.crank_speed, 1e-3)
        self._kept: dict = {}  # last Jacobian / contact slope by (kind, Δt, backward Euler)

    def residual(self, start: _Start, v, load, speeds, dt, warm):
        """(residual W + F − m dv/dt [N], memory at the end of the step) at end velocity v."""
        x1, y1 = start.position(v, dt)
        state = FilmState(eccentricity_x=x1, eccentricity_y=y1, velocity_x=v[0], velocity_y=v[1],
                          journal_speed=speeds[0], shell_speed=speeds[1],
                          viscosity=self.problem.viscosity)
        previous = start.before.memory if start.before is not None else None
        fx, fy, after = self.film.content_step(state, start.memory, dt, warm, previous)
        if self.problem.asperity is not None:
            from conrod.contact.asperity import asperity_force

            ax, ay = asperity_force(x1, y1, self.problem.clearance, self.problem.asperity)
            fx, fy = fx + ax, fy + ay
        r = np.array([load[0] + fx, load[1] + fy]) - self.mass * start.acceleration(v, dt)
        return r, after

    def free(self, start: _Start, load, speeds, dt) -> _Step | None:
        """Levenberg–Marquardt on the velocity off the circle (the film force can be nearly
        insensitive to one direction of the velocity where little film is left, so plain
        Newton steps explode), trial end positions projected onto the contact circle;
        None when the centre is pushed onto the circle. The Jacobian of the last step of
        the same kind is reused while it contracts the residual by
        :data:`CHORD_CONTRACTION` per iteration (chord iteration), else recomputed."""
        v, _ = self._admissible(start, start.predicted_velocity(), dt)
        size = math.hypot(*load) + 1.0
        if isinstance(self.film, HasJointContentStep) and self.problem.asperity is None:
            joint = self._joint(start, v, load, speeds, dt)
            if joint is not None:
                return joint
        r, warm = self.residual(start, v, load, speeds, dt, None)
        norm, damping, blocked = float(np.hypot(*r)), 1e-9, False
        kind = ("free", dt, start.before is None)
        jac, fresh = self._kept.pop(kind, None), False
        for _ in range(NEWTON_ITERATIONS):
            if norm <= RELATIVE_RESIDUAL * size:
                break
            if jac is None:
                jac, fresh = self._jacobian(start, v, r, load, speeds, dt, warm) * self.scale, True
            found = self._descent(start, v, r, norm, jac, damping, load, speeds, dt, warm,
                                  16 if fresh else 2)
            if found is None:
                if fresh:
                    break  # no decrease even with tiny steps: not converged
                jac = None
                continue
            jac = _broyden(jac, (found[0] - v) / self.scale, found[1] - r)
            v, r, warm, damping, blocked = found
            contraction = float(np.hypot(*r)) / norm
            norm = float(np.hypot(*r))
            if not fresh and contraction > CHORD_CONTRACTION:
                jac = None
            fresh = False
        self._kept[kind] = jac
        if norm > ACCEPTED_RESIDUAL * size:
            v, r, warm = self._bracketed(start, v, r, warm, load, speeds, dt)
            norm = float(np.hypot(*r))
        if norm > ACCEPTED_RESIDUAL * size and (blocked or self._near_circle(start, v, dt)):
            return None
        x1, y1 = start.position(v, dt)
        return _Step(x1, y1, float(v[0]), float(v[1]), warm, 0.0, False, norm / size,
                     norm <= ACCEPTED_RESIDUAL * size)

    def _joint(self, start: _Start, guess, load, speeds, dt) -> _Step | None:
        """The step by the film's joint Newton iteration (end velocity and the film's inner
        unknowns together, :class:`~conrod.film.capabilities.HasJointContentStep`); None
        when it does not converge inside the contact circle (the orbit's own iteration
        then takes the step)."""
        b = start.before
        if b is None:
            tau, position, velocity = dt, (start.x, start.y), (start.vx, start.vy)
        else:
            tau = dt / 1.5
            position = ((2.0 * start.x - 0.5 * b.x) / 1.5, (2.0 * start.y - 0.5 * b.y) / 1.5)
            velocity = ((2.0 * start.vx - 0.5 * b.vx) / 1.5,
                        (2.0 * start.vy - 0.5 * b.vy) / 1.5)
        done = self.film.joint_content_step(
            start.memory, b.memory if b is not None else None, dt,
            position_reference=np.array(position), velocity_reference=np.array(velocity),
            tau=tau, mass=self.mass, load=np.array(load), speeds=speeds,
            viscosity=self.problem.viscosity, guess=guess, force_tolerance=RELATIVE_RESIDUAL)
        if done is None or not done.converged:
            return None
        v = done.velocity
        x1, y1 = start.position(v, dt)
        if math.hypot(x1, y1) > self.radius:
            return None
        return _Step(x1, y1, float(v[0]), float(v[1]), done.memory, 0.0, False,
                     done.force_residual, True)

    def _descent(self, start: _Start, v, r, norm, jac, damping, load, speeds, dt, warm,
                 tries: int):
        """(v, r, memory, damping, blocked) after the first Levenberg–Marquardt step of
        ``jac`` that lowers the residual, raising the damping up to ``tries`` times; None
        when none does."""
        normal, gradient = jac.T @ jac, jac.T @ r
        level = float(np.max(np.diag(normal))) or 1.0
        for _ in range(tries):
            step = -np.linalg.solve(normal + damping * level * np.eye(2), gradient)
            trial, blocked = self._admissible(start, v + self.scale * step, dt)
            r_trial, w_trial = self.residual(start, trial, load, speeds, dt, warm)
            if np.hypot(*r_trial) < norm:
                return trial, r_trial, w_trial, max(damping / 10.0, 1e-15), blocked
            damping *= 10.0
        return None

    def _bracketed(self, start: _Start, v, r, warm, load, speeds, dt):
        """(v, r, memory) of the bracketed search from the stalled iterate v
        (:mod:`conrod.orbit.content_bracket`); the stalled iterate when it finds nothing
        better."""
        from conrod.orbit.content_bracket import bracketed_balance

        def residual(x1, y1):
            return self.residual(start, start.velocity(x1, y1, dt), load, speeds, dt, warm)

        found = bracketed_balance(residual, start.position(v, dt), load, self.radius,
                                  self.problem.clearance)
        if found is None or np.hypot(*found.residual) >= np.hypot(*r):
            return v, r, warm
        return start.velocity(found.x, found.y, dt), found.residual, found.memory

    def _admissible(self, start: _Start, v, dt):
        """(v, True) moved so that the end position lies on the contact circle when it would
        leave it (radial projection), else (v, False)."""
        x1, y1 = start.position(v, dt)
        e = math.hypot(x1, y1)
        if e <= self.radius:
            return v, False
        return start.velocity(x1 * self.radius / e, y1 * self.radius / e, dt), True

    def _near_circle(self, start: _Start, v, dt) -> bool:
        return math.hypot(*start.position(v, dt)) > self.radius - 1e-3 * self.problem.clearance

    def _jacobian(self, start: _Start, v, r, load, speeds, dt, warm):
        delta = 1e-4 * self.scale  # well above the film solver's noise
        jac = np.empty((2, 2))
        for i in range(2):
            dv = v.copy()
            dv[i] += delta
            jac[:, i] = (self.residual(start, dv, load, speeds, dt, warm)[0] - r) / delta
        return jac

    def on_circle(self, start: _Start, load, speeds, dt) -> _Step | None:
        """Centre on the contact circle: the angle balances the tangential force; None when
        the normal force pulls the centre off the circle (P_c < 0)."""
        size = math.hypot(*load) + 1.0

        def tangential(angle, warm):
            normal = np.array([math.cos(angle), math.sin(angle)])
            v = start.velocity(self.radius * normal[0], self.radius * normal[1], dt)
            r, after = self.residual(start, v, load, speeds, dt, warm)
            return float(r @ np.array([-normal[1], normal[0]])), r, v, after

        alpha = math.atan2(start.y, start.x)
        rt, r, v, warm = tangential(alpha, None)
        kind = ("circle", dt, start.before is None)
        slope, fresh = self._kept.get(kind), False
        for _ in range(NEWTON_ITERATIONS):
            if abs(rt) <= RELATIVE_RESIDUAL * size:
                break
            if not slope:
                slope, fresh = (tangential(alpha + 1e-7, warm)[0] - rt) / 1e-7, True
            change = max(min(-rt / slope if slope != 0.0 else 0.0, 0.05), -0.05)
            lam, trial = 1.0, None
            while lam >= (1e-6 if fresh else 0.25):
                trial = tangential(alpha + lam * change, warm)
                if abs(trial[0]) < abs(rt):
                    break
                lam, trial = 0.5 * lam, None
            if trial is None:
                if fresh:
                    break  # no decrease: not converged
                slope = None
                continue
            if abs(lam * change) > 1e-9:  # secant slope, above the film solver's noise
                slope = (trial[0] - rt) / (lam * change)
            fresh = False
            alpha += lam * change
            rt, r, v, warm = trial
        self._kept[kind] = slope
        normal = np.array([math.cos(alpha), math.sin(alpha)])
        contact = float(r @ normal)  # the unbalanced force pressing outwards = P_c
        if contact < 0.0:
            return None
        return _Step(self.radius * normal[0], self.radius * normal[1], float(v[0]),
                     float(v[1]), warm, contact, True, abs(rt) / size,
                     abs(rt) <= ACCEPTED_RESIDUAL * size)

    def step(self, start: _Start, load, speeds, dt, contact: bool) -> _Step | None:
        """One step from ``start``; contact tried first when on the circle."""
        attempts = (self.on_circle, self.free) if contact else (self.free, self.on_circle)
        for attempt in attempts:
            result = attempt(start, load, speeds, dt)
            if result is not None:
                return result
        return None


def _broyden(jac: np.ndarray, step: np.ndarray, change: np.ndarray) -> np.ndarray:
    """Broyden's rank-one update of ``jac`` to the secant ``change`` = J ``step``.

    C.G. Broyden, "A class of methods for solving nonlinear simultaneous equations",
    Math. Comp. 19 (1965) 577–593."""
    length = float(step @ step)
    if length == 0.0:
        return jac
    return jac + np.outer(change - jac @ step, step) / length


def content_cycle(problem: OrbitProblem, state: OrbitState, step_deg: float,
                  output_step_deg: float, *, with_mass: bool) -> CycleTrajectory:
    """One cycle from ``state`` by implicit steps of ``step_deg`` [deg] (BDF2 after a first
    backward Euler step); massless (``with_mass`` False) or with the problem's masses."""
    from conrod.orbit.rk2 import step_grid

    phi, record_every, n_out = step_grid(problem, step_deg, output_step_deg)
    balance = _Balance(problem, with_mass)
    memory = state.film_memory if state.film_memory is not None else problem.film.initial_memory()
    start = _Start(state.x, state.y, state.vx, state.vy, memory)
    contact = state.in_contact or math.hypot(state.x, state.y) >= balance.radius
    table = np.zeros((n_out, 7))
    memories: list[Any] = [None] * n_out
    last_force = _start_contact_force(problem, state, memory) if contact else 0.0
    steps, reports = 0, AngleReports()
    for k in range(len(phi) - 1):
        reports.reached(phi[k])
        if k % record_every == 0:
            row = k // record_every
            table[row] = (start.x, start.y, start.vx, start.vy, last_force,
                          problem.dry_friction * last_force, float(contact))
            memories[row] = start.memory
        done, taken, smooth = _advance(balance, problem, phi[k], phi[k + 1], start, contact)
        steps += taken
        if steps > SUBSTEP_BUDGET * (len(phi) - 1):
            raise ConvergenceError(
                f"mass-conserving orbit: more than {SUBSTEP_BUDGET}× the nominal "
                f"{len(phi) - 1} steps per cycle (steps halved over and over); reduce the "
                "step or refine solver.n_theta/n_z",
                where=f"crank angle {math.degrees(phi[k + 1]):.2f} deg")
        before = _Start(start.x, start.y, start.vx, start.vy, start.memory)
        # BDF2 needs two equal steps on the same side of a contact event
        keep = smooth and done.in_contact == contact
        start = _Start(done.x, done.y, done.vx, done.vy, done.memory, before if keep else None)
        contact, last_force = done.in_contact, done.contact_force
    end = OrbitState(start.x, start.y, start.vx, start.vy, contact, start.memory)
    traj = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, steps)
    traj.film_memory = memories
    return traj


def _advance(balance: _Balance, problem: OrbitProblem, phi0: float, phi1: float,
             start: _Start, contact: bool, depth: int = 0) -> tuple[_Step, int, bool]:
    """Step φ0 → φ1, split in halves (backward Euler) where it does not converge;
    (step, steps taken, True when taken in one piece)."""
    dt = (phi1 - phi0) / problem.crank_speed
    load = problem.loads.load(np.array([phi1]))
    speeds = problem.loads.speeds(np.array([phi1]))
    result = balance.step(start, (float(load[0][0]), float(load[1][0])),
                          (float(speeds[0][0]), float(speeds[1][0])), dt, contact)
    if result is not None and result.converged:
        return result, 1, True
    if depth >= MAX_HALVINGS:
        raise _failure(problem, phi1, result, load, bool(np.any(balance.mass > 0.0)))
    middle = 0.5 * (phi0 + phi1)
    first = _Start(start.x, start.y, start.vx, start.vy, start.memory)
    half, count, _ = _advance(balance, problem, phi0, middle, first, contact, depth + 1)
    second = _Start(half.x, half.y, half.vx, half.vy, half.memory)
    end, more, _ = _advance(balance, problem, middle, phi1, second, half.in_contact, depth + 1)
    return end, count + more, False


def _failure(problem: OrbitProblem, phi: float, result: _Step | None, load,
             with_mass: bool) -> ConvergenceError:
    """What stopped the orbit, where, by how much, and what to change."""
    size = math.hypot(float(load[0][0]), float(load[1][0])) + 1.0
    residual = result.residual * size if result is not None else float("nan")
    if with_mass:
        advice = ("refine solver.n_theta/n_z, reduce solver.max_step_deg, or check that the "
                  "oil feed (bearing.supply_pressure, grooves) can fill the film under this "
                  "load")
    else:
        advice = ("no end position inside the contact circle balances the load, not even "
                  "after a jump of the massless journal (bracketed search); refine "
                  "solver.n_theta/n_z, reduce solver.quasi_static_step_deg, or run the "
                  "orbit with mass (solver.integrator = 'auto' or 'implicit')")
    return ConvergenceError(
        f"mass-conserving orbit step did not balance the load after {MAX_HALVINGS} halvings "
        f"(force residual {residual:.3g} N of a {size - 1.0:.3g} N load); {advice}",
        where=f"crank angle {math.degrees(phi):.2f} deg", residual=residual)


def _start_contact_force(problem: OrbitProblem, state: OrbitState, memory) -> float:
    """P_c = max((W + F)·n̂, 0) at the start of a cycle on the contact circle [N]."""
    wx, wy = (float(a[0]) for a in problem.loads.load(np.array([0.0])))
    wj, wb = (float(a[0]) for a in problem.loads.speeds(np.array([0.0])))
    try:
        result, _ = problem.film.solve_with_memory(
            FilmState(eccentricity_x=state.x, eccentricity_y=state.y, velocity_x=state.vx,
                      velocity_y=state.vy, journal_speed=wj, shell_speed=wb,
                      viscosity=problem.viscosity), memory)
    except (CaseError, ConvergenceError):
        return 0.0
    e = math.hypot(state.x, state.y)
    return max(((wx + result.force_x) * state.x + (wy + result.force_y) * state.y) / e, 0.0)
