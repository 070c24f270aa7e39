"""The sweep table: one row per variant (``sweep.parquet``) and the best/worst summary."""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.io.atomic import atomic_path

LEADING_COLUMNS = ("variant", "hash")
STATUS_COLUMNS = ("status", "error", "wall_time_s", "cached")
SKIPPED_SUMMARY_ITEMS = ("wall_time_s",)
"""summary.json items not copied to the table (the row's ``wall_time_s`` is the variant's
time on its worker, run and writing included) [-]."""

CHARACTERISTICS = {
    "h_min_m": "max",
    "p_max_Pa": "min",
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
    """One table row from a variant record."""
    row: dict[str, Any] = {"variant": index + 1, "hash": record["hash"], **axes}
    row.update(status=record["status"], error=record.get("error", ""),
               wall_time_s=float(record.get("wall_time_s", float("nan"))), cached=cached)
    for name, value in record.get("summary", {}).items():
        if name in SKIPPED_SUMMARY_ITEMS or name in row:
            continue
        if isinstance(value, dict):  # the headline and the solver settings: text blocks
            continue
        if isinstance(value, list):
            if name.endswith("warnings"):
                row[name] = "; ".join(str(v) for v in value)
            continue
        row[name] = float("nan") if value is None else value
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
    """Per characteristic present: the best and worst finished variant with its axis values."""
    ok = frame[frame["status"] == "ok"] if "status" in frame else frame
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


def _axes_text(frame: pd.DataFrame, index: Any) -> str:
    return ", ".join(f"{key.rsplit('.', 1)[-1]} = {_short(frame.at[index, key])}"
                     for key in axis_columns(frame))


def _short(value: Any) -> str:
    return f"{value:.4g}" if isinstance(value, float) else str(value)
