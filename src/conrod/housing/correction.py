"""Rigid-body correction of the bore deformation (Rodin 2004, ch. 2: methods 1 and 2).

The FE model must be clamped somewhere, so its bore moves as a rigid body with the bending
and stretching of the shank; the film only feels the change of shape. Both methods
subtract a translation (a, b) of the bore centre from the radial displacements:
u_i ← u_i − a cos θ_i − b sin θ_i. As the correction is linear in u it is applied as one
projector matrix P (n × n), precomputed once.

* ``least_squares_circle`` (method 2, the default): (a, b) is the centre of the circle
  fitted by least squares to the deformed contour, i.e. the fit u_i ≈ c₀ + a cos θ_i +
  b sin θ_i to the nodal radial displacements (first order in u/R).
* ``centroid`` (method 1): (a, b) is the centroid of the area bounded by the deformed
  contour, to first order (a, b) = (1/π) ∮ u (cos θ, sin θ) dθ; the integrals (and the
  normalising ∮cos² = ∮sin² = π) use the trapezoidal rule over the nodes. On uniformly
  spaced nodes the two methods coincide exactly; they differ on non-uniform node sets.
* ``none``: P = I.

Both remove an imposed rigid translation u = a cos θ + b sin θ exactly.
"""

from __future__ import annotations

import numpy as np

from conrod.cases.housing import CorrectionName
from conrod.housing.transfer import arc_weights


def translation_estimator(angles: np.ndarray, method: CorrectionName) -> np.ndarray:
    """E (2 × n): the bore-centre translation (a, b) = E u of radial displacements u [-]."""
    cos, sin = np.cos(angles), np.sin(angles)
    if method == "least_squares_circle":
        design = np.column_stack([np.ones_like(angles), cos, sin])
        return np.linalg.pinv(design)[1:]
    if method == "centroid":
        weighted = np.vstack([cos, sin]) * arc_weights(angles)
        normal = weighted @ np.column_stack([cos, sin])   # ∮ cos², ∮ cos sin, ∮ sin² (= π I)
        return np.linalg.solve(normal, weighted)
    if method == "none":
        return np.zeros((2, len(angles)))
    raise ValueError(f"unknown correction {method!r}")


def correction_projector(angles: np.ndarray, method: CorrectionName) -> np.ndarray:
    """P (n × n) with u_corrected = P u [-] for bore-node angles θ (n,) [rad]."""
    translation = np.column_stack([np.cos(angles), np.sin(angles)])
    return np.eye(len(angles)) - translation @ translation_estimator(angles, method)
