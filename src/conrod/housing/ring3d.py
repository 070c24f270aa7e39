"""A solid ring (the big end as a 3-D body of revolution) in scikit-fem: quadratic
tetrahedra, its radial compliance at the film nodes (θ_j, z_k) of the bore, and its stiffness
condensed to the bore's corner nodes — the 3-D compliance of :mod:`conrod.housing.nodes3d`
from a model small enough for the tests and the shipped example.

Geometry: bore radius a, outer radius b(z) varying linearly from ``outer_radii[0]`` at
z = −L/2 to ``outer_radii[1]`` at z = +L/2 (a ring stiffer at one face than the other),
width L, z from the mid-plane. The structured grid n_θ × n_r × n_z of hexahedra in
(θ, r, z) is cut into six tetrahedra each (Freudenthal's subdivision, conforming), made
quadratic (ElementTetP2) with every node placed by the cylindrical map, so the bore and
the outer surface are exact circles at every node.

Linear elasticity, isotropic:

.. math:: K = \\int_V λ\\,\\operatorname{tr}ε(u)\\operatorname{tr}ε(v) + 2μ\\,ε(u):ε(v)\\,dV,
          \\quad λ = \\frac{Eν}{(1+ν)(1−2ν)},\\; μ = \\frac{E}{2(1+ν)}

held either on an outer patch |θ| ≤ ``held_half_angle`` (every node of the outer surface
there, over the width: a big end held by its shank at θ = 0) or at three outer points
against rigid motion only (``held_half_angle = None``: six components, statically
determinate).

Radial compliance at the film nodes, as the plane rod's (:mod:`conrod.housing.transfer`)
one dimension up: a nodal force f_jk acts as the outward pressure f_jk φ_jk / (a Δθ_j w_k)
with φ_jk(θ, z) = φ_j(θ) φ_k(z) the bilinear hat of film node (θ_j, z_k) on the bore
(periodic in θ), integrated against the P2 test functions on the curved bore faces: F = B f;
the displacement of node jk is the hat-weighted mean of u_r, (Bᵀ U)_jk; so C = Bᵀ K⁻¹ B is
symmetric and positive definite.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from itertools import permutations
from typing import Any

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu
from skfem import Basis, ElementTetP2, ElementVector, FacetBasis, MeshTet1, MeshTet2, asm
from skfem.models.elasticity import lame_parameters, linear_elasticity

from conrod.housing.transfer import arc_weights, axial_weights, hat_values


@dataclass(frozen=True)
class RingGeometry:
    """A solid ring: bore radius a [m], outer radii at z = ∓L/2 [m], width L [m]."""

    bore_radius: float
    outer_radii: tuple[float, float]
    width: float

    def outer_radius(self, z: np.ndarray) -> np.ndarray:
        """b(z) [m] at z [m] from the mid-plane (linear between the faces)."""
        share = (np.asarray(z) + 0.5 * self.width) / self.width
        return self.outer_radii[0] + (self.outer_radii[1] - self.outer_radii[0]) * share


def _logical_to_cartesian(geometry: RingGeometry, theta, share, z) -> np.ndarray:
    radius = geometry.bore_radius + share * (geometry.outer_radius(z) - geometry.bore_radius)
    return np.vstack([radius * np.cos(theta), radius * np.sin(theta), z])


def ring_mesh(geometry: RingGeometry, n_theta: int, n_radial: int,
              n_axial: int) -> tuple[MeshTet2, np.ndarray]:
    """The quadratic tetrahedral ring and the logical coordinates (θ, s, z) of its
    vertices (3, n_vertices) [rad, -, m] (s ∈ [0, 1] through the wall)."""
    theta = 2.0 * np.pi * np.arange(n_theta) / n_theta
    share = np.linspace(0.0, 1.0, n_radial + 1)
    axial = np.linspace(-0.5 * geometry.width, 0.5 * geometry.width, n_axial + 1)
    j, i, k = np.meshgrid(np.arange(n_theta), np.arange(n_radial + 1),
                          np.arange(n_axial + 1), indexing="ij")
    logical = np.vstack([theta[j.ravel()], share[i.ravel()], axial[k.ravel()]])

    def vertex(jj, ii, kk):
        return ((jj % n_theta) * (n_radial + 1) + ii) * (n_axial + 1) + kk

    cj, ci, ck = (a.ravel() for a in np.meshgrid(np.arange(n_theta), np.arange(n_radial),
                                                  np.arange(n_axial), indexing="ij"))
    tets = []
    for order in permutations(range(3)):  # Freudenthal: a path 000 → 111 per permutation
        step = np.zeros(3, dtype=int)
        corners = [vertex(cj, ci, ck)]
        for axis in order:
            step[axis] += 1
            corners.append(vertex(cj + step[0], ci + step[1], ck + step[2]))
        tets.append(np.vstack(corners))
    t = np.hstack(tets)
    points = _logical_to_cartesian(geometry, *logical)
    t = _positively_oriented(points, t)
    linear = MeshTet1(points, t)
    quadratic = MeshTet2.from_mesh(linear)
    doflocs = quadratic.doflocs.copy()
    edges = linear.edges
    start, end = logical[:, edges[0]], logical[:, edges[1]]
    turn = np.angle(np.exp(1j * (end[0] - start[0])))
    middle = np.vstack([start[0] + 0.5 * turn, 0.5 * (start[1] + end[1]),
                        0.5 * (start[2] + end[2])])
    doflocs[:, points.shape[1]:] = _logical_to_cartesian(geometry, *middle)
    return MeshTet2(doflocs, quadratic.t), logical


def _positively_oriented(points: np.ndarray, t: np.ndarray) -> np.ndarray:
    a, b, c, d = (points[:, t[k]] for k in range(4))
    volume = np.einsum("ij,ij->j", np.cross(b - a, c - a, axis=0), d - a)
    swapped = t.copy()
    swapped[[1, 2]] = np.where(volume < 0.0, t[[2, 1]], t[[1, 2]])
    return swapped


@dataclass
class SolidRing:
    """The solid ring in linear elasticity, held and factorised once.

    geometry : RingGeometry  The ring.
    youngs_modulus : float  E [Pa].  poisson_ratio : float  ν [-].
    n_theta, n_radial, n_axial : int  Hexahedra around, through the wall, over the width.
    held_half_angle : float or None  Half angle of the held outer patch at θ = 0 [rad];
        None: held at three points against rigid motion only.
    """

    geometry: RingGeometry
    youngs_modulus: float = 2.1e11
    poisson_ratio: float = 0.3
    n_theta: int = 24
    n_radial: int = 2
    n_axial: int = 4
    held_half_angle: float | None = np.radians(30.0)
    mesh: MeshTet2 = field(init=False, repr=False)
    basis: Basis = field(init=False, repr=False)
    stiffness: sp.csr_matrix = field(init=False, repr=False)
    held: np.ndarray = field(init=False, repr=False)
    _logical: np.ndarray = field(init=False, repr=False)
    _free: np.ndarray = field(init=False, repr=False)
    _factor: Any = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.mesh, self._logical = ring_mesh(self.geometry, self.n_theta, self.n_radial,
                                             self.n_axial)
        self.basis = Basis(self.mesh, ElementVector(ElementTetP2()), intorder=4)
        lam, mu = lame_parameters(self.youngs_modulus, self.poisson_ratio)
        self.stiffness = asm(linear_elasticity(lam, mu), self.basis).tocsr()
        self.held = self._held_dofs()
        free = np.ones(self.basis.N, dtype=bool)
        free[self.held] = False
        self._free = np.flatnonzero(free)
        reduced = self.stiffness[self._free][:, self._free].tocsc()
        self._factor = splu(reduced, permc_spec="MMD_AT_PLUS_A")

    @property
    def n_dofs(self) -> int:
        """Displacement unknowns [-]."""
        return int(self.basis.N)

    def _held_dofs(self) -> np.ndarray:
        theta, share, z = self._logical
        nodal = self.basis.nodal_dofs  # (3, n_vertices)
        outer = np.flatnonzero(share == 1.0)
        if self.held_half_angle is not None:
            gap = np.abs(np.angle(np.exp(1j * theta[outer])))
            held = outer[gap <= self.held_half_angle + 1e-12]
            edges = self.mesh.edges
            both = np.isin(edges[0], held) & np.isin(edges[1], held)
            return np.concatenate([nodal[:, held].ravel(),
                                   self.basis.edge_dofs[:, np.flatnonzero(both)].ravel()])
        bottom = outer[z[outer] == z.min()]

        def at(angle: float) -> int:
            gap = np.abs(np.angle(np.exp(1j * (theta[bottom] - angle))))
            return int(bottom[np.argmin(gap)])

        a, b, c = at(0.0), at(np.pi), at(0.5 * np.pi)
        return np.array([*nodal[:, a], nodal[1, b], nodal[2, b], nodal[2, c]])

    def solve(self, load: np.ndarray) -> np.ndarray:
        """Displacements [m] for load vector(s) (n_dof,) or (n_dof, k) [N]."""
        load = np.asarray(load, dtype=float)
        result = np.zeros(load.shape)
        free = load[self._free]
        if free.ndim == 1:
            result[self._free] = self._factor.solve(free)
            return result
        solved = np.empty(free.shape)
        for column in range(free.shape[1]):  # column by column: SuperLU's blocked solve is slow
            solved[:, column] = self._factor.solve(np.ascontiguousarray(free[:, column]))
        result[self._free] = solved
        return result

    # ---------------------------------------------------------- film nodes (θ, z)
    def bore_facets(self) -> np.ndarray:
        """Indices of the boundary faces on the bore (every corner at s = 0) [-]."""
        boundary = self.mesh.boundary_facets()
        share = self._logical[1]
        on = np.all(share[self.mesh.facets[:, boundary]] == 0.0, axis=0)
        return boundary[on]

    def load_operator(self, film_angles: np.ndarray, film_axial: np.ndarray,
                      intorder: int = 6) -> sp.csr_matrix:
        """B (n_dof × N): the FE load of a unit outward force at each film node (θ_j, z_k),
        row-major (module docstring) [-]."""
        facet_basis = FacetBasis(self.mesh, self.basis.elem, facets=self.bore_facets(),
                                 intorder=intorder)
        x, y, z = np.asarray(facet_basis.global_coordinates())
        theta = np.arctan2(y, x)
        normal = np.stack([x, y, np.zeros_like(x)]) / np.hypot(x, y)
        left, right, weight = hat_values(theta, film_angles)
        below, above, lift = _axial_hats(z, film_axial)
        n_axial = len(film_axial)
        scale = 1.0 / (self.geometry.bore_radius * np.outer(arc_weights(film_angles),
                                                           axial_weights(film_axial)).ravel())
        rows, cols, values = [], [], []
        for local in range(facet_basis.element_dofs.shape[0]):
            value = np.asarray(facet_basis.basis[local][0])
            radial = np.einsum("ifq,ifq->fq", value, normal) * facet_basis.dx
            dofs = np.broadcast_to(facet_basis.element_dofs[local][:, None], radial.shape)
            for row_node, row_share in ((left, 1.0 - weight), (right, weight)):
                for level, level_share in ((below, 1.0 - lift), (above, lift)):
                    node = row_node * n_axial + level
                    rows.append(dofs.ravel())
                    cols.append(node.ravel())
                    values.append((radial * row_share * level_share * scale[node]).ravel())
        shape = (self.basis.N, len(film_angles) * n_axial)
        return sp.coo_matrix((np.concatenate(values), (np.concatenate(rows),
                                                      np.concatenate(cols))),
                             shape=shape).tocsr()

    def bore_compliance(self, film_angles: np.ndarray, film_axial: np.ndarray) -> np.ndarray:
        """C (N × N) [m/N] at the film nodes (θ_j, z_k), row-major: radial displacement at
        node a per unit outward force at node b (module docstring)."""
        load = self.load_operator(film_angles, film_axial).tocsc()
        transpose = load.T.tocsr()
        compliance = np.empty((load.shape[1], load.shape[1]))
        for column in range(load.shape[1]):
            compliance[:, column] = transpose @ self.solve(load[:, column].toarray().ravel())
        return 0.5 * (compliance + compliance.T)

    # ------------------------------------------------------- bore corner nodes
    def bore_vertices(self) -> np.ndarray:
        """Corner nodes on the bore (s = 0) [-], ordered by θ then z."""
        theta, share, z = self._logical
        on = np.flatnonzero(share == 0.0)
        return on[np.lexsort((z[on], theta[on]))]

    def vertex_coordinates(self, vertices: np.ndarray) -> np.ndarray:
        """(x, y, z) of ``vertices`` (n, 3) [m]."""
        return self.mesh.doflocs[:, vertices].T

    def condensed_stiffness(self, vertices: np.ndarray) -> np.ndarray:
        """K̂ (3n × 3n) [N/m]: the stiffness condensed (statically, exactly) to the x, y, z
        translations of ``vertices``, node-major — a superelement of the held ring."""
        retained = self.basis.nodal_dofs[:, vertices].T.ravel()
        unit = np.zeros((self.basis.N, retained.size))
        unit[retained, np.arange(retained.size)] = 1.0
        flexibility = self.solve(unit)[retained]
        return np.linalg.inv(0.5 * (flexibility + flexibility.T))

    def point_compliance(self, vertices: np.ndarray) -> np.ndarray:
        """Radial compliance (n × n) [m/N] of unit outward point forces at ``vertices``."""
        theta = self._logical[0, vertices]
        nodal = self.basis.nodal_dofs[:, vertices]
        load = np.zeros((self.basis.N, len(vertices)))
        columns = np.arange(len(vertices))
        load[nodal[0], columns] = np.cos(theta)
        load[nodal[1], columns] = np.sin(theta)
        compliance = load.T @ self.solve(load)
        return 0.5 * (compliance + compliance.T)


def _axial_hats(z: np.ndarray, axial: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Linear hats in z on the nodes ``axial`` (increasing) at points z: (node below,
    node above, weight of the one above) [-]."""
    clipped = np.clip(z, axial[0], axial[-1])
    above = np.clip(np.searchsorted(axial, clipped, side="right"), 1, len(axial) - 1)
    below = above - 1
    lift = (clipped - axial[below]) / (axial[above] - axial[below])
    return below, above, lift
