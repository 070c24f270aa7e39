"""Hydromechanical characteristics along the orbit ([D2] Table 1 columns).

At each output angle the film model is solved once for the orbit state, giving h_min and
its shell angle, p_max, friction torque, side and supply flow; where the integrator's step
that ended there holds its own converged answer (the implicit content step of a
mass-conserving film), that answer is the row. Derived here:

* attitude angle: from the load vector to the line of centres [rad];
* journal rotation relative to the shell ∫(ω_j − ω_b)/ω dφ (trapezoid) [rad], and the
  h_min position on the journal θ − rotation [rad];
* friction power = |M_j (ω_j − ω_b)| unless the model reports its own [W];
* sliding speed at the contact point V_k + (ω_j − ω_b) R [m/s].
"""

from __future__ import annotations

import math

import numpy as np

from conrod.film.base import FilmResult, FilmState
from conrod.orbit.problem import OrbitProblem
from conrod.orbit.tilt_results import axial_of, tilt_items
from conrod.orbit.trajectory import CycleTrajectory
from conrod.results.cycle_results import CycleResults

TWO_PI = 2.0 * math.pi


def journal_rotation(
    crank_angle: np.ndarray, relative_speed: np.ndarray, crank_speed: float
) -> np.ndarray:
    """∫ (ω_j − ω_b) dt from the first output angle, trapezoid rule [rad]."""
    increments = 0.5 * (relative_speed[1:] + relative_speed[:-1]) * np.diff(crank_angle)
    return np.concatenate([[0.0], np.cumsum(increments)]) / crank_speed


def attitude_angle(
    ex: np.ndarray, ey: np.ndarray, load_x: np.ndarray, load_y: np.ndarray
) -> np.ndarray:
    """Angle from the load vector to the line of centres, in (−π, π] [rad]."""
    return np.arctan2(load_x * ey - load_y * ex, load_x * ex + load_y * ey)


def film_states(problem: OrbitProblem, traj: CycleTrajectory, wj, wb) -> list[FilmState]:
    """Film states at the output angles (with the journal's tilt when it has one)."""
    return [
        FilmState(eccentricity_x=float(traj.x[i]), eccentricity_y=float(traj.y[i]),
                  velocity_x=float(traj.vx[i]), velocity_y=float(traj.vy[i]),
                  journal_speed=float(wj[i]), shell_speed=float(wb[i]), viscosity=problem.viscosity,
                  journal_feed=problem.journal_feed(float(traj.crank_angle[i])),
                  **tilt_items(traj.tilt, i))
        for i in range(traj.crank_angle.size)
    ]


def film_results(problem: OrbitProblem, traj: CycleTrajectory, wj, wb,
                 with_pressure: bool = False) -> list[FilmResult]:
    """Film results at the output angles (with their pressure fields when
    ``with_pressure``), each with the film memory sampled there by the integrator when it
    carried one (film fraction of a mass-conserving film), else with the memory threaded
    from angle to angle (warm start). Where that memory is the answer of the implicit step
    that ended at the angle (the content step of a mass-conserving film), the row is that
    answer: one truth, the pressure of the converged state the orbit accepted there (a new
    solve with the film fraction frozen is another problem, whose pressure can be tens of
    times off in single rows)."""
    session = problem.session()
    results = []
    for i, state in enumerate(film_states(problem, traj, wj, wb)):
        if traj.film_memory:
            session.restore(traj.film_memory[i])
            results.append(session.accepted(state, with_pressure=with_pressure))
        else:
            results.append(session.solve(state, with_pressure=with_pressure))
    return results


def row_results(problem: OrbitProblem, traj: CycleTrajectory,
                with_pressure: bool = False) -> list[FilmResult]:
    """:func:`film_results` at the output angles of ``traj``, for
    :func:`cycle_characteristics` and whoever reads the same rows' fields after it (the
    sign-off), so that the film is solved there once."""
    wj, wb = problem.loads.speeds(traj.crank_angle)
    return film_results(problem, traj, wj, wb, with_pressure)


def _film_columns(results: list[FilmResult], relative_speed: np.ndarray) -> dict[str, np.ndarray]:
    def column(name: str) -> np.ndarray:
        return np.array([getattr(r, name) for r in results], dtype=float)

    torque = column("friction_torque_journal")
    own_power = column("friction_power")
    power = np.where(own_power > 0.0, own_power, np.abs(torque * relative_speed))
    return {
        "h_min": column("min_film_thickness"), "h_min_angle_shell": column("min_film_angle"),
        "p_max": column("max_pressure"), "p_max_angle_shell": column("max_pressure_angle"),
        "friction_torque": torque, "friction_power": power,
        "side_flow": column("side_flow"), "supply_flow": column("supply_flow"),
    }


def cycle_characteristics(problem: OrbitProblem, traj: CycleTrajectory,
                          results: list[FilmResult] | None = None) -> CycleResults:
    """Per-angle characteristics of the orbit ``traj`` (SI units, see :class:`CycleResults`)
    from the film ``results`` at its output angles (None: solved here, :func:`film_results`)."""
    phi = traj.crank_angle
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    relative = wj - wb
    if results is None:
        results = film_results(problem, traj, wj, wb)
    film = _film_columns(results, relative)
    rotation = journal_rotation(phi, relative, problem.crank_speed)
    contact_angle = np.arctan2(traj.y, traj.x) % TWO_PI
    tangential_speed = traj.vy * np.cos(contact_angle) - traj.vx * np.sin(contact_angle)
    axial = axial_of(problem, traj, results)  # tilt or profile: moments, edge h_min
    return CycleResults(
        axial=axial, crank_angle=phi, eccentricity_x=traj.x, eccentricity_y=traj.y,
        velocity_x=traj.vx, velocity_y=traj.vy,
        eccentricity_ratio=np.hypot(traj.x, traj.y) / problem.clearance,
        attitude_angle=attitude_angle(traj.x, traj.y, load_x, load_y),
        h_min_angle_journal=(film["h_min_angle_shell"] - rotation) % TWO_PI,
        load_x=load_x, load_y=load_y, journal_speed=wj, shell_speed=wb,
        contact_force=traj.contact_force, friction_force=traj.friction_force,
        contact_angle=contact_angle, journal_rotation=rotation,
        sliding_speed=tangential_speed + relative * problem.film.geometry.radius,
        in_contact=traj.in_contact, feed=feed_columns(problem, phi, results), **film,
)


def feed_columns(problem: OrbitProblem, phi: np.ndarray,
                 results: list[FilmResult]) -> dict[str, np.ndarray] | None:
    """Per-angle flow through the journal's oil holes (signed, into the bearing) [m³/s], the
    first hole's shell angle [rad] and feed pressure [Pa], and the film's inlet film
    fraction where it reports one [-] (:mod:`conrod.results.feed`); None without holes."""
    if problem.feed is None:
        return None
    feeds = [problem.feed.at(float(angle)) for angle in phi]
    first = problem.film.geometry.journal_holes[0].angle
    columns = {
        "journal_hole_flow": np.array([r.extra.get("journal_hole_flow_m3_per_s", np.nan)
                                       for r in results]),
        "journal_hole_angle_shell": np.array([(first + f.journal_angle) % TWO_PI
                                              for f in feeds]),
        "journal_hole_pressure": np.array([f.pressures[0] for f in feeds])}
    if all("inlet_film_fraction" in r.extra for r in results):
        columns["inlet_film_fraction"] = np.array([r.extra["inlet_film_fraction"]
                                                   for r in results])
    return columns
