"""One implicit step of the journal with mass on the deforming bore.

The orbit with mass (:mod:`conrod.orbit.coupled_orbit`) steps the journal centre by
backward Euler or BDF2 over a step Δt. Both formulas write the end position, the end
acceleration and the bore's rate in the squeeze term through one step τ (Δt for backward
Euler, 2Δt/3 for BDF2) and reference values fixed by the history:

.. math:: e = e_r + τ v,\\qquad a = (v − v_r)/τ,\\qquad ∂u/∂t = (u − u_r)/τ

so the unknowns of the step are the end velocity v and the bore displacement u, solved
together by the Newton iteration of :mod:`conrod.ehd.newton` on

.. math:: G = u − λP(C f + U c(φ)) = 0,\\qquad F(e, v, u) + W − m (v − v_r)/τ = 0.

The bore's rate is taken over the step τ of the journal (not over the short interval of an
explicit step), so the squeeze term is as stiff in u as the orbit's own damping and no
stiffer. The Jacobian is exact on the film's active set: for the Reynolds film h depends on
the journal position through −e_x cos θ − e_y sin θ and ḣ on its velocity through
−v_x cos θ − v_y sin θ, the same fields as a bore displacement −cos θ_j at every node j
with its rate. Hence, with D_j = ∂/∂u_j including the rate (1/τ) term of
:func:`conrod.ehd.response.film_response`,

.. math:: \\frac{d}{dv_x} = τ\\frac{∂}{∂e_x} + \\frac{∂}{∂v_x} = −τ \\sum_j \\cos θ_j\\,D_j

(the journal velocity terms cancel), and the same with sin θ_j for v_y: one sparse LU of
the film gives the whole Jacobian of the step.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.ehd.newton import ChordJacobian, newton_balance
from conrod.ehd.response import FilmResponse, PressureEvaluation, film_response
from conrod.film.base import FilmState


@dataclass(frozen=True)
class MassStepRequest:
    """What one implicit step of the journal with mass asks of the elastic film.

    position_reference : ndarray  e_r (2,): end position e = e_r + τ v [m].
    velocity_reference : ndarray  v_r (2,): end acceleration a = (v − v_r)/τ [m/s].
    tau : float  Step of the formula (Δt backward Euler, 2Δt/3 BDF2) [s].
    dt : float  Time step Δt [s].
    mass : ndarray  Moving mass (m_x, m_y) [kg].
    load : ndarray  Load W on the journal at the end of the step (2,) [N].
    journal_speed, shell_speed : float  ω_j, ω_b at the end of the step [rad/s].
    viscosity : float  Dynamic viscosity μ [Pa s].
    crank_angle : float  Crank angle φ at the end of the step [rad].
    guess : ndarray  Start value of the end velocity (2,) [m/s].
    bdf2 : bool  Second-order step (the previous memory is used for u_r) [-].
    """

    position_reference: np.ndarray
    velocity_reference: np.ndarray
    tau: float
    dt: float
    mass: np.ndarray
    load: np.ndarray
    journal_speed: float
    shell_speed: float
    viscosity: float
    crank_angle: float
    guess: np.ndarray
    bdf2: bool


@dataclass(frozen=True)
class MassStepOutcome:
    """End of an implicit step: velocity [m/s], position [m], the film memory there, the
    force residual |F + W − m a| [N] and whether the step converged [-]."""

    velocity: np.ndarray
    position: np.ndarray
    memory: Any
    force_residual: float
    converged: bool


def bore_reference(memory, previous, bdf2: bool) -> np.ndarray:
    """u_r of the bore rate (u − u_r)/τ: u_n (backward Euler) or (4u_n − u_{n−1})/3 [m]."""
    if not bdf2 or previous is None:
        return memory.deformation
    return (4.0 * memory.deformation - previous.deformation) / 3.0


def bore_start(memory, previous, earlier=None) -> np.ndarray:
    """Start value of u at the end of the step: u_n extrapolated linearly, or
    quadratically when ``earlier`` (two steps back) is given [m]."""
    if previous is None:
        return memory.deformation
    if earlier is not None:
        return 3.0 * (memory.deformation - previous.deformation) + earlier.deformation
    return 2.0 * memory.deformation - previous.deformation


def mass_step(film, request: MassStepRequest, memory, previous=None,
              extra_force=None, earlier=None) -> MassStepOutcome:
    """The step of ``request`` from the elastic ``film``'s ``memory`` (at the start of the
    step; ``previous``: one step earlier); ``extra_force(x, y)`` an additional force on
    the journal [N], left out of the Jacobian (the rigid asperity force, which the orbit
    passes only for a film that does not carry the asperity contact on its deformed film
    itself — :meth:`conrod.ehd.film.ElasticFilm.carries_asperity`)."""
    settings = film.settings
    turned = film.crank_speed * request.dt
    at_end = dataclasses.replace(
        memory, crank_angle=request.crank_angle, elapsed=memory.elapsed + turned,
        clocked=True, reference=bore_reference(memory, previous, request.bdf2),
        reference_dt=request.tau, iterations=0, updates=0)
    share = settings.share(at_end.elapsed)
    operator = share * film.housing.corrected_compliance
    inertia = share * film.inertia_deformation(request.crank_angle)
    tau, mass = request.tau, np.asarray(request.mass, dtype=float)

    def evaluate(u: np.ndarray, v: np.ndarray):
        x, y = request.position_reference + tau * v
        state = FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                          velocity_x=float(v[0]), velocity_y=float(v[1]),
                          journal_speed=request.journal_speed,
                          shell_speed=request.shell_speed, viscosity=request.viscosity)
        forces, h_min, payload = film.evaluator(state, at_end)(u)
        force = payload.force(film.base) - mass * (v - request.velocity_reference) / tau
        if extra_force is not None:
            force = force + np.asarray(extra_force(x, y))
        return forces, force, h_min, payload

    c = film.base.geometry.radial_clearance
    start = (bore_start(memory, previous, earlier) if share > 0.0
             else np.zeros_like(memory.deformation))
    outcome = newton_balance(
        evaluate, _responder(film, tau, mass), start, np.asarray(request.guess, dtype=float),
        np.asarray(request.load, dtype=float), inertia, operator, c,
        c * max(film.crank_speed, 1e-3), film._coupling.tolerance,
        5 * settings.max_iterations, settings.increment_share,
        chord=_chord(film, share > 0.0),
        travel=-tau * _trig(film), refresh_after_first=True)
    payload: PressureEvaluation = outcome.payload
    after = dataclasses.replace(
        at_end, inner=payload.memory(), deformation=outcome.deformation,
        iterations=outcome.iterations, updates=outcome.updates, residual=outcome.residual,
        increment=outcome.increment,
        deformation_rate=float(np.max(np.abs(outcome.deformation - memory.deformation)))
        / request.dt)
    velocity = np.asarray(outcome.velocity, dtype=float)
    after = dataclasses.replace(after, acceleration=(velocity - request.velocity_reference)
                                / tau)
    scale = float(np.hypot(*request.load)) + 1.0
    return MassStepOutcome(velocity, request.position_reference + tau * velocity, after,
                           outcome.force_residual * scale, outcome.converged)


def _chord(film, elastic: bool) -> ChordJacobian:
    """The carried Jacobian of the with-mass steps (rigid start and elastic apart)."""
    key = "mass_elastic" if elastic else "mass_rigid"
    if key not in film.chords:
        film.chords[key] = ChordJacobian()
    return film.chords[key]


def _trig(film) -> np.ndarray:
    """(cos θ_j, sin θ_j) of the bore nodes (n, 2) [-]."""
    return np.stack([np.cos(film.housing.angles), np.sin(film.housing.angles)], axis=1)


def _responder(film, tau: float, mass: np.ndarray):
    """payload → the step's exact response: ∂/∂u of the film (rate over τ included) and
    ∂/∂v through the end position and velocity, −τ Σ_j (cos θ_j, sin θ_j) ∂/∂u_j, with
    −m/τ of the inertia term on the force (module docstring)."""
    trig = _trig(film)

    def respond(payload: PressureEvaluation) -> FilmResponse:
        response = film.with_contact_response(  # asperity terms with the bore's
            film_response(film.base, payload.state, payload.pressure, film._nodal,
                          tau if film.settings.deformation_rate else None), payload)
        nodal_by_velocity = -tau * response.nodal_by_bore @ trig
        force_by_velocity = -tau * response.force_by_bore @ trig - np.diag(mass) / tau
        if not film.settings.deformation_rate:  # the journal's own squeeze term
            nodal_by_velocity = nodal_by_velocity + response.nodal_by_velocity
            force_by_velocity = force_by_velocity + response.force_by_velocity
        return FilmResponse(response.nodal_by_bore, nodal_by_velocity,
                            response.force_by_bore, force_by_velocity)
    return respond
