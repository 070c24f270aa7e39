"""The sweep table: one row per variant (``sweep.parquet``) and the best/worst summary.

Columns, in order: ``variant`` (1…n in study order), ``hash``, the axis values (one column
per axis, named by :func:`conrod.sweep.columns.axis_column`: the case key with its unit),
``status`` (:mod:`conrod.sweep.status`), ``error``, ``wall_time_s``, ``compute_time_s``,
``cached``, then every scalar of the variant's ``summary.json`` (units in the names), with
``h_min_set_by`` right after ``h_min_m`` and the warning texts in ``warnings``.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.io.atomic import atomic_path
from conrod.sweep.columns import axis_column
from conrod.sweep.status import (
    STATUS_FAILED,
    STATUS_OK,
    WARNING_SEPARATOR,
    h_min_set_by,
    variant_status,
)

LEADING_COLUMNS = ("variant", "hash")
STATUS_COLUMNS = ("status", "error", "wall_time_s", "compute_time_s", "cached")
SKIPPED_SUMMARY_ITEMS = ("wall_time_s",)
"""summary.json items not copied to the table (the row's ``wall_time_s`` is the variant's
time on its worker, run and writing included) [-]."""

CHARACTERISTICS = {
    "h_min_m": "max",
    "p_max_Pa": "min",
    "max_pressure_range_Pa": "min",
    "mean_friction_power_W": "min",
    "effective_temperature_C": "min",
    "max_contact_force_N": "min",
    "max_wear_shell_m": "min",
    "max_wear_journal_m": "min",
    "max_impact_velocity_big_end_m_s": "min",
    "max_impact_velocity_small_end_m_s": "min",
}
"""Characteristic column → which end is best (``"max"`` or ``"min"``)."""


def record_row(index: int, axes: dict[str, Any], record: dict[str, Any],
               cached: bool) -> dict[str, Any]:
    """One table row from a variant record (``axes``: case key → value)."""
    summary = record.get("summary") or {}
    failed = record.get("status") == STATUS_FAILED
    row: dict[str, Any] = {"variant": index + 1, "hash": record["hash"]}
    row.update({axis_column(key): value for key, value in axes.items()})
    row.update(status=STATUS_FAILED if failed else variant_status(summary),
               error=record.get("error", ""),
               wall_time_s=float(record.get("wall_time_s", float("nan"))),
               compute_time_s=float(record.get("compute_time_s", float("nan"))),
               cached=cached)
    for name, value in summary.items():
        if name in SKIPPED_SUMMARY_ITEMS or name in row or isinstance(value, dict):
            continue  # dicts: the headline and the solver settings (text blocks)
        if isinstance(value, list):
            if name.endswith("warnings"):
                row[name] = WARNING_SEPARATOR.join(str(v) for v in value)
            continue
        row[name] = float("nan") if value is None else value
        if name == "h_min_m":
            row["h_min_set_by"] = h_min_set_by(summary)
    return row


def rows_to_frame(rows: Iterable[dict[str, Any]]) -> pd.DataFrame:
    """DataFrame of the rows in variant order (failed rows have NaN characteristics)."""
    frame = pd.DataFrame(list(rows))
    if frame.empty:
        return frame
    return frame.sort_values("variant", kind="stable").reset_index(drop=True)


def write_parquet(frame: pd.DataFrame, path: Path) -> Path:
    """``sweep.parquet`` written atomically."""
    with atomic_path(path) as tmp:
        frame.to_parquet(tmp, index=False)
    return path


def axis_columns(frame: pd.DataFrame) -> list[str]:
    """The axis columns of a sweep table (between the leading and status columns)."""
    names = list(frame.columns)
    end = names.index("status") if "status" in names else len(names)
    return [n for n in names[:end] if n not in LEADING_COLUMNS]


def best_and_worst(frame: pd.DataFrame) -> list[dict[str, Any]]:
    """Per characteristic present: the best and worst variant among those with status
    ``ok`` (a variant with warnings is a doubtful result, not a design point)."""
    ok = frame[frame["status"] == STATUS_OK] if "status" in frame else frame
    rows = []
    for column, best in CHARACTERISTICS.items():
        if column not in ok or ok[column].isna().all():
            continue
        values = ok[column].astype(float)
        i_best = values.idxmax() if best == "max" else values.idxmin()
        i_worst = values.idxmin() if best == "max" else values.idxmax()
        rows.append({"characteristic": column,
                     "best": float(values[i_best]), "best_variant": _axes_text(frame, i_best),
                     "worst": float(values[i_worst]),
                     "worst_variant": _axes_text(frame, i_worst)})
    return rows


def status_counts(frame: pd.DataFrame) -> dict[str, int]:
    """Number of variants per status, in the order of :data:`conrod.sweep.status.STATUSES`."""
    from conrod.sweep.status import STATUSES

    counts = frame["status"].value_counts() if "status" in frame else pd.Series(dtype=int)
    return {status: int(counts.get(status, 0)) for status in STATUSES}


def _axes_text(frame: pd.DataFrame, index: Any) -> str:
    return ", ".join(f"{key.rsplit('.', 1)[-1]} = {_short(frame.at[index, key])}"
                     for key in axis_columns(frame))


def _short(value: Any) -> str:
    return f"{value:.4g}" if isinstance(value, float) else str(value)
