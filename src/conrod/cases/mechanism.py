"""``[clearance]``, ``[clearance.big_end]`` and ``[clearance.small_end]`` ([D3]).

The joint keys are fixed; the [D3] symbol of each is in its description.
``[clearance]`` itself holds the numerics of the mechanism run (all optional).
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, ValidationInfo, field_validator, model_validator

from conrod.cases.base import Section, range_error

MAX_RELATIVE_CLEARANCE = 0.1
"""Largest diametral clearance / diameter of a joint (worn engine joints: < 0.01) [-]."""
MAX_STEPS_PER_CYCLE = 250_000
"""Integrator step budget per cycle of ``conrod mechanism`` (the shipped case needs 2.4e4;
a run past it stops with exit 3 within seconds instead of minutes) [-]."""
MIN_CLEARANCE = 1.0e-6
"""Smallest diametral joint clearance: the integrator's error scale is a share of it [m]."""
MAX_OUTPUT_ROWS = 500_000
"""Most sampled result rows over all cycles [-]."""


class JointClearanceSection(Section):
    """One clearance joint with a worn elliptical shell ([D3] symbols in brackets)."""

    diameter: float = Field(gt=0.0, le=5.0, description="Journal/pin diameter D or d [m]")
    clearance_max: float = Field(
        ge=MIN_CLEARANCE, le=1.0e-2,
        description="Diametral clearance along the major axis Δmax [m]"
    )
    clearance_min: float = Field(
        ge=MIN_CLEARANCE, le=1.0e-2,
        description="Diametral clearance along the minor axis Δmin [m]"
    )
    ellipse_angle_deg: float = Field(
        default=0.0, ge=-180.0, le=180.0,
        description="Angle γ from the rod axis to the ellipse major axis, "
        "towards y_rod like the shell angle θ [deg]",
    )
    contact_stiffness: float = Field(
        default=1.0e13, gt=0.0, le=1.0e20, description="Contact stiffness c [N/m^exponent]"
    )
    contact_exponent: float = Field(
        default=1.5, ge=1.0, le=3.0, description="Contact force exponent α [-]"
    )
    damping_factor: float = Field(
        default=0.1, ge=0.0, le=2.0, description="Damping factor μ in β = 2μ√(c·m_eff) [-]"
    )
    friction_coefficient: float = Field(
        default=0.0, ge=0.0, le=1.0, description="Coulomb friction coefficient f₁₂ [-]"
    )
    damping_scale: float = Field(
        default=1.0, ge=0.0, le=10.0,
        description="Extra factor on β; [D3] uses 0.3 at the small end [-]",
    )

    @field_validator("clearance_min")
    @classmethod
    def _not_above_clearance_max(cls, value: float, info: ValidationInfo) -> float:
        clearance_max = info.data.get("clearance_max")
        if clearance_max is not None and value > clearance_max:
            raise ValueError(f"must not exceed clearance_max = {clearance_max!r} m "
                             "(a worn shell has Δmin <= Δmax)")
        return value

    @field_validator("clearance_max")
    @classmethod
    def _small_against_diameter(cls, value: float, info: ValidationInfo) -> float:
        diameter = info.data.get("diameter")
        if diameter is not None and value > MAX_RELATIVE_CLEARANCE * diameter:
            raise ValueError(f"must not exceed {MAX_RELATIVE_CLEARANCE:g} x diameter = "
                             f"{MAX_RELATIVE_CLEARANCE * diameter:g} m")
        return value


class ClearanceSection(Section):
    """The two rod joints and the numerics of ``conrod mechanism``."""

    big_end: JointClearanceSection
    small_end: JointClearanceSection
    cycles: int = Field(
        default=2, ge=1, le=50,
        description="Engine cycles integrated; results from the last one [-]",
    )
    tolerance: float = Field(
        default=1.0e-4, gt=0.0, le=1.0e-1,
        description="Local error per step relative to the smallest radial clearance [-]",
    )
    output_step_deg: float = Field(
        default=0.5, gt=0.0, le=10.0, description="Crank-angle spacing of the results [deg]"
    )
    max_step_deg: float = Field(
        default=0.25, gt=0.0, le=5.0, description="Largest integrator step [deg]"
    )
    impact_separation: float = Field(
        default=0.01, gt=0.0, le=1.0,
        description="Separation (fraction of the joint's smallest radial clearance) "
        "before a new contact entry counts as an impact [-]",
    )
    friction_velocity: float = Field(
        default=1.0e-3, gt=0.0, le=1.0,
        description="Sliding speed below which friction is smoothed v₀ [m/s]",
    )
    load_scale: float = Field(
        default=1.0, ge=0.0, le=5.0, description="Factor on the gas pressure (load) [-]"
    )
    contact_geometry: Literal["seed", "exact"] = Field(
        default="exact",
        description="exact: ellipse-circle contact along the contact normal (free-play "
        "region always convex); seed: penetration along the line of centres ([D3]), "
        "whose free-play region turns non-convex on strongly worn shells (warned) [-]",
    )
    worn_joint: Literal["auto", "big_end", "small_end"] = Field(
        default="auto",
        description="Joint diagnosed in the sweep; auto = the larger clearance_max/diameter [-]",
    )

    @model_validator(mode="after")
    def _within_budget(self) -> ClearanceSection:
        """Result rows and the smallest possible step count within the budgets."""
        rows = self.cycles * 720.0 / self.output_step_deg
        if rows > MAX_OUTPUT_ROWS:
            smallest = self.cycles * 720.0 / MAX_OUTPUT_ROWS
            raise range_error("clearance.output_step_deg", self.output_step_deg,
                              f">= {smallest:.3g} with cycles = {self.cycles} (budget "
                              f"{MAX_OUTPUT_ROWS} rows)", "deg")
        smallest_step = 720.0 / MAX_STEPS_PER_CYCLE
        if self.max_step_deg < smallest_step:
            raise range_error("clearance.max_step_deg", self.max_step_deg,
                              f">= {smallest_step:.3g} (budget {MAX_STEPS_PER_CYCLE} steps "
                              "per cycle)", "deg")
        return self
