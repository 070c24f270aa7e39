"""``[lubricant]`` section: oil properties (SPEC S2 'Viscosity')."""

from __future__ import annotations

from pydantic import Field

from conrod.cases.base import Section


class LubricantSection(Section):
    """Oil properties; constant viscosity or a viscosity-temperature law."""

    viscosity: float | None = Field(
        default=None, gt=0.0, le=10.0, description="Dynamic viscosity μ [Pa s]"
    )
    density: float = Field(default=860.0, gt=100.0, le=2000.0, description="Density ρ [kg/m^3]")
    specific_heat: float = Field(
        default=2000.0, gt=100.0, le=10000.0, description="Specific heat c_p [J/(kg K)]"
    )
