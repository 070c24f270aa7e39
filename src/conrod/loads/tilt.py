"""The journal's tilt over the cycle: a prescribed tilt γ(φ), or the external moment and the
inertia of a tilt solved with the orbit (``[misalignment]``, :mod:`conrod.cases.misalignment`).

A prescribed tilt table (``crank_angle_deg, tilt_x_rad, tilt_y_rad``) is one cycle of the
load cycle, interpolated by a periodic cubic spline so that the tilt rate γ̇ = ω dγ/dφ that
enters the squeeze term is continuous; a constant tilt has no rate. The external moment
table (``crank_angle_deg, moment_x_N_m, moment_y_N_m``) is interpolated linearly and
periodically, as the load is. Tables as the load table: ``#`` comment lines, strictly
increasing angles within one cycle, a closing row at first + cycle dropped.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from conrod.errors import CaseError
from conrod.film.profile_table import read_columns
from conrod.loads.cycle import LoadCycle

if TYPE_CHECKING:  # pragma: no cover
    from scipy.interpolate import CubicSpline


@dataclass(frozen=True)
class PeriodicTable:
    """Two columns over one cycle of crank angle.

    crank_angle : ndarray  Angles [rad], strictly increasing, within one cycle.
    values : ndarray  (n, 2) values at the angles [rad, or N m].
    cycle : float  Cycle length [rad].  smooth : bool  Periodic cubic spline (else linear).
    """

    crank_angle: np.ndarray
    values: np.ndarray
    cycle: float
    smooth: bool = True

    @cached_property
    def closed(self) -> tuple[np.ndarray, np.ndarray, CubicSpline | None]:
        """(angles with the closing one [rad], rows with the first repeated, spline)."""
        from scipy.interpolate import CubicSpline  # only a tilt table needs it (0.2 s import)

        angles = np.append(self.crank_angle, self.crank_angle[0] + self.cycle)
        rows = np.vstack([self.values, self.values[:1]])
        spline = CubicSpline(angles, rows, bc_type="periodic") if self.smooth else None
        return angles, rows, spline

    def at(self, phi: float | np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(values, d/dφ per rad) at the crank angle(s) φ [rad], shapes (..., 2)."""
        angles, rows, spline = self.closed
        reduced = angles[0] + (np.asarray(phi, dtype=float) - angles[0]) % self.cycle
        if spline is not None:
            return spline(reduced), spline(reduced, 1)
        values = np.stack([np.interp(reduced, angles, rows[:, k]) for k in range(2)], -1)
        return values, np.zeros_like(values)


@dataclass(frozen=True)
class JournalTilt:
    """The tilt of the journal in a run (module docstring).

    lever : float  ℓ = L/2 [m]: the tilt degrees of freedom of the orbit are ℓγ [m].
    prescribed : PeriodicTable or None  γ_x, γ_y over the cycle [rad] (mode prescribed).
    constant : tuple  Constant (γ_x, γ_y) [rad] when no table is given (prescribed).
    free : bool  γ solved as two more degrees of freedom.
    inertia : tuple  (J_x, J_y) [kg m²] about the film axes through the bearing centre.
    moments : PeriodicTable or None  External moment on the journal over the cycle [N m].
    constant_moment : tuple  (M_x, M_y) [N m] when no moment table is given.
    load_offset : float  Axial position a of the load line [m]: moment a(−W_y, W_x).
    crank_speed : float  ω [rad/s], for γ̇ = ω dγ/dφ.
    """

    lever: float
    crank_speed: float
    free: bool = False
    prescribed: PeriodicTable | None = None
    constant: tuple[float, float] = (0.0, 0.0)
    inertia: tuple[float, float] = (0.0, 0.0)
    moments: PeriodicTable | None = None
    constant_moment: tuple[float, float] = (0.0, 0.0)
    load_offset: float = 0.0

    def tilt_at(self, phi: float) -> tuple[float, float, float, float]:
        """Prescribed (γ_x, γ_y [rad], γ̇_x, γ̇_y [rad/s]) at the crank angle φ [rad]."""
        if self.prescribed is None:
            return (*self.constant, 0.0, 0.0)
        values, slope = self.prescribed.at(phi)
        rate = self.crank_speed * slope
        return float(values[0]), float(values[1]), float(rate[0]), float(rate[1])

    def moment_at(self, phi: float, load: tuple[float, float] = (0.0, 0.0)
                  ) -> tuple[float, float]:
        """External moment (M_x, M_y) on the journal at φ [N m] (free tilt) with the load
        W = ``load`` [N] acting at the axial offset a: + a(−W_y, W_x)."""
        if self.moments is None:
            base = self.constant_moment
        else:
            values, _ = self.moments.at(phi)
            base = (float(values[0]), float(values[1]))
        a = self.load_offset
        return base[0] - a * load[1], base[1] + a * load[0]


def read_periodic_table(path: Path, what: str, columns: tuple[str, str],
                        loads: LoadCycle, smooth: bool) -> PeriodicTable:
    """A two-column table over one cycle of ``loads`` (module docstring); CaseError naming
    the file on any problem."""
    data = read_columns(path, what, ("crank_angle_deg", *columns), min_rows=4)
    angle_deg = data["crank_angle_deg"]
    label = f"{what} {str(path)!r}"
    if np.any(np.diff(angle_deg) <= 0.0):
        raise CaseError(f"{label}: crank_angle_deg must be strictly increasing")
    cycle_deg = math.degrees(loads.cycle)
    span = angle_deg[-1] - angle_deg[0]
    keep = angle_deg - angle_deg[0] < cycle_deg - 1e-9
    if span > cycle_deg + 1e-6 or (not keep.all() and abs(span - cycle_deg) > 1e-6):
        raise CaseError(f"{label}: crank angles span {span:g} deg, more than the load cycle "
                        f"{cycle_deg:g} deg (allowed: one cycle; a closing row at first + "
                        "cycle is dropped)")
    values = np.column_stack([data[name][keep] for name in columns])
    return PeriodicTable(np.radians(angle_deg[keep]), values, loads.cycle, smooth)


def journal_tilt(case, loads: LoadCycle) -> JournalTilt | None:
    """The :class:`JournalTilt` of the case's ``[misalignment]`` (None without one), after
    checking that a bore profile, fixed in the film frame, sits on a shell at rest there
    (:func:`check_profile_frame`)."""
    check_profile_frame(case, loads)
    section = getattr(case, "misalignment", None)
    if section is None:
        return None
    lever = 0.5 * case.bearing.width
    common = {"lever": lever, "crank_speed": loads.crank_speed}
    if not section.free:
        table = (None if section.table is None else read_periodic_table(
            case.resolve(section.table), "misalignment.table", ("tilt_x_rad", "tilt_y_rad"),
            loads, smooth=True))
        if table is not None and np.abs(table.values).max() > 0.01:
            raise CaseError(f"misalignment.table {str(section.table)!r}: tilt up to "
                            f"{np.abs(table.values).max():g} rad (allowed: |tilt| <= 0.01 rad)")
        return JournalTilt(prescribed=table, constant=(section.tilt_x, section.tilt_y),
                           **common)
    moments = (None if section.moment_table is None else read_periodic_table(
        case.resolve(section.moment_table), "misalignment.moment_table",
        ("moment_x_N_m", "moment_y_N_m"), loads, smooth=False))
    return JournalTilt(free=True, inertia=(section.moment_of_inertia_x,
                                           section.moment_of_inertia_y),
                       moments=moments, constant_moment=(section.moment_x, section.moment_y),
                       load_offset=section.load_axial_offset, **common)


def cycle_tilt(axial: dict | None, i: int) -> dict[str, float]:
    """FilmState keywords of the tilt at output angle ``i`` of ``CycleResults.axial`` ({}
    when aligned)."""
    if axial is None:
        return {}
    return {name: float(axial[name][i])
            for name in ("tilt_x", "tilt_y", "tilt_rate_x", "tilt_rate_y")}


def check_profile_frame(case, loads: LoadCycle) -> None:
    """CaseError for a bore profile on a shell that turns in the film frame (ω_b ≠ 0 in the
    load table): the films hold the profile fixed in that frame, which is the shell only when
    the shell is at rest in it (a big end: the rod frame)."""
    bearing = getattr(case, "bearing", None)
    if bearing is None or (bearing.profile is None and bearing.profile_file is None):
        return
    if np.any(np.asarray(loads.shell_speed) != 0.0):
        raise CaseError(
            f"bearing.profile with a shell speed up to {np.abs(loads.shell_speed).max():g} "
            "rad/s: the profile is fixed in the film (bearing) frame, where the shell must be "
            "at rest (allowed: shell_speed = 0, e.g. the rod frame of a big end)")
