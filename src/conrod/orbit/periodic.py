"""Repeat cycles from the concentric start until the orbit is periodic.

Periodicity error of cycle k: max over the output angles of |e_k(φ) − e_{k−1}(φ)|/c [-].
The orbit is periodic when it is at most ``[solver] periodicity_tolerance``; if it is not
after ``max_cycles``, the result says so (``periodic = False`` plus a warning) instead of
returning silently.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from conrod import registry
from conrod.orbit.integrators import Integrator
from conrod.orbit.problem import OrbitProblem, OrbitState, initial_state
from conrod.orbit.trajectory import CycleTrajectory


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
    problem: OrbitProblem, state: OrbitState, settings, integrator: str | Integrator | None = None
) -> CycleTrajectory:
    """One cycle with ``integrator`` (an object, a registered name, or None: the name in
    ``settings``, the ``[solver]`` section)."""
    return _integrator(integrator or settings.integrator).cycle(problem, state, settings)


def _integrator(choice: str | Integrator) -> Integrator:
    return registry.integrator(choice) if isinstance(choice, str) else choice


def cycle_difference(a: CycleTrajectory, b: CycleTrajectory, clearance: float) -> float:
    """max |e_a − e_b|/c at the same output angles [-]."""
    return float(np.max(np.hypot(a.x - b.x, a.y - b.y)) / clearance)


def periodic_orbit(
    problem: OrbitProblem,
    settings,
    *,
    integrator: str | Integrator | None = None,
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
