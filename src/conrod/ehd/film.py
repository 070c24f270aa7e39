"""The elastohydrodynamic film: any deformable film on the bore of an elastic housing.

.. code-block:: python

    film = ElasticFilm(ReynoldsFilm(geometry, 72, 16), Housing.from_case(case),
                       crank_speed=loads.crank_speed)
    Simulation(case, film=film).run()       # the orbit code is unchanged

:class:`ElasticFilm` wraps a film that honours ``FilmState.deformation``
(:class:`~conrod.film.capabilities.SupportsDeformation`: ``reynolds``, ``mass_conserving``)
and, for every state it is asked about, solves the coupling of the film pressure and the
bore deformation (:mod:`conrod.ehd.coupling`) so that the film thickness is
h = h_rigid(e) + P(C f(p) + U c(φ)) (Rodin 2004, eqs. 7–9).

Its memory (:class:`ElasticMemory`) travels in the integrator's state through
:class:`~conrod.film.capabilities.HasMemory`: the inner film's memory, the bore deformation
of the last solve (the warm start of the next), the crank angle φ [rad] that the inertia
deformation needs — advanced by ω dt in :meth:`ElasticFilm.advance_memory`, the one hook
every fixed-step integrator calls after a step — and the coupling diagnostics. Because that
memory evolves in lock-step with a fixed step, :meth:`initial_history` is not None. The
massless orbit (``quasi_static``) passes the exact φ of each state to
:meth:`balance_velocity`; the orbit with mass (``auto``, ``implicit``, ``adaptive``: fixed
BDF2 steps of :mod:`conrod.orbit.implicit_step`) asks :meth:`step_system` for the system of
each step, journal velocity and bore solved together
(:class:`~conrod.film.capabilities.HasStepSystem`, :mod:`conrod.ehd.bore_system`; films
with the exact response, :meth:`supports_step_system`). ``rk2`` is refused for those films
(the bore rate over its short step is too stiff) and runs the others, its predictor and
corrector solves both seeing φ at the start of the step.

Deformation rate. The squeeze term 12 μ ∂h/∂t includes the bore's rate ∂u/∂t, taken
backward in time from the deformation at the previous crank angle
(:mod:`conrod.film.rated_state`: the base film ``with_deformation_rate()``, films without a
transported content of their own). Without it (Rodin 2004) the bore moves into the film with
no squeeze resistance where its inertia deformation changes fastest, and the force balance
on the deformed bore fails there with or without the journal's mass:
``ElasticSettings(deformation_rate=False)`` is refused for such a film
(:data:`conrod.ehd.memory.RATE_REFUSAL`). The largest rate seen
over a step is kept in the memory (``deformation_rate`` [m/s]).

The massless orbit asks :meth:`ElasticFilm.balance_velocity` for the velocity that balances
the load, bore displacement and velocity solved together, passing the crank angle of each
state: by Newton's method (:mod:`conrod.numerics.newton`) with the film's exact response
on its active set for a film answered by its pressure with an exact response
(:class:`~conrod.film.capabilities.HasPressureEvaluation`,
:class:`~conrod.film.capabilities.HasThicknessResponse`: the isoviscous Reynolds film), by
the finite-difference quasi-Newton iteration of :mod:`conrod.ehd.balance` for the other
films.
"""

from __future__ import annotations

import dataclasses
import functools
from typing import Any

import numpy as np

from conrod.ehd.asperity import DeformedAsperity, deformed_min_gap, open_radius
from conrod.ehd.balance import BalanceJacobian, solve_balance
from conrod.ehd.bore_system import (
    BoreSystem,
    bore_force_weights,
    bore_loads,
    newton_coupling,
    pressure_step_system,
    step_answer,
)
from conrod.ehd.coupling import (
    CouplingOutcome,
    CouplingSettings,
    JacobianCache,
    SolvedPayload,
    dominant_directions,
    film_closing,
    fixed_point_coupling,
    solve_coupling,
)
from conrod.ehd.memory import (
    RATE_REFUSAL,
    ElasticMemory,
    ElasticSettings,
    coupling_extra,
    extrapolated_deformation,
)
from conrod.ehd.viscosity_field import film_flows, with_viscosity_field
from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import FilmResult, FilmState
from conrod.film.capabilities import (
    HasPressureEvaluation,
    HasThicknessResponse,
    SupportsDeformation,
    SupportsDeformationRate,
    film_memory,
    solve_film,
)
from conrod.film.rated_state import rated
from conrod.film.step_system import StepRequest
from conrod.film.wrapper import FilmWrapper
from conrod.numerics.newton import ChordJacobian, NewtonControls, UpdateLimits, solve_step

FIELD_METHODS = {"with_viscosity_field": with_viscosity_field, "film_flows": film_flows}
"""HasViscosityField's methods, declared when the base film has them (ehd.viscosity_field)."""


class ElasticFilm(FilmWrapper):
    """Film ``base`` on the deforming bore of ``housing``.

    base : FilmModel  Film honouring ``FilmState.deformation`` on the housing's nodes.
    housing : Housing  Compliance and inertia fields at the film nodes
        (:class:`conrod.housing.housing.Housing`).
    crank_speed : float  Crank angular velocity ω [rad/s] (advances φ by ω dt).
    settings : ElasticSettings  Coupling controls.
    asperity : tuple or None  Greenwood–Tripp parameters (R [m], L [m], σ [m], K E' [Pa]) of
        :func:`conrod.contact.asperity.kernel_parameters` (mixed lubrication). With the
        exact film response the asperity pressure is taken on the deformed film, loads the
        bore and is part of the journal force (:mod:`conrod.ehd.asperity`,
        :meth:`carries_asperity`); otherwise the orbit adds the rigid asperity force.
    """

    def __init__(self, base: Any, housing: Any, crank_speed: float,
                 settings: ElasticSettings | None = None,
                 asperity: tuple[float, float, float, float] | None = None):
        if not isinstance(base, SupportsDeformation):
            raise CaseError(f"film = {base.name!r} cannot take the bore deformation of an "
                            "elastic housing (allowed: 'reynolds' or 'mass_conserving')")
        theta, z = base.grid()
        if len(theta) != len(housing.angles) or not np.allclose(theta, housing.angles):
            raise CaseError(f"housing: {len(housing.angles)} bore nodes do not match the "
                            f"film's {len(theta)} θ nodes (allowed: solver.n_theta nodes)")
        own_content = base.initial_history() is not None
        if settings is not None and not settings.deformation_rate and not own_content:
            raise CaseError(RATE_REFUSAL)
        if not housing.uniform_in_z and (len(z) != len(housing.axial)
                                         or not np.allclose(z, housing.axial)):
            raise CaseError(f"housing: the 3-D compliance has {len(housing.axial)} axial "
                            f"nodes, the film {len(z)} (allowed: solver.n_z + 1 nodes)")
        self.base = (base.with_deformation_rate() if isinstance(base, SupportsDeformationRate)
                     and not own_content else base)
        self.housing = housing
        self.crank_speed = float(crank_speed)
        self.settings = settings or ElasticSettings()
        self._z = z
        self._axial_nodes = base.deformation_shape()[1]
        self.coupling = CouplingSettings(
            tolerance=self.settings.tolerance * base.geometry.radial_clearance,
            max_iterations=self.settings.max_iterations,
            increment_share=self.settings.increment_share)
        directions = dominant_directions(housing.corrected_compliance, self.coupling.modes)
        self.jacobian = JacobianCache(directions)
        self.balance_jacobian = BalanceJacobian(directions, housing.node_angles)
        self.rigid_jacobian = BalanceJacobian(directions[:, :0], housing.node_angles)
        self._zero_operator = np.zeros_like(housing.corrected_compliance)
        self.chords = {"balance": ChordJacobian(), "rigid": ChordJacobian(),
                       "coupling": ChordJacobian()}
        self.answers: dict[int, tuple] = {}  # the step answers' characteristics, by memory
        self.exact = (isinstance(self.base, HasPressureEvaluation)
                      and isinstance(self.base, HasThicknessResponse)
                      and self.base.exact_thickness_response()
                      and self.settings.method == "quasi_newton")
        self.nodal = bore_force_weights(self.base, housing) if self.exact else None
        self.contact = (DeformedAsperity.from_parameters(asperity, self.nodal,
                                                         self.base.force_weights)
                        if asperity is not None and self.exact else None)

    def __getattr__(self, name: str) -> Any:
        if name in FIELD_METHODS:  # HasViscosityField exactly when the base film has it
            getattr(self.__dict__.get("base"), name)  # AttributeError: not declared
            return functools.partial(FIELD_METHODS[name], self)
        return super().__getattr__(name)

    @property
    def clearance(self) -> float:
        """Radial clearance c [m]."""
        return self.base.geometry.radial_clearance

    def carries_asperity(self) -> bool:
        """True when the asperity contact is part of this film's force, taken on the
        deformed film (the orbit then adds no rigid asperity force) [-]."""
        return self.contact is not None

    # ----------------------------------------------------------- capabilities
    def initial_history(self) -> np.ndarray:
        """The inner film's history, else the (zero) bore deformation [m]: a memory that
        evolves in lock-step with a fixed step."""
        inner = self.base.initial_history()
        return inner if inner is not None else np.zeros(self.housing.node_count)

    def compiled_kernel(self) -> None:
        """No compiled kernel: the coupling runs in Python around the compiled film."""
        return None

    def initial_memory(self) -> ElasticMemory:
        """Rigid bore, crank angle of the orbit start, the inner film's initial memory."""
        return ElasticMemory(film_memory(self.base), np.zeros(self.housing.node_count),
                             self.settings.start_angle)

    def solve_with_memory(self, state: FilmState, memory: ElasticMemory, *,
                          with_pressure: bool = False) -> tuple[FilmResult, ElasticMemory]:
        """Coupled result for ``state`` from ``memory`` and the memory after it."""
        if state.deformation is not None:
            raise CaseError("elastic film: the bore deformation is computed by the housing; "
                            "a FilmState.deformation cannot be added")
        outcome = self._couple(state, memory)
        result, inner = outcome.payload.finish()
        result = dataclasses.replace(result, pressure=result.pressure if with_pressure
                                     else None, extra=dict(result.extra))
        u = outcome.deformation
        result.extra.update(coupling_extra(memory, u, memory.iterations + outcome.iterations,
                                           outcome.residual, outcome.increment))
        return result, dataclasses.replace(
            memory, inner=inner, deformation=u, iterations=memory.iterations
            + outcome.iterations, residual=outcome.residual, increment=outcome.increment)

    def force_with_memory(self, state: FilmState,
                          memory: ElasticMemory) -> tuple[float, float, ElasticMemory]:
        """Coupled film force (F_x, F_y) [N] and the memory after it."""
        result, memory = self.solve_with_memory(state, memory)
        return result.force_x, result.force_y, memory

    def advance_memory(self, state: FilmState, memory: ElasticMemory,
                       dt: float) -> ElasticMemory:
        """After a step ``dt`` [s]: φ and the elapsed angle move by ω dt, the inner memory
        is advanced on the deformed film, the step diagnostics restart."""
        inner = memory.inner
        if hasattr(self.base, "advance_memory"):
            deformed = dataclasses.replace(state, deformation=self.film_field(memory.deformation))
            inner = self.base.advance_memory(deformed, inner, dt)
        start = memory.step_start if memory.step_start is not None else memory.deformation
        rate = float(np.max(np.abs(memory.deformation - start))) / dt if dt > 0 else 0.0
        if memory.clocked:
            return dataclasses.replace(memory, inner=inner)
        turned = self.crank_speed * dt
        return dataclasses.replace(
            memory, inner=inner, crank_angle=memory.crank_angle + turned,
            elapsed=memory.elapsed + turned, iterations=0, updates=0, deformation_rate=rate,
            step_start=memory.deformation, reference=memory.deformation, reference_dt=dt)

    def force(self, state: FilmState) -> tuple[float, float]:
        """Coupled film force from the initial memory (rigid start ignored) [N]."""
        fx, fy, _ = self.force_with_memory(state, self._static_memory())
        return fx, fy

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Coupled result from the initial memory (rigid start ignored)."""
        return self.solve_with_memory(state, self._static_memory(),
                                      with_pressure=with_pressure)[0]

    def balance_velocity(self, state: FilmState, load: tuple[float, float],
                         memory: ElasticMemory, crank_angle: float
                         ) -> tuple[float, float, float, ElasticMemory]:
        """Massless journal: velocity (v_x, v_y) [m/s] at which the film on the deformed
        bore balances ``load`` W [N], the relative force residual [-] and the memory after
        it (bore displacement and velocity solved together, :mod:`conrod.ehd.balance`).
        The velocity of ``state`` is the start value; ``crank_angle`` φ [rad] is the time
        of the state (a new φ makes the last deformation the reference of the rate)."""
        before, memory = memory, self._clock(memory, crank_angle)
        share = self.settings.share(memory.elapsed)
        elastic = share > 0.0
        operator = (share * self.housing.corrected_compliance if elastic
                    else self._zero_operator)
        inertia = share * self.inertia_deformation(memory.crank_angle)
        start = (extrapolated_deformation(before, memory) if elastic
                 else np.zeros(self.housing.node_count))
        c = self.clearance
        scale = c * max(self.crank_speed, 1e-3)
        velocity = np.array([state.velocity_x, state.velocity_y])

        def evaluate(u: np.ndarray, v: np.ndarray):
            moving = dataclasses.replace(state, velocity_x=float(v[0]), velocity_y=float(v[1]))
            forces, h_min, payload = self.evaluator(moving, memory)(u)
            return forces, payload.force(), h_min, payload

        if self.exact:
            system = BoreSystem(evaluate, self.responder(memory), operator, inertia, start,
                                UpdateLimits(self.settings.increment_share), c)
            outcome = solve_step(system, velocity, np.asarray(load, dtype=float), NewtonControls(
                c, scale, self.coupling.tolerance, 5 * self.settings.max_iterations,
                self.chords["balance" if elastic else "rigid"]))
        else:
            outcome = solve_balance(
                evaluate, start, velocity, np.asarray(load, dtype=float), inertia, operator,
                self.balance_jacobian if elastic else self.rigid_jacobian, c, scale,
                self.coupling.tolerance, 5 * self.settings.max_iterations,
                self.settings.increment_share)
        if not outcome.converged:
            raise ConvergenceError(
                "elastohydrodynamic force balance did not converge (residual: film force + "
                f"load, N; bore displacement residual {outcome.residual:.3g} m"
                f"{film_closing(outcome.payload, self.carries_asperity())})",
                where=f"crank angle {np.degrees(memory.crank_angle) % 720.0:.1f} deg",
                residual=outcome.force_residual * (float(np.hypot(*load)) + 1.0))
        _, inner = outcome.payload.finish()
        after = dataclasses.replace(
            memory, inner=inner, deformation=outcome.own,
            iterations=memory.iterations + outcome.solves,
            updates=memory.updates + outcome.updates, residual=outcome.residual,
            increment=outcome.increment)
        return (float(outcome.velocity[0]), float(outcome.velocity[1]),
                outcome.force_residual, after)

    # ------------------------------------------------------ journal with mass
    def supports_step_system(self) -> bool:
        """True when the journal's implicit step can take this film's bore with it: the
        exact film response (isoviscous Reynolds film) [-]."""
        return self.exact

    def step_system(self, request: StepRequest) -> BoreSystem:
        """The bore displacement with the journal's implicit step of ``request``
        (:func:`conrod.ehd.bore_system.pressure_step_system`)."""
        return pressure_step_system(self, request)

    # ---------------------------------------------------------------- coupling
    def _static_memory(self) -> ElasticMemory:
        settings = self.settings
        return dataclasses.replace(self.initial_memory(),
                                   elapsed=settings.rigid_start + settings.ramp)

    def film_field(self, deformation: np.ndarray) -> np.ndarray:
        """The bore deformation u [m] at the bore nodes as a field δ(θ, z) on the film grid
        (alike at every z for a plane housing, u(θ_j, z_k) itself over the width) [m]."""
        return self.housing.film_field(deformation, self._axial_nodes)

    def film_fields(self, state: FilmState, memory: ElasticMemory) -> dict:
        """Bore deformation δ(θ, z) [m], the inner film's film fraction and fields
        (:class:`~conrod.film.capabilities.HasFilmFields`, :mod:`conrod.ehd.fields`)."""
        from conrod.ehd.fields import elastic_fields

        return elastic_fields(self, state, memory)

    def inertia_deformation(self, crank_angle: float) -> np.ndarray:
        """Corrected inertia deformation P U c(φ) at φ [rad] [m]; zero without crank
        kinematics (table loads)."""
        if self.housing.kinematics is None:
            return np.zeros(self.housing.node_count)
        return self.housing.inertia_deformation(crank_angle)

    def _clock(self, memory: ElasticMemory, crank_angle: float) -> ElasticMemory:
        """Memory at the time φ [rad]: on a new φ the last deformation becomes the rate's
        reference and the elapsed angle grows."""
        turned = (crank_angle - memory.crank_angle) % self.settings.cycle
        if not memory.clocked:
            return dataclasses.replace(memory, clocked=True, crank_angle=crank_angle)
        if turned < 1e-12 or self.settings.cycle - turned < 1e-12:
            return memory
        dt = turned / self.crank_speed
        rate = float(np.max(np.abs(memory.deformation - memory.reference))) / dt if (
            memory.reference is not None) else 0.0
        return dataclasses.replace(
            memory, crank_angle=crank_angle, elapsed=memory.elapsed + turned, iterations=0,
            updates=0,
            reference=memory.deformation, reference_dt=dt, deformation_rate=rate)

    def evaluator(self, state: FilmState, memory: ElasticMemory, accuracy: float | None = None,
                  start: Any = None):
        """u [m] → (nodal forces [N], h_min [m], payload) of the base film on the bore
        deformed by u, with the rate (u − reference)/dt in the squeeze term, warm-started
        from ``start`` (None: ``memory.inner``); the payload is the film's pressure
        evaluation (exact path) or a :class:`SolvedPayload`. On the exact path ``accuracy``
        (None: the film's tolerance) is the relative accuracy its pressure is solved to
        where looser than its tolerance (inexact Newton, :mod:`conrod.numerics.newton`)."""
        inner = memory.inner if start is None else start

        def evaluate(u: np.ndarray):
            deformed = self.deformed(state, memory, u)
            if self.exact:  # pressure only; the characteristics once, for the answer
                solved = self.base.evaluate_pressure(deformed, inner, accuracy)
                if self.contact is not None:  # asperity pressure on the deformed film
                    solved = self.contact.attach(solved)
                forces = bore_loads(self.nodal, solved.load_pressure)
                return forces, solved.min_film_thickness(), solved
            result, after = solve_film(self.base, deformed, inner, with_pressure=True)
            forces = self.housing.nodal_forces(result.pressure, self._z)
            return forces, result.min_film_thickness, SolvedPayload(result, after)
        return evaluate

    def deformed(self, state: FilmState, memory: ElasticMemory, u: np.ndarray) -> FilmState:
        """``state`` on the bore deformed by u [m], with ``memory``'s rate in the squeeze
        term where the settings have it."""
        reference = memory.reference
        use_rate = self.settings.deformation_rate and reference is not None and (
            memory.reference_dt > 0.0)
        rate = self.film_field((u - reference) / memory.reference_dt) if use_rate else None
        return rated(state, self.film_field(u), rate)

    def accepted_result(self, state: FilmState, memory: ElasticMemory, *,
                        with_pressure: bool = False) -> FilmResult | None:
        """The answer of the implicit step that ended at ``state`` with ``memory``; None
        when ``memory`` is not such an answer (:func:`conrod.ehd.bore_system.step_answer`)."""
        return step_answer(self, state, memory, with_pressure) if self.exact else None

    def responder(self, memory: ElasticMemory):
        """payload of :meth:`evaluator` → the film's exact response there
        (:meth:`~conrod.film.capabilities.HasThicknessResponse.thickness_response`)."""
        use_rate = self.settings.deformation_rate and memory.reference is not None and (
            memory.reference_dt > 0.0)
        step = memory.reference_dt if use_rate else None

        def respond(payload):
            return self.with_contact_response(
                self.base.thickness_response(payload.state, payload, self.nodal, step),
                payload)
        return respond

    def deformed_min_film_thickness(self, position, memory: ElasticMemory) -> float:
        """h_min [m] on the bore deformed by ``memory``, journal at ``position`` (x, y) [m]
        (:func:`conrod.ehd.asperity.deformed_min_gap`; ≤ 0: closed)."""
        return deformed_min_gap(self.housing.node_angles, self.base.geometry.radial_clearance,
                                memory.deformation, position)

    def open_radius(self, x: float, y: float, memory: ElasticMemory) -> float:
        """Largest |e| [m] along the direction of (x, y) [m] at which the film on the bore
        deformed by ``memory`` stays open (:func:`conrod.ehd.asperity.open_radius`):
        the contact circle of the massless orbit on the deformed bore."""
        return open_radius(self.housing.node_angles, self.base.geometry.radial_clearance,
                           memory.deformation, x, y)

    def with_contact_response(self, response, payload):
        """``response`` of the film plus the asperity contact's local terms at ``payload``
        (:meth:`conrod.ehd.asperity.DeformedAsperity.add_response`)."""
        if self.contact is None or payload.contact_slope is None:
            return response
        return self.contact.add_response(response, payload.contact_slope)

    def _couple(self, state: FilmState, memory: ElasticMemory) -> CouplingOutcome:
        evaluate = self.evaluator(state, memory)
        share = self.settings.share(memory.elapsed)
        if share == 0.0:
            result, after = solve_film(self.base, state, memory.inner, with_pressure=True)
            zero = np.zeros(self.housing.node_count)
            return CouplingOutcome(zero, SolvedPayload(result, after), 1, 0.0, 0.0, True)
        inertia = share * self.inertia_deformation(memory.crank_angle)
        operator = share * self.housing.corrected_compliance
        if self.settings.method == "fixed_point":
            outcome = fixed_point_coupling(
                evaluate, memory.deformation, inertia, operator, self.settings.relaxation,
                self.coupling.tolerance, 100 * self.settings.max_iterations)
        elif self.exact:
            outcome = newton_coupling(self, memory, evaluate, inertia, operator)
        else:
            outcome = solve_coupling(evaluate, memory.deformation, inertia, operator,
                                     self.jacobian, self.coupling, self.clearance)
        if not outcome.converged:
            raise ConvergenceError(
                "elastohydrodynamic coupling did not converge (residual: bore displacement, m)",
                where=f"crank angle {np.degrees(memory.crank_angle) % 720.0:.1f} deg",
                residual=outcome.residual)
        return outcome

