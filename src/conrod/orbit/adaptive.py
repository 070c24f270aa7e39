"""Adaptive, implicit orbit integration ([D2]: BDF with steps ≤ 1° crank angle).

SciPy ``solve_ivp`` (Radau by default, BDF or LSODA on request) integrates the scaled state
u = (x/c, y/c, v_x/(cω), v_y/(cω)) over the crank angle φ with ``max_step`` ≤ 1°.
Hard contact ([D4] §4.1–4.2) is handled by phases located with events:

* free phase until Z = |e|/r_c − 1 crosses zero upwards (event, not a step crossing);
  at entry the normal velocity is removed (eqs 4.1.5–4.1.8: perfectly plastic impact);
* contact phase with the state (angle θ on the circle, V_k/(cω)) — the journal cannot leave
  the circle numerically — until the normal force P_c crosses zero downwards (event).

The output rows between step ends take the positions of SciPy's dense output and the
velocities solved from the equation of motion (:func:`settled_row`): the film's squeeze
pressure is too sensitive to the interpolated velocity.
"""

from __future__ import annotations

import math

import numpy as np

from conrod.errors import ConvergenceError
from conrod.io.interrupts import raise_if_interrupted
from conrod.orbit.compiled_flight import flight_rhs
from conrod.orbit.contact import contact_acceleration, contact_normal_force
from conrod.orbit.problem import (
    OrbitProblem,
    OrbitState,
    load_table,
    periodic_sample,
)
from conrod.orbit.trajectory import CycleTrajectory

FALLBACK_METHODS = ("Radau", "BDF", "LSODA")
"""Methods tried in turn when the chosen one fails on a segment (step-size collapse) [-]."""

MAX_PHASE_CHANGES = 5000
"""Most contact entries + exits per cycle before giving up (chattering) [-]."""


def compiled_free_rhs(force, params, data):
    """Compiled free-phase right-hand side du/dφ(φ, u) for a film with the compiled
    ``force`` and its ``params`` (same as :meth:`Phases.free_rhs`): u = (x/c, y/c,
    v_x/(cω), v_y/(cω)), ``data`` = (angles, table, cycle, μ, c, ω, m_x, m_y). The compiled
    flight's right-hand side (:func:`conrod.orbit.compiled_flight.flight_rhs`), compiled once
    per force function and loaded from numba's disk cache by the next process. (It was
    compiled per process and per parameter values, frozen into the code to save the
    dispatch of a tuple argument: 1.0–1.9 s of compiling in every warm run of
    ``examples/ruston_hornsby_6vebx_mk3.toml``, for 0.4 µs per call saved over its 26 660
    calls.)"""
    rhs = flight_rhs(force)

    def free_rhs(phi, u):
        return rhs(phi, u, params, data)

    return free_rhs


class Phases:
    """Right-hand sides and events of the free and the contact phase."""

    def __init__(self, problem: OrbitProblem, state: OrbitState):
        self.p = problem
        self.session = problem.session(state.film_memory)
        self.force = problem.force_function(self.session)
        self.kernel = problem.compiled_force
        self.c = problem.clearance
        self.rc = problem.contact_radius
        self.omega = problem.crank_speed
        self.radius = problem.film.geometry.radius
        self.loads = problem.loads
        self.angles, self.table = load_table(problem.loads)
        self.compiled_rhs = None if self.kernel is None else compiled_free_rhs(
            self.kernel.force, self.kernel.params,
            (self.angles, self.table, float(self.loads.cycle), float(problem.viscosity),
             self.c, float(self.omega), float(problem.mass_x), float(problem.mass_y)))
        peak = np.max(np.hypot(problem.loads.load_x, problem.loads.load_y))
        self.force_scale = float(peak) + 1.0

    def forces(self, phi: float, x: float, y: float, vx: float, vy: float):
        """X = W + F [N] and the surface speed (ω_j − ω_b) R [m/s] at φ."""
        wx, wy, wj, wb = periodic_sample(phi, self.angles, self.table, self.loads.cycle)
        fx, fy = self.force(x, y, vx, vy, wj, wb, phi)
        return wx + fx, wy + fy, (wj - wb) * self.radius

    def free_rhs(self, phi: float, u: np.ndarray) -> np.ndarray:
        if self.compiled_rhs is not None:
            # contiguous: SciPy's views of u compiled it again
            return self.compiled_rhs(float(phi), np.ascontiguousarray(u, dtype=float))
        c, w = self.c, self.omega
        x, y, vx, vy = u[0] * c, u[1] * c, u[2] * c * w, u[3] * c * w
        big_x, big_y, _ = self.forces(phi, x, y, vx, vy)
        scale = c * w * w
        return np.array(
            [u[2], u[3], big_x / (self.p.mass_x * scale), big_y / (self.p.mass_y * scale)]
        )

    def hit(self, phi: float, u: np.ndarray) -> float:
        return math.hypot(u[0], u[1]) * self.c / self.rc - 1.0

    def on_circle(self, w: np.ndarray) -> tuple[float, float, float, float]:
        """(x, y, v_x, v_y) from the contact-phase state (θ, V_k/(cω))."""
        theta, v_k = w[0], w[1] * self.c * self.omega
        cos_t, sin_t = math.cos(theta), math.sin(theta)
        return self.rc * cos_t, self.rc * sin_t, -v_k * sin_t, v_k * cos_t

    def contact_rhs(self, phi: float, w: np.ndarray) -> np.ndarray:
        x, y, vx, vy = self.on_circle(w)
        big_x, big_y, surface = self.forces(phi, x, y, vx, vy)
        ax, ay, _, _ = contact_acceleration(
            x, y, vx, vy, big_x, big_y, self.p.mass_x, self.p.mass_y,
            self.p.dry_friction, self.rc, surface, True,
        )
        tangential = -ax * math.sin(w[0]) + ay * math.cos(w[0])
        return np.array([w[1] * self.c / self.rc, tangential / (self.c * self.omega**2)])

    def normal_force(self, phi: float, w: np.ndarray, with_sign: bool = False):
        """Unclamped contact force P_c [N] in the contact phase (and the sliding sign s)."""
        x, y, vx, vy = self.on_circle(w)
        big_x, big_y, surface = self.forces(phi, x, y, vx, vy)
        p_c, s = contact_normal_force(
            x, y, vx, vy, big_x, big_y, self.p.mass_x, self.p.mass_y,
            self.p.dry_friction, self.rc, surface,
        )
        return (p_c, s) if with_sign else p_c

    def leave(self, phi: float, w: np.ndarray) -> float:
        return self.normal_force(phi, w) / self.force_scale


def adaptive_cycle(
    problem: OrbitProblem, state: OrbitState, settings, output_step_deg: float
) -> CycleTrajectory:
    """One cycle from ``state`` at φ = 0 with ``settings`` = the ``[solver]`` section."""
    phases = Phases(problem, state)
    phi_out = problem.output_angles(output_step_deg)
    table = np.zeros((phi_out.size, 7))
    end = problem.loads.cycle
    phi, contact, steps = 0.0, state.in_contact, 0
    c, w = problem.clearance, problem.crank_speed
    current = scaled_state(state, c, w, phases)
    def hit(phi_event: float, u: np.ndarray) -> float:
        return phases.hit(phi_event, u)

    def leave(phi_event: float, u: np.ndarray) -> float:
        return phases.leave(phi_event, u)

    hit.terminal, hit.direction = True, 1.0  # type: ignore[attr-defined]
    leave.terminal, leave.direction = True, -1.0  # type: ignore[attr-defined]
    for _ in range(MAX_PHASE_CHANGES):
        rhs, event = (phases.contact_rhs, leave) if contact else (phases.free_rhs, hit)
        sol = solve_segment(rhs, phi, end, current, event, settings, phases.session)
        if sol.status < 0:
            raise ConvergenceError(f"adaptive orbit integration failed: {sol.message}",
                                   where=f"crank angle {math.degrees(phi):.2f} deg")
        steps += sol.t.size - 1
        phi_end = float(sol.t[-1])
        last = sol.status == 0
        mask = (phi_out >= phi) & ((phi_out <= phi_end) if last else (phi_out < phi_end))
        record_rows(phases, sol, phi_out, mask, table, contact, settings)
        if last:
            return CycleTrajectory.from_table(
                phi_out, table, orbit_state(phases, sol.y[:, -1], contact), steps
            )
        phi = phi_end
        current, contact = switch_phase(phases, phi, sol.y[:, -1], contact)
    raise ConvergenceError("contact chattering: too many contact entries/exits",
                           where=f"crank angle {math.degrees(phi):.2f} deg")


class BudgetExhaustedError(ConvergenceError):
    """A method of :func:`solve_segment` used up its film evaluations."""


def solve_segment(rhs, phi, end, current, event, settings, session):
    """solve_ivp with the chosen method, then the others of :data:`FALLBACK_METHODS`; a
    failed attempt is rejected whole: the film memory restarts from its snapshot. A method
    that fails, or uses more than :data:`FIRST_METHOD_SHARE` of the evaluation budget
    (:func:`_budgeted`) while another is left to try, gives way to the next: Radau (fifth
    order) grinds on the kinks of a cavitating grid film's force where the lower-order BDF
    and LSODA pass (a fed two-land Reynolds film at 36 × 8, ε 0.955: Radau more than
    288 000 evaluations in half a cycle, BDF 5 700 and LSODA 7 200 for the whole cycle)."""
    from scipy.integrate import solve_ivp  # here: the implicit and elastic orbits import this
    # module for its helpers and never integrate with SciPy (its import costs 0.2-0.5 s)

    methods = [settings.adaptive_method] + [
        m for m in FALLBACK_METHODS if m != settings.adaptive_method
    ]
    start = session.snapshot()
    sol = None
    for number, method in enumerate(methods):
        session.restore(start)
        share = FIRST_METHOD_SHARE if number + 1 < len(methods) else 1.0
        try:
            sol = solve_ivp(
                _budgeted(rhs, settings, share), (phi, end), current, method=method,
                events=event, dense_output=True, max_step=math.radians(settings.max_step_deg),
                rtol=settings.relative_tolerance, atol=settings.absolute_tolerance,
            )
        except ValueError as error:  # a non-finite Jacobian or state: this method failed
            failure = error
            continue
        except BudgetExhaustedError as error:
            if number + 1 == len(methods):
                raise
            failure = error
            continue
        if sol.status >= 0:
            return sol
    if sol is None:
        raise ConvergenceError(f"adaptive orbit step failed ({failure}); use integrator = "
                               "'implicit'", where=f"crank angle {math.degrees(phi):.2f} deg")
    return sol


EVALUATIONS_PER_MIN_STEP = 400
"""Budget of film-force evaluations of one solve_ivp segment per step of max_step_deg
over the cycle (a normal cycle needs ~15); a stiffer run fails instead of hanging [-]."""
FIRST_METHOD_SHARE = 0.1
"""Share of the budget a method may use before the next of :data:`FALLBACK_METHODS` takes
over (the last one has it all): about 2.4 times what Radau needs for a normal cycle
of a grid film (about 12 000 evaluations on fed random bearings at 36 × 8) [-]."""


def _budgeted(rhs, settings, share: float = 1.0):
    """``rhs`` that raises :class:`BudgetExhaustedError` once it was called more than ``share``
    of the budget."""
    budget = int(share * EVALUATIONS_PER_MIN_STEP * math.ceil(720.0 / settings.max_step_deg))
    calls = [0]

    def counted(phi: float, u: np.ndarray) -> np.ndarray:
        calls[0] += 1
        raise_if_interrupted()
        if calls[0] > budget:
            raise BudgetExhaustedError(
                f"adaptive orbit integration exceeded its budget of {budget} film "
                "evaluations per cycle (stiff: check speed, viscosity and clearance)",
                where=f"crank angle {math.degrees(phi):.2f} deg")
        return rhs(phi, u)

    return counted


def scaled_state(state: OrbitState, c: float, w: float, phases: Phases) -> np.ndarray:
    if state.in_contact:
        theta = math.atan2(state.y, state.x)
        v_k = state.vy * math.cos(theta) - state.vx * math.sin(theta)
        return np.array([theta, v_k / (c * w)])
    return np.array([state.x / c, state.y / c, state.vx / (c * w), state.vy / (c * w)])


def orbit_state(phases: Phases, u: np.ndarray, contact: bool) -> OrbitState:
    memory = phases.session.snapshot()
    if contact:
        return OrbitState(*phases.on_circle(u), True, memory)
    c, w = phases.c, phases.omega
    return OrbitState(u[0] * c, u[1] * c, u[2] * c * w, u[3] * c * w, False, memory)


def switch_phase(phases: Phases, phi: float, u: np.ndarray, contact: bool):
    """State of the next phase after an event at φ (entry: plastic impact, eq. 4.1.5)."""
    if contact:  # leaving: free flight from the circle with the tangential velocity
        x, y, vx, vy = phases.on_circle(u)
        c, w = phases.c, phases.omega
        return np.array([x / c, y / c, vx / (c * w), vy / (c * w)]), False
    theta = math.atan2(u[1], u[0])
    v_k = (u[3] * math.cos(theta) - u[2] * math.sin(theta))
    entry = np.array([theta, v_k])
    if phases.normal_force(phi, entry) > 0.0:
        return entry, True
    x, y, vx, vy = phases.on_circle(entry)
    c, w = phases.c, phases.omega
    return np.array([x / c, y / c, vx / (c * w), vy / (c * w)]), False


SETTLE_ITERATIONS = 4
"""Most Newton iterations of :func:`settled_row` [-]."""
SETTLE_STOP = 1.0e-2
""":func:`settled_row` stops when the velocity change is below this fraction of the
integrator's error tolerance (atol + rtol |v|) [-]."""


def record_rows(phases: Phases, sol, phi_out, mask, table, contact: bool,
                settings) -> None:
    """Rows of ``table`` at the output angles ``phi_out[mask]`` from the segment ``sol``
    (free or ``contact`` phase), each on the equation of motion (:func:`settled_row`);
    the film memory is left as the segment left it."""
    rhs = phases.contact_rhs if contact else phases.free_rhs
    start = phases.session.snapshot()
    for i in np.flatnonzero(mask):
        u = settled_row(rhs, sol, phi_out[i], float(settings.absolute_tolerance),
                        float(settings.relative_tolerance))
        if not contact:
            c, w = phases.c, phases.omega
            table[i] = (u[0] * c, u[1] * c, u[2] * c * w, u[3] * c * w, 0.0, 0.0, 0.0)
            continue
        x, y, vx, vy = phases.on_circle(u)
        p_c, s = phases.normal_force(phi_out[i], u, with_sign=True)
        p_c = max(p_c, 0.0)
        table[i] = (x, y, vx, vy, p_c, phases.p.dry_friction * p_c * abs(s), 1.0)
    phases.session.restore(start)


def settled_row(rhs, sol, phi: float, atol: float, rtol: float) -> np.ndarray:
    """The state at φ [rad] of the segment ``sol`` (solve_ivp with dense output) for the
    scaled ODE u' = ``rhs``(φ, u), u = (positions, velocities): at a step end the step's
    state; between step ends the positions of the dense output with the velocities v
    solved from the equation of motion v' = rhs_v(φ, q, v), v' the derivative of the
    dense output (simplified Newton, forward-difference ∂rhs_v/∂v).

    Why: on the stiff slow manifold of a loaded film (∂rhs_v/∂v ~ −λ, λ 10³–10⁶ per
    radian) the interpolated velocity is the dense output's weakest part: p_max solved
    from it was wrong by up to 10 % (Radau, default tolerances; passenger car at 1000 rpm,
    171°) where the step ends were right to 0.06 %; solved from the equation of motion,
    an error δa of the interpolated acceleration moves v by only δa/λ (p_max within
    0.12 % there). Where the film is not stiff the solve changes v by no more than the
    dense output's own error. A Newton iteration that does not converge leaves the dense
    output's velocity.
    """
    dense = sol.sol
    ts = dense.ts
    k = min(max(int(np.searchsorted(ts, phi, side="left")) - 1, 0), dense.n_segments - 1)
    low, high = ts[k], ts[k + 1]
    interpolant = dense.interpolants[k]
    u = np.array(interpolant(phi), dtype=float)
    near = 1.0e-12 * max(1.0, abs(phi))
    if min(abs(phi - low), abs(high - phi)) <= near or high - low <= near:
        return u  # a step end
    delta = 1.0e-3 * (high - low)  # central difference of the polynomial
    rate = (interpolant(phi + delta) - interpolant(phi - delta)) / (2.0 * delta)
    half = u.size // 2
    velocity = u[half:].copy()

    def residual(v: np.ndarray) -> np.ndarray:
        state = u.copy()
        state[half:] = v
        return np.asarray(rhs(phi, state), dtype=float)[half:] - rate[half:]

    current = residual(velocity)
    jacobian = np.empty((half, half))
    for j in range(half):
        step = 1.0e-7 * max(1.0, abs(velocity[j]))
        shifted = velocity.copy()
        shifted[j] += step
        jacobian[:, j] = (residual(shifted) - current) / step
    trial = velocity
    for _ in range(SETTLE_ITERATIONS):
        if not np.all(np.isfinite(current)):
            return u
        try:
            change = np.linalg.solve(jacobian, -current)
        except np.linalg.LinAlgError:  # no velocity dependence to solve for
            return u
        trial = trial + change
        if np.all(np.abs(change) <= SETTLE_STOP * (atol + rtol * np.abs(trial))):
            u[half:] = trial
            return u
        current = residual(trial)
    return u  # not converged: the dense output's velocity
