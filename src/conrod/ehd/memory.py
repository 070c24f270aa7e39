"""State and controls of the film on the deforming bore (:class:`conrod.ehd.film.ElasticFilm`):
the memory an orbit carries from step to step (bore deformation, its reference for the rate
in the squeeze term, the coupling diagnostics) and the coupling settings (Rodin 2004: rigid
start, deformation brought in in small shares, increment safeguard)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.cases.housing import COUPLING_TOLERANCE


@dataclass(frozen=True)
class ElasticMemory:
    """Memory of :class:`ElasticFilm` (immutable; arrays never modified in place).

    inner : object  Memory of the wrapped film (None when it has none).
    deformation : ndarray  Corrected bore deformation u of the last solve [m] at the
        housing's bore nodes (n,): the film rows (n_θ) of a plane housing, the film nodes
        (n_θ (n_z + 1), row-major) of one that deforms along the width.
    crank_angle : float  Crank angle φ of the current step [rad].
    elapsed : float  Crank angle turned since the orbit started [rad].
    iterations : int  Film solves of the couplings since the last step [-].
    updates : int  Newton updates of the couplings since the last step (the film solves
        less the start values' solves and the line-search trials) [-].
    residual : float  max|G(u)| of the last coupling [m].
    increment : float  Last deformation increment max|Δu| [m].
    deformation_rate : float  max|u_new − u_old| / dt over the last step [m/s].
    reference : ndarray or None  Bore deformation at the previous crank angle [m]: the
        deformation rate of the squeeze term is (u − reference) / reference_dt.
    reference_dt : float  Time from that angle to the current one [s].
    clocked : bool  The crank angle comes with every force balance (massless orbit);
        False: it is advanced by ω dt in :meth:`ElasticFilm.advance_memory`.
    acceleration : ndarray or None  Journal acceleration (2,) at the end of an implicit step
        of the orbit with mass [m/s²]
        (:func:`conrod.ehd.bore_system.pressure_step_system`); None otherwise.
    answered : tuple or None  (:func:`answer_key` of the journal state, the pressure array)
        when ``inner`` holds the converged pressure of that state on ``deformation`` (the
        end of such a step); None otherwise. The pressure is ``inner``'s own array, so a
        memory whose inner answer another solve replaced no longer matches.
    """

    inner: Any
    deformation: np.ndarray
    crank_angle: float
    elapsed: float = 0.0
    iterations: int = 0
    updates: int = 0
    residual: float = 0.0
    increment: float = 0.0
    deformation_rate: float = 0.0
    step_start: np.ndarray | None = None
    reference: np.ndarray | None = None
    reference_dt: float = 0.0
    clocked: bool = False
    acceleration: np.ndarray | None = None
    answered: tuple | None = None


def coupling_extra(memory: ElasticMemory, u: np.ndarray, iterations: int, residual: float,
                   increment: float) -> dict[str, float]:
    """The coupling diagnostics of a result in ``FilmResult.extra`` (bore deformation u [m],
    film solves, residual [m], last increment [m])."""
    return {"coupling_iterations": float(iterations), "coupling_residual_m": residual,
            "deformation_increment_m": increment, "bore_displacement_min_m": float(u.min()),
            "bore_displacement_max_m": float(u.max()),
            "deformation_rate_m_per_s": memory.deformation_rate}


def answer_key(state: Any) -> tuple[float, ...]:
    """The journal's part of a film state (position, velocity, speeds, viscosity, tilt):
    what :attr:`ElasticMemory.answered` is matched on [SI]."""
    return (state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed, state.shell_speed, state.viscosity, state.tilt_x,
            state.tilt_y, state.tilt_rate_x, state.tilt_rate_y)


@dataclass(frozen=True)
class ElasticSettings:
    """Coupling controls of :class:`ElasticFilm`.

    tolerance : float  max|G(u)| accepted, relative to the radial clearance [-]
        (:data:`conrod.cases.housing.COUPLING_TOLERANCE`, the case's default).
    rigid_start : float  Crank angle turned with a rigid bore from the orbit start [rad]
        (Rodin 2004: 10–40°).
    cycle : float  Crank angle of one cycle [rad].
    method : 'quasi_newton' (default) or 'fixed_point': the under-relaxed fixed point
        u ← u − ω G(u), slow, kept as the reference of the tests (fixed kinematics only).
    relaxation : float  ω of the fixed point [-].
    deformation_rate : bool  Put the bore's rate ∂u/∂t in the squeeze term
        (:mod:`conrod.film.rated_state`; Reynolds film only).
    ramp : float  Crank angle over which the deformation is then brought in linearly [rad]
        (a deformation switched on at once may close the gap at the journal's current
        position, for which no film solution exists).
    increment_share : float  Largest deformation increment per update, share of h_min [-].
    max_iterations : int  Film solves per coupling before ConvergenceError [-].
    start_angle : float  Crank angle of the orbit start [rad].
    """

    tolerance: float = COUPLING_TOLERANCE
    rigid_start: float = np.radians(20.0)
    increment_share: float = 0.5
    max_iterations: int = 40
    start_angle: float = 0.0
    ramp: float = np.radians(90.0)
    cycle: float = 4.0 * np.pi
    deformation_rate: bool = True
    method: str = "quasi_newton"
    relaxation: float = 0.2

    def share(self, elapsed: float) -> float:
        """Share λ ∈ [0, 1] of the deformation applied after turning ``elapsed`` [rad]:
        0 over the rigid start, then rising linearly over ``ramp`` (Rodin's multiplier
        that adds the deformation "in small shares") [-]."""
        if elapsed < self.rigid_start:
            return 0.0
        if self.ramp <= 0.0:
            return 1.0
        return float(min((elapsed - self.rigid_start) / self.ramp, 1.0))


def start_deformation(memory: ElasticMemory, warm: ElasticMemory | None,
                      previous: ElasticMemory | None) -> np.ndarray:
    """Start of the coupling: the trial before in the same step, else the deformation
    moved on at its last rate (equal steps under BDF2), else the last deformation [m]."""
    if warm is not None:
        return warm.deformation
    if previous is not None:
        return 2.0 * memory.deformation - previous.deformation
    return memory.deformation


def content_bdf2(memory: ElasticMemory, previous: ElasticMemory | None) -> bool:
    """True when the film's content step is BDF2 (both contents carry their thickness)."""
    return (previous is not None and memory.inner.thickness is not None
            and previous.inner.thickness is not None)


def extrapolated_deformation(before: ElasticMemory, after: ElasticMemory) -> np.ndarray:
    """Start of the coupling at a new crank angle: the last deformation moved on at its
    last rate, u + (u − u_prev) Δt_new/Δt_prev [m] (the squeeze term holds the rate, so a
    start at the old deformation would begin with no bore rate at all)."""
    moved = after.reference is before.deformation and after is not before
    if not moved or before.reference is None or before.reference_dt <= 0.0:
        return after.deformation
    ratio = after.reference_dt / before.reference_dt
    return before.deformation + ratio * (before.deformation - before.reference)


RATE_REFUSAL = (
    "ElasticSettings deformation_rate = False (the squeeze term without the bore's rate "
    "∂u/∂t, the housing following the pressure quasi-statically as in Rodin 2004): on a "
    "film without a content of its own the bore then moves into the film with no squeeze "
    "resistance where its inertia deformation changes fastest, and the orbit has no force "
    "balance there, with or without the journal's mass (measured on the KamAZ-740 rod at "
    "36 × 8: both orbits stop at 197°) (allowed: deformation_rate = True, the default, the "
    "bore's rate in the squeeze term of the transient Reynolds equation, Hamrock 1994; or "
    "film = 'mass_conserving', whose content step holds the rate)")
"""Why :class:`ElasticFilm` refuses ``ElasticSettings(deformation_rate=False)`` [-]."""
