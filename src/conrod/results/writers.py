"""Writers of ``conrod run``: ``cycle.csv``, ``summary.json`` and the figures, all atomic.

Contact post-processing: ``results.contact.summary_items()`` is merged into
summary.json and ``results.contact.write_files(out_dir)`` writes its own files.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from conrod.io.atomic import write_csv, write_json
from conrod.io.result_folder import staged_result_folder
from conrod.results.cycle_results import RunResults

CYCLE_COLUMNS = {
    "crank_angle_deg": ("crank_angle", np.degrees),
    "eccentricity_ratio": ("eccentricity_ratio", None),
    "eccentricity_x": ("eccentricity_x", None),
    "eccentricity_y": ("eccentricity_y", None),
    "velocity_x_m_s": ("velocity_x", None),
    "velocity_y_m_s": ("velocity_y", None),
    "attitude_angle_deg": ("attitude_angle", np.degrees),
    "h_min_m": ("h_min", None),
    "h_min_angle_shell_deg": ("h_min_angle_shell", np.degrees),
    "h_min_angle_journal_deg": ("h_min_angle_journal", np.degrees),
    "p_max_Pa": ("p_max", None),
    "p_max_angle_shell_deg": ("p_max_angle_shell", np.degrees),
    "friction_torque_N_m": ("friction_torque", None),
    "friction_power_W": ("friction_power", None),
    "side_flow_m3_s": ("side_flow", None),
    "supply_flow_m3_s": ("supply_flow", None),
    "load_x_N": ("load_x", None),
    "load_y_N": ("load_y", None),
    "journal_speed_rad_s": ("journal_speed", None),
    "shell_speed_rad_s": ("shell_speed", None),
    "contact_force_N": ("contact_force", None),
    "friction_force_N": ("friction_force", None),
    "contact_angle_deg": ("contact_angle", np.degrees),
    "journal_rotation_deg": ("journal_rotation", np.degrees),
    "sliding_speed_m_s": ("sliding_speed", None),
    "in_contact": ("in_contact", None),
}
"""cycle.csv column → (CycleResults field, conversion). eccentricity_x/_y are in [m]."""


def cycle_table(results: RunResults) -> dict[str, np.ndarray]:
    """cycle.csv columns (engineering names with units)."""
    table = {}
    for column, (name, convert) in CYCLE_COLUMNS.items():
        values = np.asarray(getattr(results.cycle, name))
        if values.dtype == bool:
            values = values.astype(int)
        table[column] = convert(values) if convert is not None else values
    if results.contact is not None:  # contact post-processing refines/adds columns
        table.update(results.contact.cycle_columns())
    return table


def summary_items(results: RunResults) -> dict:
    """summary.json content, including the contact post-processing items."""
    items = results.summary.as_json_items()
    if results.contact is not None:
        items.update(results.contact.summary_items())
    return items


def write_run(
    results: RunResults, out_dir: str | os.PathLike[str], *, figures: bool = True
) -> list[Path]:
    """Write cycle.csv, summary.json (and figures, and the contact files) as one result set
    (:func:`conrod.io.result_folder.staged_result_folder`); return the paths."""
    with staged_result_folder(out_dir) as stage:
        paths = _write_run_files(results, stage, figures)
    return [Path(out_dir) / path.relative_to(stage) for path in paths]


def _write_run_files(results: RunResults, out: Path, figures: bool) -> list[Path]:
    paths = [
        write_csv(out / "cycle.csv", cycle_table(results)),
        write_json(out / "summary.json", summary_items(results)),
    ]
    if figures:
        from conrod.plotting.orbit_plots import write_orbit_figures

        paths += write_orbit_figures(results, out)
    if results.contact is not None:
        paths += list(results.contact.write_files(out) or [])
    return paths
