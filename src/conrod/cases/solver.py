"""``[solver]`` section: film model and numerics of the orbit (issue 4)."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from conrod.cases.base import Section

FilmName = Literal["short", "mobility", "reynolds", "mass_conserving", "table"]


class SolverSection(Section):
    """Which film model drives the orbit, and how the orbit is integrated."""

    film: FilmName = Field(default="short", description="Film model [-]")
