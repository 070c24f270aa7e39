"""``[misalignment]``: the journal's tilt in the bearing, prescribed or solved.

Tilt angles γ_x, γ_y [rad] are right-handed rotations of the journal (crank pin) about the
x and y axes of the film (bearing) frame; the journal axis at axial position z passes
through (e_x + z γ_y, e_y − z γ_x) (docs/conventions.md). Two modes:

* ``mode = "prescribed"`` (default): the tilt over the cycle, constant (``tilt_x``,
  ``tilt_y``) or a table ``table = "tilt.csv"`` with the columns ``crank_angle_deg,
  tilt_x_rad, tilt_y_rad`` (e.g. from the crank pin's bending), interpolated by a periodic
  cubic spline, its rate entering the squeeze term;
* ``mode = "free"``: γ_x, γ_y are two more degrees of freedom of the journal, moved by the
  film's moments, the external moment (``moment_x``, ``moment_y`` [N m] constant, or a
  table ``moment_table`` with ``crank_angle_deg, moment_x_N_m, moment_y_N_m``, plus the
  moment a(−W_y, W_x) of the load W acting at ``load_axial_offset`` a [m] from mid-width,
  e.g. a crank web or a rod not centred on the pin) and, in the
  orbit with mass, the rod's moments of inertia about the film's x and y axes through the
  bearing centre (``moment_of_inertia_x``, ``moment_of_inertia_y`` [kg m²]).

Example::

    [misalignment]
    table = "crank_pin_tilt.csv"
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error

MAX_TILT = 0.01
"""Largest prescribed tilt [rad] (10 mrad: far beyond a clearance of a few 1e-3 of L/2)."""


class MisalignmentSection(Section):
    """Journal tilt (module docstring)."""

    mode: Literal["prescribed", "free"] = Field(
        default="prescribed", description="Tilt prescribed over the cycle or solved [-]")
    tilt_x: float = Field(default=0.0, ge=-MAX_TILT, le=MAX_TILT,
                          description="Constant tilt about the film's x axis [rad]")
    tilt_y: float = Field(default=0.0, ge=-MAX_TILT, le=MAX_TILT,
                          description="Constant tilt about the film's y axis [rad]")
    table: Path | None = Field(default=None, strict=False,
                               description="CSV: crank_angle_deg, tilt_x_rad, tilt_y_rad [-]")
    moment_of_inertia_x: float = Field(
        default=0.0, ge=0.0, le=1e3,
        description="Rod's moment of inertia about the film x axis at the bearing [kg m^2]")
    moment_of_inertia_y: float = Field(
        default=0.0, ge=0.0, le=1e3,
        description="Rod's moment of inertia about the film y axis at the bearing [kg m^2]")
    moment_x: float = Field(default=0.0, ge=-1e6, le=1e6,
                            description="Constant external moment on the journal, x [N m]")
    moment_y: float = Field(default=0.0, ge=-1e6, le=1e6,
                            description="Constant external moment on the journal, y [N m]")
    moment_table: Path | None = Field(
        default=None, strict=False,
        description="CSV: crank_angle_deg, moment_x_N_m, moment_y_N_m [-]")
    load_axial_offset: float = Field(
        default=0.0, ge=-1.0, le=1.0,
        description="Axial position z of the load line from mid-width: moment a(−W_y, W_x) "
                    "[m]")

    @model_validator(mode="after")
    def _mode_keys(self) -> MisalignmentSection:
        """Prescribed tilt takes angles, a free tilt moments and inertias; a table replaces
        the constants."""
        prescribed = self.mode == "prescribed"
        wrong = (("moment_of_inertia_x", "moment_of_inertia_y", "moment_x", "moment_y",
                  "moment_table", "load_axial_offset") if prescribed
                 else ("tilt_x", "tilt_y", "table"))
        for name in wrong:
            if getattr(self, name):
                raise range_error(f"misalignment.{name}", getattr(self, name),
                                  f"not set with misalignment.mode = {self.mode!r}")
        for table, constants in (("table", ("tilt_x", "tilt_y")),
                                 ("moment_table", ("moment_x", "moment_y"))):
            for name in constants:
                if getattr(self, table) is not None and getattr(self, name):
                    raise range_error(f"misalignment.{name}", getattr(self, name),
                                      f"0 with misalignment.{table} (the table replaces it)",
                                      "rad" if table == "table" else "N m")
        return self

    @property
    def free(self) -> bool:
        """True when the tilt is solved as two more degrees of freedom [-]."""
        return self.mode == "free"
