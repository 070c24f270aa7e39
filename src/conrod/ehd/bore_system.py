"""The elastic films' step systems: the bore displacement solved with the journal's step.

The bore displacement u [m] at the film nodes solves

.. math:: G(u, v) = u − λP\\big(C f(u, v) + U c(φ)\\big) = 0

(Rodin 2004, eqs. 7–9: compliance C, inertia deformation U c(φ), rigid-body correction P,
ramp share λ), f the nodal loads of the film on the bore deformed by u. :class:`BoreSystem`
is that residual with its exact Jacobian blocks

.. math:: ∂G/∂u = I − λPC\\,∂f/∂u,\\quad ∂G/∂v = −λPC\\,∂f/∂v

and the film force F(u, v) on the journal with ∂F/∂u, ∂F/∂v, from the film's response
(:class:`~conrod.film.capabilities.HasThicknessResponse`), for the Newton iteration of
:mod:`conrod.numerics.newton`: at fixed journal kinematics, for the massless journal's
velocity, and in the implicit step of the journal (:class:`~conrod.film.capabilities.\
HasStepSystem`, :func:`pressure_step_system` for a film answered by its pressure,
:func:`content_step_system` for the mass-conserving film's content step).

The bore nodes are the film rows θ_j of a plane housing, or the film nodes (θ_j, z_k) of a
housing that deforms along the width (:func:`bore_force_weights`); below, j runs over them.

In the implicit step the journal's end position e = e_r + τ v moves h at film row j by
−τ(cos θ_j, sin θ_j)·δv, as a bore displacement u_j = −τ cos θ_j (−τ sin θ_j) does, so the
velocity columns of the step are those of the bore, d/dv = −τ Σ_j (cos θ_j, sin θ_j) ∂/∂u_j
(:func:`journal_columns`): with the bore's rate over τ in the film's answer, the journal's
own squeeze term is already in them (τ ∂/∂e + ∂/∂v = −τ Σ_j (cos θ_j, sin θ_j) D_j, D_j
with its rate term 1/τ); without it, ∂/∂v of the film is added. One sparse LU of the film
gives the whole Jacobian of the step, and each iterate costs one film solve. That solve
starts from the pressure of the step's previous solve (the first from the last step's
answer): the iterates of a step differ far less than the steps, and the warm-started
multigrid takes 8.7 instead of 10.9 cycles a solve on the README job (the elastic run
alone, without companion, grid error or figures, 7.85 → 7.5 s; the answer the same within
the solvers' tolerances: h_min to 1e-12, the journal velocity to 3e-9 of its largest
value).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.ehd.coupling import CouplingOutcome
from conrod.ehd.memory import answer_key, content_bdf2, coupling_extra, start_deformation
from conrod.film.base import FilmState
from conrod.film.rated_state import moved
from conrod.film.step_system import FilmResponse, StepRequest
from conrod.film.tilt import pressure_moments
from conrod.numerics.newton import (
    FORCE_TOLERANCE,
    ChordJacobian,
    NewtonControls,
    NewtonOutcome,
    StepBlocks,
    UpdateLimits,
    solve_step,
)
from conrod.numerics.pairwise import exact_order, weighted_row_sums

STEP_SOLVES = 40
"""Most film steps of the mass-conserving film's step system before the step is left to the
orbit's own iteration [-]."""

STEP_FORCE_TOLERANCE = 1e-6
"""Force balance of the implicit step on the elastic bore: |F + W| ≤ this × (|W| + 1 N) [-]
(0.1 N of a 100 kN load). A residual force of 1e-6 W moves the journal by about 1e-6 W
over the film's stiffness — at least about W/c, as the film carries W within one clearance —
so by at most about 1e-6 c, 1e-3 of the periodicity tolerance; the bore's own residual is
held to :data:`conrod.cases.housing.COUPLING_TOLERANCE` (1e-7 c). The journal's balance of a
rigid film keeps :data:`conrod.numerics.newton.FORCE_TOLERANCE` (1e-8). Loosened alone,
either tolerance saves 2–3 % of the film solves (the other then binds); together 16 %."""

FilmEvaluate = Callable[..., tuple[np.ndarray, np.ndarray, float, Any]]
"""(u [m], v [m/s]) → (nodal loads f [N], film force F [N], h_min [m], payload); with
``inexact``, (u, v, the film solve's relative accuracy [-])."""


@dataclass
class BoreSystem:
    """G(u, v) = u − λP(C f + U c(φ)) and the film force F of a film evaluation.

    film_evaluate : FilmEvaluate  The film on the bore deformed by u.
    film_respond : callable  payload → :class:`~conrod.film.step_system.FilmResponse`.
    operator : ndarray  λ P C [m/N].  inertia : ndarray  λ P U c(φ) [m].
    start : ndarray  Start of u [m].  limits : UpdateLimits  Rodin's Δ safeguard.
    scale : float  Radial clearance c, the scale of u and G [m].
    tolerance : float  max|G| accepted [m].  max_solves : int  Film solves at most [-].
    chord : ChordJacobian  The Jacobian carried from the last iteration of this kind.
    on_finish : callable or None  outcome → the film memory at the end of a step.
    force_tolerance : float  |F + W|/(|W| + 1 N) that ends the iteration [-].
    inexact : bool  ``film_evaluate`` takes the accuracy of its film solve
        (:mod:`conrod.numerics.newton`: inexact Newton).
    """

    film_evaluate: FilmEvaluate
    film_respond: Callable[[Any], FilmResponse]
    operator: np.ndarray
    inertia: np.ndarray
    start: np.ndarray
    limits: UpdateLimits
    scale: float
    tolerance: float = 0.0
    max_solves: int = 0
    chord: ChordJacobian | None = None
    on_finish: Callable[[NewtonOutcome], Any] | None = None
    inexact: bool = False
    force_tolerance: float = FORCE_TOLERANCE

    def evaluate(self, own: np.ndarray, velocity: np.ndarray, *accuracy: float):
        """(G [m], F [N], h_min [m], payload) at the displacement u and velocity v (with
        ``inexact``, the film solved to the relative ``accuracy`` given)."""
        forces, force, h_min, payload = self.film_evaluate(own, velocity, *accuracy)
        return own - self.operator @ forces - self.inertia, force, h_min, payload

    def respond(self, payload: Any) -> StepBlocks:
        """∂G/∂u, ∂G/∂v, ∂F/∂u, ∂F/∂v from the film's response at ``payload``."""
        response = self.film_respond(payload)
        identity = np.eye(len(self.start))
        return StepBlocks(identity - self.operator @ response.nodal_by_bore,
                          -(self.operator @ response.nodal_by_velocity),
                          response.force_by_bore, response.force_by_velocity)

    def finish(self, outcome: NewtonOutcome) -> Any:
        """The film memory at the end of the step of ``outcome``."""
        assert self.on_finish is not None
        return self.on_finish(outcome)


def nodal_force_weights(film, angles: np.ndarray, radius: float) -> np.ndarray:
    """W (n, n_z + 1) with f_j = Σ_k W_jk p(θ_j, z_k): R Δθ_j times the trapezoidal
    weights in z (as :func:`conrod.housing.transfer.nodal_forces`) [m²]."""
    from conrod.housing.transfer import arc_weights

    _, z = film.grid()
    widths = np.zeros(len(z))
    gaps = np.diff(z)
    widths[:-1] += 0.5 * gaps
    widths[1:] += 0.5 * gaps
    return (radius * arc_weights(angles))[:, None] * widths[None, :]


def bore_force_weights(film, housing) -> np.ndarray:
    """The nodal-load weights of the film nodes on the bore nodes of ``housing``: W
    (n_θ, n_z + 1) per film row for a plane housing (:func:`nodal_force_weights`), w
    (n_θ (n_z + 1),) per film node, R Δθ_j w_k, for one over the width [m²]."""
    if housing.uniform_in_z:
        return nodal_force_weights(film, housing.angles, housing.radius)
    from conrod.housing.transfer import node_weights

    _, z = film.grid()
    return node_weights(housing.angles, z, housing.radius).ravel()


def bore_loads(weights: Any, pressure: np.ndarray) -> np.ndarray:
    """Nodal loads [N] of the pressure p (n_θ, n_z + 1) [Pa] with the weights of
    :func:`bore_force_weights`: f_j = Σ_k W_jk p_jk per row, f_jk = w_jk p_jk per node."""
    if weights.ndim == 1:
        return weights * pressure.ravel()
    if exact_order(weights, pressure):  # the same sums in one compiled call
        return weighted_row_sums(weights, pressure)
    return (weights * pressure).sum(axis=1)


def film_node_angles(film) -> np.ndarray:
    """θ [rad] of the bore nodes of the elastic ``film`` from its base film's grid: the film
    rows, repeated over the axial nodes for a housing over the width."""
    theta, z = film.base.grid()
    return theta if film.housing.uniform_in_z else np.repeat(theta, len(z))


def directions(angles: np.ndarray) -> np.ndarray:
    """(cos θ_j, sin θ_j) of the bore nodes (n, 2) [-]."""
    return np.stack([np.cos(angles), np.sin(angles)], axis=1)


def journal_columns(response: FilmResponse, tau: float, trig: np.ndarray,
                    rate_included: bool) -> FilmResponse:
    """The film's response with its velocity columns those of the implicit step,
    −τ Σ_j (cos θ_j, sin θ_j) ∂/∂u_j, plus the film's own ∂/∂v unless the bore's rate over
    τ is in its answer (``rate_included``) (module docstring)."""
    nodal_by_velocity = -tau * response.nodal_by_bore @ trig
    force_by_velocity = -tau * response.force_by_bore @ trig
    if not rate_included:  # the journal's own squeeze term
        nodal_by_velocity = nodal_by_velocity + response.nodal_by_velocity
        force_by_velocity = force_by_velocity + response.force_by_velocity
    return FilmResponse(response.nodal_by_bore, nodal_by_velocity, response.force_by_bore,
                        force_by_velocity)


def tilt_columns(response: FilmResponse, columns: FilmResponse, tau: float, trig: np.ndarray,
                 lever: float, rate_included: bool) -> FilmResponse:
    """The step's response of a journal whose tilt is solved: the journal's columns of
    :func:`journal_columns` and the edge velocities' own (computed by the film as
    directions), and the rows of the moments over ℓ, so that the generalised force is
    (F, M/ℓ) and the velocity (v, ℓγ̇) (:mod:`conrod.orbit.tilt_steps`)."""
    moment_by_bore = response.moment_by_bore / lever
    moment_by_velocity = response.moment_by_velocity / lever
    moment_journal = -tau * moment_by_bore @ trig
    if not rate_included:
        moment_journal = moment_journal + moment_by_velocity[:, :2]
    return FilmResponse(
        response.nodal_by_bore,
        np.hstack([columns.nodal_by_velocity, response.nodal_by_velocity[:, 2:]]),
        np.vstack([response.force_by_bore, moment_by_bore]),
        np.block([[columns.force_by_velocity, response.force_by_velocity[:, 2:]],
                  [moment_journal, moment_by_velocity[:, 2:]]]))


def carried_chord(film, key: str) -> ChordJacobian:
    """The film's carried Jacobian of the iterations of kind ``key``."""
    if key not in film.chords:
        film.chords[key] = ChordJacobian()
    return film.chords[key]


def _state(request: StepRequest, velocity: np.ndarray, deformation=None,
           like: FilmState | None = None) -> FilmState:
    """The film state at the end of the step with the end velocity ``velocity`` (with the
    journal's tilt when the step has one, :class:`~conrod.film.step_system.TiltRequest`);
    without tilt ``like``, a state of the same step, moved there
    (:func:`~conrod.film.rated_state.moved`: its other fields are the step's)."""
    x, y = request.position(velocity)[:2]
    if like is not None and request.tilt is None:
        return moved(like, eccentricity_x=float(x), eccentricity_y=float(y),
                     velocity_x=float(velocity[0]), velocity_y=float(velocity[1]),
                     deformation=deformation)
    tilt = {} if request.tilt is None else dict(zip(
        ("tilt_x", "tilt_y", "tilt_rate_x", "tilt_rate_y"),
        request.tilt.at_end(request, velocity), strict=True))
    return FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                     velocity_x=float(velocity[0]), velocity_y=float(velocity[1]),
                     journal_speed=request.journal_speed, shell_speed=request.shell_speed,
                     viscosity=request.viscosity, deformation=deformation, **tilt)


def pressure_step_system(film, request: StepRequest) -> BoreSystem:
    """The step system of an elastic film answered by its pressure at the end of the step
    (:class:`conrod.ehd.film.ElasticFilm` on the isoviscous Reynolds film): the bore's rate
    in the squeeze term is (u − u_r)/τ with u_r of the step formula (:func:`bore_reference`),
    the start of u extrapolated through the last step points (:func:`bore_start`)."""
    settings, memory = film.settings, request.memory
    at_end = dataclasses.replace(
        memory, crank_angle=request.crank_angle,
        elapsed=memory.elapsed + film.crank_speed * request.dt, clocked=True,
        reference=bore_reference(memory, request.previous, request.bdf2),
        reference_dt=request.tau, iterations=0, updates=0)
    share = settings.share(at_end.elapsed)
    tau, trig = request.tau, directions(film.housing.node_angles)
    rate = tau if settings.deformation_rate else None
    free = len(request.load) == 4  # the tilt solved as two more degrees of freedom
    lever = request.tilt.lever if free else 1.0

    warm = [at_end.inner]  # the film's warm start: the step's last solve (module docstring)
    step_state = (_state(request, request.velocity_reference) if request.tilt is None
                  else None)  # checked once a step

    def evaluate(own: np.ndarray, velocity: np.ndarray, accuracy: float | None = None):
        forces, h_min, payload = film.evaluator(_state(request, velocity, like=step_state),
                                                at_end, accuracy, warm[0])(own)
        warm[0] = payload.memory()
        if not free:
            return forces, payload.force(), h_min, payload
        moments = pressure_moments(payload.load_pressure, film.base.moment_weights)
        return forces, np.concatenate([payload.force(), np.array(moments) / lever]), h_min, \
            payload

    def respond(payload) -> FilmResponse:
        response = film.with_contact_response(  # asperity terms with the bore's
            film.base.thickness_response(payload.state, payload, film.nodal, rate,
                                         (tau, lever) if free else None), payload)
        columns = journal_columns(response, tau, trig, settings.deformation_rate)
        return tilt_columns(response, columns, tau, trig, lever, settings.deformation_rate) \
            if free else columns

    def finish(outcome: NewtonOutcome):
        inner = outcome.payload.memory()
        after = dataclasses.replace(
            at_end, inner=inner, deformation=outcome.own,
            answered=(answer_key(outcome.payload.state), inner.pressure),
            iterations=outcome.solves, updates=outcome.updates, residual=outcome.residual,
            increment=outcome.increment,
            deformation_rate=float(np.abs(outcome.own - memory.deformation).max())
            / request.dt)
        velocity = np.asarray(outcome.velocity, dtype=float)
        return dataclasses.replace(after, acceleration=(velocity - request.velocity_reference)
                                   / tau)

    start = (bore_start(memory, request.previous, request.earlier) if share > 0.0
             else np.zeros_like(memory.deformation))
    travel = -tau * trig
    if free:  # the edges move by τ(sin θ, −cos θ) per unit edge velocity
        travel = np.hstack([travel, tau * np.column_stack([trig[:, 1], -trig[:, 0]])])
    key = ("mass_elastic" if share > 0.0 else "mass_rigid") + ("_tilt" if free else "")
    return BoreSystem(
        evaluate, respond, share * film.housing.corrected_compliance,
        share * film.inertia_deformation(request.crank_angle), start,
        UpdateLimits(settings.increment_share, travel), film.clearance,
        film.coupling.tolerance, 5 * settings.max_iterations, carried_chord(film, key), finish,
        inexact=True, force_tolerance=STEP_FORCE_TOLERANCE)


ANSWERS_HELD = 4096
"""Step answers whose characteristics a film keeps (``film.answers``, by the memory that
holds the answer; cleared when full) [-]: the output rows of a cycle are read three times
(the cycle table, the film fields, the elastic diagnostics), the characteristics computed
once."""


def step_answer(film, state: FilmState, memory, with_pressure: bool):
    """The answer of the implicit step of :func:`pressure_step_system` that ended at
    ``state`` with ``memory``: its converged pressure on the bore deformation it solved
    (``memory.answered``, matched to the journal state and to the pressure array ``inner``
    holds), the characteristics from it and that step's coupling diagnostics; None when
    ``memory`` is not such an answer (the run solves the film again there:
    :class:`~conrod.film.capabilities.HasAcceptedAnswer`)."""
    answered = memory.answered
    if (answered is None or state.journal_feed is not None
            or answered[1] is not getattr(memory.inner, "pressure", None)
            or answered[0] != answer_key(state)):
        return None
    held = film.answers.get(id(memory))
    if held is None or held[0] is not memory:  # the characteristics once per answer
        solved = film.base.answered_evaluation(
            film.deformed(state, memory, memory.deformation), memory.inner)
        if film.contact is not None:  # asperity pressure on the deformed film
            solved = film.contact.attach(solved)
        if len(film.answers) >= ANSWERS_HELD:
            film.answers.clear()
        held = film.answers[id(memory)] = (memory, solved.finish()[0])
    result = dataclasses.replace(held[1], pressure=held[1].pressure if with_pressure else None,
                                 extra=dict(held[1].extra))
    result.extra.update(coupling_extra(memory, memory.deformation, memory.iterations,
                                       memory.residual, memory.increment))
    return result


def newton_coupling(film, memory, evaluate, inertia, operator) -> CouplingOutcome:
    """G(u) = 0 of the elastic ``film`` at fixed kinematics (``evaluate``: u → nodal forces,
    h_min, payload) by :func:`conrod.numerics.newton.solve_step` with no journal degree of
    freedom, from ``memory``'s deformation."""
    def fixed(u: np.ndarray, _v: np.ndarray):
        forces, h_min, payload = evaluate(u)
        return forces, np.zeros(0), h_min, payload

    system = BoreSystem(fixed, film.responder(memory), operator, inertia, memory.deformation,
                        UpdateLimits(film.settings.increment_share), film.clearance)
    outcome = solve_step(system, np.zeros(0), np.zeros(0), NewtonControls(
        film.clearance, 1.0, film.coupling.tolerance, film.settings.max_iterations,
        film.chords["coupling"]))
    return CouplingOutcome(outcome.own, outcome.payload, outcome.solves, outcome.residual,
                           outcome.increment, outcome.residual <= film.coupling.tolerance)


def content_step_system(film, request: StepRequest) -> BoreSystem:
    """The step system of the mass-conserving film on the deforming bore
    (:class:`conrod.ehd.mass_conserving_ehd.ElasticMassConservingFilm`): f and F of the
    film's implicit content step on h = c − e_x cos θ − e_y sin θ + u, whose content balance
    holds the bore's rate; the journal velocity enters it only through the end position.
    Each film step starts from the last one of the iteration."""
    memory, previous, dt = request.memory, request.previous, request.dt
    turned = film.crank_speed * dt
    angle, elapsed = memory.crank_angle + turned, memory.elapsed + turned
    share = film.settings.share(elapsed)
    bdf2 = content_bdf2(memory, previous)
    rate_step = dt / (1.5 if bdf2 else 1.0)
    tau, trig = request.tau, directions(film_node_angles(film))
    before = previous.inner if previous is not None else None
    latest = [None]

    def evaluate(own: np.ndarray, velocity: np.ndarray):
        state = _state(request, velocity, film.film_field(own))
        fx, fy, inner = film.base.content_step(state, memory.inner, dt, latest[0], before)
        latest[0] = inner
        forces = bore_loads(film.nodal, film.base.gauge_pressure(inner.pressure, state))
        return forces, np.array([fx, fy]), float(inner.thickness.min()), (state, inner)

    def respond(payload) -> FilmResponse:
        state, inner = payload
        response = film.base.thickness_response(state, inner, film.nodal, rate_step)
        return journal_columns(response, tau, trig, True)

    def finish(outcome: NewtonOutcome):
        film.joint_calls += 1
        film.joint_solves += outcome.solves
        return dataclasses.replace(
            memory, inner=outcome.payload[1], deformation=outcome.own, crank_angle=angle,
            elapsed=elapsed, iterations=outcome.solves, updates=outcome.updates,
            residual=outcome.residual, increment=outcome.increment,
            deformation_rate=float(np.abs(outcome.own - memory.deformation).max()) / dt,
            reference=memory.deformation, reference_dt=dt)

    start = (start_deformation(memory, None, previous) if share > 0.0
             else np.zeros_like(memory.deformation))
    key = f"joint_{'elastic' if share > 0.0 else 'rigid'}_{'bdf2' if bdf2 else 'euler'}"
    return BoreSystem(
        evaluate, respond, share * film.housing.corrected_compliance,
        share * film.inertia_deformation(angle), start,
        UpdateLimits(film.settings.increment_share, -tau * trig), film.clearance,
        film.coupling.tolerance, STEP_SOLVES, carried_chord(film, key), finish,
        force_tolerance=STEP_FORCE_TOLERANCE)


def bore_reference(memory, previous, bdf2: bool) -> np.ndarray:
    """u_r of the bore rate (u − u_r)/τ: u_n (backward Euler) or (4u_n − u_{n−1})/3 [m]."""
    if not bdf2 or previous is None:
        return memory.deformation
    return (4.0 * memory.deformation - previous.deformation) / 3.0


def bore_start(memory, previous, earlier=None) -> np.ndarray:
    """Start value of u at the end of the step: u_n extrapolated linearly, or
    quadratically when ``earlier`` (two steps back) is given [m]."""
    if previous is None:
        return memory.deformation
    if earlier is not None:
        return 3.0 * (memory.deformation - previous.deformation) + earlier.deformation
    return 2.0 * memory.deformation - previous.deformation
