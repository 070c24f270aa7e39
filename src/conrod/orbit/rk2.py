"""[D0]'s second-order Runge–Kutta (Heun) at a fixed crank-angle step, with the [D4]
contact treatment: projection x := x/Z after a step and removal of the normal velocity
(eqs 4.1.1–4.1.8), constrained motion along the circle while the journal presses on it.
A film declaring a compiled force and radial damping
(:class:`~conrod.film.capabilities.CompiledKernel`) runs fully compiled.

The film is stiff (damping time m/B ≪ 1° of crank angle), so this explicit scheme needs a
small step (``[solver] step_deg``, 0.01° by default); it is kept for fidelity to [D4] and
as an independent check of the adaptive integrator.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np

from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import FilmState
from conrod.film.capabilities import CompiledKernel
from conrod.orbit.contact import contact_acceleration
from conrod.orbit.memory import FilmSession
from conrod.orbit.problem import OrbitProblem, OrbitState, step_grid
from conrod.orbit.progress import AngleReports
from conrod.orbit.trajectory import CycleTrajectory


@nb.njit(cache=True)
def _settle_contact(x, y, vx, vy, radius, pressing):
    """Contact bookkeeping after a step ([D4] eqs 4.1.1–4.1.8); returns state and flag.

    Beyond the circle: project and remove the outward normal velocity (plastic impact).
    While the journal was pressing on the shell (P_c > 0 at the step start) it stays on
    the circle: project and remove any normal velocity. Otherwise it is free.
    """
    e = math.hypot(x, y)
    if e > radius or (pressing and e > 0.0):
        nx, ny = x / e, y / e
        x, y = radius * nx, radius * ny
        v_n = vx * nx + vy * ny
        if pressing or v_n > 0.0:
            vx, vy = vx - v_n * nx, vy - v_n * ny
        return x, y, vx, vy, True
    return x, y, vx, vy, False


@nb.njit  # function-typed arguments: specialised per film and process, not cached
def rk2_compiled_cycle(
    force, damping, params, state, dt, load_x, load_y, journal_speed, shell_speed,
    record_every, viscosity, radius, clearance, mass_x, mass_y, dry_friction, contact_radius,
):
    """Compiled Heun steps over one cycle for a film with a compiled ``force`` and radial
    ``damping`` (:class:`~conrod.film.capabilities.CompiledKernel`, parameters ``params``).

    state = (x, y, vx, vy, in_contact) [m, m/s]; loads and speeds sampled at the n+1 step
    points [N, rad/s]; ``dt`` step [s]. Returns rows (x, y, vx, vy, P_c, P_f, contact) every
    ``record_every`` steps, the end state and the largest stability number Δt B_rr/m [-]
    (Heun is stable for real negative eigenvalues when it is ≤ 2).
    """
    x, y, vx, vy, contact = state[0], state[1], state[2], state[3], state[4] > 0.5
    n_steps = load_x.size - 1
    out = np.empty((n_steps // record_every, 7))
    stiffness = 0.0
    lightest = min(mass_x, mass_y)
    for k in range(n_steps):
        b_rr = damping(math.hypot(x, y) / clearance, viscosity, params)
        stiffness = max(stiffness, dt * b_rr / lightest)
        wj, wb = journal_speed[k], shell_speed[k]
        fx, fy = force(x, y, vx, vy, wj + wb, viscosity, params)
        ax, ay, pc, pf = contact_acceleration(
            x, y, vx, vy, load_x[k] + fx, load_y[k] + fy, mass_x, mass_y, dry_friction,
            contact_radius, (wj - wb) * radius, contact,
)
        if k % record_every == 0 and k // record_every < out.shape[0]:
            row = k // record_every
            out[row, 0], out[row, 1], out[row, 2], out[row, 3] = x, y, vx, vy
            out[row, 4], out[row, 5], out[row, 6] = pc, pf, 1.0 if contact else 0.0
        xp, yp = x + dt * vx, y + dt * vy
        vxp, vyp = vx + dt * ax, vy + dt * ay
        wj, wb = journal_speed[k + 1], shell_speed[k + 1]
        fx, fy = force(xp, yp, vxp, vyp, wj + wb, viscosity, params)
        ax2, ay2, _, _ = contact_acceleration(
            xp, yp, vxp, vyp, load_x[k + 1] + fx, load_y[k + 1] + fy, mass_x, mass_y,
            dry_friction, contact_radius, (wj - wb) * radius, contact,
)
        x, y = x + 0.5 * dt * (vx + vxp), y + 0.5 * dt * (vy + vyp)
        vx, vy = vx + 0.5 * dt * (ax + ax2), vy + 0.5 * dt * (ay + ay2)
        x, y, vx, vy, contact = _settle_contact(x, y, vx, vy, contact_radius, pc > 0.0)
    return out, np.array([x, y, vx, vy, 1.0 if contact else 0.0]), stiffness


DEFAULT_STEP_DEG = 0.01
"""rk2 step for a film whose stiffness cannot be estimated, when none is given [deg]."""
STABILITY_MARGIN = 1.8
"""Largest Δt·B/m the automatic step aims at (Heun: stable up to 2) [-]."""
GROWTH_LIMIT = 10.0
"""Largest refinement of the automatic step from one trial cycle to the next [-]: a trial
whose stability number exceeded 2 diverged, and the stiffness it met on its way towards
the shell says little about the stiffness of the orbit."""
PYTHON_STEPS = 72_000
"""Most automatic rk2 steps per 720° for a film solved in Python (two film solves each):
those of :data:`DEFAULT_STEP_DEG`, already minutes per cycle on a grid [-]."""
ALTERNATIVES = ("integrator = 'implicit' or 'auto' (the same orbit with mass, L-stable and "
                "error-controlled), 'adaptive' or 'quasi_static'")
"""The integrators that run a bearing too stiff for rk2 [-]."""


def rk2_cycle(
    problem: OrbitProblem, state: OrbitState, step_deg: float | None, output_step_deg: float,
    settings=None,
) -> CycleTrajectory:
    """One cycle of fixed-step Heun integration from ``state`` at φ = 0; ``step_deg`` None:
    the largest stable step (:func:`stable_step_cycle`; ``settings``: the ``[solver]``
    section, for the implicit cycle that measures the stiffness of the orbit, None: its
    defaults)."""
    if step_deg is None:
        return stable_step_cycle(problem, state, output_step_deg, settings)
    return _fixed_step_cycle(problem, state, step_deg, output_step_deg, given=True)


def stable_step_cycle(problem: OrbitProblem, state: OrbitState, output_step_deg: float,
                      settings=None) -> CycleTrajectory:
    """Heun at the largest step output_step_deg/k whose stability number Δt·B/m, with the
    film's squeeze damping B along the orbit, stays below :data:`STABILITY_MARGIN`. The
    first step is chosen from the damping along the implicit (TR-BDF2) cycle from the same
    state (:func:`orbit_stiffness`); a trial cycle of a film with a compiled radial damping
    that still meets more (its orbit is not quite the implicit one) tells the stiffness it
    met, and the step shrinks until the cycle is stable, at most :data:`GROWTH_LIMIT`
    times per trial. A film whose damping cannot be measured runs at
    :data:`DEFAULT_STEP_DEG`. A bearing that needs more steps than the step budget is
    refused (:class:`CaseError`, naming the working integrators)."""
    stiffness = orbit_stiffness(problem, state, output_step_deg, settings)
    compiled = _damped_kernel(problem) is not None
    if stiffness is None and not compiled:
        return _fixed_step_cycle(problem, state, DEFAULT_STEP_DEG, output_step_deg)
    divisions = max(1, math.ceil(stiffness / STABILITY_MARGIN)) if stiffness else 1
    for _ in range(12):
        step = output_step_deg / divisions
        _check_budget(problem, step, compiled)
        if not compiled:
            return _fixed_step_cycle(problem, state, step, output_step_deg)
        try:
            return _fixed_step_cycle(problem, state, step, output_step_deg)
        except ConvergenceError as error:
            stiffness = error.residual if error.residual == error.residual else None
            factor = (stiffness / STABILITY_MARGIN if stiffness and math.isfinite(stiffness)
                      else GROWTH_LIMIT)
            divisions = max(divisions + 1, math.ceil(divisions * min(factor, GROWTH_LIMIT)))
    raise ConvergenceError(
        f"rk2 found no stable step down to {output_step_deg / divisions:.3g} deg (film too "
        f"stiff for an explicit scheme); use {ALTERNATIVES}", where="automatic rk2 step")


def _check_budget(problem: OrbitProblem, step_deg: float, compiled: bool) -> None:
    """CaseError when a cycle at ``step_deg`` takes more steps than the budget (of a
    compiled loop, or :data:`PYTHON_STEPS` per 720° for a film solved in Python)."""
    from conrod.cases.solver import MAX_INTEGRATOR_STEPS

    steps = problem.loads.cycle / math.radians(step_deg)
    budget = MAX_INTEGRATOR_STEPS if compiled else PYTHON_STEPS * problem.loads.cycle / (
        4.0 * math.pi)
    if steps > budget:
        kind = "" if compiled else " for a film solved in Python (two film solves a step)"
        raise CaseError(
            f"solver.integrator = 'rk2': this bearing's film is too stiff for the explicit "
            f"scheme: a stable step (Δt·B/m ≤ 2, B the squeeze damping along the orbit) is "
            f"below {step_deg:.3g} deg, {steps:.3g} steps per cycle, more than the budget of "
            f"{budget:.0f}{kind} (allowed: {ALTERNATIVES})")


def orbit_stiffness(problem: OrbitProblem, state: OrbitState, output_step_deg: float,
                    settings=None) -> float | None:
    """Largest stability number Δt·B/m at the step ``output_step_deg`` along the orbit with
    mass from ``state`` by the implicit integrator, B the squeeze damping at its largest
    eccentricity: the film's compiled radial damping, else the largest eigenvalue of
    −∂F/∂ė there (central differences of the film force) [-]; None when that orbit or
    the damping cannot be computed."""
    from conrod.cases.solver import SolverSection

    settings = settings if settings is not None else SolverSection()
    try:
        cycle = _implicit_orbit(problem, state, settings)
    except (CaseError, ConvergenceError):
        return None
    row = int(np.argmax(np.hypot(cycle.x, cycle.y)))
    kernel = _damped_kernel(problem)
    if kernel is not None:
        ratio = min(math.hypot(cycle.x[row], cycle.y[row]) / problem.clearance, 1.0)
        damping = float(kernel.radial_damping(ratio, problem.viscosity, kernel.params))
    else:
        damping = _damping(problem, cycle, row)
    dt = math.radians(output_step_deg) / problem.crank_speed
    stiffness = dt * damping / min(problem.mass_x, problem.mass_y)
    return stiffness if math.isfinite(stiffness) and stiffness > 0.0 else None


def _damped_kernel(problem: OrbitProblem) -> CompiledKernel | None:
    """The film's compiled kernel when it has a compiled force and radial damping (the
    compiled Heun loop), else None."""
    kernel = problem.compiled_force
    return kernel if kernel is not None and kernel.radial_damping is not None else None


def _implicit_orbit(problem: OrbitProblem, state: OrbitState, settings) -> CycleTrajectory:
    """One cycle with mass by the implicit integrator from ``state``."""
    from conrod.orbit.implicit import implicit_cycle
    from conrod.orbit.implicit_step import implicit_step_cycle, implicit_step_deg

    if problem.has_film_content:
        return implicit_step_cycle(problem, state, implicit_step_deg(settings),
                                   settings.output_step_deg, with_mass=True)
    return implicit_cycle(problem, state, settings)


def _damping(problem: OrbitProblem, cycle: CycleTrajectory, row: int) -> float:
    """Largest eigenvalue modulus of the damping −∂F/∂ė [N s/m] at the output ``row`` of
    ``cycle`` (central differences of the film force, the row's film memory)."""
    memory = cycle.film_memory[row] if cycle.film_memory else None
    wj, wb = (float(a[0]) for a in problem.loads.speeds(cycle.crank_angle[row:row + 1]))
    x, y, vx, vy = (float(a[row]) for a in (cycle.x, cycle.y, cycle.vx, cycle.vy))
    phi = float(cycle.crank_angle[row])
    delta = 1e-4 * problem.clearance * problem.crank_speed
    columns = []
    for dvx, dvy in ((delta, 0.0), (0.0, delta)):
        plus = problem.force_function(problem.session(memory))(x, y, vx + dvx, vy + dvy, wj, wb,
                                                               phi)
        minus = problem.force_function(problem.session(memory))(x, y, vx - dvx, vy - dvy,
                                                                wj, wb, phi)
        columns.append([(minus[0] - plus[0]) / (2 * delta), (minus[1] - plus[1]) / (2 * delta)])
    return float(np.max(np.abs(np.linalg.eigvals(np.array(columns).T))))


def _fixed_step_cycle(
    problem: OrbitProblem, state: OrbitState, step_deg: float, output_step_deg: float,
    given: bool = False,
) -> CycleTrajectory:
    """One cycle of Heun steps of ``step_deg``; ``given``: the user's ``solver.step_deg``,
    refused (:class:`CaseError`) where the scheme is unstable for this bearing's film
    (otherwise ConvergenceError, which :func:`stable_step_cycle` answers with a finer
    step)."""
    phi, record_every, n_out = step_grid(problem, step_deg, output_step_deg)
    load_x, load_y = problem.loads.load(phi)
    wj, wb = problem.loads.speeds(phi)
    dt = (phi[1] - phi[0]) / problem.crank_speed
    start = np.array([state.x, state.y, state.vx, state.vy, float(state.in_contact)])
    kernel = problem.compiled_force
    session = None
    if kernel is not None and kernel.radial_damping is not None:
        g = problem.film.geometry
        table, end, stiffness = rk2_compiled_cycle(
            kernel.force, kernel.radial_damping, kernel.params, start, dt, load_x, load_y,
            wj, wb, record_every, problem.viscosity, g.radius, g.radial_clearance,
            problem.mass_x, problem.mass_y, problem.dry_friction, problem.contact_radius,
)
        if stiffness > 2.0 and given:
            raise CaseError(
                f"solver.step_deg = {step_deg:g}: too large for this bearing's film stiffness "
                f"(Δt·B/m = {stiffness:.3g} > 2 along the orbit: explicit Heun unstable) "
                f"(allowed: <= {step_deg * 1.9 / stiffness:.2g} deg, unset for the "
                f"automatic stable step, or {ALTERNATIVES}) [deg]")
        if stiffness > 2.0:
            raise ConvergenceError(
                f"rk2 step too large for the film stiffness: Δt·B/m = {stiffness:.3g} > 2 "
                f"(explicit Heun unstable); use solver.step_deg ≤ {step_deg * 1.9 / stiffness:.2g}"
                f" deg or {ALTERNATIVES}", where=f"step {step_deg} deg", residual=stiffness,
)
    else:
        session = problem.session(state.film_memory)
        table, end, rows_memory = _rk2_generic_cycle(
            problem, start, dt, load_x, load_y, wj, wb, record_every, session
)
    if not np.all(np.isfinite(table)):
        what = (f"solver.step_deg = {step_deg:g}" if given
                else f"solver.integrator = 'rk2' (automatic step {step_deg:g} deg)")
        raise CaseError(
            f"{what}: the explicit Heun orbit diverges at this step on this bearing's film "
            f"(too stiff for the step) (allowed: a smaller solver.step_deg, or "
            f"{ALTERNATIVES})")
    memory = session.snapshot() if session is not None else None
    end_state = OrbitState(end[0], end[1], end[2], end[3], bool(end[4] > 0.5), memory)
    traj = CycleTrajectory.from_table(phi[::record_every][:n_out], table, end_state, len(phi) - 1)
    if session is not None and session.has_memory:
        traj.film_memory = rows_memory
    return traj


def _rk2_generic_cycle(problem, start, dt, load_x, load_y, wj, wb, record_every,
                       session: FilmSession):
    """The same Heun scheme for any film model (Python loop; slow for grid models); the film
    memory is advanced in lock-step after every step (:class:`FilmSession`)."""
    force = problem.force_function(session)
    radius = problem.film.geometry.radius
    x, y, vx, vy, contact = start[0], start[1], start[2], start[3], bool(start[4] > 0.5)
    n_steps = load_x.size - 1
    out = np.empty((n_steps // record_every, 7))
    memory = [None] * out.shape[0]

    def acceleration(k, x, y, vx, vy):
        fx, fy = force(x, y, vx, vy, wj[k], wb[k], k * dt * problem.crank_speed)
        return contact_acceleration(
            x, y, vx, vy, load_x[k] + fx, load_y[k] + fy, problem.mass_x, problem.mass_y,
            problem.dry_friction, problem.contact_radius, (wj[k] - wb[k]) * radius, contact,
)

    reports = AngleReports()
    for k in range(n_steps):
        reports.reached(k * dt * problem.crank_speed)
        ax, ay, pc, pf = acceleration(k, x, y, vx, vy)
        if k % record_every == 0:
            out[k // record_every] = (x, y, vx, vy, pc, pf, float(contact))
            memory[k // record_every] = session.snapshot()
        xp, yp, vxp, vyp = x + dt * vx, y + dt * vy, vx + dt * ax, vy + dt * ay
        ax2, ay2, _, _ = acceleration(k + 1, xp, yp, vxp, vyp)
        session.advance(FilmState(eccentricity_x=x, eccentricity_y=y, velocity_x=vx, velocity_y=vy,
                                  journal_speed=wj[k], shell_speed=wb[k],
                                  viscosity=problem.viscosity,
                                  journal_feed=problem.journal_feed(k * dt * problem.crank_speed)),
                        dt)
        x, y = x + 0.5 * dt * (vx + vxp), y + 0.5 * dt * (vy + vyp)
        vx, vy = vx + 0.5 * dt * (ax + ax2), vy + 0.5 * dt * (ay + ay2)
        x, y, vx, vy, contact = _settle_contact(x, y, vx, vy, problem.contact_radius, pc > 0.0)
    return out, np.array([x, y, vx, vy, float(contact)]), memory
