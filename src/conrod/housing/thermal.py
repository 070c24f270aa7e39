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

The run's housing is at one mean temperature (uniform ΔT): a free body would only grow,
but the clamped rod's bore is distorted slightly by its held small end. The corrected bore
displacement's mean is ū_th; what is left (its out-of-round part) enters the film as the
bore profile h₀(θ) beside the assembled bore. The field is linear in ε_h: the bore
displacement per unit strain is computed once per housing and cached with the compliance.
A temperature field that varies over the housing (from a thermal film) is the same load
with a non-uniform ΔT (:func:`thermal_load`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from skfem import LinearForm, asm


def thermal_load(model, strain) -> np.ndarray:
    """FE load vector [N] of the thermal strain field ε_th(x, y) = α ΔT [-] (``strain``: a
    callable of the coordinates at quadrature points) on the plane-stress ``model``."""
    basis = model.basis
    thickness = np.repeat(model.fe_mesh.thickness[:, None], basis.X.shape[1], axis=1)
    modulus = model.material.youngs_modulus / (1.0 - model.material.poisson_ratio)

    @LinearForm
    def form(v, w):
        return w.t * modulus * strain(w.x[0], w.x[1]) * (v.grad[0][0] + v.grad[1][1])

    return asm(form, basis, t=thickness)


def unit_strain_bore(structure) -> np.ndarray:
    """Raw radial bore displacement at the film nodes [m] of a uniform unit thermal strain
    (ε_th = 1) of the whole housing ``structure``."""
    load = thermal_load(structure.model, lambda x, y: np.ones_like(x))
    return structure.film_displacement(structure.model.solve(load))


@dataclass(frozen=True)
class WarmBore:
    """The clearance change and thermal distortion of a housing (module docstring).

    section : ThermalExpansionSection  Temperatures and expansion coefficients.
    journal_radius : float  R [m].
    bore_radius : float  Housing bore radius R_b [m].
    shell_thickness : float  t_s [m].
    unit_bore : ndarray or None  Raw bore displacement per unit housing strain at the film
        nodes [m]; None for a housing without an FE model (a free ring: ε_h R_b).
    """

    section: object
    journal_radius: float
    bore_radius: float
    shell_thickness: float
    unit_bore: np.ndarray | None = None

    def bore_displacement(self, projector: np.ndarray | None = None) -> np.ndarray | float:
        """Corrected thermal bore displacement at the film nodes [m] (a number, ε_h R_b,
        without an FE model)."""
        strain = self.section.housing_strain
        if self.unit_bore is None:
            return strain * self.bore_radius
        return strain * (projector @ self.unit_bore)

    def clearance_change(self, projector: np.ndarray | None = None) -> float:
        """Δc = ū_th − ε_s t_s − ε_j R [m] (module docstring)."""
        mean = float(np.mean(self.bore_displacement(projector)))
        return (mean - self.section.shell_strain * self.shell_thickness
                - self.section.journal_strain * self.journal_radius)

    def profile(self, projector: np.ndarray) -> np.ndarray | None:
        """The out-of-round part of the thermal bore displacement [m] (None without an FE
        model)."""
        if self.unit_bore is None:
            return None
        displacement = self.bore_displacement(projector)
        return displacement - displacement.mean()
