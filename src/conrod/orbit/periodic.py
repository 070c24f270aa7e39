"""Repeat cycles from the concentric start until the orbit is periodic.

The orbit with mass by the ``implicit`` integrator (also through ``auto``) starts, when
``[solver] massless_start`` is on, from the end of the periodic massless (quasi-static)
orbit instead of the concentric position: the mass changes the orbit little, so it is
periodic within two cycles (passenger car: 3 → 2 cycles; constant load on a Reynolds
film: 5 → 2), and the massless cycles cost a fraction of one with mass. Cycles and
periodicity error are those of the orbit with mass.

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
    chosen = _integrator(integrator or settings.integrator)
    if start is None and getattr(settings, "massless_start", False) and _implicit(chosen,
                                                                                 problem):
        start = _massless_start(problem, settings)
    state = start or initial_state()
    integrator = chosen
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


def _implicit(chosen: Integrator, problem: OrbitProblem) -> bool:
    from conrod.orbit.integrators import AutomaticIntegrator, ImplicitIntegrator

    if isinstance(chosen, AutomaticIntegrator):
        chosen = chosen.choose(problem)
    return isinstance(chosen, ImplicitIntegrator)


def _massless_start(problem: OrbitProblem, settings) -> OrbitState | None:
    """End state of the periodic massless orbit (None, the concentric start, when it
    cannot be computed, e.g. a quasi-static step that does not divide the output step)."""
    from conrod.errors import CaseError, ConvergenceError

    try:
        return periodic_orbit(problem, settings, integrator="quasi_static").last.end_state
    except (CaseError, ConvergenceError):
        return None
