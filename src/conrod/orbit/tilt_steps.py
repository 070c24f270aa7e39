"""Steps of a tilted journal: the one implicit step with the tilt prescribed or solved.

A run with ``[misalignment]`` (:class:`~conrod.loads.tilt.JournalTilt`) takes the fixed
implicit steps of :mod:`conrod.orbit.implicit_step` (backward Euler, then BDF2; halving) for
every film that can take a tilt, with mass (``auto``, ``implicit``, ``adaptive``) and
massless (``quasi_static``: the same steps with zero mass and inertia):

* prescribed tilt — the journal keeps its two degrees of freedom (e_x, e_y); the tilt
  γ(φ) and its rate at the end of each step are part of the film's state;
* solved tilt — two more degrees of freedom, the edge displacements ℓγ_x, ℓγ_y (ℓ = L/2),
  with the generalised forces M/ℓ of the film's moments and of the external moment and the
  inertias J/ℓ² of the rod's moments of inertia about the film axes, so that the balance of
  the four is one Newton system in lengths and forces
  (:func:`conrod.numerics.newton.solve_step`, k = 4):

.. math:: m\\,\\ddot e = F(e, \\dot e, γ, \\dotγ) + W(φ),\\qquad
          J\\,\\ddotγ = M(e, \\dot e, γ, \\dotγ) + M_{ext}(φ).

The film's part is its step system: an elastic film's own (bore and journal together), or
for a rigid film one of :mod:`conrod.orbit.tilt_systems`. A tilted journal has no hard-contact
phase: where the film closes at an edge the step is split, and at the last halving the
orbit stops with a :class:`~conrod.errors.ConvergenceError` naming the crank angle and the
edge h_min. Contact on a tilted journal needs the mixed-lubrication model of the elastic
film (asperity pressure on its own tilted, deformed film).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.capabilities import (
    CarriesAsperityContact,
    HasContentStep,
    HasStepSystem,
    SupportsDeformation,
)
from conrod.film.step_system import TiltRequest
from conrod.orbit.journal_step import solve_journal_step
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.system_steps import SystemStepEnd
from conrod.orbit.tilt_systems import FilmTiltSystems

MAX_HALVINGS = 5
"""Most halvings of a step that does not converge [-]."""


def tilt_film(problem: OrbitProblem) -> Any:
    """The step-system provider of a tilted journal's film (module docstring); CaseError for
    a film that cannot take a tilt or a rigid-shell asperity force it cannot carry."""
    film = problem.film
    if isinstance(film, HasStepSystem) and film.supports_step_system():
        if problem.tilt.free and isinstance(film, HasContentStep):
            raise CaseError("misalignment.mode = 'free' on the elastic mass-conserving film: "
                            "its content step does not give the moments' response (allowed: "
                            "mode = 'prescribed', or film = 'reynolds')")
        return film
    if not isinstance(film, SupportsDeformation):  # the films resolving the width
        raise CaseError(f"solver.film = {film.name!r} cannot take a journal tilt "
                        "([misalignment]; allowed: a grid film that resolves the width, "
                        "'reynolds' or 'mass_conserving')")
    if problem.asperity is not None and not (isinstance(film, CarriesAsperityContact)
                                             and film.carries_asperity()):
        raise CaseError("[contact] model = 'greenwood_tripp' with [misalignment] on a rigid "
                        "bore: the rigid asperity force is not taken on the tilted film "
                        "(allowed: the elastic big end, [housing], whose film carries the "
                        "asperity pressure on its tilted film; or no asperity model)")
    return FilmTiltSystems(film)


class TiltSteps:
    """The steps of a tilted journal (module docstring)."""

    max_halvings = MAX_HALVINGS

    def __init__(self, problem: OrbitProblem, with_mass: bool):
        self.problem, self.tilt = problem, problem.tilt
        lever = self.tilt.lever
        masses = [problem.mass_x, problem.mass_y]
        if self.tilt.free:
            masses += [self.tilt.inertia[0] / lever**2, self.tilt.inertia[1] / lever**2]
        self.mass = np.array(masses) if with_mass else np.zeros(len(masses))
        self.velocity_scale = problem.clearance * max(problem.crank_speed, 1e-3)
        self.film = tilt_film(problem)

    def start_point(self, state: OrbitState) -> tuple[tuple, tuple]:
        """(position, velocity) of the journal's degrees of freedom at ``state`` [m, m/s]."""
        if not self.tilt.free:
            return (state.x, state.y), (state.vx, state.vy)
        lever = self.tilt.lever
        gx, gy, rx, ry = state.tilt if state.tilt is not None else (0.0, 0.0, 0.0, 0.0)
        return ((state.x, state.y, lever * gx, lever * gy),
                (state.vx, state.vy, lever * rx, lever * ry))

    def tilt_at(self, point, phi: float) -> tuple[float, float, float, float]:
        """(γ_x, γ_y [rad], γ̇_x, γ̇_y [rad/s]) at the step point ``point`` at φ [rad]."""
        if not self.tilt.free:
            return self.tilt.tilt_at(phi)
        lever = self.tilt.lever
        return (float(point.position[2]) / lever, float(point.position[3]) / lever,
                float(point.velocity[2]) / lever, float(point.velocity[3]) / lever)

    def starts_in_contact(self, state: OrbitState) -> bool:
        """No contact phase: False [-]."""
        return False

    def start_contact_force(self, state: OrbitState, memory: Any) -> float:
        """No contact phase: 0 N."""
        return 0.0

    def check_budget(self, taken: int, nominal: int, phi: float) -> None:
        """No step budget: the halvings are the limit."""

    def load(self, phi: float) -> np.ndarray:
        """W(φ) [N], with a solved tilt also M_ext(φ)/ℓ [N]."""
        load = self.problem.loads.load(np.array([phi]))
        values = [float(load[0][0]), float(load[1][0])]
        if self.tilt.free:
            values += [m / self.tilt.lever for m in self.tilt.moment_at(phi, values)]
        return np.array(values)

    def step(self, start, phi1: float, dt: float, contact: bool) -> SystemStepEnd | None:
        """One backward Euler (no ``start.before``) or BDF2 step ending at φ1; None where
        the film closed or failed at every trial."""
        problem = self.problem
        speeds = problem.loads.speeds(np.array([phi1]))
        tilt = TiltRequest(self.tilt.lever,
                           None if self.tilt.free else self.tilt.tilt_at(phi1))
        request = start.request(problem, phi1, dt, self.mass, self.load(phi1),
                                (float(speeds[0][0]), float(speeds[1][0])), tilt)
        guess = start.predicted_velocity(quadratic=True)
        done = solve_journal_step(self.film, request, guess, self.velocity_scale)
        if done is None:
            return None
        return SystemStepEnd(request.position(done.newton.velocity), done.velocity,
                             done.memory, done)

    def accept(self, end: SystemStepEnd, phi: float) -> None:
        """Nothing to check: a film closing at an edge fails the step itself."""

    def failure(self, phi: float, end: SystemStepEnd | None, start) -> ConvergenceError:
        """What stopped the orbit, where, by how much [N], and what to change."""
        size = float(np.linalg.norm(self.load(phi)))
        if end is None:
            what = "the film closed (h <= 0 at an edge) or its solve failed at every trial"
            residual = float("nan")
        else:
            newton = end.outcome.newton
            residual = newton.force_residual * (size + 1.0)
            what = f"force residual {residual:.3g} N of a {size:.3g} N load"
        return ConvergenceError(
            f"orbit of the tilted journal: the step did not balance the load after "
            f"{MAX_HALVINGS} halvings ({what}); reduce the tilt (misalignment.table or the "
            "external moment), refine solver.max_step_deg, or add the elastic big end with "
            "mixed lubrication ([housing], [contact] model = 'greenwood_tripp') so that edge "
            "contact carries the load", where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg",
            residual=residual)
