"""``[lubricant]`` section: oil properties.

Viscosity at the film temperature comes from exactly one of

* ``viscosity`` [Pa s]: constant;
* the Vogel law μ(T) = a exp(b/(T + c)), T in °C, with ``vogel_a`` [Pa s], ``vogel_b``,
  ``vogel_c`` [°C];
* the oil's data sheet: ``kinematic_viscosity_40C``, ``kinematic_viscosity_100C``
  [mm²/s] and ``density_15C`` [kg/m³] → Walther law (ASTM D341) and the lubricating-oil
  density table (:mod:`conrod.oil`), μ = ρ(T) ν(T);
* ``grade = "5W-30"`` etc.: typical data-sheet values of that SAE J300 grade from
  ``conrod/data/sae_j300_grades.csv`` (assumed typical values, see the file).

The effective film temperature comes from the heat balance of
:mod:`conrod.orbit.heat_balance`, starting from ``supply_temperature`` [°C].

Pressure–viscosity (:mod:`conrod.film.piezoviscosity`): ``pressure_viscosity = "barus"``
with ``pressure_viscosity_coefficient`` α [1/Pa] (engine oils ≈ 1–2.5e-8), or
``"roelands"`` with ``roelands_index`` z [-] and ``roelands_reference_pressure`` p_r
[Pa]; above ``pressure_viscosity_limit`` [Pa] the viscosity is held constant. Example::

    [lubricant]
    grade = "5W-30"
    supply_temperature = 100.0
    pressure_viscosity = "barus"
    pressure_viscosity_coefficient = 1.5e-8
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error, slip_hint, unit_slips
from conrod.film.piezoviscosity import (
    DEFAULT_LIMIT_PRESSURE,
    ROELANDS_REFERENCE_PRESSURE,
    PressureViscosity,
)
from conrod.oil import WaltherLaw, density_at, oil_grades

MAX_VISCOSITY = 10.0
"""Largest dynamic viscosity accepted anywhere in the oil's temperature range [Pa s]."""
OIL_RANGE_FACTOR = 10.0
"""A constant viscosity may be at most this many times that of the thickest SAE J300
grade at the supply temperature [-]: engine oils, and the gear and cylinder oils beside
them, stay well inside; a value above it was typed in mPa s (cP) where Pa s are asked for."""
VISCOSITY_SLIPS = unit_slips((1e-3, "mPa s"))
"""A viscosity in Pa s typed in mPa s (= cP) is refused with the value it likely means."""
KINEMATIC_SLIPS = unit_slips((1e6, "m^2/s"))
"""A kinematic viscosity in mm²/s typed in m²/s, likewise."""


def thickest_oil_viscosity(temperature: float) -> float:
    """Dynamic viscosity [Pa s] of the thickest SAE J300 grade of
    ``conrod/data/sae_j300_grades.csv`` at ``temperature`` [°C] (Walther law, data-sheet
    density)."""
    return max(1.0e-6 * WaltherLaw(g.viscosity_40, g.viscosity_100).kinematic_viscosity(
        temperature) * density_at(g.density_15, temperature) for g in oil_grades().values())

class LubricantSection(Section):
    """Oil properties: viscosity source, density, heat capacity, pressure–viscosity law."""

    viscosity: float | None = Field(
        default=None, gt=0.0, le=10.0, json_schema_extra=VISCOSITY_SLIPS,
        description="Dynamic viscosity μ (constant) [Pa s]"
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
    kinematic_viscosity_40C: float | None = Field(  # noqa: N815 (unit suffix °C)
        default=None, ge=2.0, le=1.0e5, json_schema_extra=KINEMATIC_SLIPS,
        description="Data-sheet kinematic viscosity at 40 °C [mm^2/s]",
    )
    kinematic_viscosity_100C: float | None = Field(  # noqa: N815
        default=None, ge=2.0, le=1.0e4, json_schema_extra=KINEMATIC_SLIPS,
        description="Data-sheet kinematic viscosity at 100 °C [mm^2/s]",
    )
    density_15C: float | None = Field(  # noqa: N815
        default=None, gt=500.0, le=1500.0, description="Data-sheet density at 15 °C [kg/m^3]"
    )
    grade: str | None = Field(default=None, description="SAE J300 grade, e.g. '5W-30' [-]")
    density: float = Field(default=860.0, gt=100.0, le=2000.0,
                           description="Density ρ when no density_15C is given [kg/m^3]")
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
    pressure_viscosity: Literal["none", "barus", "roelands"] = Field(
        default="none", description="Pressure–viscosity law [-]"
    )
    pressure_viscosity_coefficient: float | None = Field(
        default=None, gt=0.0, le=1.0e-7, description="Barus pressure–viscosity coefficient α [1/Pa]"
    )
    roelands_index: float | None = Field(
        default=None, gt=0.0, le=2.0, description="Roelands pressure index z [-]"
    )
    roelands_reference_pressure: float = Field(
        default=ROELANDS_REFERENCE_PRESSURE, gt=1.0e6, le=1.0e10,
        description="Roelands reference pressure p_r [Pa]",
    )
    pressure_viscosity_limit: float = Field(
        default=DEFAULT_LIMIT_PRESSURE, gt=1.0e6, le=1.0e10,
        description="Pressure above which the viscosity is held constant [Pa]",
    )

    @model_validator(mode="after")
    def _one_viscosity_source(self) -> LubricantSection:
        vogel = (self.vogel_a, self.vogel_b, self.vogel_c)
        sheet = (self.kinematic_viscosity_40C, self.kinematic_viscosity_100C)
        if any(v is not None for v in vogel) and not all(v is not None for v in vogel):
            raise ValueError("lubricant: give all three of vogel_a [Pa s], vogel_b, vogel_c [°C]")
        if any(v is not None for v in sheet) and not all(v is not None for v in sheet):
            raise ValueError("lubricant: give both kinematic_viscosity_40C and "
                             "kinematic_viscosity_100C [mm^2/s]")
        sources = [self.viscosity is not None, self.vogel_a is not None,
                   self.kinematic_viscosity_40C is not None, self.grade is not None]
        if sum(sources) != 1:
            raise ValueError(
                "lubricant: give exactly one of viscosity [Pa s], the Vogel law (vogel_a [Pa s], "
                "vogel_b, vogel_c [°C]), the data sheet (kinematic_viscosity_40C, "
                "kinematic_viscosity_100C [mm^2/s], density_15C [kg/m^3]) or grade"
            )
        self._check_sheet()
        self._check_constant_viscosity()
        self._check_vogel()
        self._check_pressure_viscosity()
        if self.max_temperature <= self.supply_temperature:
            raise range_error("lubricant.max_temperature", self.max_temperature,
                              f"> supply_temperature = {self.supply_temperature:g}", "°C")
        return self

    def _check_sheet(self) -> None:
        if self.grade is not None and self.grade.upper() not in oil_grades():
            raise ValueError(f"lubricant.grade = {self.grade!r}: unknown (allowed: "
                             f"{', '.join(g.grade for g in oil_grades().values())})")
        if self.kinematic_viscosity_40C is not None:
            if self.density_15C is None:
                raise ValueError("lubricant.density_15C: missing (allowed: > 500 and <= 1500 "
                                 "kg/m^3); the data sheet needs it to turn ν into μ")
            if not self.kinematic_viscosity_40C > self.kinematic_viscosity_100C:  # type: ignore[operator]
                raise ValueError(
                    f"lubricant.kinematic_viscosity_100C = {self.kinematic_viscosity_100C}: "
                    f"out of range (allowed: < kinematic_viscosity_40C = "
                    f"{self.kinematic_viscosity_40C} mm^2/s)")

    def _check_constant_viscosity(self) -> None:
        """A constant viscosity far above any engine oil's at the supply temperature is a
        unit slip (mPa s typed for Pa s): refused with the value it likely means."""
        if self.viscosity is None:
            return
        largest = OIL_RANGE_FACTOR * thickest_oil_viscosity(self.supply_temperature)
        if self.viscosity <= largest:
            return
        hint = slip_hint(self.viscosity, "Pa s", VISCOSITY_SLIPS["unit_slips"],
                         lambda value: value <= largest)
        raise range_error(
            "lubricant.viscosity", self.viscosity,
            f"<= {largest:.3g} Pa s at the supply temperature {self.supply_temperature:g} °C, "
            f"{OIL_RANGE_FACTOR:g} x the thickest SAE J300 grade there", "", hint)

    def _check_vogel(self) -> None:
        if self.vogel_c is None:
            return
        if self.supply_temperature + self.vogel_c <= 0.0:
            raise ValueError(
                f"lubricant.supply_temperature = {self.supply_temperature} °C must exceed "
                f"-vogel_c = {-self.vogel_c:g} °C"
            )
        self._check_vogel_range()

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

    def _check_pressure_viscosity(self) -> None:
        law = self.pressure_viscosity
        if law == "barus" and self.pressure_viscosity_coefficient is None:
            raise ValueError("lubricant.pressure_viscosity_coefficient: missing for 'barus' "
                             "(allowed: > 0 and <= 1e-07 1/Pa, engine oils ~1e-8 to 2.5e-8)")
        if law == "roelands" and self.roelands_index is None:
            raise ValueError("lubricant.roelands_index: missing for 'roelands' "
                             "(allowed: > 0 and <= 2, mineral oils ~0.5-0.7)")
        if law != "barus" and self.pressure_viscosity_coefficient is not None:
            raise ValueError("lubricant.pressure_viscosity_coefficient: only used with "
                             f"pressure_viscosity = 'barus' (got {law!r})")
        if law != "roelands" and self.roelands_index is not None:
            raise ValueError("lubricant.roelands_index: only used with "
                             f"pressure_viscosity = 'roelands' (got {law!r})")

    # ------------------------------------------------------------------ properties
    @property
    def temperature_dependent(self) -> bool:
        """True when the viscosity depends on temperature (Vogel, data sheet or grade)."""
        return self.viscosity is None

    def walther(self) -> WaltherLaw | None:
        """Walther law of the data sheet or grade; None for constant/Vogel viscosity."""
        if self.kinematic_viscosity_40C is not None:
            return WaltherLaw(self.kinematic_viscosity_40C,
                              self.kinematic_viscosity_100C)  # type: ignore[arg-type]
        if self.grade is not None:
            row = oil_grades()[self.grade.upper()]
            return WaltherLaw(row.viscosity_40, row.viscosity_100)
        return None

    def reference_density(self) -> float | None:
        """ρ(15 °C) [kg/m³] of the data sheet or grade; None otherwise."""
        if self.density_15C is not None:
            return self.density_15C
        if self.grade is not None:
            return oil_grades()[self.grade.upper()].density_15
        return None

    def density_at(self, temperature: float) -> float:
        """Density ρ [kg/m³] at ``temperature`` [°C] (``density`` without a data sheet)."""
        rho15 = self.reference_density()
        return self.density if rho15 is None else density_at(rho15, temperature)

    def viscosity_at(self, temperature: float) -> float:
        """Dynamic viscosity μ [Pa s] at ``temperature`` [°C] and zero gauge pressure."""
        if self.viscosity is not None:
            return self.viscosity
        walther = self.walther()
        if walther is not None:
            return 1.0e-6 * walther.kinematic_viscosity(temperature) * self.density_at(temperature)
        denominator = max(temperature + self.vogel_c, 1.0)  # type: ignore[operator]
        return self.vogel_a * math.exp(self.vogel_b / denominator)  # type: ignore[operator]

    def pressure_viscosity_law(self) -> PressureViscosity | None:
        """The μ(p) law for the film models; None when isoviscous."""
        if self.pressure_viscosity == "none":
            return None
        return PressureViscosity(
            law=self.pressure_viscosity,
            coefficient=self.pressure_viscosity_coefficient or 0.0,
            roelands_index=self.roelands_index or 0.6,
            roelands_pressure=self.roelands_reference_pressure,
            limit_pressure=self.pressure_viscosity_limit,
        )
