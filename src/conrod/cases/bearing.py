"""``[bearing]`` section: journal-bearing geometry and oil-supply features.

Angles of supply features are in degrees, measured on the shell in the film frame
(θ from +x towards +y, see :mod:`conrod.film.base`); everything else is SI. Example::

    [bearing]
    diameter = 0.085
    width = 0.028
    radial_clearance = 4.0e-5
    supply_pressure = 3.0e5

    [[bearing.grooves]]          # partial circumferential groove
    start_angle = 90.0
    extent = 180.0
    width = 0.004

    [[bearing.feed_holes]]
    angle = 0.0
    diameter = 0.005

    [[bearing.axial_grooves]]     # axial groove centred at θ = 180°
    angle = 180.0
    width = 0.003                # circumferential width [m]
    length = 0.020               # axial length [m], default: the full shell width

A bore/shell profile (crush and end reliefs, lemon bore, taper, crown, a measured table) is
``[bearing.profile]`` and ``profile_file`` (:mod:`conrod.cases.profile`).

An axial groove becomes a :class:`~conrod.film.base.Groove` of angular extent
width/R centred on ``angle`` and axial width ``length`` centred at mid-width, so every
grid film (and the steady calculator) holds it at the supply pressure; a groove
narrower than the grid spacing still marks its nearest column of nodes.
"""

from __future__ import annotations

import math
from pathlib import Path

from pydantic import Field, PrivateAttr, model_validator

from conrod.cases.base import Section, range_error, slip_hint, unit_slips
from conrod.cases.feed import JournalHoleSection, check_journal_holes
from conrod.cases.profile import ProfileSection
from conrod.film.base import GEOMETRY_LIMITS, BearingGeometry, FeedHole, Groove
from conrod.film.profile import BoreProfile, ProfileTable

MIN_SIZE = 1.0e-3
"""Smallest journal diameter and bearing width [m] (1 mm)."""
MIN_CLEARANCE = 1.0e-6
"""Smallest radial clearance [m] (1 µm, as the joints of the mechanism)."""
MM_SLIP = unit_slips((1e-3, "mm"))
"""A length in metres typed in millimetres is refused with the value it likely means."""
CLEARANCE_SLIPS = unit_slips((1e-3, "mm"), (1e-6, "µm"))
"""A clearance in metres typed in millimetres or micrometres, likewise."""
MAX_RELATIVE_CLEARANCE = 0.05
"""Largest radial clearance / journal radius c/R: thin-film (Reynolds) theory needs c ≪ R
(engine bearings: 0.0005–0.003) [-]."""


class GrooveSection(Section):
    """Full or partial circumferential oil groove held at the supply pressure."""

    start_angle: float = Field(default=0.0, ge=-360.0, le=360.0,
                               description="Angle θ where the groove starts [deg]")
    extent: float = Field(default=360.0, gt=0.0, le=360.0,
                          description="Angular extent, 360 for a full groove [deg]")
    width: float = Field(gt=0.0, le=1.0, description="Axial width of the groove [m]")
    axial_position: float = Field(default=0.0, ge=-2.5, le=2.5,
                                  description="Axial position of the groove centre, 0 = mid [m]")
    fed_by_journal_holes: bool = Field(
        default=False, description="Fed by the crank-pin holes (half groove): at their "
        "pressure while one opens into it, else at the supply pressure [-]")

    def to_groove(self) -> Groove:
        """SI :class:`Groove` (angles in rad)."""
        return Groove(math.radians(self.start_angle), math.radians(self.extent),
                      self.width, self.axial_position, self.fed_by_journal_holes)


class FeedHoleSection(Section):
    """Circular oil-feed hole held at the supply pressure."""

    angle: float = Field(ge=-360.0, le=360.0, description="Angle θ of the hole centre [deg]")
    diameter: float = Field(gt=0.0, le=1.0, description="Hole diameter [m]")
    axial_position: float = Field(default=0.0, ge=-2.5, le=2.5,
                                  description="Axial position of the hole centre, 0 = mid [m]")

    def to_feed_hole(self) -> FeedHole:
        """SI :class:`FeedHole` (angle in rad)."""
        return FeedHole(math.radians(self.angle), self.diameter, self.axial_position)


class AxialGrooveSection(Section):
    """Axial oil groove in the shell held at the supply pressure."""

    angle: float = Field(ge=-360.0, le=360.0, description="Angle θ of the groove centre [deg]")
    width: float = Field(gt=0.0, le=1.0, description="Circumferential width of the groove [m]")
    length: float | None = Field(default=None, gt=0.0, le=5.0,
                                 description="Axial length, default the shell width [m]")

    def to_groove(self, radius: float, shell_width: float) -> Groove:
        """SI :class:`Groove` on a journal of ``radius`` [m] and ``shell_width`` [m]."""
        extent = self.width / radius
        length = shell_width if self.length is None else self.length
        return Groove(math.radians(self.angle) - 0.5 * extent, extent, length, 0.0)


class BearingSection(Section):
    """Geometry of the big-end (or any journal) bearing and its oil supply."""

    diameter: float = Field(ge=MIN_SIZE, le=5.0, json_schema_extra=MM_SLIP,
                            description="Journal (crankpin) diameter d [m]")
    width: float = Field(ge=MIN_SIZE, le=5.0, json_schema_extra=MM_SLIP,
                         description="Working shell width l' (axial length) [m]")
    radial_clearance: float | None = Field(
        default=None, ge=MIN_CLEARANCE, le=1.0e-2, json_schema_extra=CLEARANCE_SLIPS,
        description="Radial clearance c [m]"
)
    supply_pressure: float = Field(
        default=0.0, ge=0.0, le=1.0e7, description="Gauge oil-supply pressure p_s [Pa]"
)
    cavitation_pressure: float = Field(
        default=0.0, ge=-1.0e5, le=0.0, description="Gauge cavitation pressure p_cav [Pa]"
)
    grooves: list[GrooveSection] = Field(default_factory=list,
                                         description="Oil grooves in the shell [-]")
    feed_holes: list[FeedHoleSection] = Field(default_factory=list,
                                              description="Oil-feed holes in the shell [-]")
    axial_grooves: list[AxialGrooveSection] = Field(
        default_factory=list, description="Axial oil grooves in the shell [-]")
    journal_holes: list[JournalHoleSection] = Field(
        default_factory=list, description="Oil holes in the crank pin, fed from the gallery [-]")
    profile: ProfileSection | None = Field(
        default=None, description="Parametric bore/shell profile [-]")
    profile_file: str | None = Field(
        default=None, min_length=1,
        description="Measured profile CSV: angle_deg, axial_position_m, offset_m [-]")
    _profile_table: ProfileTable | None = PrivateAttr(default=None)

    @model_validator(mode="after")
    def _consistent(self) -> BearingSection:
        """Clearance thin against the radius (features: :meth:`check_features_inside_width`,
        called for the whole case by :func:`conrod.cases.rules.check_case`)."""
        radius = 0.5 * self.diameter
        low, high = GEOMETRY_LIMITS["length_to_diameter"]
        if not low * self.diameter <= self.width <= high * self.diameter:
            raise range_error("bearing.width", self.width, f">= {low * self.diameter:g} m "
                              f"and <= {high * self.diameter:g} m, {low:g} to {high:g} x "
                              "bearing.diameter")
        if self.radial_clearance is not None:
            smallest = max(MIN_CLEARANCE, GEOMETRY_LIMITS["clearance_to_radius"][0] * radius)
            largest = MAX_RELATIVE_CLEARANCE * radius
            if not smallest <= self.radial_clearance <= largest:
                hint = slip_hint(self.radial_clearance, "m",
                                 CLEARANCE_SLIPS["unit_slips"],
                                 lambda value: smallest <= value <= largest)
                raise range_error("bearing.radial_clearance", self.radial_clearance,
                                  f">= {smallest:g} and <= {MAX_RELATIVE_CLEARANCE:g} x "
                                  f"journal radius = {largest:g}", "m", hint)
        return self

    def geometry(self, wear_angle: float | None = None) -> BearingGeometry:
        """SI :class:`BearingGeometry` with the supply features (needs the clearance);
        ``wear_angle`` [rad]: the journal angle of a hole at ``angle = "wear_diagram"``."""
        if self.radial_clearance is None:
            raise range_error("bearing.radial_clearance", None, "> 0", "m")
        self.check_features_inside_width()
        return BearingGeometry(
            diameter=self.diameter, width=self.width, radial_clearance=self.radial_clearance,
            grooves=tuple(g.to_groove() for g in self.grooves) + tuple(
                g.to_groove(0.5 * self.diameter, self.width) for g in self.axial_grooves),
            feed_holes=tuple(h.to_feed_hole() for h in self.feed_holes),
            journal_holes=tuple(h.to_journal_hole(wear_angle) for h in self.journal_holes),
            supply_pressure=self.supply_pressure,
            cavitation_pressure=self.cavitation_pressure,
            profile=self.bore_profile(),
)

    def read_profile_file(self, path: Path) -> None:
        """Read ``profile_file`` (resolved to ``path`` by the case) once, when the case is
        read; CaseError naming the file, the line and the value on any problem."""
        self._profile_table = ProfileTable.from_csv(path, "bearing.profile_file")

    def bore_profile(self) -> BoreProfile | None:
        """The bore/shell profile of ``[bearing.profile]`` and ``profile_file`` (None: a
        cylindrical bore)."""
        table = self._profile_table
        if self.profile_file is not None and table is None:
            table = ProfileTable.from_csv(Path(self.profile_file), "bearing.profile_file")
        if self.profile is None:
            return None if table is None else BoreProfile(table=table)
        return self.profile.to_profile(self.width, table)

    def check_features_inside_width(self) -> None:
        """Every groove and hole lies inside the width and leaves a land on both sides."""
        half = 0.5 * self.width
        features = [(f"grooves[{k}]", g.axial_position, g.width, "width")
                    for k, g in enumerate(self.grooves)]
        features += [(f"feed_holes[{k}]", h.axial_position, h.diameter, "diameter")
                     for k, h in enumerate(self.feed_holes)]
        for name, position, size, size_name in features:
            if size >= self.width:
                raise range_error(f"bearing.{name}.{size_name}", size,
                                  f"> 0 and < bearing.width = {self.width:g}", "m")
            reach = half - 0.5 * size
            if abs(position) >= reach:
                raise range_error(f"bearing.{name}.axial_position", position,
                                  f"> {-reach:g} and < {reach:g} (the {size_name} "
                                  f"{size:g} m inside the bearing width {self.width:g} m)", "m")
        for k, hole in enumerate(self.feed_holes):
            if hole.diameter >= 0.5 * math.pi * self.diameter:
                raise range_error(f"bearing.feed_holes[{k}].diameter", hole.diameter,
                                  f"< half the journal circumference "
                                  f"{0.5 * math.pi * self.diameter:g}", "m")
        check_journal_holes(self.journal_holes, self.diameter, self.width)
        for k, groove in enumerate(self.axial_grooves):
            if groove.length is not None and groove.length > self.width:
                raise range_error(f"bearing.axial_grooves[{k}].length", groove.length,
                                  f"<= {self.width:g}", "m")
            if groove.width >= math.pi * self.diameter:
                raise range_error(f"bearing.axial_grooves[{k}].width", groove.width,
                                  f"< {math.pi * self.diameter:g} (the circumference)", "m")
