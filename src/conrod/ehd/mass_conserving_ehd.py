"""The mass-conserving (JFO) film on a deforming bore, stepped implicitly in its content.

The rigid mass-conserving orbit advances the film content ϑh by implicit steps
(:mod:`conrod.film.mass_conserving.step`, Ausas, Jai & Buscaglia 2009): BDF2 or backward
Euler in ϑh, which has an answer for any journal motion. On a deforming bore the same step
holds the whole film thickness of the end of the step, h = h_rigid(e) + u, and the content
of the step before on its own deformed film, so

.. math:: 12μΔxΔz\\,\\frac{(ϑh)^{n+1} − (ϑh)^n}{Δt}

contains the bore's rate ∂u/∂t exactly as the discrete content balance needs it: oil
squeezed by the bore is conserved like oil squeezed by the journal. At the end of each step
the bore deformation solves G(u) = u − λP(C f(p(u)) + U c(φ)) = 0 with the pressure of that
step, by semismooth Newton steps with the step's exact response on its cavitation set
(:mod:`conrod.film.mass_conserving.response`, :func:`conrod.ehd.coupling.\
semismooth_coupling`; :func:`~conrod.ehd.coupling.secant_coupling` where the answer sits
on a switch of that set), warm-started from the trial before and, at a new step, from the
deformation extrapolated at its last rate; the crank angle φ of the step's end is the
start's plus ω Δt. A trial of the step without a coupled answer (the film closes, the
iteration does not settle) returns a NaN force, which the orbit's Newton iteration
rejects and which makes it halve the step; NaN never reaches a result.

:class:`ElasticMassConservingFilm` declares
:class:`~conrod.film.capabilities.HasContentStep`, so the orbit integrators take it through
the implicit steps of films with a content (:mod:`conrod.orbit.implicit_step`) as they take
the rigid film, and the stiff-housing limit is the rigid orbit of the same integrator. It
also declares :class:`~conrod.film.capabilities.HasStepSystem`: the orbit then hands it the
whole step, journal velocity and bore deformation in one Newton iteration
(:func:`conrod.ehd.bore_system.content_step_system`). Between steps (the per-angle
characteristics) the rows are the accepted content steps
(:class:`~conrod.film.capabilities.HasAcceptedAnswer`); an instantaneous JFO solve elsewhere
sees the bore's rate in its squeeze term (the base film ``with_deformation_rate()``).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from conrod.ehd.bore_system import BoreSystem, bore_force_weights, bore_loads, content_step_system
from conrod.ehd.coupling import CouplingOutcome, secant_coupling, semismooth_coupling
from conrod.ehd.film import ElasticFilm, ElasticMemory, ElasticSettings
from conrod.ehd.memory import content_bdf2, start_deformation
from conrod.errors import ConvergenceError
from conrod.film.base import FilmResult, FilmState
from conrod.film.capabilities import HasContentStep, HasThicknessResponse, solve_film
from conrod.film.rated_state import rated
from conrod.film.step_system import StepRequest
from conrod.numerics.newton import ChordJacobian

SEMISMOOTH_SOLVES = 8
"""Film solves of the semismooth Newton iteration before the secant one takes over [-]."""

DIFFERENCE_STEP: float | None = 1e-8
"""Forward-difference step of the coupling's Jacobian, share of the clearance [-] (the
content step's own noise is far below: measured quadratic Newton convergence)."""


class ElasticMassConservingFilm(ElasticFilm):
    """:class:`ElasticFilm` around a mass-conserving film, with the implicit content step on
    the deforming bore (module docstring).

    base : MassConservingFilm  The JFO film
        (:class:`~conrod.film.mass_conserving.film.MassConservingFilm`).
    housing : Housing  Compliance and inertia fields at the film nodes.
    crank_speed : float  ω [rad/s].
    settings : ElasticSettings  Coupling controls.
    """

    def __init__(self, base: Any, housing: Any, crank_speed: float,
                 settings: ElasticSettings | None = None):
        super().__init__(base, housing, crank_speed, settings)
        if self.settings.deformation_rate:
            self.base = base.with_deformation_rate()
        self.chords["content"] = ChordJacobian()
        self.chords["secant"] = ChordJacobian()
        self.nodal = bore_force_weights(base, housing)
        self.content_calls = 0
        self.content_solves = 0
        self.content_failures = 0
        self.joint_calls = 0
        self.joint_solves = 0

    def solve_with_memory(self, state: FilmState, memory: ElasticMemory, *,
                          with_pressure: bool = False) -> tuple[FilmResult, ElasticMemory]:
        """The film at ``state`` on the bore deformation of a content step's ``memory``
        (one instantaneous solve with the film fraction of that step and the bore's rate
        over it in the squeeze term; the coupling was solved by the step), else
        :meth:`ElasticFilm.solve_with_memory`."""
        if memory.inner is None or memory.inner.thickness is None or memory.reference is None:
            return super().solve_with_memory(state, memory, with_pressure=with_pressure)
        rate = (self.film_field((memory.deformation - memory.reference) / memory.reference_dt)
                if self.settings.deformation_rate else None)
        deformed = rated(state, self.film_field(memory.deformation), rate)
        result, inner = solve_film(self.base, deformed, memory.inner, with_pressure=True)
        result = dataclasses.replace(result, pressure=result.pressure if with_pressure
                                     else None, extra=dict(result.extra))
        result.extra.update(_coupling_diagnostics(memory))
        return result, dataclasses.replace(memory, inner=inner)

    def accepted_result(self, state: FilmState, memory: ElasticMemory, *,
                        with_pressure: bool = False) -> FilmResult | None:
        """The answer of the content step that ended at ``state`` with ``memory`` (its
        pressure and film fraction on the bore deformation it solved), with the coupling
        diagnostics; None when ``memory`` is not such an answer
        (:class:`~conrod.film.capabilities.HasAcceptedAnswer`)."""
        if memory.inner is None or memory.inner.thickness is None:
            return None
        deformed = dataclasses.replace(state, deformation=self.film_field(memory.deformation))
        result = self.base.accepted_result(deformed, memory.inner, with_pressure=with_pressure)
        if result is None:
            return None
        result.extra.update(_coupling_diagnostics(memory))
        return result

    def content_step(self, state: FilmState, memory: ElasticMemory, dt: float,
                     warm: ElasticMemory | None = None,
                     previous: ElasticMemory | None = None,
) -> tuple[float, float, ElasticMemory]:
        """Film force (F_x, F_y) [N] at the end of an implicit step ``dt`` [s] on the bore
        deformed by that step's pressure, and the memory at the end of the step.

        state : FilmState  End of the step (journal position and velocity).
        memory : ElasticMemory  Start of the step (film content, deformation, φ).
        warm : ElasticMemory or None  An earlier trial of the same step (start values).
        previous : ElasticMemory or None  One step earlier: BDF2 in the content.
        """
        turned = self.crank_speed * dt
        angle, elapsed = memory.crank_angle + turned, memory.elapsed + turned
        share = self.settings.share(elapsed)
        evaluate = self._content_evaluator(state, memory, dt, warm, previous)
        kinematics = (state.eccentricity_x, state.eccentricity_y, state.velocity_x,
                      state.velocity_y)
        try:
            if not np.all(np.isfinite(kinematics)):
                raise ConvergenceError("no journal state")
            if share == 0.0:
                outcome = _rigid(evaluate, self.housing.node_count)
            else:
                capacity = 1.5 if content_bdf2(memory, previous) else 1.0
                outcome = self._newton(
                    evaluate, start_deformation(memory, warm, previous),
                    share * self.inertia_deformation(angle),
                    share * self.housing.corrected_compliance, dt / capacity)
        except ConvergenceError:  # the film closes or its step fails at this trial
            outcome = None
        if outcome is None or not outcome.converged:  # no coupled answer at this trial
            self.content_failures += 1
            return math.nan, math.nan, dataclasses.replace(memory, residual=math.inf)
        self.content_calls += 1
        self.content_solves += outcome.iterations
        fx, fy, inner = outcome.payload[:3]
        solves = outcome.iterations + (warm.iterations if warm is not None else 0)
        after = ElasticMemory(
            inner=inner, deformation=outcome.deformation, crank_angle=angle, elapsed=elapsed,
            iterations=solves, residual=outcome.residual, increment=outcome.increment,
            deformation_rate=float(np.max(np.abs(outcome.deformation - memory.deformation)))
            / dt, reference=memory.deformation, reference_dt=dt)
        return fx, fy, after

    def supports_step_system(self) -> bool:
        """The content step with the journal velocity and the bore together is always
        available [-]."""
        return True

    def step_system(self, request: StepRequest) -> BoreSystem:
        """The content step with the journal velocity and the bore deformation solved
        together by one Newton iteration with the exact Jacobian
        (:func:`conrod.ehd.bore_system.content_step_system`)."""
        return content_step_system(self, request)

    def _newton(self, evaluate, start, inertia, operator, rate_step) -> CouplingOutcome:
        """G(u) = 0 by semismooth Newton steps with the exact ∂f/∂u of the content step on
        its converged cavitation set (:mod:`conrod.film.mass_conserving.response`);
        where these do not settle within :data:`SEMISMOOTH_SOLVES` film solves (an answer
        on a switch of the set), by the secant iteration with forward-difference Jacobians
        (:func:`conrod.ehd.coupling.secant_coupling`)."""
        def respond(payload):
            state, inner = payload[3], payload[2]
            return self.base.thickness_response(state, inner, self.nodal,
                                                rate_step).nodal_by_bore

        quick = dataclasses.replace(self.coupling, max_iterations=SEMISMOOTH_SOLVES)
        first = semismooth_coupling(evaluate, respond, start, inertia, operator, quick,
                                    self.chords["content"])
        if first.converged:
            return first
        then = secant_coupling(evaluate, respond, first.deformation, inertia, operator,
                               self.coupling, self.chords["secant"],
                               None if DIFFERENCE_STEP is None else DIFFERENCE_STEP
                               * self.base.geometry.radial_clearance)
        return dataclasses.replace(then, iterations=first.iterations + then.iterations)

    def _content_evaluator(self, state: FilmState, memory: ElasticMemory, dt: float,
                           warm: ElasticMemory | None, previous: ElasticMemory | None):
        """u [m] → (nodal forces [N], h_min [m], (F_x, F_y, film memory)) of the content
        step on the bore deformed by u; each solve starts from the last one."""
        before = previous.inner if previous is not None else None
        latest = [warm.inner if warm is not None else None]

        def evaluate(u: np.ndarray):
            deformed = dataclasses.replace(state, deformation=self.film_field(u))
            fx, fy, inner = self.base.content_step(deformed, memory.inner, dt, latest[0],
                                                   before)
            latest[0] = inner
            pressure = self.base.gauge_pressure(inner.pressure, deformed)
            forces = bore_loads(self.nodal, pressure)
            return forces, float(inner.thickness.min()), (fx, fy, inner, deformed, pressure)
        return evaluate


def _rigid(evaluate, nodes: int) -> CouplingOutcome:
    """The content step on the rigid bore (rigid start)."""
    zero = np.zeros(nodes)
    _, _, payload = evaluate(zero)
    return CouplingOutcome(zero, payload, 1, 0.0, 0.0, True)


def elastic_film(base: Any, housing: Any, crank_speed: float,
                 settings: ElasticSettings | None = None,
                 asperity: tuple[float, float, float, float] | None = None) -> ElasticFilm:
    """The film ``base`` on the deforming bore of ``housing``: the implicit content step for
    a film with a content step and its exact response (the isoviscous mass-conserving
    film), :class:`ElasticFilm` otherwise; ``asperity``: the Greenwood–Tripp parameters of
    mixed lubrication (taken on the deformed film by a film with the exact response
    answered by its pressure, the isoviscous Reynolds film, else added by the orbit on the
    rigid shell)."""
    if (isinstance(base, HasContentStep) and isinstance(base, HasThicknessResponse)
            and base.exact_thickness_response()):
        return ElasticMassConservingFilm(base, housing, crank_speed, settings)
    return ElasticFilm(base, housing, crank_speed, settings, asperity)


def _coupling_diagnostics(memory) -> dict[str, float]:
    """The coupling's diagnostics of a solved ``memory`` (ElasticMemory) for
    ``FilmResult.extra`` [-, m, m/s]."""
    return {
        "coupling_iterations": float(memory.iterations),
        "coupling_residual_m": memory.residual,
        "deformation_increment_m": memory.increment,
        "bore_displacement_min_m": float(memory.deformation.min()),
        "bore_displacement_max_m": float(memory.deformation.max()),
        "deformation_rate_m_per_s": memory.deformation_rate}
