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

**Nodes over the width** (a 3-D compliance, nodes (θ_j, z_k)): the correction is that of
the whole bore as one rigid body, not of each axial section. A rigid body moves the bore
by a translation (a, b) of its centre and a tilt (β about y, −α about x) of its axis; their
radial displacement is u = (a + β z) cos θ + (b − α z) sin θ (a rotation about the bore
axis and an axial shift have none). These four are estimated from the whole node set and
subtracted, u ← u − (a + β z) cos θ − (b − α z) sin θ:

* ``least_squares_circle``: the least-squares fit u ≈ c₀ + c₁ z + (a + β z) cos θ +
  (b − α z) sin θ over all nodes (a uniform expansion c₀ and a taper c₁ z are kept);
* ``centroid``: the first moments with the node areas Δθ_j w_k as weights,
  (a, b, β, −α) solving Σ w R (R·(a, b, β, −α)) = Σ w R u with R = (cos θ, sin θ,
  z cos θ, z sin θ);
* ``none``.

Per section (a_k, b_k at each z_k) would also remove a bent bore axis — the centres of the
sections off a straight line, the bore's own bending under a load near one face — which is
a change of shape that the film feels, not a rigid motion. A deformation alike at every z
(a plane housing seen on the 3-D nodes) is corrected exactly as on the plane nodes.
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


def rigid_modes(angles: np.ndarray, axial: np.ndarray) -> np.ndarray:
    """R (N × 4): radial displacement of a unit translation along x, y and a unit tilt
    β, −α of the bore axis at the nodes (θ_j, z_k), row-major (j, then k) [-, -, m, m]."""
    theta = np.repeat(angles, len(axial))
    z = np.tile(axial, len(angles))
    cos, sin = np.cos(theta), np.sin(theta)
    return np.column_stack([cos, sin, z * cos, z * sin])


def rigid_estimator(angles: np.ndarray, axial: np.ndarray, method: CorrectionName
                    ) -> np.ndarray:
    """E (4 × N): translation and tilt (a, b, β, −α) = E u of the whole bore [-, -, 1/m]."""
    modes = rigid_modes(angles, axial)
    if method == "least_squares_circle":
        z = np.tile(axial, len(angles))
        design = np.column_stack([np.ones_like(z), z, modes])
        return np.linalg.pinv(design)[2:]
    if method == "centroid":
        from conrod.housing.transfer import axial_weights

        area = np.outer(arc_weights(angles), axial_weights(axial)).ravel()
        weighted = modes.T * area
        return np.linalg.solve(weighted @ modes, weighted)
    if method == "none":
        return np.zeros((4, modes.shape[0]))
    raise ValueError(f"unknown correction {method!r}")


def bore_correction_projector(angles: np.ndarray, axial: np.ndarray,
                              method: CorrectionName) -> np.ndarray:
    """P (N × N) with u_corrected = P u [-] for the nodes (θ_j, z_k) of a 3-D compliance:
    the whole bore's rigid translation and tilt removed (module docstring)."""
    modes = rigid_modes(angles, axial)
    return np.eye(modes.shape[0]) - modes @ rigid_estimator(angles, axial, method)
