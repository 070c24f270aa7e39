"""The compiled TR-BDF2 orbit with mass of a tilted journal on the rigid Reynolds film.

The aligned journal's free flight (:mod:`conrod.orbit.implicit`) runs compiled with the film
force; a tilted journal runs the same step code (:mod:`conrod.orbit.tr_bdf2`) with the film's
forces and moments (:mod:`conrod.film.reynolds.tilt_flight`) on the scaled state

* prescribed tilt: u = (x/c, y/c, v_x/(cω), v_y/(cω)), the tilt γ(φ) and its rate sampled
  from the cycle's table (every :data:`SAMPLE_DEG`, linear between);
* free tilt: u = (x/c, y/c, ℓγ_x/c, ℓγ_y/c, v_x/(cω), v_y/(cω), ℓγ̇_x/(cω), ℓγ̇_y/(cω)),
  ℓ = L/2, the tilt's equation J γ̈ = M + M_ext written for the edge displacement ℓγ with
  the inertia J/ℓ² and the generalised force (M + M_ext)/ℓ,

with the film's exact-enough Jacobian (forward differences in the film's squeeze state,
refreshed after every step that needed more than one Newton iteration) and the step's error
control on all components. A tilted journal has no contact phase: where the film closes at
an edge the kernel answers NaN, the step shrinks and the orbit stops with a located
:class:`~conrod.errors.ConvergenceError`. Films or settings the kernel does not cover (a
massless tilt, an elastic bore, a film content, mixed lubrication) take the fixed implicit
steps of :mod:`conrod.orbit.tilt_steps`.
"""

from __future__ import annotations

import functools
import math

import numba as nb
import numpy as np

from conrod.errors import ConvergenceError
from conrod.film.capabilities import HasContentStep, HasStepSystem, HasTiltFlightKernel
from conrod.orbit.compiled_flight import is_global, stable_name
from conrod.orbit.problem import OrbitProblem, OrbitState, load_table, periodic_sample
from conrod.orbit.progress import REPORT_EVERY_DEG, report_angle
from conrod.orbit.tr_bdf2 import STATUS_END, UNBOUND, bind_globals, specialise
from conrod.orbit.trajectory import CycleTrajectory

SAMPLE_DEG = 0.25
"""Spacing of the sampled tilt (and external moment) table inside the compiled loop [deg]."""
NEWTON_FILM_TOLERANCE = 0.5
"""Film tolerance inside Newton as a fraction of ``relative_tolerance`` (as the aligned
flight, :data:`conrod.orbit.implicit.NEWTON_FILM_TOLERANCE`) [-]."""
FIRST_STEP = 1.0e-4
"""First trial step [rad]."""
STEPS_PER_DEGREE = 2000
"""Most accepted steps per degree of crank angle [-]."""
REFRESH_RATE = 0.1
"""Newton contraction rate above which the Jacobian is refreshed [-]: a tilted journal's
costs nine film solves (the aligned one's five), so it is kept while Newton contracts."""
NO_CIRCLE = 1.0e6
"""Contact radius handed to the segment: none (a closing edge stops the film instead) [-]."""


def tilt_force(x, y, gx, gy, vx, vy, rx, ry, omega_sum, viscosity, params):
    """(F_x, F_y, M_x, M_y): a placeholder, bound per film by :func:`tilt_segment`."""
    raise RuntimeError(UNBOUND)


def tilt_film_jacobian(x, y, gx, gy, vx, vy, rx, ry, omega_sum, viscosity, params):
    """(Q, ∂Q/∂(e, γ, ė, γ̇)): a placeholder, bound per film by :func:`tilt_segment`."""
    raise RuntimeError(UNBOUND)


def _physical(u, row, trow, data):
    """(x, y, γ_x, γ_y, v_x, v_y, γ̇_x, γ̇_y) [m, rad, m/s, rad/s] of the scaled state."""
    c, omega, lever = data[4], data[5], data[7]
    cw = c * omega
    if u.size == 8:
        return (u[0] * c, u[1] * c, u[2] * c / lever, u[3] * c / lever, u[4] * cw,
                u[5] * cw, u[6] * cw / lever, u[7] * cw / lever)
    return u[0] * c, u[1] * c, trow[0], trow[1], u[2] * cw, u[3] * cw, trow[2], trow[3]


def _rhs(phi, u, params, data):
    """du/dφ [-] of the tilted journal under the load, the external moment and the film."""
    angles, table, cycle, mu, c, omega, masses, lever, t_angles, t_table = data
    row = periodic_sample(phi, angles, table, cycle)
    trow = periodic_sample(phi, t_angles, t_table, cycle)
    x, y, gx, gy, vx, vy, rx, ry = _physical(u, row, trow, data)
    q = tilt_force(x, y, gx, gy, vx, vy, rx, ry, row[2] + row[3], mu, params)
    scale = c * omega * omega
    half = u.size // 2
    out = np.empty(u.size)
    for k in range(half):
        out[k] = u[half + k]
    out[half] = (row[0] + q[0]) / (masses[0] * scale)
    out[half + 1] = (row[1] + q[1]) / (masses[1] * scale)
    if u.size == 8:
        out[6] = (trow[4] + q[2]) / lever / (masses[2] * scale)
        out[7] = (trow[5] + q[3]) / lever / (masses[3] * scale)
    return out


def _jacobian(phi, u, f0, params, data):
    """∂(du/dφ)/∂u [-] from the bound film Jacobian ∂Q/∂(e, γ, ė, γ̇)."""
    angles, table, cycle, mu, c, omega, masses, lever, t_angles, t_table = data
    row = periodic_sample(phi, angles, table, cycle)
    trow = periodic_sample(phi, t_angles, t_table, cycle)
    x, y, gx, gy, vx, vy, rx, ry = _physical(u, row, trow, data)
    _, film = tilt_film_jacobian(x, y, gx, gy, vx, vy, rx, ry, row[2] + row[3], mu, params)
    return scaled_tilt_jacobian(film, u.size, c, omega, masses, lever)


@nb.njit(cache=True)
def scaled_tilt_jacobian(film, size, c, omega, masses, lever):
    """∂(du/dφ)/∂u [-] (size × size) from the film's ∂Q/∂(e, γ, ė, γ̇) (4 × 8)."""
    half = size // 2
    out = np.zeros((size, size))
    position = np.array([c, c, c / lever, c / lever])
    rate = position * omega
    generalised = np.array([1.0, 1.0, 1.0 / lever, 1.0 / lever])
    for k in range(half):
        out[k, half + k] = 1.0
    for r in range(half):
        denominator = masses[r] * c * omega * omega
        for j in range(half):
            out[half + r, j] = generalised[r] * film[r, j] * position[j] / denominator
            out[half + r, half + j] = (generalised[r] * film[r, 4 + j] * rate[j]
                                       / denominator)
    return out


@functools.cache
def tilt_segment(force, jacobian):
    """The compiled TR-BDF2 segment of a tilted journal for a film's compiled
    ``force`` → (F, M) and ``jacobian`` (disk-cached for module-level numba functions).

    The right-hand side and the Jacobian are inlined into the segment (numba
    ``inline="always"``): as functions of their own each was one more library into which
    numba links, and LLVM optimises again, all the code below it (the film's force,
    Jacobian and multigrid). Compiling a tilted orbit on an empty cache went 96.5–108.4 s
    (2 runs) → 66.8–88.1 s (3 runs; a 2-core machine whose speed varies by ±15 %), the
    orbit the same bit for bit and loaded from the cache by a second process; inlining
    the film's force and Jacobian into right-hand sides of their own instead gave about
    the same (65.8–74.2 s). The aligned flight
    (:mod:`conrod.orbit.compiled_flight`) keeps its right-hand side apart: its film force
    is inlined into it, and inlining that right-hand side too copies the force into each
    of the segment's five calls (61 → 225 s)."""
    cache = is_global(force) and is_global(jacobian)
    name = stable_name(force) + "_tilted"
    inline = nb.njit(cache=cache, inline="always")
    globals_ = {"tilt_force": force, "tilt_film_jacobian": jacobian}
    globals_["_physical"] = inline(bind_globals(_physical, f"{name}_physical", {}))
    rhs = inline(bind_globals(_rhs, f"{name}_rhs", globals_))
    film_jacobian = inline(bind_globals(_jacobian, f"{name}_jacobian", globals_))
    return specialise(name, rhs, film_jacobian, compiled=True, cache=cache)


def applies(problem: OrbitProblem) -> bool:
    """True when the compiled tilted flight covers ``problem``: a rigid film with a compiled
    tilted kernel, no film content, no unknowns of the film's own, no asperity force, and
    for a free tilt positive moments of inertia."""
    film, tilt = problem.film, problem.tilt
    if tilt is None or problem.asperity is not None or not isinstance(
            film, HasTiltFlightKernel):
        return False
    if isinstance(film, HasContentStep) or (isinstance(film, HasStepSystem)
                                            and film.supports_step_system()):
        return False
    if problem.mass_x <= 0.0 or problem.mass_y <= 0.0:
        return False
    return not tilt.free or min(tilt.inertia) > 0.0


def tilt_flight_cycle(problem: OrbitProblem, state: OrbitState, settings) -> CycleTrajectory:
    """One cycle of the tilted journal with mass from ``state`` (module docstring)."""
    tilt = problem.tilt
    c, w = problem.clearance, problem.crank_speed
    session = problem.session(state.film_memory)
    kernel = problem.film.tilt_flight_kernel(
        session.memory, NEWTON_FILM_TOLERANCE * float(settings.relative_tolerance),
        tilt.free)
    segment = tilt_segment(kernel.force, kernel.jacobian)
    data = _data(problem)
    u = _scaled(state, c, w, tilt)
    phi_out = problem.output_angles(settings.output_step_deg)
    out_u = np.zeros((phi_out.size, u.size))
    phi, h, next_out, steps = 0.0, FIRST_STEP, 0, 0
    end, chunk = float(problem.loads.cycle), math.radians(REPORT_EVERY_DEG)
    while phi < end:
        stop = min(end, (math.floor(phi / chunk + 1e-9) + 1) * chunk)
        if end - stop < 1e-9 * chunk:
            stop = end
        max_steps = int(STEPS_PER_DEGREE * max(math.degrees(stop - phi), 1.0))
        status, phi, u, h, taken, next_out, _ = segment(
            kernel.params, data, float(phi), float(stop), u, h,
            math.radians(settings.max_step_deg), float(settings.relative_tolerance),
            float(settings.absolute_tolerance), NO_CIRCLE, phi_out, out_u, next_out,
            max_steps, REFRESH_RATE, False)
        steps += taken
        report_angle(phi)
        if status != STATUS_END:
            raise ConvergenceError(
                "orbit of the tilted journal: the step size collapsed (the film closes at an "
                "edge, h <= 0, or stops converging); reduce the tilt or the external moment, "
                "or run the elastic big end with mixed lubrication ([housing], [contact] "
                "model = 'greenwood_tripp') so that edge contact carries the load",
                where=f"crank angle {math.degrees(phi) % 720.0:.2f} deg")
    return _trajectory(problem, phi_out, out_u, u, kernel.memory(), steps)


def _data(problem: OrbitProblem) -> tuple:
    """Data of the compiled right-hand side: load table, masses, lever, tilt table."""
    tilt = problem.tilt
    angles, table = load_table(problem.loads)
    lever = tilt.lever
    masses = np.array([problem.mass_x, problem.mass_y, tilt.inertia[0] / lever**2,
                       tilt.inertia[1] / lever**2])
    cycle = float(problem.loads.cycle)
    count = max(int(round(math.degrees(cycle) / SAMPLE_DEG)), 8)
    sampled = np.linspace(0.0, cycle, count + 1)
    load_x, load_y = problem.loads.load(sampled)
    rows = np.array([(*tilt.tilt_at(phi), *tilt.moment_at(phi, (wx, wy)))
                     for phi, wx, wy in zip(sampled, load_x, load_y, strict=True)])
    return (angles, table, cycle, float(problem.viscosity), float(problem.clearance),
            float(problem.crank_speed), masses, float(lever), sampled, rows)


def _scaled(state: OrbitState, c: float, w: float, tilt) -> np.ndarray:
    """The scaled start state (module docstring)."""
    base = [state.x / c, state.y / c, state.vx / (c * w), state.vy / (c * w)]
    if not tilt.free:
        return np.array(base)
    gx, gy, rx, ry = state.tilt if state.tilt is not None else (0.0, 0.0, 0.0, 0.0)
    lever = tilt.lever
    return np.array([base[0], base[1], lever * gx / c, lever * gy / c, base[2], base[3],
                     lever * rx / (c * w), lever * ry / (c * w)])


def _trajectory(problem: OrbitProblem, phi_out, out_u, end_u, memory,
                steps: int) -> CycleTrajectory:
    """The cycle's rows in SI units with the tilt per output angle, and the end state."""
    c, w, tilt = problem.clearance, problem.crank_speed, problem.tilt
    half = out_u.shape[1] // 2
    table = np.zeros((phi_out.size, 7))
    table[:, 0:2] = out_u[:, 0:2] * c
    table[:, 2:4] = out_u[:, half:half + 2] * c * w
    if tilt.free:
        lever = tilt.lever
        tilts = np.column_stack([out_u[:, 2:4] * c / lever, out_u[:, 6:8] * c * w / lever])
        end_tilt = (end_u[2] * c / lever, end_u[3] * c / lever, end_u[6] * c * w / lever,
                    end_u[7] * c * w / lever)
    else:
        tilts = np.array([tilt.tilt_at(float(phi)) for phi in phi_out])
        end_tilt = None
    end = OrbitState(float(end_u[0] * c), float(end_u[1] * c), float(end_u[half] * c * w),
                     float(end_u[half + 1] * c * w), False, memory,
                     None if end_tilt is None else tuple(float(v) for v in end_tilt))
    trajectory = CycleTrajectory.from_table(phi_out, table, end, steps)
    trajectory.tilt = tilts
    return trajectory
