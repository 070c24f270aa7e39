"""Plane-stress finite elements of the housing (scikit-fem, six-node isoparametric triangles).

Stiffness with a thickness t per element (plane stress, isotropic):

.. math:: K = \\int_A t\\,\\big(λ^* \\operatorname{tr}ε(u)\\operatorname{tr}ε(v)
          + 2μ\\, ε(u):ε(v)\\big)\\,dA, \\qquad λ^* = \\frac{Eν}{1-ν^2},\\; μ = \\frac{E}{2(1+ν)}

The model is clamped (all displacement components zero) on a set of degrees of freedom,
factorised once (SuperLU) and then solved for many right-hand sides.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import splu
from skfem import Basis, BilinearForm, ElementTriP2, ElementVector, FacetBasis, LinearForm, asm
from skfem.helpers import ddot, sym_grad, trace

from conrod.errors import CaseError
from conrod.housing.mesher import FeMesh


@dataclass(frozen=True)
class Material:
    """Isotropic linear-elastic material.

    youngs_modulus : float  E [Pa].
    poisson_ratio : float  ν [-].
    density : float  ρ [kg/m³].
    """

    youngs_modulus: float = 2.1e11
    poisson_ratio: float = 0.3
    density: float = 7850.0

    @property
    def plane_stress_lambda(self) -> float:
        """λ* = Eν/(1 − ν²) [Pa]."""
        return self.youngs_modulus * self.poisson_ratio / (1.0 - self.poisson_ratio**2)

    @property
    def shear_modulus(self) -> float:
        """μ = E / (2(1 + ν)) [Pa]."""
        return self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))


def vector_basis(fe_mesh: FeMesh) -> Basis:
    """Vector P2 basis on the quadratic mesh (4th-order quadrature) [-]."""
    return Basis(fe_mesh.mesh, ElementVector(ElementTriP2()), intorder=4)


def _element_field(basis: Basis, per_element: np.ndarray) -> np.ndarray:
    return np.repeat(per_element[:, None], basis.X.shape[1], axis=1)


def stiffness_matrix(basis: Basis, material: Material, thickness: np.ndarray) -> sp.csr_matrix:
    """Plane-stress stiffness K [N/m] with thickness per element [m]."""
    lam, mu = material.plane_stress_lambda, material.shear_modulus

    @BilinearForm
    def form(u, v, w):
        strain_u, strain_v = sym_grad(u), sym_grad(v)
        return w.t * (lam * trace(strain_u) * trace(strain_v) + 2.0 * mu * ddot(strain_u, strain_v))

    return asm(form, basis, t=_element_field(basis, thickness)).tocsr()


def body_force_load(basis: Basis, thickness: np.ndarray, density: float,
                    acceleration) -> np.ndarray:
    """Load vector ∫ t ρ b(x)·v dA [N] of the body force per unit mass b = acceleration(x, y).

    acceleration : callable  (x, y) at quadrature points → (b_x, b_y) [m/s²].
    """

    @LinearForm
    def form(v, w):
        b_x, b_y = acceleration(w.x[0], w.x[1])
        return w.t * density * (b_x * v[0] + b_y * v[1])

    return asm(form, basis, t=_element_field(basis, thickness))


def mass_properties(basis: Basis, thickness: np.ndarray, density: float) -> dict[str, float]:
    """Mass [kg], centre of mass (x, y) [m] and moment of inertia about it [kg m²]."""
    weight = basis.dx * _element_field(basis, thickness) * density
    x, y = np.asarray(basis.global_coordinates())
    mass = float(np.sum(weight))
    x_g, y_g = float(np.sum(weight * x)) / mass, float(np.sum(weight * y)) / mass
    inertia = float(np.sum(weight * ((x - x_g) ** 2 + (y - y_g) ** 2)))
    return {"mass": mass, "x": x_g, "y": y_g, "inertia": inertia}


@dataclass
class ClampedModel:
    """A housing FE model clamped on ``clamp_dofs``, factorised once.

    fe_mesh : FeMesh  Mesh with thickness per element.
    material : Material  Elastic constants and density.
    clamp_dofs : ndarray  Degrees of freedom held at zero [-].
    """

    fe_mesh: FeMesh
    material: Material
    clamp_dofs: np.ndarray
    basis: Basis = field(init=False)
    stiffness: sp.csr_matrix = field(init=False)
    _free: np.ndarray = field(init=False, repr=False)
    _factor: object = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.basis = vector_basis(self.fe_mesh)
        if len(self.clamp_dofs) == 0:
            raise CaseError("housing clamp: no node lies in the clamp region (allowed: at "
                            "least one node, or the model floats freely)")
        self.stiffness = stiffness_matrix(self.basis, self.material, self.fe_mesh.thickness)
        free = np.ones(self.basis.N, dtype=bool)
        free[self.clamp_dofs] = False
        self._free = np.flatnonzero(free)
        reduced = self.stiffness[self._free][:, self._free].tocsc()
        self._factor = splu(reduced, permc_spec="MMD_AT_PLUS_A")  # K is symmetric

    @property
    def n_dofs(self) -> int:
        """Number of displacement unknowns [-]."""
        return int(self.basis.N)

    def solve(self, load: np.ndarray) -> np.ndarray:
        """Displacements [m] for load vector(s) (n_dof,) or (n_dof, k) [N]; clamp dofs zero."""
        load = np.asarray(load, dtype=float)
        result = np.zeros(load.shape)
        free = load[self._free]
        if free.ndim == 1:
            result[self._free] = self._factor.solve(free)
            return result
        # column by column: SuperLU's blocked multi-right-hand-side solve is ~10x slower
        solved = np.empty(free.shape)
        for column in range(free.shape[1]):
            solved[:, column] = self._factor.solve(np.ascontiguousarray(free[:, column]))
        result[self._free] = solved
        return result

    def bore_basis(self, name: str = "big_end_bore", intorder: int = 8) -> FacetBasis:
        """Vector P2 basis on the facets of the named boundary, Gauss rule of ``intorder``
        (exact for loads whose kinks sit at facet ends; a higher order for loads with kinks
        inside the facets, whose quadrature error falls slowly with the order)."""
        facets = self.fe_mesh.boundaries[name]
        return FacetBasis(self.fe_mesh.mesh, self.basis.elem, facets=facets, intorder=intorder)

    def bore_vertex_angles(self, name: str = "big_end_bore") -> tuple[np.ndarray, float]:
        """Sorted angles of the bore corner nodes in [0, 2π) [rad] and the mean radius [m]."""
        mesh = self.fe_mesh.mesh
        vertices = np.unique(mesh.facets[:, self.fe_mesh.boundaries[name]])
        x, y = mesh.doflocs[0, vertices], mesh.doflocs[1, vertices]
        return np.sort(np.mod(np.arctan2(y, x), 2.0 * np.pi)), float(np.mean(np.hypot(x, y)))

    def body_load(self, acceleration) -> np.ndarray:
        """Load vector of a body force per unit mass (see :func:`body_force_load`) [N]."""
        return body_force_load(self.basis, self.fe_mesh.thickness, self.material.density,
                               acceleration)

    def mass_properties(self) -> dict[str, float]:
        """Mass, centre of mass and moment of inertia of the model (SI)."""
        return mass_properties(self.basis, self.fe_mesh.thickness, self.material.density)


def clamp_dofs_on_boundary(basis: Basis, fe_mesh: FeMesh, name: str) -> np.ndarray:
    """Every degree of freedom on the named boundary [-]."""
    return basis.get_dofs(fe_mesh.boundaries[name]).all()


def clamp_dofs_in_band(basis: Basis, x_position: float, half_width: float) -> np.ndarray:
    """Every degree of freedom located within |x − x_position| ≤ half_width [-]."""
    return np.flatnonzero(np.abs(basis.doflocs[0] - x_position) <= half_width)


def centroid_stresses(model: ClampedModel, displacement: np.ndarray) -> np.ndarray:
    """Plane stresses (σ_xx, σ_yy, τ_xy) at the element centroids, shape (3, n_elements) [Pa]."""
    centroid = (np.array([[1.0 / 3.0], [1.0 / 3.0]]), np.array([0.5]))
    basis = Basis(model.fe_mesh.mesh, model.basis.elem, quadrature=centroid)
    grad = basis.interpolate(displacement).grad[:, :, :, 0]
    m = model.material
    strain_xx, strain_yy = grad[0, 0], grad[1, 1]
    shear = 0.5 * (grad[0, 1] + grad[1, 0])
    volumetric = m.plane_stress_lambda * (strain_xx + strain_yy)
    return np.vstack([volumetric + 2.0 * m.shear_modulus * strain_xx,
                      volumetric + 2.0 * m.shear_modulus * strain_yy,
                      2.0 * m.shear_modulus * shear])


def von_mises(stresses: np.ndarray) -> np.ndarray:
    """Plane-stress von Mises stress sqrt(σx² − σxσy + σy² + 3τ²) [Pa] from (3, n) [Pa]."""
    s_xx, s_yy, s_xy = stresses
    return np.sqrt(s_xx**2 - s_xx * s_yy + s_yy**2 + 3.0 * s_xy**2)
