"""Steps of a film with a transported content (mass-conserving, JFO): the journal's balance
at the end of the film's implicit content step (:mod:`conrod.film.mass_conserving.step`).

F in the balance of :mod:`conrod.orbit.implicit_step` is the film force at the end of the
implicit step of the film content. Unlike the instantaneous force balance at a frozen film
fraction, this balance has an answer for any motion of the journal towards a ruptured
region (the squeezed content refills the gap and carries the load), so the step is well
posed. A film that also solves unknowns of its own with the journal's step
(:class:`~conrod.film.capabilities.HasStepSystem`: the elastic film's bore) is handed the
whole step first (:mod:`conrod.orbit.journal_step`); where that does not converge inside the
contact circle, and for the other films, the balance is solved here for the end velocity by
a damped Levenberg–Marquardt iteration with a finite-difference Jacobian, each film solve
warm-started from the previous trial; where it stalls because the film force cannot turn
with the load (a pressurised strip one row wide: the massless journal jumps), a bracketed
search for the end position finishes it (:mod:`conrod.orbit.content_bracket`). A step that
does not converge is split in halves down to 1/2^:data:`MAX_HALVINGS`, and a cycle stops
after :data:`SUBSTEP_BUDGET` × its nominal steps.

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
from conrod.film.capabilities import HasStepSystem
from conrod.orbit.journal_step import solve_journal_step
from conrod.orbit.problem import OrbitProblem, OrbitState

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
class ContentStepEnd:
    """End of one step: position [m], velocity [m/s], memory, contact force [N], whether on
    the contact circle, relative force residual [-], whether converged."""

    position: np.ndarray
    velocity: np.ndarray
    memory: Any
    contact_force: float
    in_contact: bool
    residual: float
    converged: bool


class ContentSteps:
    """Force balance of the implicit steps of a film with content (module docstring)."""

    max_halvings = MAX_HALVINGS

    def __init__(self, problem: OrbitProblem, with_mass: bool):
        self.problem = problem
        self.film = problem.film
        self.mass = np.array([problem.mass_x, problem.mass_y]) if with_mass else np.zeros(2)
        self.radius = problem.contact_radius * (1.0 - 1e-9)
        self.scale = problem.clearance * max(problem.crank_speed, 1e-3)
        self.joint = (isinstance(self.film, HasStepSystem) and problem.asperity is None
                      and self.film.supports_step_system())
        self._kept: dict = {}  # last Jacobian / contact slope by (kind, Δt, backward Euler)

    # ------------------------------------------------------------- the step driver's
    def starts_in_contact(self, state: OrbitState) -> bool:
        """On the contact circle at the start of the cycle [-]."""
        return state.in_contact or math.hypot(state.x, state.y) >= self.radius

    def start_contact_force(self, state: OrbitState, memory) -> float:
        """P_c = max((W + F)·n̂, 0) at the start of a cycle on the contact circle [N]."""
        problem = self.problem
        wx, wy = (float(a[0]) for a in problem.loads.load(np.array([0.0])))
        wj, wb = (float(a[0]) for a in problem.loads.speeds(np.array([0.0])))
        try:
            result, _ = problem.film.solve_with_memory(
                FilmState(eccentricity_x=state.x, eccentricity_y=state.y, velocity_x=state.vx,
                          velocity_y=state.vy, journal_speed=wj, shell_speed=wb,
                          viscosity=problem.viscosity, journal_feed=problem.journal_feed(0.0)),
                memory)
        except (CaseError, ConvergenceError):
            return 0.0
        e = math.hypot(state.x, state.y)
        return max(((wx + result.force_x) * state.x + (wy + result.force_y) * state.y) / e,
                   0.0)

    def check_budget(self, taken: int, nominal: int, phi: float) -> None:
        """ConvergenceError when the cycle took more than :data:`SUBSTEP_BUDGET` × its
        nominal steps."""
        if taken > SUBSTEP_BUDGET * nominal:
            raise ConvergenceError(
                f"mass-conserving orbit: more than {SUBSTEP_BUDGET}× the nominal {nominal} "
                "steps per cycle (steps halved over and over); reduce the step or refine "
                "solver.n_theta/n_z", where=f"crank angle {math.degrees(phi):.2f} deg")

    def step(self, start, phi1: float, dt: float, contact: bool) -> ContentStepEnd | None:
        """One step from ``start`` to φ1; contact tried first when on the circle."""
        load = self.problem.loads.load(np.array([phi1]))
        speeds = self.problem.loads.speeds(np.array([phi1]))
        at = _At(phi1, dt, (float(load[0][0]), float(load[1][0])),
                 (float(speeds[0][0]), float(speeds[1][0])))
        attempts = (self.on_circle, self.free) if contact else (self.free, self.on_circle)
        for attempt in attempts:
            result = attempt(start, at)
            if result is not None:
                return result
        return None

    def accept(self, end: ContentStepEnd, phi: float) -> None:
        """Nothing to check: the contact circle is a phase of these steps."""

    def failure(self, phi: float, result: ContentStepEnd | None, start) -> ConvergenceError:
        """What stopped the orbit, where, by how much, and what to change."""
        load = self.problem.loads.load(np.array([phi]))
        size = math.hypot(float(load[0][0]), float(load[1][0])) + 1.0
        residual = result.residual * size if result is not None else float("nan")
        if bool(np.any(self.mass > 0.0)):
            advice = ("refine solver.n_theta/n_z, reduce solver.max_step_deg, or check that "
                      "the oil feed (bearing.supply_pressure, grooves) can fill the film under "
                      "this load")
        else:
            advice = ("no end position inside the contact circle balances the load, not even "
                      "after a jump of the massless journal (bracketed search); refine "
                      "solver.n_theta/n_z, reduce solver.quasi_static_step_deg, or run the "
                      "orbit with mass (solver.integrator = 'auto' or 'implicit')")
        return ConvergenceError(
            f"mass-conserving orbit step did not balance the load after {MAX_HALVINGS} "
            f"halvings (force residual {residual:.3g} N of a {size - 1.0:.3g} N load); "
            f"{advice}", where=f"crank angle {math.degrees(phi):.2f} deg", residual=residual)

    # --------------------------------------------------------------- the balance
    def residual(self, start, v, at: _At, warm):
        """(residual W + F − m dv/dt [N], memory at the end of the step) at end velocity v."""
        x1, y1 = start.end_position(v, at.dt)
        load, speeds = at.load, at.speeds
        state = FilmState(eccentricity_x=x1, eccentricity_y=y1, velocity_x=v[0], velocity_y=v[1],
                          journal_speed=speeds[0], shell_speed=speeds[1],
                          viscosity=self.problem.viscosity,
                          journal_feed=self.problem.journal_feed(at.phi))
        previous = start.before.memory if start.before is not None else None
        fx, fy, after = self.film.content_step(state, start.memory, at.dt, warm, previous)
        if self.problem.asperity is not None:
            from conrod.contact.asperity import asperity_force

            ax, ay = asperity_force(x1, y1, self.problem.clearance, self.problem.asperity)
            fx, fy = fx + ax, fy + ay
        r = np.array([load[0] + fx, load[1] + fy]) - self.mass * start.acceleration(v, at.dt)
        return r, after

    def free(self, start, at: _At) -> ContentStepEnd | None:
        """Levenberg–Marquardt on the velocity off the circle (the film force can be nearly
        insensitive to one direction of the velocity where little film is left, so plain
        Newton steps explode), trial end positions projected onto the contact circle;
        None when the centre is pushed onto the circle. The Jacobian of the last step of
        the same kind is reused while it contracts the residual by
        :data:`CHORD_CONTRACTION` per iteration (chord iteration), else recomputed."""
        v, _ = self._admissible(start, start.predicted_velocity(), at.dt)
        size = math.hypot(*at.load) + 1.0
        if self.joint:
            joint = self._joint(start, v, at)
            if joint is not None:
                return joint
        r, warm = self.residual(start, v, at, None)
        norm, damping, blocked = float(np.hypot(*r)), 1e-9, False
        kind = ("free", at.dt, start.before is None)
        jac, fresh = self._kept.pop(kind, None), False
        for _ in range(NEWTON_ITERATIONS):
            if norm <= RELATIVE_RESIDUAL * size:
                break
            if jac is None:
                jac, fresh = self._jacobian(start, v, r, at, warm) * self.scale, True
            found = self._descent(start, v, r, norm, jac, damping, at, warm,
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
            v, r, warm = self._bracketed(start, v, r, warm, at)
            norm = float(np.hypot(*r))
        if norm > ACCEPTED_RESIDUAL * size and (blocked or self._near_circle(start, v, at.dt)):
            return None
        return ContentStepEnd(start.end_position(v, at.dt), v, warm, 0.0, False, norm / size,
                              norm <= ACCEPTED_RESIDUAL * size)

    def _joint(self, start, guess, at: _At) -> ContentStepEnd | None:
        """The step by the film's step system (end velocity and the film's own unknowns
        together, :mod:`conrod.orbit.journal_step`); None when it does not reach its
        tolerances inside the contact circle (the iteration here then takes the step)."""
        request = start.request(self.problem, at.phi, at.dt, self.mass, np.array(at.load),
                                at.speeds)
        done = solve_journal_step(self.film, request, guess, self.scale)
        if done is None or not done.newton.settled:
            return None
        end = start.end_position(done.velocity, at.dt)
        if math.hypot(*end) > self.radius:
            return None
        return ContentStepEnd(end, done.velocity, done.memory, 0.0, False,
                              done.newton.force_residual, True)

    def _descent(self, start, v, r, norm, jac, damping, at: _At, warm, tries: int):
        """(v, r, memory, damping, blocked) after the first Levenberg–Marquardt step of
        ``jac`` that lowers the residual, raising the damping up to ``tries`` times; None
        when none does."""
        normal, gradient = jac.T @ jac, jac.T @ r
        level = float(np.max(np.diag(normal))) or 1.0
        for _ in range(tries):
            step = -np.linalg.solve(normal + damping * level * np.eye(2), gradient)
            trial, blocked = self._admissible(start, v + self.scale * step, at.dt)
            r_trial, w_trial = self.residual(start, trial, at, warm)
            if np.hypot(*r_trial) < norm:
                return trial, r_trial, w_trial, max(damping / 10.0, 1e-15), blocked
            damping *= 10.0
        return None

    def _bracketed(self, start, v, r, warm, at: _At):
        """(v, r, memory) of the bracketed search from the stalled iterate v
        (:mod:`conrod.orbit.content_bracket`); the stalled iterate when it finds nothing
        better."""
        from conrod.orbit.content_bracket import bracketed_balance

        def residual(x1, y1):
            return self.residual(start, start.end_velocity(np.array([x1, y1]), at.dt), at,
                                 warm)

        found = bracketed_balance(residual, start.end_position(v, at.dt), at.load,
                                  self.radius, self.problem.clearance)
        if found is None or np.hypot(*found.residual) >= np.hypot(*r):
            return v, r, warm
        return (start.end_velocity(np.array([found.x, found.y]), at.dt), found.residual,
                found.memory)

    def _admissible(self, start, v, dt):
        """(v, True) moved so that the end position lies on the contact circle when it would
        leave it (radial projection), else (v, False)."""
        end = start.end_position(v, dt)
        e = math.hypot(*end)
        if e <= self.radius:
            return v, False
        return start.end_velocity(end * self.radius / e, dt), True

    def _near_circle(self, start, v, dt) -> bool:
        return (math.hypot(*start.end_position(v, dt))
                > self.radius - 1e-3 * self.problem.clearance)

    def _jacobian(self, start, v, r, at: _At, warm):
        delta = 1e-4 * self.scale  # well above the film solver's noise
        jac = np.empty((2, 2))
        for i in range(2):
            dv = v.copy()
            dv[i] += delta
            jac[:, i] = (self.residual(start, dv, at, warm)[0] - r) / delta
        return jac

    def on_circle(self, start, at: _At) -> ContentStepEnd | None:
        """Centre on the contact circle: the angle balances the tangential force; None when
        the normal force pulls the centre off the circle (P_c < 0)."""
        size = math.hypot(*at.load) + 1.0

        def tangential(angle, warm):
            normal = np.array([math.cos(angle), math.sin(angle)])
            v = start.end_velocity(self.radius * normal, at.dt)
            r, after = self.residual(start, v, at, warm)
            return float(r @ np.array([-normal[1], normal[0]])), r, v, after

        alpha = math.atan2(start.y, start.x)
        rt, r, v, warm = tangential(alpha, None)
        kind = ("circle", at.dt, start.before is None)
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
        return ContentStepEnd(self.radius * normal, v, warm, contact, True, abs(rt) / size,
                              abs(rt) <= ACCEPTED_RESIDUAL * size)


@dataclass(frozen=True)
class _At:
    """Where a step ends: φ1 [rad], Δt [s], load (W_x, W_y) [N], speeds (ω_j, ω_b) [rad/s]."""

    phi: float
    dt: float
    load: tuple[float, float]
    speeds: tuple[float, float]


def _broyden(jac: np.ndarray, step: np.ndarray, change: np.ndarray) -> np.ndarray:
    """Broyden's rank-one update of ``jac`` to the secant ``change`` = J ``step``.

    C.G. Broyden, "A class of methods for solving nonlinear simultaneous equations",
    Math. Comp. 19 (1965) 577–593."""
    length = float(step @ step)
    if length == 0.0:
        return jac
    return jac + np.outer(change - jac @ step, step) / length
