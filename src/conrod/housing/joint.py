"""The rod/cap joint of the built-in rod: points along the split line and the normal stress
across it, a linear operator on the FE displacement field.

The joint is the part of the split line inside the big end: on each side of the bore (the
two bolt sides, ``+`` towards +y_rod), from the bore to the outline. ``JOINT_POINTS`` points
per side at the centres of equal segments sample it. The normal stress across the joint is

.. math:: σ_{nn} = \\mathbf n\\cdot σ\\,\\mathbf n, \\qquad
          σ = λ^*\\operatorname{tr}ε\\,I + 2μ ε

with n the split-line normal (towards the rod side), evaluated exactly in the element that
holds each point (P2 gradients at the point's own reference coordinates). Negative is
pressure (the joint pressed together); in the bonded model a positive σ_nn is tension the
real joint cannot carry: it would open there.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from skfem import Basis, MeshTri

JOINT_POINTS = 16
"""Sample points per joint side [-]."""


@dataclass(frozen=True)
class JointLine:
    """Sample points of the joint, side ``+`` then side ``−``.

    points : ndarray  (2 k, 2) rod frame [m].
    distance : ndarray  (2 k,) distance from the bore centre along the split line [m].
    side : ndarray  (2 k,) +1 or −1 [-].
    normal : ndarray  (2,) split-line normal towards the rod side [-].
    segment : ndarray  (2 k,) length of the joint each point stands for [m].
    """

    points: np.ndarray
    distance: np.ndarray
    side: np.ndarray
    normal: np.ndarray
    segment: np.ndarray


def joint_line(geometry, mesh, n_points: int = JOINT_POINTS) -> JointLine:
    """The joint of the built-in rod ``geometry`` (:class:`~conrod.housing.geometry.
    RodGeometry`) meshed by ``mesh`` (its MeshTri2): from the bore to the mesh's outline on
    both sides of the split line."""
    normal = geometry.split_normal()
    tangent = np.array([-normal[1], normal[0]])
    points, distance, side, segment = [], [], [], []
    for sign in (1.0, -1.0):
        outer = mesh_reach(mesh, sign * tangent, geometry.bore_radius)
        edges = np.linspace(geometry.bore_radius, outer, n_points + 1)
        centres = 0.5 * (edges[1:] + edges[:-1])
        points.append(sign * centres[:, None] * tangent[None, :])
        distance.append(centres)
        side.append(np.full(n_points, sign))
        segment.append(np.diff(edges))
    return JointLine(np.vstack(points), np.concatenate(distance), np.concatenate(side),
                     normal, np.concatenate(segment))


def mesh_reach(mesh, direction: np.ndarray, bore_radius: float) -> float:
    """Distance from the bore centre along ``direction`` (2,) to the first boundary edge of
    ``mesh``'s corner triangles beyond the bore of ``bore_radius`` [m]."""
    return ray_reach(mesh, np.zeros(2), direction, bore_radius * (1.0 + 1.0e-3))


def ray_reach(mesh, origin: np.ndarray, direction: np.ndarray, skip: float = 0.0) -> float:
    """Distance from ``origin`` (2,) [m] along the unit ``direction`` (2,) to the first
    boundary edge of ``mesh``'s corner triangles farther than ``skip`` [m]; inf when none."""
    corners = int(mesh.t.max()) + 1
    linear = MeshTri(mesh.doflocs[:, :corners], mesh.t)
    facets = linear.facets[:, linear.boundary_facets()]
    a = linear.p[:, facets[0]] - np.asarray(origin, dtype=float)[:, None]
    edge = linear.p[:, facets[1]] - linear.p[:, facets[0]]
    # ray r d = a + s (b − a): solve [d, −edge] (r, s) = a by Cramer's rule
    det = -direction[0] * edge[1] + direction[1] * edge[0]
    with np.errstate(divide="ignore", invalid="ignore"):
        reach = (-a[0] * edge[1] + a[1] * edge[0]) / det
        share = (direction[0] * a[1] - direction[1] * a[0]) / det
    hit = (np.abs(det) > 0.0) & (share >= 0.0) & (share <= 1.0) & (reach > skip)
    return float(np.min(reach[hit])) if hit.any() else float("inf")


@dataclass(frozen=True)
class SplitLine:
    """The split line of an imported mesh: through the bore centre, inclined by
    ``split_angle`` [rad] from the perpendicular to the rod axis (as the built-in rod's).

    split_angle : float  [rad].  bore_radius : float  [m].
    """

    split_angle: float
    bore_radius: float

    def split_normal(self) -> np.ndarray:
        """Unit normal of the split line pointing to the rod side [-]."""
        return np.array([np.cos(self.split_angle), np.sin(self.split_angle)])


def normal_stress_operator(model, points: np.ndarray, normal: np.ndarray) -> sp.csr_matrix:
    """S (k × n_dof) [Pa/m]: σ_nn at ``points`` (k, 2) [m] of an FE displacement field of
    ``model`` (:class:`~conrod.housing.fe.ClampedModel`), n the unit normal (2,) [-]."""
    mesh = model.fe_mesh.mesh
    corners = int(mesh.t.max()) + 1
    finder = MeshTri(mesh.doflocs[:, :corners], mesh.t).element_finder()
    elements = finder(points[:, 0], points[:, 1])
    local = mesh.mapping().invF(points.T[:, :, None], tind=elements)
    lam, mu = model.material.plane_stress_lambda, model.material.shear_modulus
    rows, columns, values = [], [], []
    for k, element in enumerate(elements):
        basis = Basis(mesh, model.basis.elem, elements=np.array([element]),
                      quadrature=(local[:, k, :], np.array([0.5])))
        for i, dof in enumerate(basis.element_dofs[:, 0]):
            grad = basis.basis[i][0].grad[:, :, 0, 0]  # ∂u_a/∂x_b of shape function i
            strain = 0.5 * (grad + grad.T)
            stress = lam * np.trace(strain) * np.eye(2) + 2.0 * mu * strain
            rows.append(k)
            columns.append(dof)
            values.append(float(normal @ stress @ normal))
    return sp.csr_matrix((values, (rows, columns)), shape=(len(points), model.n_dofs))


def joint_force(line: JointLine, stress: np.ndarray, thickness: float) -> np.ndarray:
    """Normal force across each joint side (+, −) [N] of σ_nn at the points [Pa] (midpoint
    rule over the segments, plane-stress ``thickness`` [m]); negative: pressed together."""
    weights = line.segment * thickness
    return np.array([np.sum((stress * weights)[line.side == sign]) for sign in (1.0, -1.0)])
