"""``[load]`` section: a tabulated bearing load instead of the engine loads of ``[engine]``.

With both sections the table is the bearing load (``conrod run``, ``conrod loads``) and
``[engine]`` gives only the crank train — the rod's inertia deformation of an elastic big
end and the moving masses; both must turn at the same speed.

The table (CSV) has the columns ``crank_angle_deg, load_x_N, load_y_N``: the load pressing
the journal on the shell in the bearing (film) frame. Read by
:func:`conrod.loads.table_load.read_load_table`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field

from conrod.cases.base import Section

MIN_TABLE_SPEED = 0.1
"""Slowest crank speed of a bearing given by its load table [rpm] (a slow machine)."""


class LoadTableSection(Section):
    """Load diagram in the bearing frame read from CSV."""

    table: Path = Field(
        strict=False, description="CSV with columns crank_angle_deg, load_x_N, load_y_N [-]"
    )
    speed: float = Field(
        ge=MIN_TABLE_SPEED, le=30000.0,
        description="Crank speed n mapping angle to time [rpm]"
)
    cycle_deg: Literal[360, 720] = Field(default=720, description="Load cycle length [deg]")
    journal_speed: float | None = Field(
        default=None, ge=-1.0e4, le=1.0e4,
        description="Journal angular velocity ω_j, default: the crank speed [rad/s]",
)
    shell_speed: float = Field(
        default=0.0, ge=-1.0e4, le=1.0e4, description="Shell angular velocity ω_b [rad/s]"
)
    scale: float = Field(
        default=1.0, gt=0.0, le=1.0e6, description="Factor applied to the tabulated loads [-]"
)
