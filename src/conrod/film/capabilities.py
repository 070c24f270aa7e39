"""Optional capabilities a film model declares on top of :class:`~conrod.film.base.FilmModel`.

Consumers (the orbit integrators, running-in, the elastic housing) ask
``isinstance(film, Capability)`` of these runtime-checkable protocols, never for a concrete
class, and never read a model's internals. A wrapper film (grooved, worn, mixed-lubrication)
declares what its inner model declares by delegating the methods.

* :class:`HasCompiledKernel` — a numba-compiled force (and, optionally, a compiled massless
  orbit cycle) that the fast orbit paths run instead of the Python film interface;
* :class:`SupportsDeformation` — the model honours ``FilmState.deformation``; a model that
  does not must refuse a deformation with :class:`~conrod.errors.CaseError`
  (:func:`refuse_deformation`), never ignore it;
* :class:`SupportsDeformationRate` — a version of the model that also puts the bore's rate
  ``RatedFilmState.deformation_rate`` in its squeeze term;
* :class:`HasMemory` — the answer depends on a memory value the integrator owns;
* :class:`HasContentStep` — an implicit (BDF2 / backward Euler) step of a transported film
  content (mass-conserving film), the orbit's step for films with content;
* :class:`HasMixableContent` — the content as a vector, for the cycle-to-cycle map;
* :class:`HasStepSystem` — unknowns of the film's own (a bore displacement, ...) solved
  together with the journal's implicit step, as a step system with exact Jacobian blocks;
* :class:`HasThicknessResponse` — the exact response of the film's nodal loads and force to
  a change of its film thickness by whole rows (a bore displacement), with its rate;
* :class:`HasPressureEvaluation` — an answer by the pressure alone, the other
  characteristics computed once for the accepted one;
* :class:`HasAcceptedAnswer` — a memory after an implicit step that holds the step's own
  converged answer, which the characteristics at the step's end report;
* :class:`HasForceJacobian` — the film's own ∂F/∂(e, ė) at a state (the implicit orbit
  integrator's Newton matrix);
* :class:`HasTiltJacobian` — the film's own ∂(F, M)/∂(e, γ, ė, γ̇) (a tilted journal);
* :class:`HasSensitivities` — force, stiffness and damping from the film's own solver;
* :class:`HasFlightKernel` — a compiled force and Jacobian with a warm start that the
  implicit orbit integrator runs inside its compiled free flight;
* :class:`HasTiltFlightKernel` — the same for the forces and moments of a tilted journal;
* :class:`CarriesAsperityContact` — the film's force holds the asperity contact;
* :class:`HasDeformedGap` — a deforming bore that says where its deformed film closes;
* :class:`HasViscosityField` — a viscosity field μ(θ, z) on its grid (a thermal film);
* :class:`HasFilmFields` — fields of its own on the film grid at an answer (the bore
  deformation, a film temperature, ...), which the fields over the cycle and the sign-off
  indicators take up by their names.

A memory (:class:`HasMemory`) is owned by the *integrator*: it initialises it, threads it
through every solve, advances it over a step, snapshots it and restores it on a rejected
step. Memory values are immutable: a solve returns a new one and never changes its argument.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any, Protocol, runtime_checkable

import numpy as np

from conrod.errors import CaseError
from conrod.film.base import FilmResult, FilmState
from conrod.film.step_system import FilmResponse, StepRequest, StepSystem

QuasiStaticCycle = Callable[["QuasiStaticRequest"], tuple[np.ndarray, np.ndarray, float]]
"""request → (rows (x, y, v_x, v_y, 0, 0, contact) at the output steps, end state array
starting (x, y, v_x, v_y), worst relative force residual [-])."""


@dataclass(frozen=True)
class QuasiStaticRequest:
    """One massless (quasi-static) orbit cycle asked of a compiled film kernel.

    x, y, vx, vy : float  Start position [m] and velocity [m/s] of the journal centre.
    dt : float  Time step [s].
    load_x, load_y : ndarray  Load W at the n + 1 step points [N].
    journal_speed, shell_speed : ndarray  ω_j, ω_b at the step points [rad/s].
    record_every : int  Steps between recorded rows [-].
    viscosity : float  Dynamic viscosity μ [Pa s].
    contact_radius : float  Radius of the contact circle the centre may not leave [m].
    crank_speed : float  Crank angular velocity ω (velocity scale c ω) [rad/s].
    """

    x: float
    y: float
    vx: float
    vy: float
    dt: float
    load_x: np.ndarray
    load_y: np.ndarray
    journal_speed: np.ndarray
    shell_speed: np.ndarray
    record_every: int
    viscosity: float
    contact_radius: float
    crank_speed: float


@dataclass(frozen=True)
class CompiledKernel:
    """What the compiled orbit loops need from a film.

    force : numba function ``(x, y, v_x, v_y, ω_j + ω_b, μ, params) -> (F_x, F_y)`` [N],
        compiled with ``numba.njit``; the orbit's compiled loops call it directly.
    params : tuple  Constant parameters of ``force`` (floats and arrays, SI units).
    quasi_static_cycle : QuasiStaticCycle or None  The film's own massless Heun cycle
        (e.g. an exact inversion of the force); None: the orbit's generic compiled Newton
        loop on ``force`` is used.
    radial_damping : numba function ``(ε, μ, params) -> B_rr`` [N s/m] or None  Squeeze
        damping for the stability limit of the explicit ``rk2`` loop; None: ``rk2`` runs
        the Python loop.
    """

    force: Any
    params: tuple
    quasi_static_cycle: QuasiStaticCycle | None = None
    radial_damping: Any = None


@runtime_checkable
class HasCompiledKernel(Protocol):
    """A film with a compiled force for the fast orbit paths."""

    def compiled_kernel(self) -> CompiledKernel | None:
        """The kernel, or None when this configuration of the model has none."""
        ...


@runtime_checkable
class SupportsDeformation(Protocol):
    """A film that adds ``FilmState.deformation`` δ(θ, z) [m] to its film thickness."""

    def deformation_shape(self) -> tuple[int, int]:
        """Shape of the δ array it accepts: (len θ, len z) of :meth:`FilmModel.grid`."""
        ...


@runtime_checkable
class HasMemory(Protocol):
    """A film whose answer depends on an explicit memory value owned by the integrator."""

    def initial_memory(self) -> Any:
        """Memory at the start of an orbit (cold warm start, full film, ...)."""
        ...

    def solve_with_memory(
        self, state: FilmState, memory: Any, *, with_pressure: bool = False
) -> tuple[FilmResult, Any]:
        """Result for ``state`` starting from ``memory`` and the memory after the solve."""
        ...

    def force_with_memory(self, state: FilmState, memory: Any) -> tuple[float, float, Any]:
        """Film force (F_x, F_y) [N] starting from ``memory`` and the memory after it."""
        ...

    def advance_memory(self, state: FilmState, memory: Any, dt: float) -> Any:
        """Memory after a time step ``dt`` [s] taken from ``state`` (transport of the film
        content); unchanged for a memory that only holds a warm start."""
        ...


@runtime_checkable
class HasContentStep(Protocol):
    """A film with a transported film content (mass-conserving) that solves its content
    balance implicitly over a time step: the orbit integrators of films with content take
    BDF2 / backward Euler steps through it, which have an answer for any journal motion."""

    def content_step(self, state: FilmState, memory: Any, dt: float, warm: Any = None,
                     previous: Any = None) -> tuple[float, float, Any]:
        """(F_x, F_y) [N] at the end of a step ``dt`` [s] from the content of ``memory``
        (``state``: end of the step, its velocity the journal velocity there), and the
        memory at the end of the step; ``warm``: start values from an earlier trial;
        ``previous``: the memory one step earlier (second-order BDF2 step), None: backward
        Euler."""
        ...


@runtime_checkable
class HasMixableContent(Protocol):
    """A film whose content (the film fraction ϑ on its grid) can be extrapolated between
    cycles with the journal position: the acceleration of the cycle-to-cycle map of the
    orbit carries it in its state."""

    def content_vector(self, memory: Any) -> np.ndarray:
        """The content of ``memory`` as a flat vector (film fraction ϑ [-])."""
        ...

    def with_content(self, memory: Any, vector: np.ndarray) -> Any:
        """``memory`` with the content ``vector`` (clipped to 0 ≤ ϑ ≤ 1)."""
        ...


@runtime_checkable
class HasForceJacobian(Protocol):
    """A film that gives the derivatives of its force with respect to the journal-centre
    state, J = ∂F/∂(e_x, e_y, ė_x, ė_y) (2 × 4: N/m, N s/m), from its own solver (e.g.
    the linearised solve on the converged cavitation set); the implicit orbit integrator
    uses it for its Newton iteration instead of finite differences."""

    def force_jacobian(self, state: FilmState, memory: Any) -> tuple[np.ndarray, np.ndarray,
                                                                        Any]:
        """(F (2,) [N], J (2, 4), memory after the solve) at ``state`` from ``memory``
        (None for a memoryless film)."""
        ...


@runtime_checkable
class HasTiltJacobian(Protocol):
    """A film that gives the derivatives of its force and tilting moments
    Q = (F_x, F_y, M_x, M_y) with respect to the journal's position, tilt and their rates,
    ∂Q/∂(e_x, e_y, γ_x, γ_y, ė_x, ė_y, γ̇_x, γ̇_y) (4 × 8), from its own solver: the
    implicit step of a tilted journal uses it (:mod:`conrod.orbit.tilt_systems`)."""

    def tilt_jacobian(self, state: FilmState, memory: Any) -> tuple[np.ndarray, np.ndarray,
                                                                      Any]:
        """(Q (4,) [N, N m], ∂Q/∂(q, q̇) (4 × 8), memory after the solve) at ``state``."""
        ...


@runtime_checkable
class HasSensitivities(Protocol):
    """A film that linearises itself: force, stiffness K = −∂F/∂e [N/m] and damping
    C = −∂F/∂ė [N s/m] at a state from its own solver (the Reynolds film's solve on its
    converged active set); other films are linearised by central differences of the force
    (:func:`conrod.film.linearised.linearise`)."""

    def sensitivities(self, state: FilmState) -> Any:
        """:class:`~conrod.film.linearised.FilmLinearisation` at ``state``."""
        ...


@runtime_checkable
class HasFlightKernel(Protocol):
    """A film whose force, warm-started, can run inside the compiled implicit free flight
    (:class:`~conrod.film.reynolds.flight.FlightKernel`: compiled force and Jacobian with
    the warm-start field in their parameters)."""

    def flight_kernel(self, memory: Any, newton_tolerance: float) -> Any:
        """The kernel warm-started from ``memory``, force evaluations solved to
        ``newton_tolerance`` [-]; None when this configuration has none."""
        ...


@runtime_checkable
class HasTiltFlightKernel(Protocol):
    """A film whose forces and tilting moments under a tilted journal, warm-started, run
    inside the compiled free flight of a tilted journal (:mod:`conrod.orbit.tilt_flight`)."""

    def tilt_flight_kernel(self, memory: Any, newton_tolerance: float,
                           free: bool = True) -> Any:
        """The kernel warm-started from ``memory`` (``free`` False: a prescribed tilt, the
        Jacobian's tilt columns not needed); None when this configuration has none."""
        ...


@runtime_checkable
class CarriesAsperityContact(Protocol):
    """A film whose force already holds the Greenwood–Tripp asperity contact, taken on its
    own (deformed) film thickness (:class:`conrod.ehd.film.ElasticFilm`)."""

    def carries_asperity(self) -> bool:
        """True when this configuration of the film carries the asperity force [-]."""
        ...


@runtime_checkable
class HasDeformedGap(Protocol):
    """A film on a deforming bore that says where its deformed film closes, so the orbit's
    contact circle is not rigid (:class:`conrod.ehd.film.ElasticFilm`)."""

    def deformed_min_film_thickness(self, position: Any, memory: Any) -> float:
        """h_min on the deformed film with the journal centre at ``position`` [m]."""
        ...

    def open_radius(self, x: float, y: float, memory: Any) -> float:
        """Largest |e| along (x, y) at which the deformed film stays open [m]."""
        ...


@dataclass(frozen=True)
class FilmField:
    """A field a film declares on its grid (:class:`HasFilmFields`).

    values : ndarray  The field at the grid nodes (n_θ, n_z) of :meth:`FilmModel.grid`.
    units : str  Its unit as UDUNITS writes it ('m', 'Pa', 'degC', '1'); a field conrod
        knows by name comes in its unit (``deformation`` m, ``temperature`` degC: the
        ``[limits]`` and the maps read it so).
    long_name : str  What it is, in words.
    """

    values: np.ndarray
    units: str
    long_name: str


@runtime_checkable
class HasFilmFields(Protocol):
    """A film that reports fields of its own on its grid at an answer: the elastic bore's
    deformation δ(θ, z), a thermal film's temperature T(θ, z), ... The fields over the cycle
    (``conrod run --fields``) and the per-cell sign-off indicators take every declared field
    up by its name ('deformation' [m], 'temperature' [degC], ...): a new field plugs in by
    being declared here, nothing else changes."""

    def film_fields(self, state: FilmState, memory: Any) -> dict[str, FilmField]:
        """name → :class:`FilmField` at the answer of ``state`` whose memory after the
        solve is ``memory`` (None for a memoryless film)."""
        ...


@runtime_checkable
class HasStepSystem(Protocol):
    """A film with unknowns of its own (the displacement of a deforming bore; a film
    temperature, ...) that are solved together with the journal's implicit step: for a
    step request it returns the system of its own residual G(y, v) and its force F(y, v)
    on the journal, with the exact Jacobian blocks, which the orbit's one Newton iteration
    solves with the journal's balance (:mod:`conrod.film.step_system`)."""

    def supports_step_system(self) -> bool:
        """True when this configuration of the film can take the step this way."""
        ...

    def step_system(self, request: StepRequest) -> StepSystem:
        """The film's :class:`~conrod.film.step_system.StepSystem` for ``request``."""
        ...


@runtime_checkable
class HasThicknessResponse(Protocol):
    """A film that gives the exact response of its loads to its film thickness at one solve:
    ∂f/∂u and ∂F/∂u of the nodal loads f_j = Σ_k W_jk p_jk and of the force F on the
    journal to a displacement u_j of whole film rows (with the rate u_j/τ_r in its squeeze or
    content term) — or, given per-node weights, of f_jk = w_jk p_jk to a displacement u_jk of
    single film nodes — and ∂/∂v of the journal's own squeeze term
    (:class:`~conrod.film.step_system.FilmResponse`)."""

    def exact_thickness_response(self) -> bool:
        """True when this configuration's response is exact (isoviscous) [-]."""
        ...

    def thickness_response(self, state: FilmState, solved: Any, nodal: np.ndarray,
                           rate_step: float | None) -> FilmResponse:
        """The response at the solve of ``state`` whose answer is ``solved`` (it holds the
        converged pressure, and the film fraction of a content step); ``nodal`` W
        (n_θ, n_z + 1) [m²] per film row, or w (n_θ (n_z + 1),) [m²] per film node
        (row-major); ``rate_step`` τ_r [s] of the film-thickness rate (None: the rate is
        not in the film's answer)."""
        ...


@runtime_checkable
class HasPressureEvaluation(Protocol):
    """A film that answers a state by its pressure alone, warm-started from its memory (the
    other characteristics, friction and flows, computed once, for the accepted answer:
    :class:`~conrod.film.reynolds.response.PressureEvaluation`), or, without a solve, from
    the converged pressure a memory holds (the answer of the step that solved it)."""

    def evaluate_pressure(self, state: FilmState, memory: Any, accuracy: Any = None) -> Any:
        """The evaluation of ``state`` from ``memory`` (None: cold) to ``accuracy`` [-]."""

    def answered_evaluation(self, state: FilmState, memory: Any) -> Any:
        """The evaluation of ``state`` whose converged pressure ``memory`` holds."""


@runtime_checkable
class HasAcceptedAnswer(Protocol):
    """A film whose memory after an implicit step (:class:`HasContentStep`) holds that
    step's converged answer (pressure and film fraction): the characteristics at the end
    of the step are read from it. A new instantaneous solve there would be another problem
    (the film fraction frozen, the squeeze of the velocity instead of the content balance)
    with another pressure."""

    def accepted_result(self, state: FilmState, memory: Any, *,
                        with_pressure: bool = False) -> FilmResult | None:
        """The answer of the step that ended at ``state`` with ``memory``; None when
        ``memory`` is not the answer of a step ending at ``state``."""
        ...


@runtime_checkable
class HasEccentricityRange(Protocol):
    """A film whose values are tabulated up to a largest eccentricity ratio and extrapolated
    beyond it (the table and mobility films): a run whose orbit goes past it says so."""

    eccentricity_max: float
    """Largest tabulated eccentricity ratio [-]."""


@runtime_checkable
class HasViscosityField(Protocol):
    """A film that honours a viscosity field μ(θ, z) [Pa s] on its grid (``FilmState.
    viscosity_field``, or one it carries) in its conductances h³/(12μ) and shear."""

    def with_viscosity_field(self, field: np.ndarray | None) -> Any:
        """The film carrying ``field`` [Pa s] for states without one (None: scalar)."""
        ...

    def film_flows(self, state: FilmState, memory: Any) -> tuple[Any, Any]:
        """(:class:`conrod.film.thermal.flows.FilmFlows` of ``state``, new memory)."""
        ...


@runtime_checkable
class SupportsDeformationRate(Protocol):
    """A film that can put the bore's rate ∂u/∂t
    (``RatedFilmState.deformation_rate``, :mod:`conrod.film.rated_state`) in its squeeze
    term."""

    def with_deformation_rate(self) -> Any:
        """The same film, its squeeze term including the bore's rate."""
        ...


def refuse_deformation(state: FilmState, name: str) -> None:
    """CaseError when ``state`` carries a deformation the film ``name`` cannot honour, or a
    journal tilt (:func:`refuse_tilt`): a film uniform along the width honours neither."""
    refuse_tilt(state, name)
    if state.deformation is not None:
        raise CaseError(
            f"film = {name!r} cannot take a deformation field δ(θ, z) (allowed: a film "
            "model that honours it: 'reynolds' or 'mass_conserving')"
)


def refuse_tilt(state: FilmState, name: str) -> None:
    """CaseError when ``state`` tilts the journal and the film ``name`` cannot honour it
    (the short-bearing closed form and the maps are for an aligned journal)."""
    if state.tilted:
        raise CaseError(
            f"film = {name!r} cannot take a journal tilt (tilt_x = {state.tilt_x:g}, tilt_y = "
            f"{state.tilt_y:g} rad; allowed: a grid film that resolves the width, "
            "'reynolds' or 'mass_conserving')")


def film_memory(film: Any) -> Any:
    """Initial memory of ``film`` (None for a memoryless film)."""
    return film.initial_memory() if isinstance(film, HasMemory) else None


def accepted_film(film: Any, state: FilmState, memory: Any, *, with_pressure: bool = False,
                  answers: bool | None = None) -> tuple[FilmResult, Any]:
    """(result, memory) of the film at a state an integrator accepted with ``memory``: the
    step's own answer when the memory holds it (:class:`HasAcceptedAnswer`; ``answers``,
    if the caller asked once: a Protocol's isinstance costs ~40 µs), else a solve."""
    if isinstance(film, HasAcceptedAnswer) if answers is None else answers:
        result = film.accepted_result(state, memory, with_pressure=with_pressure)
        if result is not None:
            return result, memory
    return solve_film(film, state, memory, with_pressure=with_pressure)


def solve_film(
    film: Any, state: FilmState, memory: Any, *, with_pressure: bool = False
) -> tuple[FilmResult, Any]:
    """(result, new memory) of any film: memoryless films ignore and return ``memory``."""
    if isinstance(film, HasMemory):
        return film.solve_with_memory(state, memory, with_pressure=with_pressure)
    return film.solve(state, with_pressure=with_pressure), memory
