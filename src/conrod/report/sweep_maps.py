"""The engine-map section of a sweep report: for a study over two numeric axes (speed ×
load, say) contour maps of the sign-off characteristics — MOFT, POFP, the largest pressure
range Δp, friction power, oil flow and the largest temperature — with the limit contours of
the case's ``[limits]`` and the warned and failed variants marked."""

from __future__ import annotations

import pandas as pd

from conrod.report.html import Image, Section

MAPS = (
    (("film_h_min_m", "h_min_m"), "limit_min_film_thickness_m", "MOFT (film h_min)",
     "smallest film thickness over the cycle in µm"),
    (("p_max_Pa",), "limit_max_pressure_Pa", "POFP (film p_max)",
     "largest film pressure over the cycle in MPa"),
    (("max_pressure_range_Pa",), "limit_pressure_range_Pa", "largest pressure range Δp",
     "largest pressure range max − min at one point of the lining over the cycle in MPa"),
    (("mean_total_friction_power_W", "mean_friction_power_W"), None, "friction power",
     "cycle-mean friction power loss (film, contact, asperities) in W"),
    (("mean_side_flow_m3_s",), None, "oil flow (side)", "cycle-mean side flow in l/min"),
    (("max_film_temperature_C", "effective_temperature_C"), "limit_max_temperature_C",
     "largest temperature", "largest film temperature (the film's field where computed, "
     "else the effective temperature of the heat balance) in °C"),
)
"""(candidate columns, limit column, title, caption) of each map, in order."""
MARKERS = ("Small dots: status ok; hollow circles: warnings (a crossed limit or a doubtful "
           "result); crosses: failed (a hole in the map). Dashed red: the limit contour.")


def engine_map_section(frame: pd.DataFrame, axes: list[str],
                       keys: dict[str, str]) -> Section | None:
    """Contour maps over the first two numeric axes; None when the study has fewer than two
    numeric axes with at least two values each."""
    from conrod.plotting.report_plots import png_bytes
    from conrod.plotting.sweep_maps import engine_map_figure
    from conrod.sweep.columns import axis_label

    numeric = [a for a in axes if pd.api.types.is_numeric_dtype(frame[a])
               and frame[a].nunique() >= 2]
    if len(numeric) < 2:
        return None
    x, y = numeric[0], numeric[1]
    labels = {column: axis_label(keys[column]) for column in axes}
    section = Section("Engine maps", two_columns=True)
    for candidates, limit_column, title, caption in MAPS:
        column = next((c for c in candidates if c in frame and frame[c].notna().any()), None)
        if column is None:
            continue
        limit = _limit(frame, limit_column)
        limit_text = "" if limit is None else " The limit of the case's [limits] dashed."
        section.blocks.append(Image(
            f"{title} over {keys[x]} and {keys[y]}",
            f"{caption[0].upper()}{caption[1:]} ({column}) over {labels[x]} and "
            f"{labels[y]}.{limit_text} {MARKERS}",
            png_bytes(engine_map_figure(frame, x, y, column, limit, labels, title))))
    return section


def _limit(frame: pd.DataFrame, column: str | None) -> float | None:
    """The study's limit (the same in every variant) from its column; None when unset."""
    if column is None or column not in frame:
        return None
    values = frame[column].dropna().unique()
    return float(values[0]) if len(values) == 1 else None
