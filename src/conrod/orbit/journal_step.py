"""The journal's part of one implicit step, and the one place that solves a step system.

A film with unknowns of its own (:class:`~conrod.film.capabilities.HasStepSystem`) answers
a :class:`~conrod.film.step_system.StepRequest` with its step system: its residual G(y, v)
and its force F(y, v) on the journal with their exact Jacobian blocks. The journal adds its
inertia and the load: with e = e_r + τ v and a = (v − v_r)/τ its balance is

.. math:: F(y, v) − m\\,(v − v_r)/τ\\;(+ A(e)) + W = 0,\\qquad
          ∂/∂v:\\; ∂F/∂v − \\mathrm{diag}(m)/τ

(A the Greenwood–Tripp asperity force on the rigid shell when the film does not carry it,
left out of the Jacobian), and the Newton iteration of :mod:`conrod.numerics.newton` solves
y and v together, the inverse Jacobian carried from step to step with Broyden's updates.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.step_system import StepRequest, StepSystem
from conrod.numerics.newton import (
    FORCE_TOLERANCE,
    NewtonControls,
    NewtonOutcome,
    StepBlocks,
    solve_step,
)


class JournalStep:
    """The film's step system with the journal's inertia (and a rigid asperity force).

    system : StepSystem  The film's part.  request : StepRequest  The step.
    extra_force : callable or None  (x, y) → an additional force on the journal [N], left
        out of the Jacobian.
    """

    def __init__(self, system: StepSystem, request: StepRequest, extra_force=None):
        self.system, self.request, self.extra_force = system, request, extra_force
        self.start, self.limits = system.start, system.limits
        self.mass = np.asarray(request.mass, dtype=float)

    @property
    def inexact(self) -> bool:
        """True when the film's part solves its film to the accuracy asked
        (:mod:`conrod.numerics.newton`)."""
        return bool(getattr(self.system, "inexact", False))

    def evaluate(self, own: np.ndarray, velocity: np.ndarray, *accuracy: float):
        """(G, F − m a (+ A) [N], h_min [m], payload) at y and the end velocity v (and the
        relative accuracy of the film's solve, where the film's part is inexact)."""
        request = self.request
        g, force, h_min, payload = self.system.evaluate(own, velocity, *accuracy)
        force = force - self.mass * (velocity - request.velocity_reference) / request.tau
        if self.extra_force is not None:
            extra = np.asarray(self.extra_force(*request.position(velocity)[:2]))
            force = force + (extra if force.size == 2 else np.pad(extra, (0, force.size - 2)))
        return g, force, h_min, payload

    def respond(self, payload: Any) -> StepBlocks:
        """The film's blocks with −diag(m)/τ on ∂F/∂v."""
        blocks = self.system.respond(payload)
        return dataclasses.replace(blocks, force_by_journal=blocks.force_by_journal
                                   - np.diag(self.mass) / self.request.tau)


@dataclass(frozen=True)
class JournalOutcome:
    """End of a step solved with the film's unknowns: the Newton outcome (end velocity
    [m/s], residuals) and the film memory at the end of the step."""

    newton: NewtonOutcome
    memory: Any

    @property
    def velocity(self) -> np.ndarray:
        """End velocity v (k,) [m/s]."""
        return np.asarray(self.newton.velocity, dtype=float)


def solve_journal_step(film, request: StepRequest, guess: np.ndarray, velocity_scale: float,
                       extra_force=None) -> JournalOutcome | None:
    """The step of ``request`` with ``film``'s own unknowns from the end velocity ``guess``
    [m/s] (scale of the velocity ``velocity_scale`` [m/s]); None where the film closes or
    its solve fails at the start value."""
    try:
        system = film.step_system(request)
        newton = solve_step(JournalStep(system, request, extra_force), guess, request.load,
                            NewtonControls(system.scale, velocity_scale, system.tolerance,
                                           system.max_solves, system.chord,
                                           force_tolerance=getattr(
                                               system, "force_tolerance", FORCE_TOLERANCE)))
    except (CaseError, ConvergenceError):
        return None
    return JournalOutcome(newton, system.finish(newton))
