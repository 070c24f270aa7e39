"""One implicit content step of the journal and the deforming bore solved together.

The content orbit (:mod:`conrod.orbit.content_orbit`) steps the journal by backward Euler
or BDF2 over Δt; both write the end position and the end acceleration through one step τ
(Δt for backward Euler, 2Δt/3 for BDF2) and reference values fixed by the history,

.. math:: e = e_r + τ v,\\qquad a = (v − v_r)/τ,

so the unknowns of a step are the end velocity v and the bore displacement u, solved
together by the Newton iteration of :mod:`conrod.ehd.newton` on

.. math:: G = u − λP(C f + U c(φ)) = 0,\\qquad F(e, u) + W − m (v − v_r)/τ = 0,

f and F the nodal forces and the force of the film's implicit content step
(:mod:`conrod.film.mass_conserving_step`) on the film h = c − e_x cos θ − e_y sin θ + u.
The end position moves h at film row i by −cos θ_i ∂e_x − sin θ_i ∂e_y, exactly as a bore
displacement u_i = −cos θ_i (resp. −sin θ_i) does (a bore node per film row), and the
content step sees the journal velocity only through the position (its squeeze is the
change of the content). Hence the velocity columns of the Jacobian are

.. math:: \\frac{d}{dv_x} = −τ \\sum_i \\cos θ_i \\frac{∂}{∂u_i}

from the bore columns of the step's exact response on its cavitation set
(:mod:`conrod.ehd.mass_conserving_response`): one sparse LU gives the whole Jacobian,
and each iterate costs one film step — no finite differences of whole bore couplings.
A start memory without its film thickness (the first step from a non-content memory)
adds the journal's squeeze to the known content; the Jacobian then leaves it out and the
iteration converges more slowly.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.ehd.mass_conserving_response import force_by_bore, pressure_by_bore
from conrod.ehd.memory import content_bdf2, start_deformation
from conrod.ehd.newton import ChordJacobian, newton_balance
from conrod.ehd.response import FilmResponse
from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import FilmState
from conrod.film.mass_conserving_results import axial_weights

JOINT_SOLVES = 40
"""Most film steps of one joint Newton iteration before the step is left to the orbit's
own iteration [-]."""


@dataclass(frozen=True)
class JointOutcome:
    """End of a joint step: velocity v [m/s] (2,), the elastic memory there, the force
    residual |F + W − m a| / (|W| + 1 N) [-], max|G| [m], whether it converged."""

    velocity: np.ndarray
    memory: Any
    force_residual: float
    bore_residual: float
    converged: bool


def joint_content_step(film, memory, previous, dt: float, *, position_reference,
                       velocity_reference, tau: float, mass, load, speeds,
                       viscosity: float, guess, force_tolerance: float) -> JointOutcome | None:
    """The content step of ``film`` (:class:`~conrod.ehd.mass_conserving_ehd.\
ElasticMassConservingFilm`) from ``memory`` (``previous``: one step earlier, BDF2 in the
    content) with the journal and the bore together (module docstring); None when the
    film closes or fails at the start value."""
    turned = film.crank_speed * dt
    angle, elapsed = memory.crank_angle + turned, memory.elapsed + turned
    share = film.settings.share(elapsed)
    operator = share * film.housing.corrected_compliance
    inertia = share * film.inertia_deformation(angle)
    mass = np.asarray(mass, dtype=float)
    bdf2 = content_bdf2(memory, previous)
    rate_step = dt / (1.5 if bdf2 else 1.0)
    evaluate = _evaluator(film, memory, previous, dt, np.asarray(position_reference, float),
                          np.asarray(velocity_reference, float), tau, mass, speeds,
                          viscosity)
    start = (start_deformation(memory, None, previous) if share > 0.0
             else np.zeros_like(memory.deformation))
    c = film.base.geometry.radial_clearance
    try:
        outcome = newton_balance(
            evaluate, _responder(film, tau, mass, rate_step), start,
            np.asarray(guess, dtype=float), np.asarray(load, dtype=float), inertia, operator,
            c, c * max(film.crank_speed, 1e-3), film._coupling.tolerance, JOINT_SOLVES,
            film.settings.increment_share, chord=_chord(film, share > 0.0, bdf2),
            travel=-tau * _trig(film), refresh_after_first=True)
    except (CaseError, ConvergenceError):
        return None
    fx, fy, inner = outcome.payload.step
    converged = (outcome.residual <= film._coupling.tolerance
                 and outcome.force_residual <= force_tolerance)
    film.joint_calls += 1
    film.joint_solves += outcome.iterations
    after = dataclasses.replace(
        memory, inner=inner, deformation=outcome.deformation, crank_angle=angle,
        elapsed=elapsed, iterations=outcome.iterations, updates=outcome.updates,
        residual=outcome.residual,
        increment=outcome.increment,
        deformation_rate=float(np.max(np.abs(outcome.deformation - memory.deformation)))
        / dt, reference=memory.deformation, reference_dt=dt)
    return JointOutcome(np.asarray(outcome.velocity, dtype=float), after,
                        outcome.force_residual, outcome.residual, converged)


@dataclass(frozen=True)
class _Payload:
    """One film step of the iteration: (F_x, F_y, film memory) and its deformed state."""

    step: tuple
    state: FilmState


def _evaluator(film, memory, previous, dt, position_reference, velocity_reference, tau,
               mass, speeds, viscosity):
    """(u, v) → (nodal forces [N], F − m a [N] (2,), h_min [m], payload); each film step
    starts from the last one."""
    before = previous.inner if previous is not None else None
    latest = [None]

    def evaluate(u: np.ndarray, v: np.ndarray):
        x, y = position_reference + tau * v
        state = FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                          velocity_x=float(v[0]), velocity_y=float(v[1]),
                          journal_speed=speeds[0], shell_speed=speeds[1],
                          viscosity=viscosity, deformation=film._field(u))
        fx, fy, inner = film.base.content_step(state, memory.inner, dt, latest[0], before)
        latest[0] = inner
        forces = np.sum(film._nodal * film.base.gauge_pressure(inner.pressure, state), axis=1)
        force = np.array([fx, fy]) - mass * (v - velocity_reference) / tau
        return forces, force, float(inner.thickness.min()), _Payload((fx, fy, inner), state)
    return evaluate


def _responder(film, tau: float, mass: np.ndarray, rate_step: float):
    """payload → FilmResponse of the step: ∂f/∂u, ∂F/∂u on the step's cavitation set and
    the velocity columns −τ Σ_i (cos θ_i, sin θ_i) ∂/∂u_i, with −m/τ on the force."""
    base = film.base
    dx, dz = base.spacing()
    trig = _trig(film)

    def respond(payload: _Payload) -> FilmResponse:
        state, inner = payload.state, payload.step[2]
        viscous = 12.0 * state.viscosity * dx * dz / rate_step
        d_pressure = pressure_by_bore(base.fields(state), inner.pressure, inner.fraction,
                                      viscous)
        nodal = np.einsum("rjk,jk->jr", d_pressure, film._nodal)
        force = force_by_bore(d_pressure, axial_weights(inner.pressure.shape[1], dz),
                              trig[:, 0], trig[:, 1], base.geometry.radius)
        return FilmResponse(nodal, -tau * nodal @ trig, force,
                            -tau * force @ trig - np.diag(mass) / tau)
    return respond


def _chord(film, elastic: bool, bdf2: bool) -> ChordJacobian:
    """The carried Jacobian of the joint steps (rigid start / elastic, Euler / BDF2)."""
    key = f"joint_{'elastic' if elastic else 'rigid'}_{'bdf2' if bdf2 else 'euler'}"
    if key not in film.chords:
        film.chords[key] = ChordJacobian()
    return film.chords[key]


def _trig(film) -> np.ndarray:
    """(cos θ_i, sin θ_i) of the film rows (= bore nodes) (n, 2) [-]."""
    theta, _ = film.base.grid()
    return np.stack([np.cos(theta), np.sin(theta)], axis=1)
