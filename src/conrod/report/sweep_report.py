"""Sections of the report of a sweep folder: the study, the base case's inputs, the best and
worst variants, trend plots of each characteristic and the variant table."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from conrod.report.html import Image, Section, Table
from conrod.report.inputs import flatten, unit_of
from conrod.report.run_report import inputs_section
from conrod.sweep.runner import read_description, read_table
from conrod.sweep.table import CHARACTERISTICS, axis_columns, best_and_worst

TREND_COLUMNS = ("h_min_m", "p_max_Pa", "mean_friction_power_W", "mean_side_flow_m3_s",
                 "effective_temperature_C", "max_contact_force_N", "max_wear_shell_m",
                 "max_impact_velocity_big_end_m_s", "max_impact_velocity_small_end_m_s",
                 "impacts_per_cycle")
TABLE_COLUMNS = ("h_min_m", "p_max_Pa", "mean_friction_power_W", "mean_side_flow_m3_s",
                 "effective_temperature_C", "max_contact_force_N",
                 "max_impact_velocity_big_end_m_s", "max_impact_velocity_small_end_m_s",
                 "impacts_per_cycle", "wall_time_s")
CAPTION_UNITS = {"h_min_m": "smallest film thickness over the cycle in m",
                 "p_max_Pa": "largest film pressure over the cycle in Pa",
                 "mean_friction_power_W": "cycle-mean friction power loss in W",
                 "mean_side_flow_m3_s": "cycle-mean side flow in m³/s",
                 "effective_temperature_C": "effective film temperature (heat balance) in °C",
                 "max_contact_force_N": "largest hard-contact force in N",
                 "max_wear_shell_m": "largest wear depth per cycle on the shell in m",
                 "max_impact_velocity_big_end_m_s": "largest impact velocity in the big end "
                 "in m/s", "max_impact_velocity_small_end_m_s": "largest impact velocity in "
                 "the small end in m/s", "impacts_per_cycle": "impacts per cycle (count)"}


def sweep_sections(folder: Path, case_file: Path | None = None) -> tuple[str, list[Section]]:
    """(title, sections) of the report of a sweep folder."""
    frame, study = read_table(folder), read_description(folder)
    axes = axis_columns(frame)
    if case_file is None and study.get("base_case"):
        case_file = Path(study["base_case"])
    sections = [_study_section(frame, study, axes), inputs_section(case_file, None, tuple(axes))]
    sections.append(_best_worst_section(frame))
    sections.append(_trend_section(frame, axes))
    sections.append(_variant_section(frame, axes))
    title = study.get("title") or f"conrod sweep: {folder.name}"
    return title, sections


def _study_section(frame: pd.DataFrame, study: dict, axes: list[str]) -> Section:
    ok = int((frame["status"] == "ok").sum())
    section = Section("Study", [
        f"Study file: {study.get('study_file', '–')}; {study.get('mode', 'product')} of the axes; "
        f"{len(frame)} variants, {ok} finished, {len(frame) - ok} failed.",
    ])
    rows = [[key, unit_of(key), ", ".join(_short(v) for v in pd.unique(frame[key]))]
            for key in axes]
    section.blocks.append(Table(["axis (case key)", "unit", "values"], rows,
                                "The axes of the study and the values each takes."))
    if study.get("override"):
        fixed = ", ".join(f"{k} = {v}" for k, v in flatten(study["override"]).items())
        section.blocks.append(f"Set in every variant: {fixed}.")
    return section


def _best_worst_section(frame: pd.DataFrame) -> Section:
    found = best_and_worst(frame)
    rows = [[r["characteristic"], f"{r['best']:.4g}", r["best_variant"], f"{r['worst']:.4g}",
             r["worst_variant"]] for r in found]
    best = ", ".join(f"{r['characteristic']}: {CHARACTERISTICS[r['characteristic']]}imum"
                     for r in found)
    return Section("Best and worst variants", [Table(
        ["characteristic (unit in the name)", "best", "variant", "worst", "variant "], rows,
        f"Among the finished variants; best is the {best}.", numeric=("best", "worst"))])


def _trend_section(frame: pd.DataFrame, axes: list[str]) -> Section:
    from conrod.plotting.report_plots import png_bytes
    from conrod.plotting.sweep_plots import sweep_figure

    numeric = [a for a in axes if pd.api.types.is_numeric_dtype(frame[a])]
    x = numeric[0] if numeric else axes[0]
    hue = next((a for a in axes if a != x), None)
    units = {key: unit_of(key) for key in axes}
    section = Section("Trends", two_columns=True)
    for column in TREND_COLUMNS:
        if column not in frame or frame[column].isna().all():
            continue
        x_text = f"{x}" + (f" in {units[x]}" if units.get(x) else "")
        hue_text = f", one line per value of {hue}" if hue else ""
        section.blocks.append(Image(
            f"{column} against {x}",
            f"{CAPTION_UNITS[column][0].upper()}{CAPTION_UNITS[column][1:]} against {x_text}"
            f"{hue_text}; finished variants only.",
            png_bytes(sweep_figure(frame, x, column, hue, units))))
    return section


def _variant_section(frame: pd.DataFrame, axes: list[str]) -> Section:
    columns = ["variant", *axes, "status",
               *[c for c in TABLE_COLUMNS if c in frame], "error"]
    rows = [[_short(row[c]) for c in columns] for _, row in frame.iterrows()]
    return Section("Variants", [Table(
        columns, rows, "One row per variant (sweep.parquet); characteristics in the units of "
        "their names; wall_time_s is the variant's time on its worker.",
        numeric=tuple(c for c in columns if c not in ("status", "error")))])


def _short(value) -> str:
    if isinstance(value, float):
        return "–" if value != value else f"{value:.4g}"
    return str(value)
