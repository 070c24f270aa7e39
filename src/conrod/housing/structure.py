"""FE-backed housings: the built-in parametric rod and an imported mesh, condensed to the
film nodes (compliance and inertia base fields) through :mod:`conrod.housing.transfer`."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp

from conrod.housing.fe import (
    ClampedModel,
    Material,
    clamp_dofs_in_band,
    clamp_dofs_on_boundary,
    vector_basis,
)
from conrod.housing.geometry import REGIONS, RodGeometry
from conrod.housing.inertia import base_accelerations
from conrod.housing.mesher import Circle, FeMesh, distance_mesh, quadratic_mesh
from conrod.housing.transfer import bore_load_operator, interpolation_matrix

NON_ALIGNED_ORDER = 32
"""Gauss order on the bore facets when the film nodes are not bore nodes: a uniform
pressure on a 144 × 12 P2 ring is then within 0.04 % of Lamé at every one of 60 film nodes
(0.14 % with order 8) [-]."""
_SIZE_GROWTH = 0.3
"""Growth of the target edge length with the distance from the bore [-]."""


@dataclass
class StructuralHousing:
    """A clamped FE housing seen from the film nodes.

    model : ClampedModel  The factorised FE model.
    film_angles : ndarray  Film-node angles θ_j [rad].
    """

    model: ClampedModel
    film_angles: np.ndarray
    bore_angles: np.ndarray = field(init=False)
    bore_radius: float = field(init=False)
    load_operator: sp.csr_matrix = field(init=False, repr=False)
    interpolation: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.bore_angles, self.bore_radius = self.model.bore_vertex_angles()
        self.interpolation = interpolation_matrix(self.bore_angles, self.film_angles)
        hats, order = self.bore_angles, 8  # bore nodes at the film nodes: their own hats
        if self.interpolation.shape[0] != self.interpolation.shape[1] or not np.array_equal(
                self.interpolation, np.eye(len(self.film_angles))):
            # other bore nodes: the load and the displacement on the film nodes' own hats,
            # integrated on the bore facets (consistent with any bore mesh; sharing film
            # forces onto bore nodes would load every other node of a twice finer bore),
            # their kinks inside facets integrated by a finer rule
            hats, order = self.film_angles, NON_ALIGNED_ORDER
            self.interpolation = np.eye(len(self.film_angles))
        self.load_operator = bore_load_operator(self.model.bore_basis(intorder=order), hats,
                                                self.bore_radius)

    def film_load(self, forces: np.ndarray) -> np.ndarray:
        """FE load vector(s) [N] of film nodal forces (n,) or (n, k) [N]."""
        return self.load_operator @ (self.interpolation.T @ forces)

    def film_displacement(self, displacement: np.ndarray) -> np.ndarray:
        """Radial displacement at the film nodes [m] of FE field(s) (n_dof,) or (n_dof, k)."""
        return self.interpolation @ (self.load_operator.T @ displacement)

    def compliance(self) -> np.ndarray:
        """C (n × n) [m/N]: radial displacement at film node i per outward force at node j."""
        bore_load = self.load_operator.tocsc()
        transpose = bore_load.T.tocsr()
        bore_compliance = np.empty((bore_load.shape[1], bore_load.shape[1]))
        for column in range(bore_load.shape[1]):  # one right-hand side at a time: no dense B
            load = bore_load[:, column].toarray().ravel()
            bore_compliance[:, column] = transpose @ self.model.solve(load)
        bore_compliance = 0.5 * (bore_compliance + bore_compliance.T)
        return self.interpolation @ bore_compliance @ self.interpolation.T

    def inertia_fields(self) -> np.ndarray:
        """FE displacement fields (n_dof, 4) [m per unit coefficient] of the base loads."""
        loads = np.column_stack([
            self.model.body_load(lambda x, y, k=k: base_accelerations(x, y)[k])
            for k in range(4)])
        return self.model.solve(loads)


def bore_fixed_points(radius: float, n_nodes: int) -> np.ndarray:
    """Bore nodes at θ_k = 2πk/n on the circle of ``radius`` [m], shape (n, 2)."""
    angles = 2.0 * np.pi * np.arange(n_nodes) / n_nodes
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])


def rod_mesh(geometry: RodGeometry, n_bore_nodes: int, max_size: float,
             thickness: dict[str, float]) -> FeMesh:
    """Quadratic mesh of the built-in rod with regions and thickness per element."""
    r_b = geometry.bore_radius
    bore_step = 2.0 * np.pi * r_b / n_bore_nodes
    max_size = max(max_size, bore_step)

    def size(points: np.ndarray) -> np.ndarray:
        from_bore = np.maximum(np.hypot(points[:, 0], points[:, 1]) - r_b, 0.0)
        return np.minimum(bore_step + _SIZE_GROWTH * from_bore, max_size)

    points, triangles = distance_mesh(geometry.signed_distance, size, geometry.bounding_box(),
                                      bore_step, bore_fixed_points(r_b, n_bore_nodes))
    return rod_fe_mesh(geometry, points, triangles, thickness)


def rod_fe_mesh(geometry: RodGeometry, points: np.ndarray, triangles: np.ndarray,
                thickness: dict[str, float]) -> FeMesh:
    """FeMesh of the rod from corner points (n, 2) [m] and triangles (m, 3)."""
    circles = {"big_end_bore": Circle(0.0, 0.0, geometry.bore_radius),
               "small_end_bore": Circle(geometry.centre_distance, 0.0,
                                        geometry.small_end_bore_radius)}
    mesh, groups = quadratic_mesh(points, triangles, circles)
    region = geometry.region_of(points[triangles].mean(axis=1))
    per_region = np.array([thickness[name] for name in REGIONS])
    return FeMesh(mesh, groups, per_region[region], region, REGIONS, geometry.bore_radius)


def rod_clamp_dofs(fe_mesh: FeMesh, geometry: RodGeometry, clamp: str, position: float,
                   band: float) -> np.ndarray:
    """Clamped dofs: the small-end bore, or a band |x − position L| ≤ band across the shank."""
    basis = vector_basis(fe_mesh)
    if clamp == "small_end":
        return clamp_dofs_on_boundary(basis, fe_mesh, "small_end_bore")
    return clamp_dofs_in_band(basis, position * geometry.centre_distance, band)


def structural_rod(fe_mesh: FeMesh, material: Material, clamp_dofs: np.ndarray,
                   film_angles: np.ndarray) -> StructuralHousing:
    """Factorise the clamped rod and condense it to the film nodes."""
    return StructuralHousing(ClampedModel(fe_mesh, material, clamp_dofs), film_angles)
