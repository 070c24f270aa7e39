"""What a film with unknowns of its own is asked, and answers, at one implicit step of the
journal (:class:`~conrod.film.capabilities.HasStepSystem`), and the film's response to a
change of its film thickness (:class:`~conrod.film.capabilities.HasThicknessResponse`).

The orbit steps the journal by backward Euler or BDF2 over Δt; both write the end position
and the end acceleration through one step τ (Δt for backward Euler, 2Δt/3 for BDF2) and
reference values fixed by the history,

.. math:: e = e_r + τ v,\\qquad a = (v − v_r)/τ,

so the unknowns of a step are the journal's end velocity v (k components) and the film's
own unknowns y (a bore displacement, a film temperature, ...). The film answers a
:class:`StepRequest` with a :class:`StepSystem`: the start of y, its residual G(y, v) and
its force on the journal F(y, v) with their exact Jacobian blocks, the update limits, the
Newton controls of its unknowns and, at the end, the film memory there. The journal's
inertia −m a and the load W are the orbit's (:mod:`conrod.orbit.journal_step`); the one
Newton iteration is :func:`conrod.numerics.newton.solve_step`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from conrod.numerics.newton import ChordJacobian, NewtonOutcome, StepBlocks, UpdateLimits


@dataclass(frozen=True)
class StepRequest:
    """One implicit step of the journal, as a film with own unknowns sees it.

    position_reference : ndarray  e_r (k,): end position e = e_r + τ v [m].
    velocity_reference : ndarray  v_r (k,): end acceleration a = (v − v_r)/τ [m/s].
    tau : float  Step of the formula (Δt backward Euler, 2Δt/3 BDF2) [s].
    dt : float  Time step Δt [s].
    mass : ndarray  Moving mass (k,) [kg] (the orbit adds −m a; given for completeness).
    load : ndarray  Load W on the journal at the end of the step (k,) [N].
    journal_speed, shell_speed : float  ω_j, ω_b at the end of the step [rad/s].
    viscosity : float  Dynamic viscosity μ [Pa s].
    crank_angle : float  Crank angle φ at the end of the step [rad].
    bdf2 : bool  Second-order step (the previous memory holds the point before) [-].
    memories : tuple  Film memories at the last step points, newest first: the start of the
        step, then (BDF2) one and, when known, two steps earlier.
    tilt : TiltRequest or None  The journal's tilt at the end of the step (prescribed, or
        the journal's degrees of freedom 3 and 4); None: aligned.
    """

    position_reference: np.ndarray
    velocity_reference: np.ndarray
    tau: float
    dt: float
    mass: np.ndarray
    load: np.ndarray
    journal_speed: float
    shell_speed: float
    viscosity: float
    crank_angle: float
    bdf2: bool
    memories: tuple
    tilt: TiltRequest | None = None

    @property
    def memory(self) -> Any:
        """Film memory at the start of the step."""
        return self.memories[0]

    @property
    def previous(self) -> Any:
        """Film memory one step earlier (BDF2), else None."""
        return self.memories[1] if len(self.memories) > 1 else None

    @property
    def earlier(self) -> Any:
        """Film memory two steps earlier, else None."""
        return self.memories[2] if len(self.memories) > 2 else None

    def position(self, velocity: np.ndarray) -> np.ndarray:
        """End position e_r + τ v [m] at the end velocity ``velocity`` [m/s]."""
        return self.position_reference + self.tau * velocity


@dataclass(frozen=True)
class TiltRequest:
    """The journal's tilt in a step (:mod:`conrod.film.tilt`).

    lever : float  ℓ = L/2 [m]: the journal's tilt degrees of freedom are ℓγ [m] and ℓγ̇
        [m/s], their generalised forces M/ℓ [N] and inertias J/ℓ² [kg].
    prescribed : tuple or None  (γ_x, γ_y [rad], γ̇_x, γ̇_y [rad/s]) at the end of the step;
        None: free, the journal's degrees of freedom 3 and 4.
    """

    lever: float
    prescribed: tuple[float, float, float, float] | None = None

    def at_end(self, request: StepRequest, velocity: np.ndarray
               ) -> tuple[float, float, float, float]:
        """(γ_x, γ_y, γ̇_x, γ̇_y) at the end of ``request`` with the end velocity ``velocity``
        [rad, rad/s]."""
        if self.prescribed is not None:
            return self.prescribed
        position = request.position(velocity)
        lever = self.lever
        return (float(position[2]) / lever, float(position[3]) / lever,
                float(velocity[2]) / lever, float(velocity[3]) / lever)


class StepSystem(Protocol):
    """A film's part of one implicit step (module docstring).

    start : ndarray  Start of the film's own unknowns y (n,).
    limits : UpdateLimits  How far one Newton update may move the film thickness.
    scale : float  Scale of y and G (the radial clearance for a bore) [unit of y].
    tolerance : float  max|G| accepted [unit of y].
    max_solves : int  Film evaluations before the iteration gives up [-].
    chord : ChordJacobian  The Jacobian carried from the film's last step of this kind.
    """

    start: np.ndarray
    limits: UpdateLimits
    scale: float
    tolerance: float
    max_solves: int
    chord: ChordJacobian

    def evaluate(self, own: np.ndarray, velocity: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, float, Any]:
        """(G (n,), film force F on the journal (k,) [N], h_min [m], payload) at y and the
        end velocity v [m/s] (end position e_r + τ v)."""
        ...

    def respond(self, payload: Any) -> StepBlocks:
        """∂G/∂y, ∂G/∂v, ∂F/∂y, ∂F/∂v at the evaluation of ``payload``."""
        ...

    def finish(self, outcome: NewtonOutcome) -> Any:
        """The film memory at the end of the step of ``outcome``."""
        ...


@dataclass(frozen=True)
class FilmResponse:
    """Response of a film's loads to its film thickness, at one solve.

    A bore displacement u_j raises the film thickness by u_j on the whole film row j (every
    axial node) and, with a rate step τ_r, its rate by u_j/τ_r; a journal velocity v changes
    the film-thickness rate by −(v_x cos θ + v_y sin θ).

    nodal_by_bore : ndarray  ∂f/∂u (n × n) of the nodal loads f_j = Σ_k W_jk p_jk [N/m].
    nodal_by_velocity : ndarray  ∂f/∂v (n × 2) of the journal's squeeze term [N s/m].
    force_by_bore : ndarray  ∂F/∂u (2 × n) of the film force on the journal [N/m].
    force_by_velocity : ndarray  ∂F/∂v (2 × 2) [N s/m].
    moment_by_bore, moment_by_velocity : ndarray or None  ∂M/∂u (2 × n) [N m/m] and
        ∂M/∂v [N m s/m] of the tilting moments, with the velocity columns of a solved
        tilt after the journal's two (2 × 4); None when not asked for.
    """

    nodal_by_bore: np.ndarray
    nodal_by_velocity: np.ndarray
    force_by_bore: np.ndarray
    force_by_velocity: np.ndarray
    moment_by_bore: np.ndarray | None = None
    moment_by_velocity: np.ndarray | None = None
