"""The orbit integrators as objects (names in :mod:`conrod.registry`).

Each integrator integrates one cycle, ``cycle(problem, state, settings)`` with the
``[solver]`` section ``settings``, and returns a
:class:`~conrod.orbit.trajectory.CycleTrajectory` whose end state carries the film memory
on to the next cycle. A new integrator is a class with ``name`` and ``cycle`` registered
in :data:`conrod.registry.INTEGRATORS`, or any such object handed to
:class:`~conrod.simulation.simulation.Simulation`.

An integrator also declares what it can run (:func:`declared` reads a declaration with its
default for an integrator that does not make it):

* ``with_mass`` — the journal moves with its mass (False: the massless orbit whose
  velocity balances the load) [default True];
* ``fixed_step`` — it advances a film memory that evolves in lock-step with a fixed step
  (a film content, the bore of an elastic film without the exact response) [False];
* ``journal_step`` — it solves a film's own unknowns together with the journal
  (:class:`~conrod.film.capabilities.HasStepSystem`: the implicit steps of
  :mod:`conrod.orbit.implicit_step`, or the massless balance of the film and its bore)
  [False];
* ``massless_start`` — with ``[solver] massless_start`` it starts from the periodic
  massless orbit (:mod:`conrod.orbit.periodic`) [False].

An integrator may also offer ``lead_in(problem, state, settings)``: the last
``[solver] lead_in`` share of a cycle from the concentric ``state``, ending at φ = 0, or
None where it has none for ``problem`` (:mod:`conrod.orbit.periodic`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

from conrod.errors import CaseError
from conrod.orbit.implicit_step import (
    implicit_step_cycle,
    implicit_step_deg,
    needs_journal_step,
    steps_implicitly,
)
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.trajectory import CycleTrajectory

DECLARATION_DEFAULTS = {"with_mass": True, "fixed_step": False, "journal_step": False,
                        "massless_start": False}
"""What an integrator that does not declare it is taken to do (module docstring)."""


@runtime_checkable
class Integrator(Protocol):
    """One cycle of the journal-centre orbit."""

    name: str

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle from ``state`` at φ = 0."""
        ...


def declared(integrator: Any, declaration: str) -> bool:
    """The integrator's ``declaration`` (module docstring), its default when it makes
    none [-]."""
    return bool(getattr(integrator, declaration, DECLARATION_DEFAULTS[declaration]))


def resolved(integrator: Any, problem: OrbitProblem) -> Any:
    """The integrator that runs ``problem``: the one an automatic integrator chooses
    (``choose(problem)``), else ``integrator`` itself."""
    choose = getattr(integrator, "choose", None)
    return choose(problem) if choose is not None else integrator


class _FixedStepLeadIn:
    """The lead-in of an integrator that runs an elastic bore by the fixed implicit steps
    (:func:`_fixed_step_lead_in`)."""

    def lead_in(self, problem: OrbitProblem, state: OrbitState,
                settings: Any) -> CycleTrajectory | None:
        """The last ``[solver] lead_in`` share of a cycle, or None (module docstring)."""
        return _fixed_step_lead_in(problem, state, settings)


@dataclass(frozen=True)
class AdaptiveIntegrator(_FixedStepLeadIn):
    """Implicit, error-controlled (SciPy Radau/BDF/LSODA) with contact phases."""

    name: str = "adaptive"
    with_mass: bool = True
    fixed_step: bool = False
    journal_step: bool = True

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle; a film whose own unknowns are solved with the journal's step (the
        elastic bore) runs the fixed implicit steps of :mod:`conrod.orbit.implicit_step`
        (steps ≤ ``max_step_deg``); refuses another film whose content evolves in lock-step
        with a fixed step."""
        from conrod.orbit.adaptive import adaptive_cycle

        if needs_journal_step(problem.film) or problem.tilt is not None:
            return _fixed_step_cycle(problem, state, settings)
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
    fixed_step: bool = True
    journal_step: bool = True

    def choose(self, problem: OrbitProblem) -> Integrator:
        """The integrator used for ``problem``."""
        if problem.has_film_content and not steps_implicitly(problem):
            return QuasiStaticIntegrator()
        return ImplicitIntegrator()

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle with :meth:`choose`."""
        return self.choose(problem).cycle(problem, state, settings)

    def lead_in(self, problem: OrbitProblem, state: OrbitState,
                settings: Any) -> CycleTrajectory | None:
        """The lead-in of :meth:`choose`'s integrator, if it has one."""
        chosen = getattr(self.choose(problem), "lead_in", None)
        return None if chosen is None else chosen(problem, state, settings)


@dataclass(frozen=True)
class ImplicitIntegrator(_FixedStepLeadIn):
    """TR-BDF2 (L-stable, second order, error-controlled, steps ≤ ``max_step_deg``) with
    contact phases; compiled with the film force for films with a compiled kernel."""

    name: str = "implicit"
    with_mass: bool = True
    fixed_step: bool = False
    journal_step: bool = True
    massless_start: bool = True

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle; a film with a transported content that steps it implicitly
        (mass-conserving) or whose own unknowns are solved with the journal's step (the
        elastic bore) runs the fixed BDF2 steps of :mod:`conrod.orbit.implicit_step` with
        mass at the largest step ≤ ``max_step_deg`` that divides ``output_step_deg``."""
        from conrod.orbit.implicit import implicit_cycle
        from conrod.orbit.tilt_flight import applies, tilt_flight_cycle

        if applies(problem):  # a tilted journal on the rigid Reynolds film: compiled
            return tilt_flight_cycle(problem, state, settings)
        if steps_implicitly(problem):
            return _fixed_step_cycle(problem, state, settings)
        return implicit_cycle(problem, state, settings)


@dataclass(frozen=True)
class HeunIntegrator:
    """Second-order Runge–Kutta (Heun) at the fixed step ``[solver] step_deg``."""

    name: str = "rk2"
    with_mass: bool = True
    fixed_step: bool = True
    journal_step: bool = False

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle of fixed-step Heun integration (an aligned journal only)."""
        from conrod.orbit.rk2 import rk2_cycle

        if problem.tilt is not None:
            raise CaseError("solver.integrator = 'rk2' with [misalignment]: the explicit "
                            "steps do not carry the journal's tilt (allowed: auto, implicit, "
                            "adaptive, quasi_static)")

        return rk2_cycle(problem, state, settings.step_deg, settings.output_step_deg,
                         settings)


@dataclass(frozen=True)
class QuasiStaticIntegrator:
    """Massless orbit (film force balances the load), Heun at
    ``[solver] quasi_static_step_deg``."""

    name: str = "quasi_static"
    with_mass: bool = False
    fixed_step: bool = True
    journal_step: bool = True

    def cycle(self, problem: OrbitProblem, state: OrbitState, settings: Any) -> CycleTrajectory:
        """One cycle of the massless orbit; a tilted journal takes the implicit steps of
        :mod:`conrod.orbit.tilt_steps` without mass or inertia."""
        from conrod.orbit.quasi_static import quasi_static_cycle

        if problem.tilt is not None:
            return implicit_step_cycle(problem, state, settings.quasi_static_step_deg,
                                       settings.output_step_deg, with_mass=False)

        return quasi_static_cycle(problem, state, settings.quasi_static_step_deg,
                                  settings.output_step_deg)


def _fixed_step_cycle(problem: OrbitProblem, state: OrbitState,
                      settings: Any) -> CycleTrajectory:
    """One cycle with mass by :func:`conrod.orbit.implicit_step.implicit_step_cycle` at the
    largest step ≤ ``max_step_deg`` that divides ``output_step_deg``."""
    return implicit_step_cycle(problem, state, implicit_step_deg(settings),
                               settings.output_step_deg, with_mass=True)


def _fixed_step_lead_in(problem: OrbitProblem, state: OrbitState,
                        settings: Any) -> CycleTrajectory | None:
    """The last ``[solver] lead_in`` share of a cycle by the fixed implicit steps with mass
    where the film's own unknowns are solved only with the journal's step (the elastic
    Reynolds bore, whose deformation follows the journal from any start); None for another
    film or a lead-in of 0."""
    share = getattr(settings, "lead_in", 0.0)
    if share <= 0.0 or not needs_journal_step(problem.film):
        return None
    return implicit_step_cycle(problem, state, implicit_step_deg(settings),
                               settings.output_step_deg, with_mass=True, lead_in=share)
