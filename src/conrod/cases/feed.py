"""``[[bearing.journal_holes]]``: oil holes drilled in the journal (crank pin), fed from the
main gallery through the crank drilling. Example::

    [[bearing.journal_holes]]
    angle = 45.0                 # [deg] on the pin, from the outward crank radius towards
                                 # rotation, or "wear_diagram" (the least-worn angle)
    diameter = 0.005             # [m] at the pin surface
    gallery_pressure = 3.0e5     # [Pa] gauge; or a table [[crank angle deg, Pa], ...]
    drilling_inner_radius = 0.0  # [m] where the oil enters the drilling, from the crank axis
    # drilling_outer_radius      # [m] the hole's mouth from the crank axis; default from
                                 # the crank radius, pin radius and angle
    loss_coefficient = 0.0       # [-] share of gallery pressure + centrifugal head lost

The feed pressure at the hole's mouth is (1 − k)(p_gallery(φ) + ρ ω² (r_out² − r_in²)/2)
(:mod:`conrod.loads.oil_feed`); the hole turns with the crank pin, so it sweeps the shell at
ω_crank − ω_rod (docs/conventions.md, "Oil holes in the crank pin").
"""

from __future__ import annotations

import math
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error
from conrod.film.base import JournalHole

GalleryTable = list[list[float]]


class JournalHoleSection(Section):
    """One oil hole in the crank pin and its feed from the main gallery."""

    angle: float | Literal["wear_diagram"] = Field(
        default="wear_diagram", description="Angle of the hole on the pin, from the outward "
        "crank radius towards rotation [deg], or 'wear_diagram' (the least-worn angle of "
        "the journal wear diagram) [-]")
    diameter: float = Field(gt=0.0, le=1.0, description="Hole diameter at the pin surface [m]")
    axial_position: float = Field(default=0.0, ge=-2.5, le=2.5,
                                  description="Axial position of the hole centre, 0 = mid [m]")
    gallery_pressure: float | GalleryTable = Field(
        default=0.0, description="Gauge gallery pressure [Pa], constant or a table of "
        "[crank angle deg, Pa] rows over the cycle")
    drilling_inner_radius: float = Field(
        default=0.0, ge=0.0, le=5.0,
        description="Radius from the crank axis where the oil enters the drilling [m]")
    drilling_outer_radius: float | None = Field(
        default=None, gt=0.0, le=5.0, description="Radius from the crank axis of the hole's "
        "mouth on the pin [m]; default from the crank radius, pin radius and angle")
    loss_coefficient: float = Field(
        default=0.0, ge=0.0, lt=1.0,
        description="Share of the ideal feed pressure lost in the drilling [-]")

    @model_validator(mode="after")
    def _gallery(self) -> JournalHoleSection:
        """Angle within ±360°; gallery pressure ≥ 0 Pa; a table's angles increasing within
        one cycle."""
        if self.angle != "wear_diagram" and not -360.0 <= self.angle <= 360.0:
            raise range_error("bearing.journal_holes.angle", self.angle,
                              ">= -360 and <= 360, or 'wear_diagram'", "deg")
        value = self.gallery_pressure
        if not isinstance(value, list):
            if not (math.isfinite(value) and value >= 0.0):
                raise range_error("bearing.journal_holes.gallery_pressure", value,
                                  ">= 0, gauge", "Pa")
            return self
        if len(value) < 2:
            raise range_error("bearing.journal_holes.gallery_pressure", value,
                              "a number or at least 2 rows [crank angle deg, Pa]")
        for k, row in enumerate(value):
            if len(row) != 2:
                raise range_error(f"bearing.journal_holes.gallery_pressure[{k}]", row,
                                  "a row [crank angle deg, Pa]")
            angle, pressure = row
            if not (math.isfinite(pressure) and pressure >= 0.0):
                raise range_error(f"bearing.journal_holes.gallery_pressure[{k}]", pressure,
                                  ">= 0, gauge", "Pa")
            if not (0.0 <= angle <= 720.0) or (k and angle <= value[k - 1][0]):
                raise range_error(f"bearing.journal_holes.gallery_pressure[{k}] crank angle",
                                  angle, "increasing, within 0 to 720", "deg")
        return self

    def to_journal_hole(self, wear_angle: float | None = None) -> JournalHole:
        """SI :class:`JournalHole` (angle in rad); ``wear_angle`` [rad] for 'wear_diagram'."""
        if self.angle == "wear_diagram":
            if wear_angle is None:
                raise range_error("bearing.journal_holes.angle", self.angle,
                                  "a number of deg; 'wear_diagram' needs [engine] (the "
                                  "wear diagram of its loads)")
            angle = wear_angle
        else:
            angle = math.radians(self.angle)
        return JournalHole(angle, self.diameter, self.axial_position)


def check_journal_holes(holes: list[JournalHoleSection], diameter: float,
                        width: float) -> None:
    """Every journal hole fits the bearing: smaller than the width, inside it, smaller than
    half the pin circumference (one clear line naming the hole)."""
    half = 0.5 * width
    for k, hole in enumerate(holes):
        name = f"bearing.journal_holes[{k}]"
        largest = min(width, 0.5 * math.pi * diameter)
        if hole.diameter >= largest:
            raise range_error(f"{name}.diameter", hole.diameter,
                              f"> 0 and < {largest:g} (the bearing width {width:g} m and "
                              "half the pin circumference)", "m")
        reach = half - 0.5 * hole.diameter
        if abs(hole.axial_position) >= reach:
            raise range_error(f"{name}.axial_position", hole.axial_position,
                              f"> {-reach:g} and < {reach:g} (the hole of {hole.diameter:g} m "
                              f"on the pin inside the bearing width {width:g} m)", "m")
