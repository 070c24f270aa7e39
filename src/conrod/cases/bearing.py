"""``[bearing]`` section: journal-bearing geometry and oil-supply features (SPEC S2)."""

from __future__ import annotations

from pydantic import Field

from conrod.cases.base import Section


class BearingSection(Section):
    """Geometry of the big-end (or any journal) bearing."""

    diameter: float = Field(gt=0.0, le=5.0, description="Journal (crankpin) diameter d [m]")
    width: float = Field(gt=0.0, le=5.0, description="Working shell width l' (axial length) [m]")
    radial_clearance: float | None = Field(
        default=None, gt=0.0, le=1.0e-2, description="Radial clearance c [m]"
    )
