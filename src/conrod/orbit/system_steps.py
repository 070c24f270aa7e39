"""Steps of a film whose own unknowns are solved only with the journal's implicit step.

A film on a deforming bore (:class:`conrod.ehd.film.ElasticFilm`) has unknowns of its own at
every step — the bore displacement — which the film's response couples to the journal's
position and velocity; it declares :class:`~conrod.film.capabilities.HasStepSystem`, and
every step of the orbit (:mod:`conrod.orbit.implicit_step`) is its step system solved with
the journal's balance (:mod:`conrod.orbit.journal_step`). The start value of the end
velocity is extrapolated through the last three step points (linearly after a restart). A
step that does not converge is split in halves down to 1/2^:data:`MAX_HALVINGS`.

Contact. With mixed lubrication the elastic film carries the Greenwood–Tripp asperity
pressure on its deformed film (:mod:`conrod.ehd.asperity`): film and asperities hold
the journal while the deformed film is open (h_min > 0), with no contact circle. Without an
asperity model the journal has no contact phase here: a step whose end leaves the contact
circle widened by one clearance, or whose deformed film closes, stops the orbit with
:class:`~conrod.errors.ConvergenceError` naming the crank angle, h_min on the deformed film
[m] and the fix (mixed lubrication in ``[contact]``, or the massless orbit).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.capabilities import CarriesAsperityContact, HasDeformedGap
from conrod.orbit.journal_step import JournalOutcome, solve_journal_step
from conrod.orbit.problem import OrbitProblem, OrbitState

MAX_HALVINGS = 4
"""Most halvings of a step that does not converge [-]."""

SHORTEST_STEP_DEG = 0.25
"""Shortest step of the orbit with mass on the elastic bore [deg]: shorter steps stiffen
the bore's squeeze term 12μ ∂u/∂t until the step's Newton iteration cycles between
cavitation sets (measured on the KamAZ-740 rod at 36 × 8: 0.125° stops at 57°, 0.2° at
718° with a force residual of 1e-3 of the load; 0.25°, 0.5° and 1° run); refused before
the orbit starts."""

THIN_FILM_SHARE = 0.05
"""h_min on the deformed film below this share of the clearance: a failing step is put down
to the film closing, and mixed lubrication is the advice [-]."""


@dataclass(frozen=True)
class SystemStepEnd:
    """End of a step: position [m], velocity [m/s], film memory, and the Newton outcome."""

    position: np.ndarray
    velocity: np.ndarray
    memory: Any
    outcome: JournalOutcome
    contact_force: float = 0.0
    in_contact: bool = False

    @property
    def converged(self) -> bool:
        """The step's balance is acceptable [-]."""
        return self.outcome.newton.converged


class SystemSteps:
    """The steps of a film with a step system (module docstring)."""

    max_halvings = MAX_HALVINGS

    def __init__(self, problem: OrbitProblem, with_mass: bool):
        self.problem = problem
        masses = (problem.mass_x, problem.mass_y) if with_mass else (0.0, 0.0)
        self.mass = np.array(masses)
        self.velocity_scale = problem.clearance * max(problem.crank_speed, 1e-3)
        self.extra_force = _asperity(problem)
        self.checked = False
        # asked once, not at every accepted step: a Protocol's isinstance costs ~40 µs
        self.asperity_film = isinstance(problem.film, CarriesAsperityContact)

    def starts_in_contact(self, state: OrbitState) -> bool:
        """No contact phase: False [-]."""
        return False

    def start_contact_force(self, state: OrbitState, memory: Any) -> float:
        """No contact phase: 0 N."""
        return 0.0

    def check_budget(self, taken: int, nominal: int, phi: float) -> None:
        """No step budget: the halvings are the limit."""

    def step(self, start, phi1: float, dt: float, contact: bool) -> SystemStepEnd | None:
        """One backward Euler (no ``start.before``) or BDF2 step ending at φ1; None where
        the film closed at every trial. The first step (a whole one) is checked against
        :data:`SHORTEST_STEP_DEG`."""
        if not self.checked:
            self.checked = True
            _check_step(self.problem, dt, bool(np.any(self.mass > 0.0)))
        request = start.request(self.problem, phi1, dt, self.mass, _load(self.problem, phi1),
                                _speeds(self.problem, phi1))
        guess = start.predicted_velocity(quadratic=True)
        done = solve_journal_step(self.problem.film, request, guess, self.velocity_scale,
                                  self.extra_force)
        if done is None:
            return None
        return SystemStepEnd(request.position(done.newton.velocity), done.velocity,
                             done.memory, done)

    def accept(self, end: SystemStepEnd, phi: float) -> None:
        """ConvergenceError when the journal centre leaves the (widened) contact circle and
        no asperity contact on the deformed film carries the load there; with it the
        journal is held by film and asperities while the deformed film is open
        (h_min > 0), and a closed film stops the step itself."""
        problem = self.problem
        film = problem.film
        if self.asperity_film and film.carries_asperity():
            return
        e = float(np.hypot(*end.position))
        if e > problem.contact_radius:
            h_min = _deformed_h_min(problem, end.position, end.memory)
            raise ConvergenceError(
                f"orbit with mass on the elastic bore: the journal centre left the contact "
                f"circle (e = {e:.3g} m > {problem.contact_radius:.3g} m; h_min = "
                f"{h_min:.3g} m on the deformed film), which this orbit does not treat; "
                f"{failure_advice(problem, h_min)}",
                where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg")

    def failure(self, phi: float, end: SystemStepEnd | None, start) -> ConvergenceError:
        """What stopped the orbit, where, by how much [N], h_min on the deformed film at the
        last accepted state [m], and what to change."""
        problem = self.problem
        size = float(np.hypot(*_load(problem, phi)))
        h_min = _deformed_h_min(problem, start.position, start.memory)
        if end is None:
            what = (f"the deformed film closed at every trial end state; h_min = {h_min:.3g} "
                    "m on the deformed film at the last accepted step")
            residual = float("nan")
        else:
            newton = end.outcome.newton
            residual = newton.force_residual * (float(np.hypot(*_load(problem, phi))) + 1.0)
            what = (f"force residual {residual:.3g} N of a {size:.3g} N load, bore residual "
                    f"{newton.residual:.3g} m, h_min = {h_min:.3g} m on the deformed "
                    "film at the last accepted step")
        return ConvergenceError(
            f"orbit with mass on the elastic bore: the step did not balance the load after "
            f"{MAX_HALVINGS} halvings ({what}); {failure_advice(problem, h_min)}",
            where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg", residual=residual)


def failure_advice(problem: Any, h_min: float) -> str:
    """What to change when the journal with mass cannot go on: without an asperity model
    nothing carries the load once the deformed film closes (h_min [m] small or unknown);
    with a film still open the step or the increment share is what to change."""
    massless = "run the massless orbit (solver.integrator = 'quasi_static')"
    closing = not h_min > THIN_FILM_SHARE * problem.clearance  # NaN: not known, say it
    if problem.asperity is None and closing:
        return ("enable mixed lubrication ([contact] model = 'greenwood_tripp') so that "
                f"asperity contact carries the load on the deformed film, or {massless}")
    return ("change solver.max_step_deg (steps of 0.25-2 deg run on the shipped rods; much "
            "shorter steps stiffen the bore's squeeze term, across whose cavitation boundary "
            f"the iteration can cycle), lower housing.increment_share, or {massless}")


def _check_step(problem: OrbitProblem, dt: float, with_mass: bool) -> None:
    """CaseError when the journal with mass takes steps ``dt`` [s] shorter than
    :data:`SHORTEST_STEP_DEG`."""
    step = math.degrees(dt * problem.crank_speed)
    if with_mass and step < SHORTEST_STEP_DEG * (1.0 - 1e-9):
        raise CaseError(
            f"solver.max_step_deg: steps of {step:.3g} deg with an elastic [housing] and the "
            f"journal with mass: steps below {SHORTEST_STEP_DEG} deg stiffen the bore's "
            "squeeze term until the step's Newton iteration cycles between cavitation sets "
            f"(allowed: >= {SHORTEST_STEP_DEG} deg with output_step_deg a multiple of the "
            "step, or integrator = 'quasi_static' for the massless journal) [deg]")


def _deformed_h_min(problem: OrbitProblem, position, memory) -> float:
    """h_min on the deformed film with the journal at ``position`` [m] (NaN for a film that
    does not say)."""
    film = problem.film
    if not isinstance(film, HasDeformedGap):
        return float("nan")
    return film.deformed_min_film_thickness(position, memory)


def _load(problem: OrbitProblem, phi: float) -> np.ndarray:
    load = problem.loads.load(np.array([phi]))
    return np.array([float(load[0][0]), float(load[1][0])])


def _speeds(problem: OrbitProblem, phi: float) -> tuple[float, float]:
    speeds = problem.loads.speeds(np.array([phi]))
    return float(speeds[0][0]), float(speeds[1][0])


def _asperity(problem: OrbitProblem):
    """(x, y) → Greenwood–Tripp asperity force on the rigid shell [N]; None without mixed
    lubrication or when the film carries it on the deformed film
    (:attr:`~conrod.orbit.problem.OrbitProblem.rigid_asperity`)."""
    params = problem.rigid_asperity
    if params is None:
        return None
    from conrod.contact.asperity import asperity_force

    def force(x: float, y: float):
        return asperity_force(x, y, problem.clearance, params)
    return force
