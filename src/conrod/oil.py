"""Oil properties from a data sheet: Walther viscosity–temperature law, density, SAE grades.

Kinematic viscosity ν [mm²/s] follows the Walther (MacCoull) equation of ASTM D341 [1],

.. math:: \\log_{10}\\log_{10}(ν + 0.7) = A − B \\log_{10} T,   T in K,

whose two constants follow exactly from the two data-sheet points ν(40 °C), ν(100 °C)
(valid for ν ≥ 2 mm²/s; ASTM D341's extra terms for thinner fluids are not used).
Density follows the volume-correction factor of the petroleum measurement tables for
lubricating oils [2],

.. math:: ρ(T) = ρ_{15} \\exp[−α_{15} Δt (1 + 0.8 α_{15} Δt)],  α_{15} = K_1/ρ_{15},
          Δt = T − 15 °C,  K_1 = 0.6278 kg/(m³ K),

and the dynamic viscosity is μ = ρ ν [Pa s].

Typical values of the common SAE J300 grades live in ``conrod/data/sae_j300_grades.csv``
with the source (or the stated assumption) of every number.

[1] ASTM D341, Standard Practice for Viscosity–Temperature Equations and Charts for
    Liquid Petroleum or Hydrocarbon Products.
[2] API Manual of Petroleum Measurement Standards ch. 11.1 / ASTM D1250 (1980),
    tables 53D/54D (lubricating oils: K₀ = 0, K₁ = 0.6278).
"""

from __future__ import annotations

import csv
import functools
import math
from dataclasses import dataclass
from importlib import resources

KELVIN = 273.15
"""0 °C in K."""
WALTHER_SHIFT = 0.7
"""Constant added to ν [mm²/s] in the Walther equation of ASTM D341."""
LUBE_OIL_K1 = 0.6278
"""K₁ of the lubricating-oil volume-correction table [kg/(m³ K)]."""
GRADES_FILE = "sae_j300_grades.csv"


def _walther(nu: float) -> float:
    return math.log10(math.log10(nu + WALTHER_SHIFT))


@dataclass(frozen=True)
class WaltherLaw:
    """Walther law through two data-sheet points.

    viscosity_40 : float  Kinematic viscosity ν at 40 °C [mm²/s].
    viscosity_100 : float  Kinematic viscosity ν at 100 °C [mm²/s].
    """

    viscosity_40: float
    viscosity_100: float

    @property
    def slope(self) -> float:
        """B of log log(ν + 0.7) = A − B log T [-]."""
        t40, t100 = math.log10(40.0 + KELVIN), math.log10(100.0 + KELVIN)
        return (_walther(self.viscosity_40)
                - _walther(self.viscosity_100)) / (t100 - t40)

    @property
    def intercept(self) -> float:
        """A of log log(ν + 0.7) = A − B log T [-]."""
        return _walther(self.viscosity_40) + self.slope * math.log10(40.0 + KELVIN)

    def kinematic_viscosity(self, temperature: float) -> float:
        """ν(T) [mm²/s] at ``temperature`` [°C]."""
        exponent = self.intercept - self.slope * math.log10(temperature + KELVIN)
        return 10.0 ** (10.0**exponent) - WALTHER_SHIFT


def density_at(density_15: float, temperature: float) -> float:
    """ρ(T) [kg/m³] from ρ(15 °C) [kg/m³] at ``temperature`` [°C] (lubricating-oil table)."""
    alpha = LUBE_OIL_K1 / density_15
    dt = temperature - 15.0
    return density_15 * math.exp(-alpha * dt * (1.0 + 0.8 * alpha * dt))


@dataclass(frozen=True)
class OilGrade:
    """One row of the SAE J300 grade table (units in brackets)."""

    grade: str
    viscosity_40: float
    """Typical ν at 40 °C [mm²/s]."""
    viscosity_100: float
    """Typical ν at 100 °C [mm²/s]."""
    density_15: float
    """Typical density at 15 °C [kg/m³]."""
    kv100_min: float
    """SAE J300 lower limit of ν at 100 °C [mm²/s]."""
    kv100_max: float
    """SAE J300 upper limit (exclusive) of ν at 100 °C [mm²/s]."""
    hths_min: float
    """SAE J300 minimum high-temperature high-shear viscosity at 150 °C [mPa s]."""
    basis: str
    source: str


@functools.lru_cache(maxsize=1)
def oil_grades() -> dict[str, OilGrade]:
    """All grades of the data file, keyed by the upper-case grade name ('5W-30')."""
    text = resources.files("conrod.data").joinpath(GRADES_FILE).read_text(encoding="utf-8")
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    grades = {}
    for row in rows:
        grade = OilGrade(
            grade=row["grade"],
            viscosity_40=float(row["kinematic_viscosity_40C_mm2_per_s"]),
            viscosity_100=float(row["kinematic_viscosity_100C_mm2_per_s"]),
            density_15=float(row["density_15C_kg_per_m3"]),
            kv100_min=float(row["j300_kv100_min_mm2_per_s"]),
            kv100_max=float(row["j300_kv100_max_mm2_per_s"]),
            hths_min=float(row["j300_hths150_min_mPa_s"]),
            basis=row["typical_values_basis"], source=row["source"],
        )
        grades[grade.grade.upper()] = grade
    return grades
