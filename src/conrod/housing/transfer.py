"""Transfer between the film grid and the finite-element bore (the documented coupling).

The FE bore has corner nodes at angles α_k; the film grid has n circumferential nodes θ_j
(the film frame of :mod:`conrod.film.base`), both with periodic piecewise-linear hat
functions φ_j(θ) (φ_j(θ_j) = 1, ∫φ_j dθ = Δθ_j, the mean spacing of the two neighbouring
intervals).

* **Nodal force** f_j [N]: the film pressure integrated over node j's arc and the whole
  width, f_j = R Δθ_j ∫ p(θ_j, z) dz (trapezoidal rule in z), positive outward on the
  housing.
* **FE bore nodes ↔ film nodes**: radial displacements are interpolated periodic-linearly
  from the bore nodes to the film nodes, u_film = L u_bore, and nodal forces are shared
  back with the transpose, f_bore = Lᵀ f_film (the same total force). L is the identity
  when the bore nodes are the film nodes (the built-in rod; an imported mesh with a bore
  node at every film angle). The film compliance is C = L C_bore Lᵀ: symmetric, and
  positive definite when L has full row rank (at least as many bore nodes as film nodes;
  a coarser bore gives a positive semi-definite C).
* **Force → FE load**: a nodal force f_k at bore node k acts as the outward line load
  q(θ) = f_k φ_k(θ) / (R Δα_k) [N/m] (hats on the bore nodes, so their kinks sit at
  facet ends), integrated against the FE test functions on the curved bore facets
  (consistent nodal loads): F = B f_bore.
* **FE displacement → bore node**: u_k = (1/Δα_k) ∫ φ_k(θ) u_r(θ) dθ, the hat-weighted
  mean of the radial displacement around α_k — which is u_k = (Bᵀ U)_k with the same B.

Hence C_bore = Bᵀ K⁻¹ B is symmetric (Betti) and positive definite by construction.
A 2-D model deforms the same at every z, so the film uses u_j at every axial node.

**Nodes over the width** (a 3-D compliance, :mod:`conrod.housing.nodes3d`): the film nodes
(θ_j, z_k) are each a bore node, with the nodal force f_jk = R Δθ_j w_k p(θ_j, z_k) (w_k
the trapezoidal weight of z_k, :func:`axial_weights`) and the displacement u_jk seen by the
film at that node alone (:func:`node_forces`).
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp
from skfem import FacetBasis


def arc_weights(angles: np.ndarray) -> np.ndarray:
    """Δθ_j: half the sum of the two periodic intervals around each node [rad]."""
    gaps = np.diff(np.append(angles, angles[0] + 2.0 * np.pi))
    return 0.5 * (gaps + np.roll(gaps, 1))


def hat_values(theta: np.ndarray, angles: np.ndarray) -> tuple[np.ndarray, np.ndarray,
                                                                  np.ndarray]:
    """Periodic hat functions at points θ: (left node, right node, weight of the right) [-].

    angles must be strictly increasing in [0, 2π); θ any [rad].
    """
    theta = np.mod(theta, 2.0 * np.pi)
    right = np.searchsorted(angles, theta, side="right") % len(angles)
    left = (right - 1) % len(angles)
    span = np.mod(angles[right] - angles[left], 2.0 * np.pi)
    span = np.where(span == 0.0, 2.0 * np.pi, span)
    weight = np.mod(theta - angles[left], 2.0 * np.pi) / span
    return left, right, weight


def bore_load_operator(facet_basis: FacetBasis, angles: np.ndarray,
                       radius: float) -> sp.csr_matrix:
    """B (n_dof × n): FE load vector of unit outward nodal forces at the film nodes [1/m·m].

    facet_basis : FacetBasis  Vector P2 basis on the bore facets (bore centred at 0).
    angles : ndarray  Film-node angles θ_j, strictly increasing in [0, 2π) [rad].
    radius : float  Bore radius R used for the arc lengths [m].
    """
    coords = np.asarray(facet_basis.global_coordinates())          # (2, facets, points)
    theta = np.arctan2(coords[1], coords[0])
    normal = coords / np.hypot(coords[0], coords[1])         # outward radial e_r
    left, right, weight = hat_values(theta, angles)
    scale = 1.0 / (radius * arc_weights(angles))
    rows, cols, values = [], [], []
    for local in range(facet_basis.element_dofs.shape[0]):
        value = np.asarray(facet_basis.basis[local][0])             # (2, facets, points)
        radial = np.einsum("ifq,ifq->fq", value, normal) * facet_basis.dx
        dofs = np.broadcast_to(facet_basis.element_dofs[local][:, None], radial.shape)
        for node, share in ((left, 1.0 - weight), (right, weight)):
            rows.append(dofs.ravel())
            cols.append(node.ravel())
            values.append((radial * share * scale[node]).ravel())
    shape = (facet_basis.N, len(angles))
    matrix = sp.coo_matrix((np.concatenate(values), (np.concatenate(rows),
                                                      np.concatenate(cols))), shape=shape)
    return matrix.tocsr()


def interpolation_matrix(source: np.ndarray, target: np.ndarray) -> np.ndarray:
    """L (len(target) × len(source)): periodic linear interpolation in angle [-].

    Both angle sets strictly increasing in [0, 2π) [rad]; identity when they are equal.
    """
    if len(source) == len(target) and np.allclose(source, target, rtol=0.0, atol=1.0e-9):
        return np.eye(len(source))
    left, right, weight = hat_values(target, source)
    matrix = np.zeros((len(target), len(source)))
    rows = np.arange(len(target))
    np.add.at(matrix, (rows, left), 1.0 - weight)
    np.add.at(matrix, (rows, right), weight)
    return matrix


def nodal_forces(pressure: np.ndarray, z: np.ndarray, angles: np.ndarray, radius: float,
                 pressure_angles: np.ndarray | None = None) -> np.ndarray:
    """Film nodal forces f_j = R Δθ_j ∫ p(θ_j, z) dz [N] from p (n_θ, n_z + 1) [Pa].

    pressure_angles : ndarray or None  θ of the pressure rows [rad] when they are not the
        film nodes ``angles``; the line load ∫p dz [N/m] is then interpolated periodic-
        linearly to ``angles``.
    """
    line_load = np.trapezoid(pressure, z, axis=1)
    if pressure_angles is not None:
        line_load = interpolation_matrix(np.asarray(pressure_angles), angles) @ line_load
    return radius * arc_weights(angles) * line_load


def axial_weights(z: np.ndarray) -> np.ndarray:
    """w_k: the trapezoidal weights of the axial nodes z (Σ w_k = z_max − z_min) [m]."""
    gaps = np.diff(np.asarray(z, dtype=float))
    weights = np.zeros(len(z))
    weights[:-1] += 0.5 * gaps
    weights[1:] += 0.5 * gaps
    return weights


def node_weights(angles: np.ndarray, z: np.ndarray, radius: float) -> np.ndarray:
    """W (n_θ, n_z) = R Δθ_j w_k: the area of film node (θ_j, z_k) [m²]."""
    return (radius * arc_weights(angles))[:, None] * axial_weights(z)[None, :]


def node_forces(pressure: np.ndarray, z: np.ndarray, angles: np.ndarray,
                radius: float) -> np.ndarray:
    """Film nodal forces per node f_jk = R Δθ_j w_k p(θ_j, z_k) [N], flattened row-major
    (j, then k), from p (n_θ, n_z + 1) [Pa] on the film nodes θ [rad], z [m]."""
    return (node_weights(angles, z, radius) * pressure).ravel()
