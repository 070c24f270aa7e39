"""Newton iteration of the coupled bore and film with the film's exact response.

Unknowns z = (u/c, v/v_s): the corrected bore displacement u [m] at the film nodes and, for
the massless journal, its velocity v [m/s]; residuals r = (G/c, (F + W)/W_s) with
G = u − λP(C f + U c(φ)) (:mod:`conrod.ehd.balance` has the same system solved by a
quasi-Newton method with finite differences). Here the Jacobian is exact:

.. math:: J = \\begin{pmatrix} I - λPC\\,∂f/∂u & -λPC\\,∂f/∂v \\\\
                               ∂F/∂u & ∂F/∂v \\end{pmatrix}

with ∂f/∂u, ∂f/∂v, ∂F/∂u, ∂F/∂v from one sparse LU of the film on its converged active set
(:mod:`conrod.ehd.response`). A Jacobian is reused while an update reduces the residual
norm to at most :data:`CONTRACTION` of its value (chord steps, also across steps) and
rebuilt otherwise — for the implicit step with mass also after the first update of a step
(``refresh_after_first``); each update is cut back (halving) until the residual norm decreases —
across a switch of the cavitation set, where no cut may decrease it, the best trial is
taken — and scaled so that max|Δu| stays below a share of the current h_min (Rodin 2004:
the relaxation factor Δ of the deformation increment). With the velocity held
(``with_velocity=False``) the same iteration solves G(u) = 0 at fixed journal kinematics.
"""

from __future__ import annotations

import numpy as np

from conrod.ehd.balance import ACCEPTABLE, FORCE_TOLERANCE, BalanceOutcome

CONTRACTION = 0.1
"""Keep a Jacobian while an update reduces the residual norm to at most this share [-]."""

LINE_SEARCH_CUTS = 6
"""Trials of an update (halving the step) before the best one is taken [-]."""


class ChordJacobian:
    """The inverse Jacobian of the last Newton iteration, carried to the next state (the
    next step) while it keeps contracting; ``builds`` counts the film responses [-]."""

    def __init__(self) -> None:
        self.inverse: np.ndarray | None = None
        self.builds = 0


def newton_balance(evaluate, respond, u0, v0, load, inertia, operator, clearance: float,
                   v_scale: float, tolerance: float, max_iterations: int, share: float,
                   with_velocity: bool = True,
                   chord: ChordJacobian | None = None,
                   travel: np.ndarray | None = None,
                   refresh_after_first: bool = False) -> BalanceOutcome:
    """(u, v) with G = 0 (and F + W = 0 when ``with_velocity``) from (u0 [m], v0 [m/s]).

    evaluate : callable  (u, v) → (nodal forces f [N], film force F [N] (2,), h_min [m],
        payload); respond : callable  payload → FilmResponse at that evaluation.
    load : W [N] (2,); inertia : λ P U c(φ) [m]; operator : λ P C [m/N];
    tolerance : max|G| accepted [m]; max_iterations : film solves before giving up [-];
    chord : the Jacobian carried from the last call (updated in place), None: fresh.
    travel : ndarray (n, 2) or None  Film-thickness change at the bore nodes per unit
        velocity update [s] when the velocity also moves the journal (implicit step of the
        orbit with mass, −τ (cos θ_j, sin θ_j)): an update then keeps the whole change of the
        film thickness, max|Δu + travel Δv|, ≤ share h_min; None: no such limit.
    refresh_after_first : bool  Rebuild the Jacobian after the first update when the
        residual is not yet within tolerance. The Jacobian carried from the last step
        removes most of the start value's error (on the KamAZ-740 36 × 8 with mass a typical
        step goes from 6e-5 to 2e-7 of c in one update) but contracts what is left, which
        lies where the film's active set moved, by only ~0.4 per update; a fresh Jacobian
        at that point converges quadratically (to 1e-14 in one update).
    """
    c, n = clearance, len(u0)
    w_scale = float(np.hypot(*load)) + 1.0
    v = np.asarray(v0, dtype=float)
    solves = 0

    def residual(z: np.ndarray):
        nonlocal solves
        u = c * z[:n]
        velocity = v_scale * z[n:] if with_velocity else v
        forces, film_force, h_min, payload = evaluate(u, velocity)
        solves += 1
        g = (u - operator @ forces - inertia) / c
        if with_velocity:
            g = np.concatenate([g, (film_force + load) / w_scale])
        return g, h_min, payload

    z = np.asarray(u0, dtype=float) / c
    if with_velocity:
        z = np.concatenate([z, v / v_scale])
    r, h_min, payload = residual(z)
    chord = chord if chord is not None else ChordJacobian()
    inverse, increment, updates = chord.inverse, 0.0, 0
    if inverse is not None and inverse.shape[0] != z.size:
        inverse = None
    while solves < max_iterations and not _done(r, n, c, tolerance, with_velocity):
        if inverse is None:
            inverse = _inverse(respond(payload), operator, n, c, v_scale, w_scale,
                               with_velocity)
            chord.builds += 1
        step = -inverse @ r
        step *= _limit(step, n, h_min / c, share, with_velocity)
        if travel is not None:
            step *= _travel_limit(step, n, travel * v_scale / c, h_min / c, share)
        norm = float(np.linalg.norm(r))
        best, best_lam, lam = None, 1.0, 1.0
        for _ in range(LINE_SEARCH_CUTS):
            trial = _attempt(residual, z + lam * step)
            if trial is not None and (best is None or _norm(trial) < _norm(best)):
                best, best_lam = trial, lam
            if best is not None and (_norm(best) < norm or solves >= max_iterations):
                break
            lam *= 0.5
        if best is None:
            break
        # the best trial is taken even when it does not descend: across a switch of the
        # film's cavitation set the residual is only piecewise smooth (semismooth Newton)
        z = z + best_lam * step
        increment = float(c * np.max(np.abs(best_lam * step[:n])))
        r, h_min, payload = best
        updates += 1
        if (_norm(best) > CONTRACTION * norm or best_lam < 1.0
                or (refresh_after_first and updates == 1)):
            inverse = None
    chord.inverse = inverse
    bore = float(c * np.max(np.abs(r[:n])))
    force = float(np.max(np.abs(r[n:]))) if with_velocity else 0.0
    velocity = v_scale * z[n:] if with_velocity else v
    return BalanceOutcome(c * z[:n], velocity, payload, solves, bore, force, increment,
                          bore <= 1e3 * tolerance and force <= ACCEPTABLE, updates)


def _norm(trial) -> float:
    return float(np.linalg.norm(trial[0]))


def _attempt(residual, z: np.ndarray):
    """residual(z), or None where the film closes or its solve fails."""
    from conrod.errors import CaseError, ConvergenceError

    try:
        return residual(z)
    except (CaseError, ConvergenceError):
        return None


def _done(r: np.ndarray, n: int, c: float, tolerance: float, with_velocity: bool) -> bool:
    bore = float(c * np.max(np.abs(r[:n])))
    force = float(np.max(np.abs(r[n:]))) if with_velocity else 0.0
    return bore <= tolerance and force <= FORCE_TOLERANCE


def _inverse(response, operator, n: int, c: float, v_scale: float, w_scale: float,
             with_velocity: bool) -> np.ndarray:
    """J⁻¹ of the scaled system from the film response (module docstring)."""
    size = n + 2 if with_velocity else n
    jac = np.zeros((size, size))
    jac[:n, :n] = np.eye(n) - operator @ response.nodal_by_bore
    if with_velocity:
        jac[:n, n:] = -(operator @ response.nodal_by_velocity) * v_scale / c
        jac[n:, :n] = response.force_by_bore * c / w_scale
        jac[n:, n:] = response.force_by_velocity * v_scale / w_scale
    try:
        return np.linalg.inv(jac)
    except np.linalg.LinAlgError:  # a force insensitive to the velocity: least squares
        return np.linalg.pinv(jac)


def _limit(step: np.ndarray, n: int, h_min_scaled: float, share: float,
           with_velocity: bool) -> float:
    """Scale ≤ 1 keeping max|Δu| ≤ share h_min and |Δv| ≤ 10 c ω [-]."""
    scale = 1.0
    largest_u = float(np.max(np.abs(step[:n]))) if n else 0.0
    allowed = share * max(h_min_scaled, 0.0)
    if largest_u > allowed and largest_u > 0.0:
        scale = allowed / largest_u
    if with_velocity:
        largest_v = float(np.hypot(*step[n:]))
        if largest_v * scale > 10.0:
            scale = 10.0 / largest_v
    return scale


def _travel_limit(step: np.ndarray, n: int, travel_scaled: np.ndarray, h_min_scaled: float,
                  share: float) -> float:
    """Scale ≤ 1 keeping the change of the film thickness by the bore and the journal
    together, max|Δu + travel Δv|, ≤ share h_min (Rodin's Δ safeguard on the whole gap)."""
    change = float(np.max(np.abs(step[:n] + travel_scaled @ step[n:])))
    allowed = share * max(h_min_scaled, 0.0)
    return allowed / change if change > allowed and change > 0.0 else 1.0
