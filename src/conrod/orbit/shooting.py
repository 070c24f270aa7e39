"""Quasi-Newton shooting on the one-cycle map of the orbit.

The periodic orbit is a zero of F(X₀) = P(X₀) − X₀, with P the map from the state at
φ = 0 to the state one cycle later (journal position and velocity scaled by c and c ω,
and the film content where the film carries one). Newton's step is

.. math:: X_{k+1} = X_k + (I − M)^{-1} F(X_k), \\qquad M = ∂P/∂X₀

(the monodromy matrix). Here M is not integrated along the cycle but estimated from the
cycles already run by the least-change multisecant (Broyden) update: M = ΔP ΔX⁺ on the
span of the differences ΔX of the last ``depth`` starts and ΔP of their images, and
M = 0 on the rest. M = 0 is the right first guess for a damped journal: the free motion of
the journal in its film decays within a fraction of a cycle (passenger car: |M| ≈ 2e-5,
measured as the contraction from the second to the third plainly repeated cycle), so the
first step is the plain repetition X₁ = P(X₀), and the secant pairs take over where a
slow mode (a lightly loaded bearing, the film content, a deforming bore) makes M large.
For a map linear near its fixed point the step is exact on the span of the pairs; the
low-rank form keeps the solve of (I − M) δ = F at the cost of a k × k system for any
state size (Woodbury), so a film content of 10⁵ nodes costs nothing.

What makes a shot cycle periodic is its own closure (:func:`conrod.orbit.periodic.cycle_closure`):
with M = 0 the second cycle from any start is accepted when it closes on itself, which
the plainly repeated cycles learn only one cycle later from the difference of the second
and third cycles.

Safeguards as the Anderson mixing (:mod:`conrod.orbit.acceleration`): a proposal outside
``limit`` (a fraction of the contact circle), not finite, or farther from P(X_k) than
:data:`GROWTH` × ‖F_k‖ is replaced by P(X_k) and the secant history restarted.

[1] C.G. Broyden, "A class of methods for solving nonlinear simultaneous equations",
    Math. Comp. 19 (1965) 577–593.
[2] H. Fang, Y. Saad, "Two classes of multisecant methods for nonlinear acceleration",
    Numer. Linear Algebra Appl. 16 (2009) 197–221.
"""

from __future__ import annotations

import numpy as np

from conrod.orbit.acceleration import CycleMapHistory

DEPTH = 4
"""Secant pairs kept (the journal state has 4 components) [-]."""
GROWTH = 50.0
"""Largest distance of a proposal from P(X_k), in units of the residual ‖F_k‖ [-]: the
Newton step of a mode contracting by λ per cycle moves λ/(1 − λ) ‖F‖ beyond P(X_k), so
modes up to λ = 0.98 per cycle get their whole step."""


class CycleShooting(CycleMapHistory):
    """Next start of the cycle map by a Newton step with the secant monodromy.

    limit : float  Largest |position| of a proposal, scaled like the state [-].
    depth : int  Secant pairs used [-].
    """

    def __init__(self, limit: float, depth: int = DEPTH):
        super().__init__(limit, depth)  # its own default: more pairs than Anderson's

    def propose(self, start: np.ndarray, image: np.ndarray) -> np.ndarray | None:
        """Next start after the cycle ``start`` → ``image`` (scaled states, positions
        first); None: continue from ``image`` itself (no pair yet, or rejected)."""
        if not self.record(start, image):
            return None
        residual = self.images[-1] - self.starts[-1]
        proposal = self.starts[-1] + newton_step(self.monodromy_factors(), residual)
        return self.checked(proposal, residual, GROWTH)

    def monodromy_factors(self) -> tuple[np.ndarray, np.ndarray]:
        """(U, Vᵀ) with the secant monodromy M = U Vᵀ = ΔP ΔX⁺ [-]."""
        d_start = np.diff(np.array(self.starts), axis=0).T
        d_image = np.diff(np.array(self.images), axis=0).T
        return d_image, np.linalg.pinv(d_start, rcond=1e-10)


def newton_step(factors: tuple[np.ndarray, np.ndarray], residual: np.ndarray) -> np.ndarray:
    """δ solving (I − U Vᵀ) δ = F (Woodbury: δ = F + U (I − Vᵀ U)⁻¹ Vᵀ F) [-]; F itself
    where the small system is singular (M has an eigenvalue 1: no isolated orbit)."""
    u, vt = factors
    small = np.eye(u.shape[1]) - vt @ u
    try:
        return residual + u @ np.linalg.solve(small, vt @ residual)
    except np.linalg.LinAlgError:
        return residual
