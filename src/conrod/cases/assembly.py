"""``[housing.assembly]``: the big end as assembled — bolt preload at the cap joint and the
crush of the bearing shell, a static load case of the finite-element housing whose bore
shape enters the film as a bore profile (docs/elastic.md, *The assembled bore*).

Example::

    [housing.assembly]
    bolt_preload = 60.0e3        # [N] per bolt
    crush_height = 40.0e-6       # [m] per half shell
    shell_youngs_modulus = 2.1e11  # [Pa] steel back of the shell

The joint between rod and cap is **bonded** (the built-in rod is one body, as for the
compliance): the joint pressure is the normal stress across the split line, and where the
bonded joint would carry tension over the cycle the report says the joint opens there (a
frictionless contact joint that really separates is not built).
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section

JointModelName = Literal["bonded"]
"""Joint models built: ``bonded`` (rod and cap one body; opening is reported, not modelled)."""
ClearanceReferenceName = Literal["assembled", "nominal"]
"""What ``[bearing] radial_clearance`` is: the mean clearance of the assembled bore, or that of
the shell in the unstressed housing bore."""


class AssemblySection(Section):
    """Bolt preload and shell crush of the assembled big end (module docstring)."""

    bolt_preload: float = Field(default=0.0, ge=0.0, le=2.0e6, description=(
        "Preload of each of the two cap bolts [N]"))
    bolt_distance: float | None = Field(default=None, gt=0.0, le=5.0, description=(
        "Distance between the two bolt axes; built-in rod default: the bore diameter plus "
        "the thinner head wall (bolts at mid-wall); required on an imported mesh [m]"))
    bolt_thread_depth: float | None = Field(default=None, gt=0.0, le=1.0, description=(
        "Distance from the split line into the rod to the centre of the thread engagement; "
        "built-in rod default half the head wall thickness; required on an imported mesh "
        "[m]"))
    crush_height: float = Field(default=0.0, ge=0.0, le=1.0e-3, description=(
        "Crush height of each half shell: its outer circumference less half the housing bore "
        "circumference [m]"))
    interference: float = Field(default=0.0, ge=0.0, le=3.0e-4, description=(
        "Radial interference of the shell in the housing bore, instead of crush_height "
        "(crush_height = π × interference) [m]"))
    shell_youngs_modulus: float = Field(default=2.1e11, gt=1.0e9, le=1.0e12, description=(
        "Young's modulus of the shell (its steel back) [Pa]"))
    joint: JointModelName = Field(default="bonded", description=(
        "Rod/cap joint model: bonded (opening over the cycle is reported) [-]"))
    clearance_reference: ClearanceReferenceName = Field(default="assembled", description=(
        "bearing.radial_clearance is the mean clearance of the assembled bore (assembled: the "
        "bore's out-of-round shape enters the film) or of the shell in the unstressed housing "
        "(nominal: its mean expansion enters too) [-]"))

    @model_validator(mode="after")
    def _one_crush(self) -> AssemblySection:
        if self.crush_height > 0.0 and self.interference > 0.0:
            raise ValueError(f"housing.assembly.interference = {self.interference!r}: give "
                             "crush_height or interference, not both (allowed: one of them 0)")
        return self

    @property
    def active(self) -> bool:
        """True when some preload or crush loads the housing [-]."""
        return self.bolt_preload > 0.0 or self.shell_crush_height > 0.0

    @property
    def shell_crush_height(self) -> float:
        """Crush height per half shell [m] (from ``interference`` when that is given)."""
        if self.interference > 0.0:
            return math.pi * self.interference
        return self.crush_height


class ThermalExpansionSection(Section):
    """Journal and housing at their running temperatures: the clearance change and the
    housing's thermal distortion (docs/elastic.md, *The warm bore*). The housing is at one
    mean temperature (``housing_temperature``) or conducts from its shell-side temperature
    around the bore (``shell_temperatures`` at ``shell_temperature_angles``) to the
    crankcase (FE housings). With ``[solver] thermal = "film"`` and none of the three
    temperatures given, they come from the film's energy solution (docs/thermal.md,
    *Thermal distortion from the film*)."""

    journal_temperature: float | None = Field(default=None, ge=-40.0, le=400.0, description=(
        "Mean temperature of the journal (crank pin); leave out with the other temperatures "
        "to take them from the thermal film [degC]"))
    housing_temperature: float | None = Field(default=None, ge=-40.0, le=400.0, description=(
        "Mean temperature of the housing and its shell, uniform [degC]"))
    shell_temperature_angles: list[float] = Field(default_factory=list, max_length=360,
                                                  description=(
        "Shell angles of shell_temperatures, film frame (0 = towards the small end) [deg]"))
    shell_temperatures: list[float] = Field(default_factory=list, max_length=360,
                                            description=(
        "Shell-side temperature of the housing bore at shell_temperature_angles, "
        "interpolated periodically [degC]"))
    ambient_temperature: float | None = Field(default=None, ge=-40.0, le=300.0, description=(
        "Crankcase temperature the housing's faces and outline give heat to (with "
        "shell_temperatures) [degC]"))
    surface_heat_transfer: float = Field(default=300.0, gt=0.0, le=1.0e5, description=(
        "Heat-transfer coefficient of the housing's faces and outline to the crankcase "
        "(oil splash and mist) [W/(m^2 K)]"))
    conductivity: float = Field(default=45.0, gt=0.1, le=500.0, description=(
        "Thermal conductivity of the housing (steel default) [W/(m K)]"))
    reference_temperature: float = Field(default=20.0, ge=-40.0, le=100.0, description=(
        "Temperature at which bearing.radial_clearance is given (measured) [degC]"))
    journal_expansion: float = Field(default=11.5e-6, ge=0.0, le=5.0e-5, description=(
        "Linear expansion coefficient of the journal (steel default) [1/K]"))
    housing_expansion: float = Field(default=11.5e-6, ge=0.0, le=5.0e-5, description=(
        "Linear expansion coefficient of the housing (steel default; aluminium 23e-6) [1/K]"))
    shell_expansion: float | None = Field(default=None, ge=0.0, le=5.0e-5, description=(
        "Linear expansion coefficient of the shell through its thickness; default that of "
        "the housing [1/K]"))

    @model_validator(mode="after")
    def _one_housing_temperature(self) -> ThermalExpansionSection:
        field = bool(self.shell_temperatures)
        if self.from_film:
            return self
        if self.journal_temperature is None:
            raise ValueError("housing.thermal.journal_temperature is required with "
                             "housing_temperature or shell_temperatures (or leave out all "
                             "three: the temperatures of [solver] thermal = 'film')")
        if (self.housing_temperature is None) == (not field):
            raise ValueError("housing.thermal: give housing_temperature (uniform) or "
                             "shell_temperatures (conduction from the bore), one of them")
        if len(self.shell_temperatures) != len(self.shell_temperature_angles):
            raise ValueError(f"housing.thermal.shell_temperature_angles has "
                             f"{len(self.shell_temperature_angles)} values, "
                             f"shell_temperatures {len(self.shell_temperatures)} (allowed: "
                             "the same number)")
        for name in ("shell_temperature_angles", "shell_temperatures"):
            low, high = (0.0, 360.0) if name.endswith("angles") else (-40.0, 400.0)
            for value in getattr(self, name):
                if not low <= value <= high:
                    raise ValueError(f"housing.thermal.{name} contains {value!r}: out of "
                                     f"range (allowed: >= {low:g} and <= {high:g})")
        if field and self.ambient_temperature is None:
            raise ValueError("housing.thermal.ambient_temperature is required with "
                             "shell_temperatures (the crankcase temperature [degC])")
        return self

    @property
    def from_film(self) -> bool:
        """True when no temperature is given: the thermal film gives them [-]."""
        return (self.journal_temperature is None and self.housing_temperature is None
                and not self.shell_temperatures)

    def at_temperatures(self, journal: float, angles: list[float], shell: list[float],
                        ambient: float) -> ThermalExpansionSection:
        """This section with given temperatures: the journal's [degC], the shell-side ones
        ``shell`` [degC] at ``angles`` [deg] conducting to the crankcase at its own
        ``ambient_temperature`` or ``ambient`` [degC]; one angle: the housing uniform at it
        (a housing without an FE model, which cannot conduct)."""
        if len(shell) == 1:
            return self.model_copy(update={"journal_temperature": float(journal),
                                           "housing_temperature": float(shell[0])})
        return self.model_copy(update={
            "journal_temperature": float(journal), "shell_temperature_angles": list(angles),
            "shell_temperatures": list(shell), "ambient_temperature": float(
                ambient if self.ambient_temperature is None else self.ambient_temperature)})

    @property
    def conducting(self) -> bool:
        """True when the housing's temperature follows from its shell-side temperatures [-]."""
        return bool(self.shell_temperatures)

    @property
    def active(self) -> bool:
        """True when the journal or the housing is not at the reference temperature [-]."""
        return (self.conducting or self.from_film
                or self.journal_temperature != self.reference_temperature
                or self.housing_temperature != self.reference_temperature)

    @property
    def journal_strain(self) -> float:
        """Free thermal strain of the journal α_j (T_j − T_ref) [-]."""
        return self.journal_expansion * (self.journal_temperature - self.reference_temperature)
