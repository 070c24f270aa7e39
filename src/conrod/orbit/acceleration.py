"""Anderson acceleration of the cycle-to-cycle map of the orbit.

The periodic orbit is a fixed point of the map P: state at φ = 0 → state one cycle later.
Repeating cycles (x_{k+1} = P(x_k)) converges linearly, as fast as the slowest decaying
free motion of the journal; Anderson's mixing [1] (type II, as analysed by Walker & Ni
[2]) takes the next start as the combination of the last few images that minimises the
linearised residual f = P(x) − x:

.. math:: γ = \\arg\\min_γ \\|f_k − ΔF γ\\|_2, \\qquad x_{k+1} = P(x_k) − ΔG γ,

with ΔF, ΔG the differences of the last ``depth`` residuals and images. For a map that is
linear near its fixed point this is a secant (multisecant Broyden) method: the error of
the slowest modes is removed after as many cycles as the state has components, instead
of shrinking by the same factor every cycle.

Safeguards (the map is not linear far from the orbit): no step before two cycles are
known; a proposal that leaves ``limit`` (a fraction of the contact circle) or moves
farther from P(x_k) than ``growth`` × ‖f_k‖ is replaced by P(x_k) and the history
restarted.

[1] D.G. Anderson, "Iterative procedures for nonlinear integral equations", J. ACM 12
    (1965) 547–560.
[2] H.F. Walker, P. Ni, "Anderson acceleration for fixed-point iterations", SIAM J.
    Numer. Anal. 49 (2011) 1715–1735.
"""

from __future__ import annotations

import numpy as np

DEPTH = 3
"""Residuals kept by the mixing (the state has 2 or 4 components) [-]."""
GROWTH = 4.0
"""Largest distance of a proposal from P(x_k), in units of the residual ‖f_k‖ [-]."""


class CycleMapHistory:
    """The last (start, image) pairs of the cycle map and the safeguard of a proposed
    start, shared by the extrapolations of the cycle map (this mixing and
    :class:`conrod.orbit.shooting.CycleShooting`).

    limit : float  Largest |position| of a proposal, scaled like the state [-].
    depth : int  Differences of pairs used [-].
    """

    def __init__(self, limit: float, depth: int = DEPTH):
        self.limit = limit
        self.depth = depth
        self.starts: list[np.ndarray] = []
        self.images: list[np.ndarray] = []

    def reset(self) -> None:
        """Forget the history (after a contact at φ = 0 or a rejected proposal)."""
        self.starts.clear()
        self.images.clear()

    def record(self, start: np.ndarray, image: np.ndarray) -> bool:
        """Keep the pair ``start`` → ``image``; True once there are two to difference."""
        self.starts.append(np.asarray(start, dtype=float))
        self.images.append(np.asarray(image, dtype=float))
        del self.starts[:-(self.depth + 1)], self.images[:-(self.depth + 1)]
        return len(self.starts) >= 2

    def checked(self, proposal: np.ndarray, residual: np.ndarray,
                growth: float) -> np.ndarray | None:
        """``proposal``, or None (history reset) when it is not finite, lies outside
        ``limit`` or farther from the last image than ``growth`` × ‖residual‖."""
        step = float(np.linalg.norm(proposal - self.images[-1]))
        if (not np.all(np.isfinite(proposal))
                or np.hypot(proposal[0], proposal[1]) > self.limit
                or step > growth * float(np.linalg.norm(residual))):
            self.reset()
            return None
        return proposal


class AndersonMixing(CycleMapHistory):
    """Next start of the cycle map from the history of (start, image) pairs.

    limit : float  Largest |position| of a proposal, scaled like the state [-].
    depth : int  Residual differences used [-].
    """

    def propose(self, start: np.ndarray, image: np.ndarray) -> np.ndarray | None:
        """Next start after the cycle ``start`` → ``image`` (scaled states, positions
        first); None: continue from ``image`` itself (plain repetition)."""
        if not self.record(start, image):
            return None
        residuals = np.array(self.images) - np.array(self.starts)
        d_residual = np.diff(residuals, axis=0).T
        d_image = np.diff(np.array(self.images), axis=0).T
        gamma, *_ = np.linalg.lstsq(d_residual, residuals[-1], rcond=1e-10)
        return self.checked(self.images[-1] - d_image @ gamma, residuals[-1], GROWTH)
