"""Massless journal on a deforming bore: bore displacement and journal velocity together.

At a fixed journal position x the quasi-static orbit needs the velocity v for which the film
balances the load, F(u, v) + W = 0, on the bore deformation that this film produces,
G(u, v) = u − P(C f(u, v) + U c(φ)) = 0. Solving the two one inside the other fails on a
compliant rod: at a fixed velocity the pressure on a bore that closes in under it grows
without bound (no solution of G = 0), while the force balance limits it to the load. So the
unknowns z = (u/c, v/(c ω)) are solved together by a quasi-Newton iteration on the scaled
residuals r = (G/c, (F + W)/W_s):

.. math:: J = \\begin{pmatrix} I - P C\\,∂f/∂u & -P C\\,∂f/∂v \\\\
                               -N\\,∂f/∂u & ∂F/∂v \\end{pmatrix}

with ∂f/∂u from finite differences along the dominant directions W of P C
(:func:`conrod.ehd.coupling.dominant_directions`), ∂f/∂v and ∂F/∂v from two more film
solves, N the 2 × n matrix (cos θ_j, sin θ_j) of the bore nodes (film rows, or film nodes
(θ_j, z_k) of a housing over the width) taking nodal forces to the film force on the
journal (F = −N f), then Broyden's updates of J⁻¹ carried from step to step; the
increment is scaled when |Δu| exceeds a share of h_min (Rodin's Δ safeguard) or |Δv|
exceeds 10 c ω.
"""

from __future__ import annotations

import numpy as np

from conrod.numerics.newton import (
    ACCEPTABLE,
    FORCE_TOLERANCE,
    NewtonOutcome,
    update_limit,
)

Evaluate = object
"""(u [m], v [m/s] (2,)) → (nodal forces f [N], film force F [N] (2,), h_min [m], payload)."""


class BalanceJacobian:
    """Inverse Jacobian of the scaled (u, v) system, carried between steps."""

    def __init__(self, directions: np.ndarray, angles: np.ndarray):
        self.directions = directions
        self.normals = np.vstack([np.cos(angles), np.sin(angles)])
        self.inverse: np.ndarray | None = None
        self.builds = 0

    def rebuild(self, evaluate, u, v, forces, film_force, operator, c, v_scale, w_scale):
        """J⁻¹ from finite differences at (u, v); returns the film solves used."""
        n, w = u.size, self.directions
        du = np.empty((n, w.shape[1]))
        for k in range(w.shape[1]):
            shifted = evaluate(u + 1e-4 * c * w[:, k], v)[0]
            du[:, k] = (shifted - forces) / (1e-4 * c)
        dv, dF = np.empty((n, 2)), np.empty((2, 2))
        for k in range(2):
            step = np.zeros(2)
            step[k] = 1e-4 * v_scale
            shifted, force = evaluate(u, v + step)[:2]
            dv[:, k] = (shifted - forces) / step[k]
            dF[:, k] = (force - film_force) / step[k]
        jac = np.zeros((n + 2, n + 2))
        jac[:n, :n] = np.eye(n) - operator @ du @ w.T
        jac[:n, n:] = -(operator @ dv) * v_scale / c
        jac[n:, :n] = -(self.normals @ du @ w.T) * c / w_scale
        jac[n:, n:] = dF * v_scale / w_scale
        self.inverse = np.linalg.inv(jac)
        self.builds += 1
        return w.shape[1] + 2

    def broyden(self, s: np.ndarray, y: np.ndarray) -> None:
        """Good Broyden update of J⁻¹ from the scaled step s and residual change y."""
        assert self.inverse is not None
        hy = self.inverse @ y
        denominator = float(s @ hy)
        if abs(denominator) > 1e-30 * max(float(s @ s), 1e-300):
            self.inverse += np.outer(s - hy, s @ self.inverse) / denominator


def solve_balance(evaluate, u0, v0, load, inertia, operator, jacobian: BalanceJacobian,
                  clearance: float, v_scale: float, tolerance: float, max_iterations: int,
                  share: float) -> NewtonOutcome:
    """(u, v) with G = 0 and F + W = 0 from (u0 [m], v0 [m/s]); ``load`` W [N] (2,),
    ``inertia`` P U c(φ) [m], ``operator`` P C [m/N], ``tolerance`` on max|G| [m].
    Quasi-Newton steps with backtracking on max|r|; the Jacobian is rebuilt (once per
    solve) when a step has to be cut to a quarter."""
    c, n = clearance, u0.size
    w_scale = float(np.hypot(*load)) + 1.0
    solves = 0

    def residual(z: np.ndarray):
        nonlocal solves
        u, v = c * z[:n], v_scale * z[n:]
        forces, film_force, h_min, payload = evaluate(u, v)
        solves += 1
        g = u - operator @ forces - inertia
        r = np.concatenate([g / c, (film_force + load) / w_scale])
        return r, forces, film_force, h_min, payload

    z = np.concatenate([np.asarray(u0, dtype=float) / c, np.asarray(v0, dtype=float) / v_scale])
    r, forces, film_force, h_min, payload = residual(z)
    fresh, increment, since, updates = False, 0.0, 0, 0
    for _ in range(max_iterations):
        since += 1
        if since > 8:  # slow contraction: a new Jacobian is allowed again
            fresh, since = False, 0
        if _converged(r, n, c, tolerance):
            break
        if jacobian.inverse is None:
            solves += jacobian.rebuild(evaluate, c * z[:n], v_scale * z[n:], forces,
                                       film_force, operator, c, v_scale, w_scale)
            fresh, since = True, 0
        step = -jacobian.inverse @ r
        step *= update_limit(step[:n], step[n:], h_min / c, share)
        norm, lam = float(np.max(np.abs(r))), 1.0
        while True:
            trial = residual(z + lam * step)
            if float(np.max(np.abs(trial[0]))) < norm or lam < 1.0 / 64.0:
                break
            lam *= 0.5
            if lam < 0.25 and not fresh:
                break
        if lam < 0.25 and not fresh:  # poor Jacobian: rebuild here and retry
            jacobian.inverse = None
            continue
        jacobian.broyden(lam * step, trial[0] - r)
        z = z + lam * step
        updates += 1
        r, forces, film_force, h_min, payload = trial
        increment = float(c * np.max(np.abs(lam * step[:n]))) if n else 0.0
    bore = float(c * np.max(np.abs(r[:n]))) if n else 0.0
    force = float(np.max(np.abs(r[n:])))
    return NewtonOutcome(c * z[:n], v_scale * z[n:], payload, solves, bore, force, increment,
                         bore <= 1e3 * tolerance and force <= ACCEPTABLE,
                         bore <= tolerance and force <= FORCE_TOLERANCE, updates)


def _converged(r: np.ndarray, n: int, c: float, tolerance: float) -> bool:
    bore = float(c * np.max(np.abs(r[:n]))) if n else 0.0
    return bore <= tolerance and float(np.max(np.abs(r[n:]))) <= FORCE_TOLERANCE
