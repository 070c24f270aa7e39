"""Numeric CSV tables with named columns, and the measured bore profile read from one.

``read_columns`` reads any table of finite numbers with a header (``#`` comment lines for
provenance, UTF-8): the bore profile ``[bearing] profile_file`` and the tilt and moment
tables of ``[misalignment]`` (:mod:`conrod.loads.tilt`). Every problem is one
:class:`~conrod.errors.CaseError` naming the file, the line, the column and the value.

A measured profile (:class:`ProfileTable`) has the columns ``angle_deg, axial_position_m,
offset_m``: the shell angle θ [deg] in the film (bearing) frame, the axial position z [m]
from mid-width and the offset [m] added to the film thickness (positive = more clearance).
The rows form a tensor grid: every angle with the same axial positions (one axial position:
a profile uniform along the width). It is interpolated linearly onto the film grid,
periodically in θ; its axial positions must span the width.
"""

from __future__ import annotations

import math
import os
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from conrod.errors import CaseError
from conrod.io.text import csv_data_lines, read_utf8

PROFILE_COLUMNS = ("angle_deg", "axial_position_m", "offset_m")
"""Columns of a measured profile table."""
MAX_OFFSET = 1.0e-3
"""Largest |offset| of a profile table [m] (1 mm: 20 × a large engine clearance)."""


def read_columns(path: str | os.PathLike[str], what: str, required: tuple[str, ...],
                 min_rows: int = 1) -> dict[str, np.ndarray]:
    """Column name → float array of the ``required`` columns of the CSV at ``path``
    (``what`` names it in messages, e.g. ``"bearing.profile_file"``)."""
    path = Path(path)
    lines = csv_data_lines(read_utf8(path, what), path, what)
    if len(lines) < min_rows + 1:
        raise CaseError(f"{what} {str(path)!r}: needs a header and at least {min_rows} data "
                        f"row(s) (found {len(lines) - 1})")
    header = [name.strip() for name in lines[0][1].split(",")]
    missing = [name for name in required if name not in header]
    if missing:
        raise CaseError(f"{what} {str(path)!r}, line {lines[0][0]}: missing column(s) "
                        f"{', '.join(missing)} (found: {', '.join(header)}; required: "
                        f"{', '.join(required)})")
    rows = [_row(path, what, number, line, header) for number, line in lines[1:]]
    data = np.array(rows, dtype=float)
    return {name: data[:, header.index(name)] for name in required}


def _row(path: Path, what: str, number: int, line: str, header: list[str]) -> list[float]:
    """Finite floats of one data row, or a CaseError naming line, column and value."""
    cells = line.split(",")
    if len(cells) != len(header):
        raise CaseError(f"{what} {str(path)!r}, line {number}: {len(cells)} values, expected "
                        f"{len(header)} ({', '.join(header)})")
    values = []
    for name, cell in zip(header, cells, strict=True):
        try:
            value = float(cell)
        except ValueError:
            raise CaseError(f"{what} {str(path)!r}, line {number}: {name} = "
                            f"{cell.strip()!r} is not a number") from None
        if not math.isfinite(value):
            raise CaseError(f"{what} {str(path)!r}, line {number}: {name} = {cell.strip()} "
                            "is not finite (allowed: finite numbers)")
        values.append(value)
    return values


@dataclass(frozen=True)
class ProfileTable:
    """A measured bore/shell profile on a tensor grid (module docstring).

    angles : tuple  Shell angles θ [rad], increasing, within one turn.
    axial_positions : tuple  Axial positions z [m] from mid-width, increasing.
    offsets : tuple  Offset [m] per angle (rows) and axial position (columns), positive =
        more clearance.
    source : str  Where it came from (file name) for messages [-].
    """

    angles: tuple[float, ...]
    axial_positions: tuple[float, ...]
    offsets: tuple[tuple[float, ...], ...]
    source: str = ""

    @classmethod
    def from_arrays(cls, angles: np.ndarray, axial_positions: np.ndarray,
                    offsets: np.ndarray, source: str = "") -> ProfileTable:
        """A table from arrays: angles [rad] (n,), axial positions [m] (m,), offsets [m]
        (n, m)."""
        offsets = np.asarray(offsets, dtype=float).reshape(len(angles), len(axial_positions))
        return cls(tuple(float(a) for a in angles), tuple(float(z) for z in axial_positions),
                   tuple(tuple(float(v) for v in row) for row in offsets), source)

    @classmethod
    def from_csv(cls, path: str | os.PathLike[str],
                 what: str = "bearing.profile_file") -> ProfileTable:
        """Read and check a profile table (module docstring); CaseError on any problem."""
        columns = read_columns(path, what, PROFILE_COLUMNS, min_rows=2)
        label = f"{what} {str(path)!r}"
        angle = np.round(columns["angle_deg"], 9)
        axial = np.round(columns["axial_position_m"], 12)
        offset = columns["offset_m"]
        if np.any(np.abs(offset) > MAX_OFFSET):
            row = int(np.argmax(np.abs(offset)))
            raise CaseError(f"{label}: offset_m = {offset[row]:g} in data row {row + 1} is out "
                            f"of range (allowed: |offset| <= {MAX_OFFSET:g} m)")
        angles, axial_positions = np.unique(angle), np.unique(axial)
        if angles[-1] - angles[0] >= 360.0:
            raise CaseError(f"{label}: angle_deg spans {angles[-1] - angles[0]:g} deg (allowed: "
                            "less than 360 deg, one turn, 360 = 0)")
        if angles.size < 2:
            raise CaseError(f"{label}: {angles.size} distinct angle (allowed: >= 2 angles)")
        grid = np.full((angles.size, axial_positions.size), np.nan)
        rows = np.searchsorted(angles, angle), np.searchsorted(axial_positions, axial)
        grid[rows] = offset
        if np.count_nonzero(~np.isnan(grid)) != angle.size or np.isnan(grid).any():
            raise CaseError(f"{label}: the rows are not a tensor grid ({angles.size} angles × "
                            f"{axial_positions.size} axial positions need "
                            f"{angles.size * axial_positions.size} distinct rows, found "
                            f"{angle.size}); give every angle at the same axial positions")
        return cls.from_arrays(np.radians(angles), axial_positions, grid, str(path))

    def field(self, theta: np.ndarray, z: np.ndarray, width: float) -> np.ndarray:
        """The offset interpolated at the nodes θ [rad] × z [m], shape (len θ, len z) [m]:
        linear and periodic in θ, linear in z (uniform with one axial position)."""
        angles = np.asarray(self.angles)
        offsets = np.asarray(self.offsets)
        axial = np.asarray(self.axial_positions)
        if axial.size > 1:
            reach = 0.5 * width * (1.0 - 1e-9)
            if axial[0] > -reach or axial[-1] < reach:
                raise CaseError(
                    f"bearing.profile_file {self.source!r}: axial positions from {axial[0]:g} "
                    f"to {axial[-1]:g} m do not span the width (allowed: from <= "
                    f"{-0.5 * width:g} to >= {0.5 * width:g} m, the edges included, or one "
                    "axial position for a profile uniform along the width)")
        closed = np.append(angles, angles[0] + 2.0 * np.pi)
        wrapped = angles[0] + (np.asarray(theta) - angles[0]) % (2.0 * np.pi)
        by_angle = np.empty((closed.size, len(z)))
        for k, row in enumerate(np.vstack([offsets, offsets[:1]])):
            by_angle[k] = row[0] if axial.size == 1 else np.interp(z, axial, row)
        out = np.empty((len(theta), len(z)))
        for j in range(len(z)):
            out[:, j] = np.interp(wrapped, closed, by_angle[:, j])
        return out
