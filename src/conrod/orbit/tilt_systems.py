"""Step systems of a rigid film under a tilted journal: the film's part of one implicit step
of the journal (:mod:`conrod.orbit.tilt_steps`) when the film has no unknowns of its own.

The journal's degrees of freedom are the centre (e_x, e_y) and, when the tilt is solved,
the edge displacements (ℓγ_x, ℓγ_y), ℓ = L/2, so that all four are lengths and their
generalised forces (F_x, F_y, M_x/ℓ, M_y/ℓ) forces; a prescribed tilt is part of the film's
state at the end of the step. A system has no own unknowns (n = 0): ``evaluate(y, v)``
solves the film at the end position e = e_r + τv with the end velocity v and returns its
generalised force; ``respond`` gives ∂Q/∂v = τ ∂Q/∂q + ∂Q/∂q̇:

* :class:`PressureSystem` — the isoviscous Reynolds film answered by its pressure alone,
  with the exact derivatives of its forces and moments on the converged active set
  (:class:`~conrod.film.capabilities.HasTiltJacobian`);
* :class:`ContentSystem` — a film with a transported content (mass-conserving): the force
  and moments at the end of its implicit content step, derivatives by forward differences;
* :class:`SolveSystem` — any other grid film with memory: its solve, forward differences.

Update limits: one Newton update may change the film thickness at the edges by at most
:data:`GAP_SHARE` of the current h_min (Rodin's safeguard, :mod:`conrod.numerics.newton`).
"""

from __future__ import annotations

import dataclasses
import math
from typing import Any

import numpy as np

from conrod.film.base import FilmState
from conrod.film.capabilities import HasContentStep, HasPressureEvaluation, HasTiltJacobian
from conrod.film.step_system import StepRequest
from conrod.film.tilt import moment_weights, pressure_moments
from conrod.numerics.newton import ChordJacobian, StepBlocks, UpdateLimits

FORCE_TOLERANCE = 1.0e-7
"""|Q + W|/(|W| + 1 N) that ends a step's iteration [-]: the journal moves by ~1e-7 c per
unit of it, far below the step's own error; tighter only adds film solves."""
JACOBIAN_TOLERANCE = 1.0e-9
"""Multigrid tolerance of the adjoint solves of a step's Jacobian [-] (a chord Jacobian
needs far less than the film's own 1e-12)."""
STEP_FILM_TOLERANCE = 1.0e-9
"""Multigrid tolerance of the Reynolds film inside a step's iteration [-]: its force is
then within ~3e-11 of the converged one (~0.03 × the tolerance), far inside
:data:`FORCE_TOLERANCE` (the compiled free flight solves to 5e-7)."""
GAP_SHARE = 0.5
"""Largest change of the film thickness by one update, share of h_min [-]."""
MAX_SOLVES = 40
"""Film evaluations of one step before it is split [-]."""
DIFFERENCE = 1.0e-6
"""Forward-difference step of the velocity, share of the velocity scale c ω [-]."""
SAMPLE_ANGLES = 16
"""Shell angles at which the update limit watches the edges' film thickness [-]."""


def end_state(request: StepRequest, velocity: np.ndarray) -> FilmState:
    """Film state at the end of ``request`` with the end velocity ``velocity`` (tilted)."""
    x, y = request.position(velocity)[:2]
    gx, gy, rx, ry = request.tilt.at_end(request, velocity)
    return FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                     velocity_x=float(velocity[0]), velocity_y=float(velocity[1]),
                     journal_speed=request.journal_speed, shell_speed=request.shell_speed,
                     viscosity=request.viscosity, tilt_x=gx, tilt_y=gy, tilt_rate_x=rx,
                     tilt_rate_y=ry)


def travel_rows(tau: float, journal: int) -> np.ndarray:
    """Film-thickness change at the edges per unit update of v, (2 × :data:`SAMPLE_ANGLES`,
    k) [s]: −τ(cos θ, sin θ) by the centre, ±τ(sin θ, −cos θ) by the edge displacements."""
    theta = np.linspace(0.0, 2.0 * math.pi, SAMPLE_ANGLES, endpoint=False)
    rows = []
    for side in (1.0, -1.0):
        columns = [-np.cos(theta), -np.sin(theta), side * np.sin(theta), -side * np.cos(theta)]
        rows.append(np.column_stack(columns[:journal]))
    return tau * np.vstack(rows)


class FilmTiltSystems:
    """The film of a tilted journal as a step-system provider (``step_system(request)``,
    :func:`conrod.orbit.journal_step.solve_journal_step`)."""

    def __init__(self, film: Any):
        self.film = film
        self.chords: dict[str, ChordJacobian] = {}
        theta, z = film.grid()
        axial = np.full(z.size, z[1] - z[0])
        axial[[0, -1]] *= 0.5  # the trapezoid rule of the grid films
        area = np.outer(np.full(theta.size, film.geometry.radius * 2.0 * math.pi / theta.size),
                        axial)
        self.moment_weights = moment_weights(np.cos(theta), np.sin(theta), z, area)
        if isinstance(film, HasContentStep):
            self.kind: type = ContentSystem
        elif isinstance(film, HasPressureEvaluation) and isinstance(film, HasTiltJacobian) \
                and film.exact_thickness_response():
            self.kind = PressureSystem
            if getattr(film, "tolerance", 0.0) < STEP_FILM_TOLERANCE:  # the step's iterates
                self.film = dataclasses.replace(film, tolerance=STEP_FILM_TOLERANCE)
        else:
            self.kind = SolveSystem

    def step_system(self, request: StepRequest):
        """The system of one step (module docstring)."""
        key = f"{len(request.load)}_{request.bdf2}"
        chord = self.chords.setdefault(key, ChordJacobian())
        return self.kind(self, request, chord)


class SolveSystem:
    """A film's solve at the end of the step; ∂Q/∂v by forward differences. The Jacobian is
    carried from step to step while it contracts (a rigid film's changes slowly)."""

    force_tolerance = FORCE_TOLERANCE

    def __init__(self, owner: FilmTiltSystems, request: StepRequest, chord: ChordJacobian):
        self.owner, self.film, self.request = owner, owner.film, request
        self.journal = len(request.load)
        self.start = np.zeros(0)
        self.scale = self.film.geometry.radial_clearance
        self.tolerance, self.max_solves, self.chord = self.scale, MAX_SOLVES, chord
        self.limits = UpdateLimits(GAP_SHARE, travel_rows(request.tau, self.journal))
        self.latest = request.memory

    def generalised(self, force: tuple[float, float], pressure: np.ndarray) -> np.ndarray:
        """(F_x, F_y) [N], with a solved tilt also (M_x, M_y)/ℓ [N] of ``pressure`` [Pa]."""
        if self.journal == 2:
            return np.array(force)
        moments = np.array(pressure_moments(pressure, self.owner.moment_weights))
        return np.concatenate([force, moments / self.request.tilt.lever])

    def solve(self, state: FilmState) -> tuple[np.ndarray, float, Any]:
        """(Q, h_min [m], memory after) of the film at ``state`` from the latest memory."""
        result, memory = self.film.solve_with_memory(state, self.latest, with_pressure=True)
        return (self.generalised((result.force_x, result.force_y), result.pressure),
                result.min_film_thickness, memory)

    def evaluate(self, own: np.ndarray, velocity: np.ndarray):
        """(G (0,), Q (k,) [N], h_min [m], payload) at the end velocity v [m/s]."""
        state = end_state(self.request, velocity)
        generalised, h_min, memory = self.solve(state)
        self.latest = memory
        return np.zeros(0), generalised, h_min, (velocity.copy(), generalised, memory)

    def respond(self, payload: Any) -> StepBlocks:
        """∂Q/∂v by forward differences of :meth:`evaluate` from ``payload``."""
        velocity, base, memory = payload
        step = DIFFERENCE * self.film.geometry.radial_clearance * max(
            abs(self.request.journal_speed), 1.0)
        columns = []
        for j in range(self.journal):
            moved = velocity.copy()
            moved[j] += step
            self.latest = memory
            columns.append((self.solve(end_state(self.request, moved))[0] - base) / step)
        self.latest = memory
        return _blocks(np.column_stack(columns))

    def finish(self, outcome) -> Any:
        """The film memory at the answer."""
        return outcome.payload[2]


class ContentSystem(SolveSystem):
    """The film's implicit content step to the end of the step (BDF2 after the first)."""

    def solve(self, state: FilmState) -> tuple[np.ndarray, float, Any]:
        request = self.request
        previous = request.previous if request.bdf2 else None
        fx, fy, after = self.film.content_step(state, request.memory, request.dt, self.latest,
                                               previous)
        pressure = self.film.gauge_pressure(after.pressure, state)
        return self.generalised((fx, fy), pressure), float(after.thickness.min()), after


class PressureSystem(SolveSystem):
    """The isoviscous Reynolds film by its pressure alone; exact ∂Q/∂v from its
    linearisation with the tilt set (:meth:`ReynoldsFilm.tilt_jacobian`)."""

    def solve(self, state: FilmState) -> tuple[np.ndarray, float, Any]:
        evaluation = self.film.evaluate_pressure(state, self.latest)
        force = tuple(evaluation.force())
        return (self.generalised(force, evaluation.pressure), evaluation.min_film_thickness(),
                evaluation.memory())

    def respond(self, payload: Any) -> StepBlocks:
        velocity, _, memory = payload
        state = end_state(self.request, velocity)
        tau, lever = self.request.tau, self.request.tilt.lever
        if self.journal == 2:  # prescribed tilt: ∂F/∂(e, ė) at the tilted state
            _, jacobian, _ = self.film.tilt_jacobian(state, memory, JACOBIAN_TOLERANCE,
                                                     tilt=False)
            return _blocks(tau * jacobian[:, :2] + jacobian[:, 2:])
        _, jacobian, _ = self.film.tilt_jacobian(state, memory, JACOBIAN_TOLERANCE)
        scale = np.array([1.0, 1.0, 1.0 / lever, 1.0 / lever])  # q = (e, ℓγ), Q = (F, M/ℓ)
        by_position = jacobian[:, :4] * scale[:, None] * scale[None, :]
        by_rate = jacobian[:, 4:] * scale[:, None] * scale[None, :]
        return _blocks(tau * by_position + by_rate)


def _blocks(force_by_journal: np.ndarray) -> StepBlocks:
    """Blocks of a system without own unknowns."""
    k = force_by_journal.shape[0]
    return StepBlocks(np.zeros((0, 0)), np.zeros((0, k)), np.zeros((k, 0)), force_by_journal)
