"""Steady heat conduction in the plane housing: its temperature field from the shell-side
temperature of the bore, the thermal load of the bore's thermal distortion.

On the plane-stress model (thickness t per element, conductivity k) the temperature T(x, y)
solves

.. math:: \\int_A t\\,k\\,\\nabla T\\cdot\\nabla v\\,dA + \\int_A 2 h\\,(T − T_a)\\,v\\,dA
          + \\int_{Γ_o} t\\,h\\,(T − T_a)\\,v\\,ds = 0

with T given on the big-end bore (the shell-side temperature T_b(θ), interpolated
periodically in θ between the given angles), both faces and the outline Γ_o cooled with the
surface heat-transfer coefficient h towards the crankcase temperature T_a. Six-node
triangles (scikit-fem, the mesh of the structure). The field's mean over the big end and
its thermal load (:func:`conrod.housing.thermal.thermal_load`) follow.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve
from skfem import Basis, BilinearForm, ElementTriP2, FacetBasis, LinearForm, asm
from skfem.helpers import dot, grad


@dataclass(frozen=True)
class Cooling:
    """How the housing loses heat.

    conductivity : float  k [W/(m K)].
    heat_transfer : float  h on the outline [W/(m² K)].
    ambient : float  Crankcase temperature T_a [degC].
    face_heat_transfer : float or None  h on both faces [W/(m² K)]; None: ``heat_transfer``.
    """

    conductivity: float
    heat_transfer: float
    ambient: float
    face_heat_transfer: float | None = None


def periodic_temperature(angles_deg, temperatures):
    """T_b(θ) [degC] of θ [rad]: linear and periodic between the given angles [deg] (one
    value: uniform)."""
    angles = np.radians(np.asarray(angles_deg, dtype=float))
    values = np.asarray(temperatures, dtype=float)
    if values.size == 1:
        return lambda theta: np.full(np.shape(theta), float(values[0]))
    order = np.argsort(np.mod(angles, 2.0 * np.pi))
    angles, values = np.mod(angles, 2.0 * np.pi)[order], values[order]
    closed_angles = np.concatenate([angles - 2.0 * np.pi, angles, angles + 2.0 * np.pi])
    closed_values = np.tile(values, 3)
    return lambda theta: np.interp(np.mod(theta, 2.0 * np.pi), closed_angles, closed_values)


def temperature_field(model, bore_temperature, cooling: Cooling) -> tuple[Basis, np.ndarray]:
    """The housing's temperature (scalar P2 basis on the structure's mesh, nodal values
    [degC]) for the shell-side temperature ``bore_temperature(θ)`` [degC] (module
    docstring)."""
    fe_mesh = model.fe_mesh
    basis = Basis(fe_mesh.mesh, ElementTriP2(), intorder=4)
    thickness = np.repeat(fe_mesh.thickness[:, None], basis.X.shape[1], axis=1)
    k, h, ambient = cooling.conductivity, cooling.heat_transfer, cooling.ambient
    face = h if cooling.face_heat_transfer is None else cooling.face_heat_transfer

    @BilinearForm
    def area(u, v, w):
        return w.t * k * dot(grad(u), grad(v)) + 2.0 * face * u * v

    @LinearForm
    def area_sink(v, w):
        return 2.0 * face * ambient * v

    matrix = asm(area, basis, t=thickness).tocsr()
    load = asm(area_sink, basis)
    bore = fe_mesh.boundaries["big_end_bore"]
    outline = np.setdiff1d(fe_mesh.mesh.boundary_facets(), bore)
    if outline.size:
        facets = FacetBasis(fe_mesh.mesh, basis.elem, facets=outline, intorder=4)
        edge_thickness = np.repeat(fe_mesh.thickness[facets.tind][:, None],
                                   facets.X.shape[1], axis=1)

        @BilinearForm
        def edge(u, v, w):
            return w.t * h * u * v

        @LinearForm
        def edge_sink(v, w):
            return w.t * h * ambient * v

        matrix = matrix + asm(edge, facets, t=edge_thickness).tocsr()
        load = load + asm(edge_sink, facets, t=edge_thickness)
    held = basis.get_dofs(bore).all()
    x, y = basis.doflocs[:, held]
    values = np.zeros(basis.N)
    values[held] = bore_temperature(np.arctan2(y, x))
    free = np.setdiff1d(np.arange(basis.N), held)
    rhs = load[free] - matrix[free][:, held] @ values[held]
    values[free] = spsolve(sp.csc_matrix(matrix[free][:, free]), rhs)
    return basis, values


def area_mean(basis: Basis, values: np.ndarray, thickness: np.ndarray,
              regions: np.ndarray | None = None) -> float:
    """Volume-weighted mean of a P2 field [its unit] over the elements (all, or those with
    ``regions`` True)."""
    field = np.asarray(basis.interpolate(values))
    weight = basis.dx * thickness[:, None]
    if regions is not None:
        weight = weight * regions[:, None]
    return float(np.sum(weight * field) / np.sum(weight))
