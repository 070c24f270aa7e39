"""``[clearance.big_end]`` and ``[clearance.small_end]`` sections (issue 6, seed 003)."""

from __future__ import annotations

from pydantic import Field

from conrod.cases.base import Section


class JointClearanceSection(Section):
    """One clearance joint with a worn elliptical shell (seed 003 symbols in brackets)."""

    diameter: float = Field(gt=0.0, le=5.0, description="Journal/pin diameter D or d [m]")
    clearance_max: float = Field(
        gt=0.0, le=1.0e-2, description="Diametral clearance along the major axis Δmax [m]"
    )
    clearance_min: float = Field(
        gt=0.0, le=1.0e-2, description="Diametral clearance along the minor axis Δmin [m]"
    )


class ClearanceSection(Section):
    """The two rod joints."""

    big_end: JointClearanceSection
    small_end: JointClearanceSection
