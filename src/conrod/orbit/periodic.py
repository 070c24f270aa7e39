"""Repeat cycles from the concentric start until the orbit is periodic (SPEC S3).

Periodicity error of cycle k: max over the output angles of |e_k(φ) − e_{k−1}(φ)|/c [-].
The orbit is periodic when it is at most ``[solver] periodicity_tolerance``; if it is not
after ``max_cycles``, the result says so (``periodic = False`` plus a warning) instead of
returning silently.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from conrod.orbit.adaptive import adaptive_cycle
from conrod.orbit.problem import OrbitProblem, OrbitState, initial_state
from conrod.orbit.quasi_static import quasi_static_cycle
from conrod.orbit.rk2 import rk2_cycle
from conrod.orbit.trajectory import CycleTrajectory
from conrod.errors import CaseError


@dataclass
class PeriodicOrbit:
    """The last cycle and how it converged.

    last : CycleTrajectory  Samples of the last cycle.
    previous : CycleTrajectory or None  The cycle before it.
    cycles : int  Cycles integrated [-].
    periodicity_error : float  max |Δe|/c between the last two cycles [-] (inf after one).
    periodic : bool  Error within the tolerance [-].
    history : list  Periodicity error after each cycle [-].
    """

    last: CycleTrajectory
    previous: CycleTrajectory | None
    cycles: int
    periodicity_error: float
    periodic: bool
    history: list[float]


def integrate_cycle(
    problem: OrbitProblem, state: OrbitState, settings, integrator: str | None = None
) -> CycleTrajectory:
    """One cycle with the integrator named in ``settings`` (the ``[solver]`` section)."""
    name = integrator or settings.integrator
    if name == "adaptive" and problem.has_history:
        raise CaseError(
            f"solver.integrator = 'adaptive': the {problem.film.name} film carries a history "
            "field that is advanced in lock-step with a fixed step (allowed: rk2, quasi_static)"
        )
    if name == "rk2":
        return rk2_cycle(problem, state, settings.step_deg, settings.output_step_deg)
    if name == "quasi_static":
        return quasi_static_cycle(
            problem, state, settings.quasi_static_step_deg, settings.output_step_deg
        )
    return adaptive_cycle(problem, state, settings, settings.output_step_deg)


def cycle_difference(a: CycleTrajectory, b: CycleTrajectory, clearance: float) -> float:
    """max |e_a − e_b|/c at the same output angles [-]."""
    return float(np.max(np.hypot(a.x - b.x, a.y - b.y)) / clearance)


def periodic_orbit(
    problem: OrbitProblem,
    settings,
    *,
    integrator: str | None = None,
    start: OrbitState | None = None,
    on_cycle: Callable[[int, float], None] | None = None,
) -> PeriodicOrbit:
    """Integrate cycles from ``start`` (concentric) until periodic or ``max_cycles``."""
    state = start or initial_state()
    previous: CycleTrajectory | None = None
    history: list[float] = []
    error = float("inf")
    for cycle in range(1, settings.max_cycles + 1):
        current = integrate_cycle(problem, state, settings, integrator)
        if previous is not None:
            error = cycle_difference(current, previous, problem.clearance)
        history.append(error)
        if on_cycle is not None:
            on_cycle(cycle, error)
        if cycle >= settings.min_cycles and error <= settings.periodicity_tolerance:
            return PeriodicOrbit(current, previous, cycle, error, True, history)
        previous, state = current, current.end_state
    return PeriodicOrbit(current, previous, settings.max_cycles, error, False, history)
