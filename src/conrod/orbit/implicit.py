"""One cycle of the orbit with mass by TR-BDF2 (:mod:`conrod.orbit.tr_bdf2`).

Free flight is integrated by the TR-BDF2 segment: compiled together with the film force
for a film with a compiled kernel (short bearing, tables), in Python with the film solved
through its :class:`~conrod.orbit.memory.FilmSession` otherwise. The state is scaled as in
:mod:`conrod.orbit.adaptive`, u = (x/c, y/c, v_x/(c ω), v_y/(c ω)), over the crank angle.
Hard contact is the adaptive integrator's: a segment stops where the centre reaches the
contact circle (located on the step's cubic interpolant), the plastic impact removes the
normal velocity, the contact phase runs on the circle until the normal force vanishes.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from conrod.errors import CaseError, ConvergenceError, FilmThicknessError
from conrod.film.base import FilmState
from conrod.film.capabilities import HasFlightKernel, HasForceJacobian
from conrod.orbit.adaptive import (
    MAX_PHASE_CHANGES,
    Phases,
    orbit_state,
    record_rows,
    scaled_state,
    solve_segment,
    switch_phase,
)
from conrod.orbit.compiled_flight import flight_segment
from conrod.orbit.problem import OrbitProblem, OrbitState, periodic_sample
from conrod.orbit.progress import REPORT_EVERY_DEG, report_angle
from conrod.orbit.tr_bdf2 import (
    STATUS_END,
    STATUS_HIT,
    STATUS_JACOBIAN,
    STATUS_NEWTON,
    specialise,
)
from conrod.orbit.trajectory import CycleTrajectory

FIRST_STEP = 1.0e-4
"""First trial step of a free segment [rad] (error control grows it)."""
PYTHON_REFRESH_RATE = 0.1
"""Newton contraction rate above which a film solved in Python gets a new Jacobian (a
compiled film gets one after every step that needed more than one iteration) [-]."""
NEWTON_FILM_TOLERANCE = 0.5
"""Multigrid tolerance of a compiled grid film inside Newton, as a fraction of the
integrator's ``relative_tolerance`` [-]: a relative force error δ moves a stage by about δ
times the state, below the Newton stop (5 % of the tolerance) for δ ≤ 0.05 rtol; the
multigrid's force error is ~0.03 × its tolerance (last relative change per cycle;
measured on the passenger-car case at 72×16), so 0.5 rtol leaves a factor ~3 (and the
absolute tolerance, 1e-4 by default, a far larger one). Passenger car 72×16: 21 800
multigrid cycles per cycle at 0.1, 19 600 at 0.5, 18 400 at 1.0; the orbits of all three
within 3.3e-5 c of one at 5e-3."""
STEPS_PER_DEGREE = 2000
"""Most accepted steps per degree of crank angle in a segment before giving up [-]."""


def _failure_hint(film) -> str:
    """What to change when the free flight fails on ``film``."""
    if getattr(film, "pressure_viscosity", None) is not None:
        return ("the film's viscosity rises with pressure, so near this angle its force "
                "changes by orders of magnitude over a small change of the journal velocity "
                "(rigid bore beyond the pressure-viscosity law's range): check p_max with the "
                "short film, run the isoviscous film (lubricant.pressure_viscosity = "
                "'none') or an elastic big end")
    return ("loosen [solver] relative_tolerance/absolute_tolerance or use "
            "integrator = 'adaptive'")


def implicit_cycle(problem: OrbitProblem, state: OrbitState, settings) -> CycleTrajectory:
    """One cycle from ``state`` at φ = 0; ``settings`` = the ``[solver]`` section."""
    if problem.has_film_content:
        raise CaseError(
            f"solver.integrator = 'implicit': the {problem.film.name} film carries a film "
            "content that is advanced in lock-step with a fixed step (allowed: rk2, "
            "quasi_static)")
    phases = Phases(problem, state)
    runner = _FreeFlight(problem, phases, settings)
    phi_out = problem.output_angles(settings.output_step_deg)
    table = np.zeros((phi_out.size, 7))
    free_u = np.zeros((phi_out.size, 4))
    free_rows = np.zeros(phi_out.size, dtype=bool)
    end = float(problem.loads.cycle)
    phi, contact, steps, next_out = 0.0, state.in_contact, 0, 0
    current = scaled_state(state, problem.clearance, problem.crank_speed, phases)
    leave = _leave_event(phases)
    for _ in range(MAX_PHASE_CHANGES):
        if not contact:
            first = next_out
            status, phi, u, taken, next_out = runner.run(phi, end, current, phi_out,
                                                         free_u, next_out)
            free_rows[first:next_out] = True
            steps += taken
            if status == STATUS_END:
                _fill_free(table, free_u, free_rows, problem)
                return CycleTrajectory.from_table(
                    phi_out, table, orbit_state(phases, u, False), steps)
            current, contact = switch_phase(phases, phi, u, False)
            continue
        sol = solve_segment(phases.contact_rhs, phi, end, current, leave, settings,
                             phases.session)
        if sol.status < 0:
            raise ConvergenceError(f"contact phase integration failed: {sol.message}",
                                   where=f"crank angle {math.degrees(phi):.2f} deg")
        steps += sol.t.size - 1
        phi_end = float(sol.t[-1])
        last = sol.status == 0
        mask = (phi_out >= phi) & ((phi_out <= phi_end) if last else (phi_out < phi_end))
        record_rows(phases, sol, phi_out, mask, table, True, settings)
        if last:
            _fill_free(table, free_u, free_rows, problem)
            return CycleTrajectory.from_table(
                phi_out, table, orbit_state(phases, sol.y[:, -1], True), steps)
        next_out = int(np.searchsorted(phi_out, phi_end, side="left"))
        phi = phi_end
        current, contact = switch_phase(phases, phi, sol.y[:, -1], True)
    raise ConvergenceError("contact chattering: too many contact entries/exits",
                           where=f"crank angle {math.degrees(phi):.2f} deg")


class _FreeFlight:
    """TR-BDF2 free-flight segments of one cycle (compiled or Python)."""

    def __init__(self, problem: OrbitProblem, phases: Phases, settings):
        kernel = problem.compiled_force
        self.compiled = kernel is not None
        self.chunked = kernel is None  # a closed-form or tabulated force: one chunk
        self.flight = None
        self.session = phases.session
        self.refresh_rate = 0.0 if self.compiled else PYTHON_REFRESH_RATE
        self.hint = _failure_hint(problem.film)
        if self.compiled:
            self.segment, self.params = flight_segment(kernel.force), kernel.params
        elif problem.asperity is None and isinstance(problem.film, HasFlightKernel):
            self.flight = problem.film.flight_kernel(
                phases.session.memory,
                NEWTON_FILM_TOLERANCE * float(settings.relative_tolerance))
        self.evaluate = self.flight is None  # stage derivatives: see tr_bdf2._stage
        if self.flight is not None:  # grid film compiled, expensive Jacobian: keep it
            self.compiled = True
            self.segment = flight_segment(self.flight.force, self.flight.jacobian)
            self.params = self.flight.params
        elif not self.compiled:
            jacobian = None
            if problem.asperity is None and isinstance(problem.film, HasForceJacobian):
                jacobian = functools.partial(_film_jacobian, problem, phases)
            self.segment = specialise("python", functools.partial(_guarded_rhs, phases),
                                      jacobian, compiled=False)
            self.params = ()
        self.data = (phases.angles, phases.table, float(problem.loads.cycle),
                     float(problem.viscosity), float(problem.clearance),
                     float(problem.crank_speed), float(problem.mass_x),
                     float(problem.mass_y))
        self.circle = problem.contact_radius / problem.clearance
        self.max_step = math.radians(settings.max_step_deg)
        self.rtol = float(settings.relative_tolerance)
        self.atol = float(settings.absolute_tolerance)
        self.h = FIRST_STEP

    def run(self, phi, end, u, phi_out, out_u, next_out):
        """(status, φ, u, steps, next output row) of one segment from φ; for a film
        solved on a grid integrated in chunks ending on multiples of
        :data:`~conrod.orbit.progress.REPORT_EVERY_DEG` (each reported to the progress
        display; ~0.5 ms of call overhead each, which a compiled closed-form film would
        feel)."""
        chunk = math.radians(REPORT_EVERY_DEG) if self.chunked else end
        h, total = min(self.h, FIRST_STEP * 10), 0
        while True:
            stop = min(end, (math.floor(phi / chunk + 1e-9) + 1) * chunk)
            if end - stop < 1e-9 * chunk:
                stop = end
            status, phi, u, h, steps, next_out = self._chunk(phi, stop, u, h, phi_out,
                                                             out_u, next_out)
            total += steps
            report_angle(phi)
            if status != STATUS_END or stop >= end:
                return status, phi, u, total, next_out

    def _chunk(self, phi, end, u, h, phi_out, out_u, next_out):
        max_steps = int(STEPS_PER_DEGREE * max(math.degrees(end - phi), 1.0))
        result = self.segment(self.params, self.data, float(phi), float(end),
                              np.asarray(u, dtype=float), h, self.max_step, self.rtol,
                              self.atol, self.circle, phi_out, out_u, next_out, max_steps,
                              self.refresh_rate, self.evaluate)
        status, phi_new, u_new, h, steps, next_out, self.evaluations = result
        self.h = h
        if self.flight is not None:  # the warm start goes on in the session
            self.session.restore(self.flight.memory())
        if status not in (STATUS_END, STATUS_HIT):
            what = {STATUS_NEWTON: "Newton iteration failed at the smallest step",
                    STATUS_JACOBIAN: "the film's force Jacobian could not be evaluated "
                    "at the state reached"}.get(status, "step size collapsed")
            raise ConvergenceError(
                f"implicit orbit integration: {what} (eccentricity ratio "
                f"{math.hypot(u_new[0], u_new[1]):.4f}); {self.hint}",
                where=f"crank angle {math.degrees(phi_new):.2f} deg")
        return status, phi_new, u_new, h, steps, next_out


def _guarded_rhs(phases: Phases, phi, u, params, data) -> np.ndarray:
    """du/dφ [-] of the free flight solved in Python; NaN where a Newton iterate or a
    predicted stage lies beyond the shell (the film cannot be solved there), which the
    step takes as a failed iteration and retries shorter (the compiled Reynolds force of
    :mod:`conrod.film.reynolds.flight` gives NaN there too)."""
    try:
        return phases.free_rhs(phi, u)
    except FilmThicknessError:
        return np.full(4, np.nan)


def _film_jacobian(problem: OrbitProblem, phases: Phases, phi, u, f0, params, data):
    """∂(du/dφ)/∂u [-] from the film's own ∂F/∂(e, ė)
    (:class:`~conrod.film.capabilities.HasForceJacobian`)."""
    c, w = problem.clearance, problem.crank_speed
    _, _, wj, wb = periodic_sample(phi, phases.angles, phases.table, problem.loads.cycle)
    state = FilmState(eccentricity_x=u[0] * c, eccentricity_y=u[1] * c, velocity_x=u[2] * c * w,
                      velocity_y=u[3] * c * w, journal_speed=wj, shell_speed=wb,
                      viscosity=problem.viscosity, journal_feed=problem.journal_feed(phi))
    _, film, _ = problem.film.force_jacobian(state, phases.session.memory)
    out = np.zeros((4, 4))
    out[0, 2] = out[1, 3] = 1.0
    for row, mass in ((0, problem.mass_x), (1, problem.mass_y)):
        scale = mass * c * w * w
        out[2 + row, :2] = film[row, :2] * c / scale
        out[2 + row, 2:] = film[row, 2:] * c * w / scale
    return out


def _leave_event(phases: Phases):
    def leave(phi_event: float, u: np.ndarray) -> float:
        return phases.leave(phi_event, u)

    leave.terminal, leave.direction = True, -1.0  # type: ignore[attr-defined]
    return leave


def _fill_free(table, free_u, free_rows, problem: OrbitProblem) -> None:
    """Rows of the free phases in SI units (contact columns zero)."""
    c, w = problem.clearance, problem.crank_speed
    rows = np.flatnonzero(free_rows)
    table[rows, 0] = free_u[rows, 0] * c
    table[rows, 1] = free_u[rows, 1] * c
    table[rows, 2] = free_u[rows, 2] * c * w
    table[rows, 3] = free_u[rows, 3] * c * w
    table[rows, 4:] = 0.0
