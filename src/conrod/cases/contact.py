"""``[contact]`` section: dry contact, friction, Hertz stress, wear and asperity contact
([D4]).

Defaults describe a steel crankpin in a steel-backed aluminium-tin (AlSn20) shell, the
usual passenger-car big end; for a babbitt (white-metal) lining use
``shell_elastic_modulus = 5.0e10`` and ``shell_poisson_ratio = 0.35``. The lining is
treated as a homogeneous half-space (its steel backing is ignored), which slightly
underestimates the contact stiffness of thin linings.

Wear coefficients are *energy* wear coefficients k [m^3/J]: wear depth = k × friction
work per unit surface area (see :mod:`conrod.contact.wear` for the mapping from [D4]'s
engineering unit). [D4] chooses them "approximately", the shell's an order of magnitude
smaller than the journal's; the defaults keep that ratio and must be calibrated for a
real material pair.

Greenwood–Tripp parameters (``model = "greenwood_tripp"``): combined RMS roughness σ of
both surfaces, asperity (summit) density η and summit radius β. Typical finished bearing
surfaces have ηβσ ≈ 0.03–0.06 and σ/β ≈ 10⁻³–10⁻²; the defaults give ηβσ = 0.04,
σ/β = 0.02.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from conrod.cases.base import Section


class ContactSection(Section):
    """Dry contact / mixed-lubrication parameters. Hard contact is always enforced by
    the orbit solver (the journal never leaves the clearance circle)."""

    model: Literal["hard", "greenwood_tripp"] = Field(
        default="hard", description="Contact model: rigid circle or asperity contact [-]"
)
    dry_friction_coefficient: float = Field(
        default=0.1, ge=0.0, le=1.0, description="Dry friction coefficient μ_dry [-]"
)
    journal_elastic_modulus: float = Field(
        default=2.1e11, gt=1.0e8, le=1.0e12,
        description="Young's modulus of the journal (crankpin) E_1, steel [Pa]",
)
    journal_poisson_ratio: float = Field(
        default=0.3, ge=0.0, lt=0.5, description="Poisson ratio of the journal ν_1 [-]"
)
    shell_elastic_modulus: float = Field(
        default=7.0e10, gt=1.0e8, le=1.0e12,
        description="Young's modulus of the shell lining E_2, Al-Sn [Pa]",
)
    shell_poisson_ratio: float = Field(
        default=0.33, ge=0.0, lt=0.5, description="Poisson ratio of the shell lining ν_2 [-]"
)
    wear_coefficient_journal: float = Field(
        default=1.0e-15, ge=0.0, le=1.0e-9,
        description="Energy wear coefficient of the journal k_j (depth per work per area) [m^3/J]",
)
    wear_coefficient_shell: float = Field(
        default=1.0e-16, ge=0.0, le=1.0e-9,
        description="Energy wear coefficient of the shell k_b (depth per work per area) [m^3/J]",
)
    surface_elements: int = Field(
        default=360, ge=8, le=36000,
        description="Number of surface elements around journal and shell for work and wear [-]",
)
    roughness: float = Field(
        default=0.4e-6, gt=0.0, le=1.0e-4,
        description="Combined RMS roughness σ = √(σ_1² + σ_2²) (Greenwood–Tripp) [m]",
)
    asperity_density: float = Field(
        default=5.0e9, gt=0.0, le=1.0e16, description="Asperity summit density η [1/m^2]"
)
    asperity_radius: float = Field(
        default=20.0e-6, gt=0.0, le=1.0e-2, description="Asperity summit radius β [m]"
)
    contact_threshold_ratio: float = Field(
        default=0.01, ge=0.0, lt=1.0,
        description="Asperity force, as a share of the peak bearing load, above which a crank "
        "angle counts as in asperity contact (asperity contact intervals) [-]",
)
