"""``[limits]``: what the bearing is signed off against (the lining's and the film's limits).

Every limit is optional (no default: a bearing maker's values belong to the lining, not to
conrod). Each given limit is checked against the run's value over the cycle; the headline,
``summary.json``, ``margins.csv`` and the report give the margin, and a crossed limit is a
warning (exit 4). Typical values for steel-backed AlSn and lead-bronze linings, and their
sources, are in docs/signoff.md.

Example::

    [limits]
    min_film_thickness = 0.5e-6   # MOFT [m]
    max_pressure = 250e6          # POFP [Pa]
    pressure_range = 200e6        # lining fatigue: largest max - min at one point [Pa]
    asperity_pressure = 20e6      # Greenwood-Tripp contact pressure [Pa]
    max_temperature = 150.0       # film temperature [degC]
"""

from __future__ import annotations

from pydantic import Field

from conrod.cases.base import Section


class LimitsSection(Section):
    """Sign-off limits (module docstring); None: not checked."""

    min_film_thickness: float | None = Field(
        default=None, gt=0.0, le=1e-3,
        description="Smallest allowed film thickness over the cycle, MOFT [m]")
    max_pressure: float | None = Field(
        default=None, gt=0.0, le=1e10,
        description="Largest allowed film pressure over the cycle, POFP [Pa]")
    pressure_range: float | None = Field(
        default=None, gt=0.0, le=1e10,
        description="Largest allowed pressure range max - min at one point of the lining "
                    "over the cycle (hydrodynamic fatigue) [Pa]")
    asperity_pressure: float | None = Field(
        default=None, gt=0.0, le=1e10,
        description="Largest allowed Greenwood-Tripp asperity contact pressure [Pa]")
    max_temperature: float | None = Field(
        default=None, gt=-50.0, le=500.0,
        description="Largest allowed film temperature [degC]")

    def given(self) -> dict[str, float]:
        """The limits set in the case (name → value in the unit of its field) [-]."""
        return {name: value for name, value in self.model_dump().items() if value is not None}
