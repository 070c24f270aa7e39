"""Orbit by fixed implicit steps of the journal together with the film's own unknowns.

One step from φ_n to φ_{n+1} = φ_n + Δφ (Δt = Δφ/ω) solves, for the end velocity v,

.. math:: e^{n+1} = e^n + Δt\\,v,\\qquad
          F(e^{n+1}, v;\\ \\text{film state}) + W(φ_{n+1}) − m\\,\\frac{v − v^n}{Δt} = 0

by backward Euler — the first step of a cycle, after a halved step and after a contact
event — and BDF2 otherwise,

.. math:: e^{n+1} = \\tfrac{4e^n − e^{n−1}}{3} + \\tfrac{2Δt}{3} v^{n+1},\\qquad
          m\\frac{3v^{n+1} − 4v^n + v^{n−1}}{2Δt} = F + W

(both L-stable, BDF2 second order), m the moving mass (0: the massless orbit). Both formulas
write the end position and acceleration through one step τ (Δt, or 2Δt/3) and reference
values fixed by the history, e = e_r + τ v, a = (v − v_r)/τ (:meth:`StepPoint.request`).

The film's state moves with the step in one of two ways, chosen by what the film declares:

* a film with unknowns of its own and no other way to step them
  (:class:`~conrod.film.capabilities.HasStepSystem` without a content step: the elastic
  Reynolds film's bore) returns a step system that the one Newton iteration solves with the
  journal (:mod:`conrod.orbit.journal_step`, :mod:`conrod.orbit.system_steps`);
* a film with a transported content (:class:`~conrod.film.capabilities.HasContentStep`:
  the mass-conserving film) steps its content implicitly; the journal's balance has contact
  circle phases and its own iteration with a bracketed search, and a film that also
  declares a step system (the elastic mass-conserving film's bore) is handed the whole step
  first (:mod:`conrod.orbit.content_steps`).

A step that does not converge is split in halves (backward Euler), down to the strategy's
limit; then the orbit stops with :class:`~conrod.errors.ConvergenceError` naming the crank
angle, the force residual [N] and what to change.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from conrod.film.capabilities import HasContentStep, HasStepSystem
from conrod.film.step_system import StepRequest, TiltRequest
from conrod.orbit.problem import OrbitProblem, OrbitState, step_grid
from conrod.orbit.progress import AngleReports
from conrod.orbit.trajectory import CycleTrajectory


def needs_journal_step(film) -> bool:
    """True when ``film``'s own unknowns are solved only together with the journal's
    implicit step: a step system and no content step of its own to fall back on (the
    elastic Reynolds film with its exact response)."""
    return (isinstance(film, HasStepSystem) and film.supports_step_system()
            and not isinstance(film, HasContentStep))


def steps_implicitly(problem: OrbitProblem) -> bool:
    """True when the orbit with mass of ``problem`` runs by the fixed implicit steps of this
    module: a film content with its implicit step, unknowns solved with the journal's, or a
    tilted journal (:mod:`conrod.orbit.tilt_steps`)."""
    return ((problem.has_film_content and isinstance(problem.film, HasContentStep))
            or needs_journal_step(problem.film) or problem.tilt is not None)


def implicit_step_deg(settings) -> float:
    """The largest step ≤ ``max_step_deg`` that divides ``output_step_deg`` [deg]."""
    output = settings.output_step_deg
    return output / math.ceil(output / settings.max_step_deg - 1e-9)


class StepPoint:
    """The journal at a step point: position [m], velocity [m/s], film memory, and the
    point one step earlier (``before``; None: the next step is backward Euler)."""

    def __init__(self, position, velocity, memory: Any, before: StepPoint | None = None):
        self.position = np.asarray(position, dtype=float)
        self.velocity = np.asarray(velocity, dtype=float)
        self.memory = memory
        self.before = before

    @property
    def x(self) -> float:
        """Position along film x [m]."""
        return self.position[0]

    @property
    def y(self) -> float:
        """Position along film y [m]."""
        return self.position[1]

    def restart(self) -> StepPoint:
        """This point without its history (the next step is backward Euler)."""
        return StepPoint(self.position, self.velocity, self.memory)

    def followed_by(self, position, velocity, memory: Any, keep: bool) -> StepPoint:
        """The next point; it keeps this one (and the one before) when ``keep``: BDF2 needs
        equal steps on the same side of a contact event."""
        behind = None
        if keep:
            older = self.before
            behind = StepPoint(self.position, self.velocity, self.memory,
                               None if older is None else older.restart())
        return StepPoint(position, velocity, memory, behind)

    def end_position(self, v: np.ndarray, dt: float) -> np.ndarray:
        """End position of the step at end velocity ``v`` [m]."""
        b = self.before
        if b is None:
            return self.position + dt * v
        return (dt * v + 2.0 * self.position - 0.5 * b.position) / 1.5

    def end_velocity(self, position: np.ndarray, dt: float) -> np.ndarray:
        """End velocity of the step that ends at ``position`` [m/s]."""
        b = self.before
        if b is None:
            return (position - self.position) / dt
        return (1.5 * position - 2.0 * self.position + 0.5 * b.position) / dt

    def acceleration(self, v: np.ndarray, dt: float) -> np.ndarray:
        """dv/dt at the end of the step [m/s²]."""
        b = self.before
        if b is None:
            return (v - self.velocity) / dt
        return (1.5 * v - 2.0 * self.velocity + 0.5 * b.velocity) / dt

    def predicted_velocity(self, quadratic: bool = False) -> np.ndarray:
        """Start of the iteration for the end velocity [m/s]: extrapolated linearly over two
        equal steps (BDF2) or, when ``quadratic`` and three points are known, through the
        last three; else the velocity at the start."""
        b = self.before
        if b is None:
            return self.velocity.copy()
        if quadratic and b.before is not None:
            return 3.0 * (self.velocity - b.velocity) + b.before.velocity
        return 2.0 * self.velocity - b.velocity

    def request(self, problem: OrbitProblem, phi1: float, dt: float, mass: np.ndarray,
                load: np.ndarray, speeds: tuple[float, float],
                tilt: TiltRequest | None = None) -> StepRequest:
        """The step to φ1 as a film with own unknowns sees it (τ, e_r, v_r of the formula;
        ``tilt`` the journal's tilt at the end of the step, None: aligned)."""
        b = self.before
        if b is None:
            tau, e_ref, v_ref, memories = dt, self.position, self.velocity, (self.memory,)
        else:
            tau = 2.0 * dt / 3.0
            e_ref = (4.0 * self.position - b.position) / 3.0
            v_ref = (4.0 * self.velocity - b.velocity) / 3.0
            memories = (self.memory, b.memory) + (
                (b.before.memory,) if b.before is not None else ())
        return StepRequest(e_ref, v_ref, tau, dt, mass, load, speeds[0], speeds[1],
                           problem.viscosity, phi1, b is not None, memories, tilt)


def implicit_step_cycle(problem: OrbitProblem, state: OrbitState, step_deg: float,
                        output_step_deg: float, *, with_mass: bool,
                        lead_in: float = 0.0) -> CycleTrajectory:
    """One cycle from ``state`` by implicit steps of ``step_deg`` [deg] (BDF2 after a first
    backward Euler step); massless (``with_mass`` False) or with the problem's masses.
    ``lead_in`` > 0: only the last ``lead_in`` share of the cycle (whole output intervals,
    at least one), ending at φ = cycle ≡ 0 — the lead-in of :mod:`conrod.orbit.periodic`."""
    phi, record_every, n_out = step_grid(problem, step_deg, output_step_deg)
    if lead_in > 0.0:
        rows = min(max(round(lead_in * n_out), 1), n_out)
        phi, n_out = phi[(n_out - rows) * record_every:], rows
    steps_of = _strategy(problem)(problem, with_mass)
    memory = state.film_memory if state.film_memory is not None else problem.film.initial_memory()
    point = StepPoint(*_start(steps_of, state), memory)
    contact = steps_of.starts_in_contact(state)
    force = steps_of.start_contact_force(state, memory) if contact else 0.0
    table, memories = np.zeros((n_out, 7)), [None] * n_out
    tilts = np.zeros((n_out, 4)) if problem.tilt is not None else None
    taken, reports = 0, AngleReports()
    for k in range(len(phi) - 1):
        if k % record_every == 0:
            row = k // record_every
            table[row] = (*point.position[:2], *point.velocity[:2], force,
                          problem.dry_friction * force, float(contact))
            memories[row] = point.memory
            if tilts is not None:
                tilts[row] = steps_of.tilt_at(point, phi[k])
        done, count, whole = _advance(steps_of, phi[k], phi[k + 1], point, contact)
        taken += count
        steps_of.check_budget(taken, len(phi) - 1, phi[k + 1])
        point = point.followed_by(done.position, done.velocity, done.memory,
                                  whole and done.in_contact == contact)
        contact, force = done.in_contact, done.contact_force
        reports.reached(phi[k + 1])
    end = OrbitState(float(point.position[0]), float(point.position[1]),
                     float(point.velocity[0]), float(point.velocity[1]), contact, point.memory,
                     None if tilts is None else steps_of.tilt_at(point, phi[-1]))
    trajectory = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, taken)
    trajectory.film_memory = memories
    trajectory.tilt = tilts
    return trajectory


def _start(steps_of, state: OrbitState) -> tuple[tuple, tuple]:
    """(position, velocity) of the journal's degrees of freedom at the start of a cycle:
    (x, y), or with a solved tilt those of the strategy (:mod:`conrod.orbit.tilt_steps`)."""
    start = getattr(steps_of, "start_point", None)
    if start is None:
        return (state.x, state.y), (state.vx, state.vy)
    return start(state)


def _strategy(problem: OrbitProblem):
    """The steps of this film: with a tilted journal the tilt's steps; its content step,
    else its step system."""
    if problem.tilt is not None:
        from conrod.orbit.tilt_steps import TiltSteps

        return TiltSteps
    if isinstance(problem.film, HasContentStep):
        from conrod.orbit.content_steps import ContentSteps

        return ContentSteps
    from conrod.orbit.system_steps import SystemSteps

    return SystemSteps


def _advance(steps_of, phi0: float, phi1: float, start: StepPoint, contact: bool,
             depth: int = 0) -> tuple[Any, int, bool]:
    """Step φ0 → φ1, split in halves (backward Euler) where it does not converge;
    (end of the step, steps taken, True when taken in one piece)."""
    result = steps_of.step(start, phi1, (phi1 - phi0) / steps_of.problem.crank_speed, contact)
    if result is not None and result.converged:
        steps_of.accept(result, phi1)
        return result, 1, True
    if depth >= steps_of.max_halvings:
        raise steps_of.failure(phi1, result, start)
    middle = 0.5 * (phi0 + phi1)
    half, count, _ = _advance(steps_of, phi0, middle, start.restart(), contact, depth + 1)
    second = StepPoint(half.position, half.velocity, half.memory)
    end, more, _ = _advance(steps_of, middle, phi1, second, half.in_contact, depth + 1)
    return end, count + more, False

