"""Bearing load from a table: ``[load] table = "load.csv"``.

The CSV has the columns ``crank_angle_deg, load_x_N, load_y_N`` (bearing/film frame, load
pressing the journal on the shell), optionally ``journal_speed_rad_s`` and
``shell_speed_rad_s`` per angle (e.g. a rod-frame journal speed ω − dβ/dt); otherwise the
speeds of ``[load]`` apply. Lines starting with ``#`` are comments (provenance); a row
starting with a spreadsheet error value such as ``#N/A`` is an error. UTF-8 text.
One cycle of ``cycle_deg``; a closing row at ``first + cycle_deg`` is dropped (periodic).
"""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np

from conrod.cases.load import LoadTableSection
from conrod.errors import CaseError
from conrod.io.text import csv_data_lines, read_utf8
from conrod.loads.cycle import LoadCycle
from conrod.units import rpm_to_rad_s

REQUIRED_COLUMNS = ("crank_angle_deg", "load_x_N", "load_y_N")
OPTIONAL_COLUMNS = ("journal_speed_rad_s", "shell_speed_rad_s")


def read_load_columns(path: Path) -> dict[str, np.ndarray]:
    """Read the table as column name → float array; :class:`CaseError` on any problem
    (naming the file, the line, the column, the value and what is allowed)."""
    what = "load.table"
    lines = csv_data_lines(read_utf8(path, what), path, what)
    if len(lines) < 5:
        raise CaseError(f"{what} {str(path)!r}: needs a header and at least 4 data rows "
                        f"(found {len(lines) - 1})")
    header = [name.strip() for name in lines[0][1].split(",")]
    missing = [name for name in REQUIRED_COLUMNS if name not in header]
    if missing:
        raise CaseError(
            f"{what} {str(path)!r}, line {lines[0][0]}: missing column(s) {', '.join(missing)} "
            f"(found: {', '.join(header)}; required: {', '.join(REQUIRED_COLUMNS)})"
        )
    data = np.array([_row_values(path, number, line, header) for number, line in lines[1:]])
    names = REQUIRED_COLUMNS + tuple(n for n in OPTIONAL_COLUMNS if n in header)
    return {name: data[:, header.index(name)] for name in names}


def _row_values(path: Path, number: int, line: str, header: list[str]) -> list[float]:
    """Finite floats of one data row, or a CaseError naming line, column and value."""
    cells = line.split(",")
    if len(cells) != len(header):
        raise CaseError(f"load.table {str(path)!r}, line {number}: {len(cells)} values, "
                        f"expected {len(header)} ({', '.join(header)})")
    values = []
    for name, cell in zip(header, cells, strict=True):
        try:
            value = float(cell)
        except ValueError:
            raise CaseError(f"load.table {str(path)!r}, line {number}: {name} = "
                            f"{cell.strip()!r} is not a number") from None
        if not math.isfinite(value):
            raise CaseError(f"load.table {str(path)!r}, line {number}: {name} = "
                            f"{cell.strip()} is not finite (allowed: finite numbers)")
        values.append(value)
    return values


def load_cycle_from_table(section: LoadTableSection, path: Path) -> LoadCycle:
    """Build the :class:`LoadCycle` of a ``[load]`` section whose table is at ``path``."""
    if not isinstance(section, LoadTableSection) or not isinstance(path, str | os.PathLike):
        raise CaseError(f"load_cycle_from_table: section = {type(section).__name__}, path = "
                        f"{path!r}: a LoadTableSection (case.load) and a table path are required")
    columns = read_load_columns(path)
    angle_deg = columns["crank_angle_deg"]
    if np.any(np.diff(angle_deg) <= 0.0):
        raise CaseError(f"load.table {str(path)!r}: crank_angle_deg must be strictly increasing")
    keep = angle_deg - angle_deg[0] < section.cycle_deg - 1e-9
    if np.count_nonzero(~keep) > 1 or (np.any(~keep) and not _closes_cycle(angle_deg, section)):
        raise CaseError(
            f"load.table {str(path)!r}: crank angles span "
            f"{angle_deg[-1] - angle_deg[0]:g} deg, more than load.cycle_deg = {section.cycle_deg}"
        )
    crank_speed = rpm_to_rad_s(section.speed)
    journal = crank_speed if section.journal_speed is None else section.journal_speed
    journal_speed = columns.get("journal_speed_rad_s", np.full(angle_deg.size, float(journal)))
    shell_speed = columns.get("shell_speed_rad_s", np.full(angle_deg.size, section.shell_speed))
    return LoadCycle(
        crank_angle=np.radians(angle_deg[keep]),
        load_x=section.scale * columns["load_x_N"][keep],
        load_y=section.scale * columns["load_y_N"][keep],
        journal_speed=journal_speed[keep],
        shell_speed=shell_speed[keep],
        crank_speed=crank_speed,
        cycle=math.radians(section.cycle_deg),
    )


def _closes_cycle(angle_deg: np.ndarray, section: LoadTableSection) -> bool:
    return abs(angle_deg[-1] - angle_deg[0] - section.cycle_deg) < 1e-6
