"""Orbit with mass of a film that solves its own state together with the journal's step.

A film on a deforming bore (:class:`conrod.ehd.film.ElasticFilm`) has unknowns of its
own at every step — the bore displacement — which the film's response couples to the
journal's position and velocity. Such a film declares :class:`HasCoupledMassStep`: given
the reference values of an implicit step it solves the end velocity and its own unknowns in
one Newton iteration (:mod:`conrod.ehd.mass_step`). This module holds the time
stepping: fixed steps of ``Δφ ≤ max_step_deg``, backward Euler for the first step of a
cycle and after a halved step, BDF2 otherwise,

.. math:: e^{n+1} = \\tfrac{4e^n − e^{n−1}}{3} + \\tfrac{2Δt}{3} v^{n+1},\\qquad
          m\\frac{3v^{n+1} − 4v^n + v^{n−1}}{2Δt} = F + W

(both L-stable, BDF2 second order; as the film-content orbit of
:mod:`conrod.orbit.content_orbit`). A step that does not converge is split in halves
(backward Euler) down to 1/2^:data:`MAX_HALVINGS`; then the orbit stops with
:class:`~conrod.errors.ConvergenceError` naming the crank angle and the force residual [N].

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
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.capabilities import CarriesAsperityContact, HasCoupledMassStep, HasDeformedGap
from conrod.orbit.problem import OrbitProblem, OrbitState
from conrod.orbit.progress import AngleReports
from conrod.orbit.trajectory import CycleTrajectory

MAX_HALVINGS = 4
"""Most halvings of a step that does not converge [-]."""


def coupled_mass_film(problem: OrbitProblem) -> bool:
    """True when ``problem.film`` takes the coupled step of the journal with mass."""
    film = problem.film
    return isinstance(film, HasCoupledMassStep) and film.supports_mass_step()


def coupled_step_deg(settings) -> float:
    """The largest step ≤ ``max_step_deg`` that divides ``output_step_deg`` [deg]."""
    output = settings.output_step_deg
    return output / math.ceil(output / settings.max_step_deg - 1e-9)


class _Point:
    """Journal state at a step point: position, velocity [m, m/s] and the film memory."""

    def __init__(self, position, velocity, memory, before: _Point | None = None):
        self.position = np.asarray(position, dtype=float)
        self.velocity = np.asarray(velocity, dtype=float)
        self.memory = memory
        self.before = before


def coupled_cycle(problem: OrbitProblem, state: OrbitState, step_deg: float,
                  output_step_deg: float) -> CycleTrajectory:
    """One cycle with mass from ``state`` by implicit steps of ``step_deg`` [deg]."""
    from conrod.orbit.rk2 import step_grid

    phi, record_every, n_out = step_grid(problem, step_deg, output_step_deg)
    film = problem.film
    memory = state.film_memory if state.film_memory is not None else film.initial_memory()
    point = _Point((state.x, state.y), (state.vx, state.vy), memory)
    table = np.zeros((n_out, 7))
    memories: list[Any] = [None] * n_out
    steps, reports = 0, AngleReports()
    for k in range(len(phi) - 1):
        if k % record_every == 0:
            row = k // record_every
            table[row, :4] = (*point.position, *point.velocity)
            memories[row] = point.memory
        point, taken, whole = _advance(problem, phi[k], phi[k + 1], point)
        steps += taken
        if not whole:
            point.before = None  # BDF2 needs two equal steps: restart by backward Euler
        reports.reached(phi[k + 1])
    end = OrbitState(float(point.position[0]), float(point.position[1]),
                     float(point.velocity[0]), float(point.velocity[1]), False, point.memory)
    trajectory = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end, steps)
    trajectory.film_memory = memories
    return trajectory


def _advance(problem: OrbitProblem, phi0: float, phi1: float, start: _Point,
             depth: int = 0) -> tuple[_Point, int, bool]:
    """Step φ0 → φ1, split in halves where it does not converge; (end point, steps taken,
    True when taken in one piece)."""
    try:
        outcome = _step(problem, phi1, (phi1 - phi0) / problem.crank_speed, start)
    except (CaseError, ConvergenceError):  # the film closed at a trial end state
        outcome = None
    if outcome is not None and outcome.converged:
        _check_circle(problem, _Point(outcome.position, outcome.velocity, outcome.memory),
                      phi1)
        older = start.before
        behind = _Point(start.position, start.velocity, start.memory,  # two points kept
                        None if older is None else _Point(older.position, older.velocity,
                                                          older.memory))
        return _Point(outcome.position, outcome.velocity, outcome.memory, behind), 1, True
    if depth >= MAX_HALVINGS:
        raise _failure(problem, phi1, outcome, start)
    middle = 0.5 * (phi0 + phi1)
    first = _Point(start.position, start.velocity, start.memory)
    half, count, _ = _advance(problem, phi0, middle, first, depth + 1)
    half.before = None
    end, more, _ = _advance(problem, middle, phi1, half, depth + 1)
    return end, count + more, False


def _failure(problem: OrbitProblem, phi: float, outcome, start: _Point) -> ConvergenceError:
    """What stopped the orbit, where, by how much [N], h_min on the deformed film at the
    last accepted state [m], and what to change."""
    size = float(np.hypot(*_load(problem, phi)))
    h_min = _deformed_h_min(problem, start)
    if outcome is None:
        what = (f"the deformed film closed at every trial end state; h_min = {h_min:.3g} m "
                "on the deformed film at the last accepted step")
        residual = float("nan")
    else:
        residual = outcome.force_residual
        what = (f"force residual {residual:.3g} N of a {size:.3g} N load, bore residual "
                f"{outcome.memory.residual:.3g} m, h_min = {h_min:.3g} m on the deformed "
                "film at the last accepted step")
    return ConvergenceError(
        f"orbit with mass on the elastic bore: the step did not balance the load after "
        f"{MAX_HALVINGS} halvings ({what}); {_advice(problem, h_min)}",
        where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg", residual=residual)


def _deformed_h_min(problem: OrbitProblem, point: _Point) -> float:
    """h_min on the deformed film at ``point`` [m] (NaN for a film that does not say)."""
    film = problem.film
    if not isinstance(film, HasDeformedGap):
        return float("nan")
    return film.deformed_min_film_thickness(point.position, point.memory)


THIN_FILM_SHARE = 0.05
"""h_min on the deformed film below this share of the clearance: a failing step is put down
to the film closing, and mixed lubrication is the advice [-]."""


def _advice(problem: OrbitProblem, h_min: float) -> str:
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


def _step(problem: OrbitProblem, phi1: float, dt: float, start: _Point):
    """One backward Euler (no ``start.before``) or BDF2 step ending at φ1."""
    from conrod.ehd.mass_step import MassStepRequest

    before = start.before
    if before is None:
        tau, e_ref, v_ref = dt, start.position, start.velocity
        guess = start.velocity
    else:
        tau = 2.0 * dt / 3.0
        e_ref = (4.0 * start.position - before.position) / 3.0
        v_ref = (4.0 * start.velocity - before.velocity) / 3.0
        guess = 2.0 * start.velocity - before.velocity
        if before.before is not None:  # quadratic through the last three points
            guess = 3.0 * (start.velocity - before.velocity) + before.before.velocity
    speeds = problem.loads.speeds(np.array([phi1]))
    request = MassStepRequest(
        position_reference=e_ref, velocity_reference=v_ref, tau=tau, dt=dt,
        mass=np.array([problem.mass_x, problem.mass_y]), load=_load(problem, phi1),
        journal_speed=float(speeds[0][0]), shell_speed=float(speeds[1][0]),
        viscosity=problem.viscosity, crank_angle=phi1, guess=guess, bdf2=before is not None)
    previous = before.memory if before is not None else None
    earlier = before.before.memory if before is not None and before.before is not None else None
    return problem.film.mass_step(request, start.memory, previous, _asperity(problem),
                                  earlier)


def _load(problem: OrbitProblem, phi: float) -> np.ndarray:
    load = problem.loads.load(np.array([phi]))
    return np.array([float(load[0][0]), float(load[1][0])])


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


def _check_circle(problem: OrbitProblem, point: _Point, phi: float) -> None:
    """ConvergenceError when the journal centre leaves the (widened) contact circle and no
    asperity contact on the deformed film carries the load there; with it the journal is
    held by film and asperities while the deformed film is open (h_min > 0), and a closed
    film stops the step itself."""
    film = problem.film
    if isinstance(film, CarriesAsperityContact) and film.carries_asperity():
        return
    e = float(np.hypot(*point.position))
    if e > problem.contact_radius:
        h_min = _deformed_h_min(problem, point)
        raise ConvergenceError(
            f"orbit with mass on the elastic bore: the journal centre left the contact "
            f"circle (e = {e:.3g} m > {problem.contact_radius:.3g} m; h_min = {h_min:.3g} m "
            f"on the deformed film), which this orbit does not treat; "
            f"{_advice(problem, h_min)}",
            where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg")
