"""Sections of the report of a sweep folder: the study, the base case's inputs, the best and
worst variants, the variants that are not ``ok`` and why, trend plots of each
characteristic and the variant table."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from conrod.report.html import Image, Section, Table
from conrod.report.inputs import flatten, unit_of
from conrod.report.run_report import inputs_section
from conrod.report.sweep_maps import engine_map_section
from conrod.sweep.runner import read_description, read_table
from conrod.sweep.status import STATUS_OK
from conrod.sweep.table import CHARACTERISTICS, axis_columns, best_and_worst, status_counts

TREND_COLUMNS = ("h_min_m", "p_max_Pa", "max_pressure_range_Pa", "mean_friction_power_W",
                 "mean_side_flow_m3_s", "effective_temperature_C", "max_contact_force_N",
                 "max_wear_shell_m", "max_impact_velocity_big_end_m_s",
                 "max_impact_velocity_small_end_m_s", "impacts_per_cycle")
TABLE_COLUMNS = ("h_min_m", "h_min_set_by", "p_max_Pa", "mean_friction_power_W",
                 "mean_side_flow_m3_s", "effective_temperature_C", "max_contact_force_N",
                 "max_impact_velocity_big_end_m_s", "max_impact_velocity_small_end_m_s",
                 "impacts_per_cycle", "wall_time_s")
CAPTION_UNITS = {"h_min_m": "smallest film thickness over the cycle in m",
                 "p_max_Pa": "largest film pressure over the cycle in Pa",
                 "max_pressure_range_Pa": "largest pressure range max − min at one point "
                 "of the lining over the cycle in Pa",
                 "mean_friction_power_W": "cycle-mean friction power loss in W",
                 "mean_side_flow_m3_s": "cycle-mean side flow in m³/s",
                 "effective_temperature_C": "effective film temperature (heat balance) in °C",
                 "max_contact_force_N": "largest hard-contact force in N",
                 "max_wear_shell_m": "largest wear depth per cycle on the shell in m",
                 "max_impact_velocity_big_end_m_s": "largest impact velocity in the big end "
                 "in m/s", "max_impact_velocity_small_end_m_s": "largest impact velocity in "
                 "the small end in m/s", "impacts_per_cycle": "impacts per cycle (count)"}
MARKERS = ("Filled markers on the lines: status ok; hollow circles: variants with warnings "
           "or a non-periodic orbit (doubtful, see 'Variants that are not ok'); failed "
           "variants are not drawn.")
CONTACT_MARKER = (" Hollow triangles: the journal touches the shell (hard contact), so the "
                  "smallest gap is the contact threshold of the contact model, not a film "
                  "thickness.")


def sweep_sections(folder: Path, case_file: Path | None = None) -> tuple[str, list[Section]]:
    """(title, sections) of the report of a sweep folder."""
    frame, study = read_table(folder), read_description(folder)
    axes = axis_columns(frame)
    keys = _axis_keys(study, axes)
    if case_file is None and study.get("base_case"):
        case_file = Path(study["base_case"])
    sections = [_study_section(frame, study, axes, keys),
                inputs_section(case_file, None, tuple(keys.values()))]
    sections.append(_best_worst_section(frame))
    sections.append(_problems_section(frame, axes))
    engine_maps = engine_map_section(frame, axes, keys)
    if engine_maps is not None:
        sections.append(engine_maps)
    sections.append(_trend_section(frame, axes, keys))
    sections.append(_variant_section(frame, axes))
    title = study.get("title") or f"conrod sweep: {folder.name}"
    return title, sections


def _axis_keys(study: dict, axes: list[str]) -> dict[str, str]:
    """Axis column → case key (``study.json``; a folder without it: the column)."""
    columns = {str(column): key for key, column in (study.get("axis_columns") or {}).items()}
    return {column: columns.get(column, column) for column in axes}


def _study_section(frame: pd.DataFrame, study: dict, axes: list[str],
                   keys: dict[str, str]) -> Section:
    counts = ", ".join(f"{n} {status.replace('_', ' ')}"
                       for status, n in status_counts(frame).items())
    section = Section("Study", [
        f"Study file: {study.get('study_file', '–')}; {study.get('mode', 'product')} of the axes; "
        f"{len(frame)} variants: {counts}.",
    ])
    rows = [[keys[column], column, unit_of(keys[column]),
             ", ".join(_short(v) for v in pd.unique(frame[column]))] for column in axes]
    section.blocks.append(Table(["axis (case key)", "column", "unit", "values"], rows,
                                "The axes of the study, their table columns (unit in the "
                                "name) and the values each takes."))
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
        f"Among the variants with status ok (variants with warnings are listed apart); best "
        f"is the {best}.", numeric=("best", "worst"))])


def _problems_section(frame: pd.DataFrame, axes: list[str]) -> Section:
    problems = frame[frame["status"] != STATUS_OK]
    section = Section("Variants that are not ok")
    if problems.empty:
        section.blocks.append("Every variant finished with a periodic orbit and no warning.")
        return section
    rows = [[str(row["variant"]), *[_short(row[a]) for a in axes], str(row["status"]),
             str(row["error"] or row.get("warnings", "") or "orbit not periodic")]
            for _, row in problems.iterrows()]
    section.blocks.append(Table(
        ["variant", *axes, "status", "why"], rows,
        "Variants with warnings (doubtful results: contact carrying the load, temperature out "
        "of the oil's range, ...), a non-periodic orbit or no result, with the messages of "
        "conrod run.", numeric=tuple(axes)))
    return section


def _trend_section(frame: pd.DataFrame, axes: list[str], keys: dict[str, str]) -> Section:
    from conrod.plotting.report_plots import png_bytes
    from conrod.plotting.sweep_plots import sweep_figure
    from conrod.sweep.columns import axis_label

    numeric = [a for a in axes if pd.api.types.is_numeric_dtype(frame[a])]
    x = numeric[0] if numeric else axes[0]
    hue = next((a for a in axes if a != x), None)
    labels = {column: axis_label(keys[column]) for column in axes}
    section = Section("Trends", two_columns=True)
    for column in TREND_COLUMNS:
        if column not in frame or frame[column].isna().all():
            continue
        hue_text = f", one line per value of {labels[hue]}" if hue else ""
        contact = CONTACT_MARKER if column == "h_min_m" and "h_min_set_by" in frame and (
            frame["h_min_set_by"] == "contact").any() else ""
        section.blocks.append(Image(
            f"{column} against {keys[x]}",
            f"{CAPTION_UNITS[column][0].upper()}{CAPTION_UNITS[column][1:]} against "
            f"{labels[x].replace(' [', ' in ').rstrip(']')}{hue_text}. {MARKERS}{contact}",
            png_bytes(sweep_figure(frame, x, column, hue, labels))))
    return section


def _variant_section(frame: pd.DataFrame, axes: list[str]) -> Section:
    columns = ["variant", *axes, "status",
               *[c for c in TABLE_COLUMNS if c in frame], "error"]
    rows = [[_short(row[c]) for c in columns] for _, row in frame.iterrows()]
    return Section("Variants", [Table(
        columns, rows, "One row per variant (sweep.parquet); axes and characteristics in the "
        "units of their names; h_min_set_by: film, or contact where the smallest gap is the "
        "contact threshold; wall_time_s is the variant's time on its worker.",
        numeric=tuple(c for c in columns if c not in ("status", "error", "h_min_set_by")))])


def _short(value) -> str:
    if isinstance(value, float):
        return "–" if value != value else f"{value:.4g}"
    return str(value)
