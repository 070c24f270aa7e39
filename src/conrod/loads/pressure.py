"""Cylinder pressure over the 4-stroke cycle: measured trace or [D3] parametric model.

Both are periodic over 4π (720°) with φ = 0 at firing TDC and give the **absolute**
pressure [Pa]; the gas force uses the gauge pressure p − p_ambient.

.. code-block:: python

    pressure = build_pressure(case)
    pressure.gauge(np.radians([0.0, 10.0]))   # [Pa]
"""

from __future__ import annotations

import abc
import csv
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Protocol

import numpy as np

from conrod.cases.base import range_error
from conrod.cases.case import Case
from conrod.cases.engine import PressureModelSection
from conrod.errors import CaseError
from conrod.io.text import csv_data_lines, read_utf8
from conrod.loads.kinematics import piston_displacement_series

CYCLE = 4.0 * math.pi
"""Length of the 4-stroke cycle [rad]."""
DEFAULT_AMBIENT = 1.0e5
"""Ambient (crankcase) pressure used with a trace unless the case gives one [Pa]."""
MAX_TRACE_GAP_DEG = 20.0
"""Largest allowed gap between consecutive trace angles, wrap-around included [deg]."""


class CylinderPressure(Protocol):
    """Absolute cylinder pressure as a periodic function of crank angle."""

    @property
    def ambient(self) -> float:
        """Ambient (crankcase) pressure [Pa]."""
        ...

    def absolute(self, crank_angle: np.ndarray) -> np.ndarray:
        """Absolute pressure [Pa] at crank angles [rad] (any real values; period 4π)."""
        ...

    def gauge(self, crank_angle: np.ndarray) -> np.ndarray:
        """Gauge pressure p − p_ambient [Pa]."""
        ...


class _GaugeMixin(abc.ABC):
    ambient: float

    @abc.abstractmethod
    def absolute(self, crank_angle: np.ndarray) -> np.ndarray:
        """Absolute pressure [Pa] at crank angles [rad]."""

    def gauge(self, crank_angle: np.ndarray) -> np.ndarray:
        """Gauge pressure p − p_ambient [Pa] at crank angles [rad]."""
        return self.absolute(crank_angle) - self.ambient


@dataclass(frozen=True)
class TracePressure(_GaugeMixin):
    """Measured/simulated trace interpolated linearly and periodically.

    crank_angle : ndarray  Trace angles, strictly increasing, spanning < 4π [rad].
    pressure : ndarray  Absolute pressure at those angles [Pa].
    ambient : float  Ambient pressure [Pa].
    """

    crank_angle: np.ndarray
    pressure: np.ndarray
    ambient: float = DEFAULT_AMBIENT

    def absolute(self, crank_angle: np.ndarray) -> np.ndarray:
        """Absolute pressure [Pa], periodic linear interpolation of the trace."""
        return np.interp(
            np.asarray(crank_angle, dtype=float), self.crank_angle, self.pressure, period=CYCLE
        )


@dataclass(frozen=True)
class ParametricPressure(_GaugeMixin):
    """Parametric 4-stroke diesel pressure of [D3] §2 (with its printing errors corrected).

    With S(φ) the series piston displacement, S_c = S_p/(ε − 1) and p_c = p_a ε^{n1}:

    * 0–15°: p = p_c + (p_z − p_c) S/S(15°)  (rise, linear in displacement as in [D3])
    * 15°–15°+θ: p = p_z
    * 15°+θ–170°: p = p_z [(S_c + S(15°+θ))/(S_c + S)]^{n2}
    * 170°–360°: p = p_b;  360°–540°: p = p_a
    * 540°–720°: p = p_a [(S_c + S_p)/(S_c + S)]^{n1}

    crank_radius, rod_length : float  r and L [m].
    compression_ratio ... expansion_index : see :class:`PressureModelSection` [Pa], [-], [deg].
    ambient : float  Ambient pressure [Pa].
    """

    crank_radius: float
    rod_length: float
    compression_ratio: float
    intake_pressure: float
    max_pressure: float
    exhaust_pressure: float
    max_pressure_duration_deg: float
    compression_index: float
    expansion_index: float
    ambient: float

    @property
    def compression_end_pressure(self) -> float:
        """p_c = p_a ε^{n1} [Pa]."""
        return self.intake_pressure * self.compression_ratio**self.compression_index

    def _displacement(self, crank_angle: np.ndarray | float) -> np.ndarray:
        return piston_displacement_series(crank_angle, self.crank_radius, self.rod_length)

    def absolute(self, crank_angle: np.ndarray) -> np.ndarray:
        """Absolute pressure [Pa] at crank angles [rad] (period 4π)."""
        phi = np.mod(np.asarray(crank_angle, dtype=float), CYCLE)
        stroke = 2.0 * self.crank_radius
        clearance_height = stroke / (self.compression_ratio - 1.0)
        s = self._displacement(phi)
        rise_end = math.radians(15.0)
        plateau_end = rise_end + math.radians(self.max_pressure_duration_deg)
        p_c, p_z = self.compression_end_pressure, self.max_pressure
        rise = p_c + (p_z - p_c) * s / self._displacement(rise_end)
        s_plateau = self._displacement(plateau_end)
        expansion = (
            p_z * ((clearance_height + s_plateau) / (clearance_height + s)) ** self.expansion_index
        )
        compression = (
            self.intake_pressure
            * ((clearance_height + stroke) / (clearance_height + s)) ** self.compression_index
        )
        conditions = [
            phi <= rise_end,
            phi <= plateau_end,
            phi <= math.radians(170.0),
            phi <= 2.0 * math.pi,
            phi <= 3.0 * math.pi,
        ]
        choices = [
            rise,
            np.full_like(phi, p_z),
            expansion,
            np.full_like(phi, self.exhaust_pressure),
            np.full_like(phi, self.intake_pressure),
        ]
        return np.select(conditions, choices, default=compression)

    @classmethod
    def from_section(
        cls, model: PressureModelSection, crank_radius: float, rod_length: float
    ) -> ParametricPressure:
        """Build from ``[engine.pressure_model]``; check p_z ≥ p_c (else CaseError)."""
        pressure = cls(
            crank_radius=crank_radius,
            rod_length=rod_length,
            compression_ratio=model.compression_ratio,
            intake_pressure=model.intake_pressure,
            max_pressure=model.max_pressure,
            exhaust_pressure=model.exhaust_pressure,
            max_pressure_duration_deg=model.max_pressure_duration,
            compression_index=model.compression_index,
            expansion_index=model.expansion_index,
            ambient=model.ambient_pressure,
        )
        p_c = pressure.compression_end_pressure
        if model.max_pressure < p_c:
            raise range_error(
                "engine.pressure_model.max_pressure",
                model.max_pressure,
                f">= compression-end pressure p_a*eps^n1 = {p_c:.4g}",
                "Pa",
            )
        return pressure


def _trace_error(path: Path, line: int, message: str) -> CaseError:
    return CaseError(f"pressure trace {str(path)!r}, line {line}: {message}")


def _read_rows(path: Path) -> tuple[list[int], list[list[str]], dict[str, int]]:
    lines = csv_data_lines(read_utf8(path, "pressure trace"), path, "pressure trace")
    rows = list(csv.reader([s for _, s in lines]))
    header = {name.strip(): i for i, name in enumerate(rows[0])}
    for needed in ("crank_angle_deg", "pressure_Pa"):
        if needed not in header:
            raise _trace_error(
                path, lines[0][0], f"missing column '{needed}' (header: {', '.join(header)})"
            )
    return [n for n, _ in lines[1:]], rows[1:], header


def _parse_float(path: Path, line: int, text: str, column: str) -> float:
    try:
        value = float(text)
    except ValueError:
        raise _trace_error(path, line, f"{column} = {text!r} is not a number") from None
    if not math.isfinite(value):
        raise _trace_error(path, line, f"{column} = {text.strip()} is not finite")
    return value


def read_pressure_trace(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """Read and check a trace CSV: returns (crank angle [deg], absolute pressure [Pa]).

    Lines starting with ``#`` are comments (provenance). Checks: numbers are finite,
    pressures > 0, angles strictly increasing, one full cycle covered (span ≥ 720° −
    the largest allowed gap, ≤ 720°; no gap above ``MAX_TRACE_GAP_DEG``).
    """
    numbers, rows, header = _read_rows(path)
    ia, ip = header["crank_angle_deg"], header["pressure_Pa"]
    angles: list[float] = []
    pressures: list[float] = []
    for line, row in zip(numbers, rows, strict=True):
        if len(row) <= max(ia, ip):
            raise _trace_error(path, line, f"expected {len(header)} columns, got {len(row)}")
        angle = _parse_float(path, line, row[ia], "crank_angle_deg")
        pressure = _parse_float(path, line, row[ip], "pressure_Pa")
        if pressure <= 0.0:
            raise _trace_error(
                path, line, f"pressure_Pa = {pressure:g} must be > 0 (absolute) [Pa]"
            )
        if angles and angle <= angles[-1]:
            raise _trace_error(
                path,
                line,
                f"crank_angle_deg = {angle:g} is not above the "
                f"previous {angles[-1]:g} (angles must increase)",
            )
        angles.append(angle)
        pressures.append(pressure)
    if len(angles) < 4:
        raise CaseError(f"pressure trace {str(path)!r}: needs at least 4 rows, got {len(angles)}")
    _check_coverage(path, np.array(angles), numbers)
    return _drop_duplicate_end(np.array(angles), np.array(pressures))


def _check_coverage(path: Path, angles: np.ndarray, numbers: list[int]) -> None:
    span = angles[-1] - angles[0]
    if span > 720.0 + 1e-9:
        raise CaseError(
            f"pressure trace {str(path)!r}: angles span {span:g} deg "
            f"({angles[0]:g}..{angles[-1]:g}); one cycle of 720 deg is expected"
        )
    gaps = np.diff(angles)
    wrap_gap = 720.0 - span
    worst = int(np.argmax(gaps))
    if gaps[worst] > MAX_TRACE_GAP_DEG:
        raise _trace_error(
            path,
            numbers[worst + 1],
            f"missing angles: gap of {gaps[worst]:g} deg from {angles[worst]:g} to "
            f"{angles[worst + 1]:g} (allowed: <= {MAX_TRACE_GAP_DEG:g} deg)",
        )
    if wrap_gap > MAX_TRACE_GAP_DEG:
        raise CaseError(
            f"pressure trace {str(path)!r}: covers only {angles[0]:g}..{angles[-1]:g} "
            f"deg; the full 720 deg cycle is needed (missing angles)"
        )


def _drop_duplicate_end(angles: np.ndarray, pressures: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    if angles[-1] - angles[0] >= 720.0 - 1e-9:
        return angles[:-1], pressures[:-1]
    return angles, pressures


def pressure_from_trace(path: Path, ambient: float = DEFAULT_AMBIENT) -> TracePressure:
    """Read, check and wrap a trace file as a :class:`TracePressure`."""
    angles, pressures = read_pressure_trace(path)
    return TracePressure(np.radians(angles), pressures, ambient)


def build_pressure(case: Case) -> CylinderPressure:
    """Cylinder pressure of ``case``: ``[engine] pressure_trace`` or ``[engine.pressure_model]``."""
    case.require("cylinder pressure", "engine")
    engine = case.engine
    assert engine is not None
    if engine.pressure_trace is not None:
        ambient = (
            engine.ambient_pressure if engine.ambient_pressure is not None else DEFAULT_AMBIENT
        )
        return pressure_from_trace(case.resolve(engine.pressure_trace), ambient)
    assert engine.pressure_model is not None
    return ParametricPressure.from_section(
        engine.pressure_model, engine.crank_radius, engine.rod_length
    )
