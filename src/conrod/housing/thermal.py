"""The warm bore: journal and housing at their mean running temperatures.

**Clearance change.** Measured at the reference temperature T_ref, the radial clearance
changes when the journal and the housing run warmer:

.. math:: Δc = \\bar u_{th} − ε_s t_s − ε_j R, \\qquad ε = α (T − T_{ref})

with ū_th the mean radial displacement of the housing bore from its thermal strain ε_h (a
free ring: ε_h R_b exactly, Timoshenko & Goodier ch. 13), the shell at the housing's
temperature growing inwards through its thickness t_s, and the journal of radius R growing
by ε_j R. ``[bearing] radial_clearance`` becomes c + Δc for the run.

**Thermal distortion (FE housings).** The housing's temperature field T(x, y) is a thermal
load of the plane-stress model (initial strain ε_th = α ΔT in both directions):

.. math:: f = \\int_A t\\,\\frac{E}{1 − ν}\\,α ΔT(x, y)\\,\\nabla\\!\\cdot v\\,dA

At one mean housing temperature (uniform ΔT) a free body would only grow; the clamped
rod's bore is not distorted by its held small end either (measured 4e-7 µm out of round on
the KamAZ rod), and the field is linear in ε_h: the bore displacement per unit strain is
computed once per housing and cached with the compliance. A housing that conducts from its
shell-side temperature T_b(θ) to the crankcase (:mod:`conrod.housing.conduction`) has a
non-uniform field: its thermal load distorts the bore. The corrected bore displacement's
mean is ū_th; what is left (its out-of-round part) enters the film as the bore profile
h₀(θ) beside the assembled bore; the shell is at the mean shell-side temperature.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from skfem import LinearForm, asm

THERMAL_FORMAT = 2
"""Version of the thermal load and conduction model, part of their cache key [-]."""


def thermal_load(model, strain) -> np.ndarray:
    """FE load vector [N] of the thermal strain field ε_th = α ΔT [-] on the plane-stress
    ``model``: a callable of the coordinates, or its values at the quadrature points of
    the model's basis (n_elements, n_points)."""
    basis = model.basis
    thickness = np.repeat(model.fe_mesh.thickness[:, None], basis.X.shape[1], axis=1)
    modulus = model.material.youngs_modulus / (1.0 - model.material.poisson_ratio)
    if callable(strain):
        x, y = np.asarray(basis.global_coordinates())
        strain = strain(x, y)

    @LinearForm
    def form(v, w):
        return w.t * modulus * w.strain * (v.grad[0][0] + v.grad[1][1])

    return asm(form, basis, t=thickness, strain=np.asarray(strain, dtype=float))


def unit_strain_bore(structure) -> np.ndarray:
    """Raw radial bore displacement at the film nodes [m] of a uniform unit thermal strain
    (ε_th = 1) of the whole housing ``structure``."""
    load = thermal_load(structure.model, lambda x, y: np.ones_like(x))
    return structure.film_displacement(structure.model.solve(load))


def field_bore(structure, section, cooling) -> tuple[np.ndarray, float, float, np.ndarray]:
    """Raw thermal bore displacement at the film nodes [m] of the housing's conduction field
    from the shell-side temperatures of ``section`` (:mod:`conrod.housing.conduction`), the
    field's volume mean over the big end [degC], the mean shell-side temperature [degC] and
    the field at the mesh's corner nodes [degC]."""
    from conrod.housing.conduction import area_mean, periodic_temperature, temperature_field

    model = structure.model
    bore = periodic_temperature(section.shell_temperature_angles, section.shell_temperatures)
    basis, values = temperature_field(model, bore, cooling)
    at_points = np.asarray(basis.interpolate(values))
    strain = section.housing_expansion * (at_points - section.reference_temperature)
    displacement = structure.film_displacement(model.solve(thermal_load(model, strain)))
    fe_mesh = model.fe_mesh
    big_end = np.isin(fe_mesh.region, [k for k, name in enumerate(fe_mesh.region_names)
                                       if name in ("cap", "head")])
    mean = area_mean(basis, values, fe_mesh.thickness, big_end if big_end.any() else None)
    corners = int(fe_mesh.mesh.t.max()) + 1
    return (displacement, mean, float(np.mean(bore(structure.film_angles))),
            values[basis.nodal_dofs[0][:corners]])


@dataclass(frozen=True)
class WarmBore:
    """The clearance change and thermal distortion of a housing (module docstring).

    section : ThermalExpansionSection  Temperatures and expansion coefficients.
    journal_radius : float  R [m].
    bore_radius : float  Housing bore radius R_b [m].
    shell_thickness : float  t_s [m].
    bore : ndarray or None  Raw thermal bore displacement at the film nodes [m]; None for a
        housing without an FE model (a free ring at the housing temperature: ε_h R_b).
    housing_temperature : float  Mean temperature of the (big end of the) housing [degC].
    shell_temperature : float  Mean shell-side temperature, the shell's own [degC].
    corner_temperature : ndarray or None  The conduction field at the mesh's corner nodes
        [degC]; None for a uniform housing temperature.
    """

    section: object
    journal_radius: float
    bore_radius: float
    shell_thickness: float
    bore: np.ndarray | None = None
    housing_temperature: float = 20.0
    shell_temperature: float = 20.0
    corner_temperature: np.ndarray | None = None

    @property
    def shell_strain(self) -> float:
        """Thermal strain of the shell through its thickness [-]."""
        alpha = self.section.shell_expansion
        alpha = self.section.housing_expansion if alpha is None else alpha
        return alpha * (self.shell_temperature - self.section.reference_temperature)

    def bore_displacement(self, projector: np.ndarray | None = None) -> np.ndarray | float:
        """Corrected thermal bore displacement at the film nodes [m] (raw without a
        ``projector``: the same mean on the uniform film nodes; a number, ε_h R_b, without an
        FE model)."""
        if self.bore is None:
            strain = self.section.housing_expansion * (
                self.housing_temperature - self.section.reference_temperature)
            return strain * self.bore_radius
        return self.bore if projector is None else projector @ self.bore

    def clearance_change(self, projector: np.ndarray | None = None) -> float:
        """Δc = ū_th − ε_s t_s − ε_j R [m] (module docstring)."""
        mean = float(np.mean(self.bore_displacement(projector)))
        return (mean - self.shell_strain * self.shell_thickness
                - self.section.journal_strain * self.journal_radius)

    def profile(self, projector: np.ndarray) -> np.ndarray | None:
        """The out-of-round part of the thermal bore displacement [m] (None without an FE
        model)."""
        if self.bore is None:
            return None
        displacement = self.bore_displacement(projector)
        return displacement - displacement.mean()
