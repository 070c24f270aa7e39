"""``[engine]`` and ``[engine.pressure_model]`` sections ([D3] §2).

The key names are fixed; later checks rely on them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section, slip_hint, unit_slips

MIN_ENGINE_SPEED = 1.0
"""Slowest crank speed of an engine [rpm]."""
MIN_MEAN_PISTON_SPEED = 1.5
"""Slowest mean piston speed 2 S n of a running engine [m/s]: idling car and truck engines
run at 2–3 m/s, slow marine two-strokes at 5–8 m/s (their strokes are metres long). A speed
giving less was almost always typed in rad/s where rpm are asked for."""
RPM_PER_RAD_S = 30.0 / 3.141592653589793
"""rad/s → rpm [-]."""
MM_SLIP = unit_slips((1e-3, "mm"))
"""A length in metres typed in millimetres is refused with the value it likely means."""


class PressureModelSection(Section):
    """Parametric 4-stroke cylinder-pressure model of [D3] (all pressures absolute)."""

    compression_ratio: float = Field(gt=1.0, le=40.0, description="Compression ratio ε [-]")
    intake_pressure: float = Field(gt=0.0, le=1.0e7, description="Intake pressure p_a [Pa]")
    max_pressure: float = Field(gt=0.0, le=5.0e7, description="Maximum pressure p_z [Pa]")
    exhaust_pressure: float = Field(gt=0.0, le=1.0e7, description="Exhaust pressure p_b [Pa]")
    max_pressure_duration: float = Field(
        ge=0.0, le=150.0, description="Duration θ of constant p_z after 15° ATDC [deg]"
)
    compression_index: float = Field(gt=1.0, le=1.7, description="Polytropic index n1 [-]")
    expansion_index: float = Field(gt=1.0, le=1.7, description="Polytropic index n2 [-]")
    ambient_pressure: float = Field(
        default=1.0e5, gt=0.0, le=1.0e6, description="Ambient (crankcase) pressure [Pa]"
)


class EngineSection(Section):
    """Crank train of one cylinder and its cylinder pressure."""

    bore: float = Field(gt=0.0, le=2.0, json_schema_extra=MM_SLIP,
                        description="Cylinder bore D_p [m]")
    stroke: float = Field(gt=0.0, le=4.0, json_schema_extra=MM_SLIP,
                          description="Piston stroke S_p = 2 r [m]")
    rod_length: float = Field(
        gt=0.0, le=10.0, json_schema_extra=MM_SLIP,
        description="Rod length L, big-end to small-end centre [m]"
)
    speed: float = Field(ge=MIN_ENGINE_SPEED, le=30000.0, description="Crank speed n [rpm]")
    piston_mass: float = Field(gt=0.0, le=1.0e4, description="Piston, pin and rings m_p [kg]")
    rod_mass: float = Field(gt=0.0, le=1.0e4, description="Connecting-rod mass m_rod [kg]")
    rod_cg_from_big_end: float = Field(
        gt=0.0, le=10.0, description="Rod centre of mass from the big-end centre L_1 [m]"
)
    rod_inertia: float | None = Field(
        default=None,
        gt=0.0,
        le=1.0e3,
        description="Rod moment of inertia about its centre of mass J_c [kg m^2]; "
        "three-mass rod model when given",
)
    pressure_trace: Path | None = Field(
        default=None, strict=False,
        description="CSV file with columns crank_angle_deg, pressure_Pa (absolute) over 0..720 [-]",
)
    pressure_model: PressureModelSection | None = None
    ambient_pressure: float | None = Field(
        default=None,
        gt=0.0,
        le=1.0e6,
        description="Ambient (crankcase) pressure used with pressure_trace; default 1e5 [Pa]",
)
    kinematics: Literal["exact", "series"] = Field(
        default="exact",
        description="Piston acceleration of the two-mass model: exact or the [D3] "
        "series r ω²(cos φ + λ cos 2φ) [-]",
)

    @model_validator(mode="after")
    def _check_geometry(self) -> EngineSection:
        crank_radius = self.stroke / 2.0
        if self.rod_length <= crank_radius:
            raise ValueError(
                f"engine.rod_length = {self.rod_length!r} m must exceed the crank radius "
                f"stroke/2 = {crank_radius:g} m (allowed: rod_length > {crank_radius:g} m)"
)
        if self.rod_cg_from_big_end >= self.rod_length:
            raise ValueError(
                f"engine.rod_cg_from_big_end = {self.rod_cg_from_big_end!r} m must lie on the rod "
                f"(allowed: 0 < rod_cg_from_big_end < rod_length = {self.rod_length:g} m)"
)
        if (self.pressure_trace is None) == (self.pressure_model is None):
            raise ValueError(
                "engine: give exactly one of pressure_trace (CSV file) or [engine.pressure_model]"
)
        if self.ambient_pressure is not None and self.pressure_model is not None:
            raise ValueError(
                "engine.ambient_pressure is for pressure_trace; with [engine.pressure_model] "
                "set engine.pressure_model.ambient_pressure instead"
)
        self._check_mean_piston_speed()
        return self

    def _check_mean_piston_speed(self) -> None:
        """A speed whose mean piston speed 2 S n is below any running engine's, while the
        same number read as rad/s gives one, is refused with the likely intended rpm."""
        def piston_speed(rpm: float) -> float:
            return 2.0 * self.stroke * rpm / 60.0

        if piston_speed(self.speed) >= MIN_MEAN_PISTON_SPEED:
            return
        hint = slip_hint(self.speed, "rpm", [(RPM_PER_RAD_S, "rad/s")],
                         lambda rpm: piston_speed(rpm) >= MIN_MEAN_PISTON_SPEED)
        if not hint:
            return
        slowest = 60.0 * MIN_MEAN_PISTON_SPEED / (2.0 * self.stroke)
        raise ValueError(
            f"engine.speed = {self.speed!r}: out of range (allowed: >= {slowest:.4g} rpm with "
            f"the stroke {self.stroke:g} m, a mean piston speed 2 S n >= "
            f"{MIN_MEAN_PISTON_SPEED:g} m/s; this speed gives "
            f"{piston_speed(self.speed):.2g} m/s, below any running engine's){hint}")

    @property
    def crank_radius(self) -> float:
        """Crank radius r = stroke/2 [m]."""
        return self.stroke / 2.0
