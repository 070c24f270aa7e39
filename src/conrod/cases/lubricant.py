"""``[lubricant]`` section: oil properties.

Viscosity is either constant (``viscosity``) or given by the Vogel law

.. math:: μ(T) = a \\exp\\left(\\frac{b}{T + c}\\right),  T in °C,

with ``vogel_a`` [Pa s], ``vogel_b`` [°C], ``vogel_c`` [°C]. The effective film temperature
comes from the heat balance of :mod:`conrod.orbit.heat_balance`, starting from
``supply_temperature`` [°C].
"""

from __future__ import annotations

import math

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error

MAX_VISCOSITY = 10.0
"""Largest dynamic viscosity accepted anywhere in the oil's temperature range [Pa s]."""


class LubricantSection(Section):
    """Oil properties; constant viscosity or a viscosity-temperature (Vogel) law."""

    viscosity: float | None = Field(
        default=None, gt=0.0, le=10.0, description="Dynamic viscosity μ (constant) [Pa s]"
    )
    vogel_a: float | None = Field(
        default=None, gt=0.0, le=10.0, description="Vogel law factor a in μ = a exp(b/(T+c)) [Pa s]"
    )
    vogel_b: float | None = Field(
        default=None, gt=0.0, le=1.0e5, description="Vogel law constant b [°C]"
    )
    vogel_c: float | None = Field(
        default=None, gt=-273.0, le=1.0e3, description="Vogel law constant c [°C]"
    )
    density: float = Field(default=860.0, gt=100.0, le=2000.0, description="Density ρ [kg/m^3]")
    specific_heat: float = Field(
        default=2000.0, gt=100.0, le=10000.0, description="Specific heat c_p [J/(kg K)]"
    )
    supply_temperature: float = Field(
        default=90.0, gt=-50.0, le=300.0, description="Oil supply (inlet) temperature [°C]"
    )
    max_temperature: float = Field(
        default=200.0, gt=-50.0, le=400.0,
        description="Highest temperature at which the oil data are valid; a heat-balance "
        "temperature above it is flagged in the results [°C]",
    )

    @model_validator(mode="after")
    def _one_viscosity_source(self) -> LubricantSection:
        vogel = (self.vogel_a, self.vogel_b, self.vogel_c)
        has_vogel = all(v is not None for v in vogel)
        if any(v is not None for v in vogel) and not has_vogel:
            raise ValueError("lubricant: give all three of vogel_a [Pa s], vogel_b, vogel_c [°C]")
        if has_vogel == (self.viscosity is not None):
            raise ValueError(
                "lubricant: give exactly one of viscosity [Pa s] or the Vogel law "
                "(vogel_a [Pa s], vogel_b [°C], vogel_c [°C])"
            )
        if has_vogel and self.supply_temperature + self.vogel_c <= 0.0:  # type: ignore[operator]
            raise ValueError(
                f"lubricant.supply_temperature = {self.supply_temperature} °C must exceed "
                f"-vogel_c = {-self.vogel_c:g} °C"  # type: ignore[operator]
            )
        if has_vogel:
            self._check_vogel_range()
        if self.max_temperature <= self.supply_temperature:
            raise range_error("lubricant.max_temperature", self.max_temperature,
                              f"> supply_temperature = {self.supply_temperature:g}", "°C")
        return self

    def _check_vogel_range(self) -> None:
        """μ(T) of the Vogel law stays <= MAX_VISCOSITY (no overflow) from the supply
        temperature up: the viscosity falls with temperature, so the supply end decides."""
        a, b, c = self.vogel_a, self.vogel_b, self.vogel_c
        exponent = b / (self.supply_temperature + c)  # type: ignore[operator]
        if exponent > math.log(MAX_VISCOSITY / a):  # type: ignore[operator]
            largest_b = math.log(MAX_VISCOSITY / a) * (self.supply_temperature + c)  # type: ignore
            raise range_error(
                "lubricant.vogel_b", b, f"> 0 and <= {largest_b:.4g} (Vogel law with vogel_a = "
                f"{a:g} Pa s, vogel_c = {c:g} °C gives mu({self.supply_temperature:g} °C) "
                f"above {MAX_VISCOSITY:g} Pa s)", "°C")

    @property
    def temperature_dependent(self) -> bool:
        """True when the viscosity follows the Vogel law."""
        return self.viscosity is None

    def viscosity_at(self, temperature: float) -> float:
        """Dynamic viscosity μ [Pa s] at ``temperature`` [°C]."""
        if self.viscosity is not None:
            return self.viscosity
        denominator = max(temperature + self.vogel_c, 1.0)  # type: ignore[operator]
        return self.vogel_a * math.exp(self.vogel_b / denominator)  # type: ignore[operator]
