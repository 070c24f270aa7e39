"""``[bearing.profile]``: the parametric bore/shell profile h₀(θ, z) of the bearing.

Angles in degrees on the shell in the film (bearing) frame, θ from +x towards +y (for a big
end x along the rod towards the small end); lengths in metres. The profile is fixed in that
frame, so a shell profile turns with the rod. A measured profile is ``[bearing]
profile_file`` (columns ``angle_deg, axial_position_m, offset_m``); both may be given and
add up. Shapes and formulas: :mod:`conrod.film.profile`. Example::

    [bearing.profile]
    crush_relief_depth = 12.0e-6     # [m] at the rod/cap joint faces
    crush_relief_extent = 20.0       # [deg] from each joint face
    joint_angles = [90.0, 270.0]     # [deg] the split, perpendicular to the rod axis
    end_relief_depth = 6.0e-6        # [m] at both edges
    end_relief_length = 4.0e-3       # [m] axial length of the relief
"""

from __future__ import annotations

import math

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error
from conrod.film.profile import BoreProfile, Harmonic, ProfileTable


class HarmonicSection(Section):
    """One out-of-round term a cos(n(θ − φ))."""

    order: int = Field(ge=1, le=64, description="Order n (2 ovality, 3 trilobe) [-]")
    amplitude: float = Field(ge=-1e-3, le=1e-3, description="Amplitude a [m]")
    angle: float = Field(default=0.0, ge=-360.0, le=360.0, description="Phase φ [deg]")


class ProfileSection(Section):
    """Parametric bore/shell profile (module docstring)."""

    crush_relief_depth: float = Field(default=0.0, ge=0.0, le=1e-3,
                                      description="Crush relief depth at the joint faces [m]")
    crush_relief_extent: float = Field(default=0.0, ge=0.0, le=90.0,
                                       description="Crush relief extent from a joint face "
                                                   "[deg]")
    joint_angles: list[float] = Field(default=[90.0, 270.0], min_length=1, max_length=4,
                                      description="Shell angles of the rod/cap joints [deg]")
    end_relief_depth: float = Field(default=0.0, ge=0.0, le=1e-3,
                                    description="End relief (edge chamfer) depth at the edges "
                                                "[m]")
    end_relief_length: float = Field(default=0.0, ge=0.0, le=1.0,
                                     description="Axial length of the end relief [m]")
    preload: float = Field(default=0.0, ge=0.0, le=0.9,
                           description="Elliptical (lemon) bore preload m, 0 = none [-]")
    offset_halves: float = Field(default=0.0, ge=0.0, le=1e-3,
                                 description="Offset of the two halves along the split [m]")
    lobe_angle: float = Field(default=0.0, ge=-360.0, le=360.0,
                              description="Centre of the first lobe / half [deg]")
    taper: float = Field(default=0.0, ge=-1e-3, le=1e-3,
                         description="Axial taper, clearance at z = +L/2 minus at -L/2 [m]")
    crown: float = Field(default=0.0, ge=-1e-3, le=1e-3,
                         description="Crown, clearance at the edges minus at mid-width [m]")
    out_of_round: list[HarmonicSection] = Field(default_factory=list,
                                                description="Out-of-round harmonics [-]")

    @model_validator(mode="after")
    def _pairs(self) -> ProfileSection:
        """Depth and extent (length) of a relief go together."""
        for depth, size, what in (("crush_relief_depth", "crush_relief_extent", "deg"),
                                  ("end_relief_depth", "end_relief_length", "m")):
            if (getattr(self, depth) > 0.0) != (getattr(self, size) > 0.0):
                raise range_error(f"bearing.profile.{size}", getattr(self, size),
                                  f"> 0 with bearing.profile.{depth} > 0, else 0", what)
        return self

    def to_profile(self, width: float, table: ProfileTable | None = None) -> BoreProfile:
        """SI :class:`BoreProfile` for a shell of ``width`` [m] (the end relief within half
        the width), with the measured ``table`` when given."""
        if self.end_relief_length > 0.5 * width:
            raise range_error("bearing.profile.end_relief_length", self.end_relief_length,
                              f"> 0 and <= half the bearing width = {0.5 * width:g}", "m")
        return BoreProfile(
            crush_relief_depth=self.crush_relief_depth,
            crush_relief_extent=math.radians(self.crush_relief_extent),
            joint_angles=tuple(math.radians(a) for a in self.joint_angles),
            end_relief_depth=self.end_relief_depth, end_relief_length=self.end_relief_length,
            preload=self.preload, offset_halves=self.offset_halves,
            lobe_angle=math.radians(self.lobe_angle), taper=self.taper, crown=self.crown,
            out_of_round=tuple(Harmonic(h.order, h.amplitude, math.radians(h.angle))
                               for h in self.out_of_round),
            table=table)
