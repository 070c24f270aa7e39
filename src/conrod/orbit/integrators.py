"""The orbit integrators as objects (names in :mod:`conrod.registry`).

Each integrator integrates one cycle, ``cycle(problem, state, settings)`` with the
``[solver]`` section ``settings``, and returns a
:class:`~conrod.orbit.trajectory.CycleTrajectory` whose end state carries the film memory
on to the next cycle. A new integrator is a class with ``name`` and ``cycle`` registered
in :data:`conrod.registry.INTEGRATORS`, or any such object handed to
:class:`~conrod.simulation.simulation.Simulation`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

from conrod.errors import CaseError
from conrod.film.capabilities import HasContentStep
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.trajectory import CycleTrajectory


@runtime_checkable
class Integrator(Protocol):
    """One cycle of the journal-centre orbit."""

    name: str

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle from ``state`` at φ = 0."""
        ...


@dataclass(frozen=True)
class AdaptiveIntegrator:
    """Implicit, error-controlled (SciPy Radau/BDF/LSODA) with contact phases."""

    name: str = "adaptive"

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle; a film on an elastic bore runs the fixed-step orbit with mass of
        :mod:`conrod.orbit.coupled_orbit` (steps ≤ ``max_step_deg``); refuses another film
        whose content evolves in lock-step with a fixed step."""
        from conrod.orbit.adaptive import adaptive_cycle

        if _coupled(problem):
            return _coupled_cycle(problem, state, settings)
        if problem.has_film_content:
            raise CaseError(
                f"solver.integrator = 'adaptive': the {problem.film.name} film carries a "
                "history field that is advanced in lock-step with a fixed step (allowed: rk2, "
                "quasi_static)"
)
        return adaptive_cycle(problem, state, settings, settings.output_step_deg)


@dataclass(frozen=True)
class AutomaticIntegrator:
    """The default: the orbit with mass by ``implicit`` — TR-BDF2 for films without a film
    content, BDF2 steps of the film content for the mass-conserving film, BDF2 steps of the
    journal and the bore together for the film on an elastic bore — and the massless
    ``quasi_static`` orbit for another film whose content is transported in lock-step with
    a fixed step."""

    name: str = "auto"

    def choose(self, problem: OrbitProblem) -> Integrator:
        """The integrator used for ``problem``."""
        if problem.has_film_content and not isinstance(problem.film, HasContentStep) and (
                not _coupled(problem)):
            return QuasiStaticIntegrator()
        return ImplicitIntegrator()

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle with :meth:`choose`."""
        return self.choose(problem).cycle(problem, state, settings)


@dataclass(frozen=True)
class ImplicitIntegrator:
    """TR-BDF2 (L-stable, second order, error-controlled, steps ≤ ``max_step_deg``) with
    contact phases; compiled with the film force for films with a compiled kernel."""

    name: str = "implicit"

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle; a film with a transported content that steps it implicitly
        (mass-conserving) runs the BDF2 orbit with mass of :mod:`conrod.orbit.content_orbit`
        at the largest step ≤ ``max_step_deg`` that divides ``output_step_deg``; so does a
        film on an elastic bore, whose bore deformation is solved with the journal's step
        (:mod:`conrod.orbit.coupled_orbit`)."""
        from conrod.orbit.implicit import implicit_cycle

        if problem.has_film_content and isinstance(problem.film, HasContentStep):
            from conrod.orbit.content_orbit import content_cycle

            output = settings.output_step_deg
            step = output / math.ceil(output / settings.max_step_deg - 1e-9)
            return content_cycle(problem, state, step, output, with_mass=True)
        if _coupled(problem):
            return _coupled_cycle(problem, state, settings)
        return implicit_cycle(problem, state, settings)


@dataclass(frozen=True)
class HeunIntegrator:
    """Second-order Runge–Kutta (Heun) at the fixed step ``[solver] step_deg``."""

    name: str = "rk2"

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle of fixed-step Heun integration."""
        from conrod.orbit.rk2 import rk2_cycle

        return rk2_cycle(problem, state, settings.step_deg, settings.output_step_deg)


@dataclass(frozen=True)
class QuasiStaticIntegrator:
    """Massless orbit (film force balances the load), Heun at
    ``[solver] quasi_static_step_deg``."""

    name: str = "quasi_static"

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle of the massless orbit."""
        from conrod.orbit.quasi_static import quasi_static_cycle

        return quasi_static_cycle(problem, state, settings.quasi_static_step_deg,
                                  settings.output_step_deg)


def _coupled(problem: OrbitProblem) -> bool:
    """The film solves its own unknowns (the elastic bore) with the journal's step."""
    from conrod.orbit.coupled_orbit import coupled_mass_film

    return coupled_mass_film(problem)


def _coupled_cycle(problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
    """One cycle of :func:`conrod.orbit.coupled_orbit.coupled_cycle` at the largest step ≤
    ``max_step_deg`` that divides ``output_step_deg``."""
    from conrod.orbit.coupled_orbit import coupled_cycle, coupled_step_deg

    return coupled_cycle(problem, state, coupled_step_deg(settings), settings.output_step_deg)
