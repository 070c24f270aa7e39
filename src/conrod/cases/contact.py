"""``[contact]`` section: dry contact, friction and wear (issue 5, SPEC S4, seed 004)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from conrod.cases.base import Section


class ContactSection(Section):
    """Dry contact / mixed-lubrication parameters. Hard contact is always enforced by
    the orbit solver (the journal never leaves the clearance circle)."""

    model: Literal["hard", "greenwood_tripp"] = Field(
        default="hard", description="Contact model: rigid circle or asperity contact [-]"
    )
    dry_friction_coefficient: float = Field(
        default=0.1, ge=0.0, le=1.0, description="Dry friction coefficient μ_dry [-]"
    )
