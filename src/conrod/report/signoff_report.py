"""The sign-off section of a run report: the margins against ``[limits]`` (the values the
headline prints, from ``summary.json["signoff"]``), the worst cell of each per-cell
indicator map and the cavitation-erosion indicator, then the maps themselves (the figures
``conrod run`` wrote)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from conrod.report.html import Image, Section, Table

DISPLAY = {"m": (1e6, "µm"), "Pa": (1e-6, "MPa"), "degC": (1.0, "°C"), "Pa/s": (1e-9, "GPa/s")}
"""SI unit → (factor, engineering unit) of the report's tables."""
HEADLINE_FORMATS = {"m": "{:.3f}", "Pa": "{:.2f}", "degC": "{:.1f}"}
"""Formats of the margins table: the headline's (film h_min in µm, p_max in MPa, °C)."""
FIGURES = ("indicator_maps_shell.png", "indicator_maps_journal.png", "erosion_map.png")
"""The sign-off figures of a run folder, in their order."""


def signoff_section(summary: dict[str, Any], folder: Path,
                    catalogue: dict[str, tuple]) -> Section | None:
    """Margins table, worst cells and the map figures; None for a folder without a
    sign-off. Takes the map figures out of ``catalogue`` (file → (title, caption))."""
    signoff = summary.get("signoff")
    if not isinstance(signoff, dict):
        return None
    section = Section("Sign-off: margins and per-cell indicators")
    margins = signoff.get("margins") or {}
    if margins:
        section.blocks.append(margins_table(margins))
    else:
        section.blocks.append("No [limits] in the case: no margins (the maps below show the "
                              "values a limit would be checked against).")
    indicators = signoff.get("indicators")
    if isinstance(indicators, dict):
        section.blocks.append(worst_cells_table(indicators))
        if indicators.get("erosion_note"):
            section.blocks.append(str(indicators["erosion_note"]))
    for note in signoff.get("notes") or []:
        section.blocks.append(str(note))
    for name in FIGURES:
        if name in catalogue:
            title, caption = catalogue.pop(name)
            section.blocks.append(Image(title, caption, (folder / name).read_bytes()))
    return section


def margins_table(margins: dict[str, dict]) -> Table:
    """One row per limit: value, limit, margin, crank angle, shell angle, z, verdict."""
    rows = []
    for name, item in margins.items():
        unit = next((k.removeprefix("limit_") for k in item if k.startswith("limit_")), "")
        factor, shown = DISPLAY.get(unit, (1.0, unit))
        value, limit = item.get(f"value_{unit}"), item.get(f"limit_{unit}")
        margin = item.get("margin")
        verdict = ("not checked" if value is None
                   else "CROSSED" if item.get("crossed") else "ok")
        style = HEADLINE_FORMATS.get(unit, "{:.4g}")
        rows.append([str(item.get("label", name)), _number(value, factor, shown, style),
                     _number(limit, factor, shown, style),
                     "–" if margin is None else f"{margin:+.1%}",
                     _angle(item.get("crank_angle_deg")), _angle(item.get("theta_deg")),
                     "–" if item.get("z_m") is None else f"{item['z_m'] * 1e3:+.1f} mm",
                     verdict, str(item.get("source", ""))])
    return Table(["limit", "value", "limit value", "margin", "crank angle", "shell angle θ",
                  "z", "verdict", "value from"], rows,
                 "Margins against the case's [limits]: (limit − value)/limit, for the film "
                 "thickness (value − limit)/limit; negative: the limit is crossed (a warning, "
                 "exit 4). The film h_min and p_max are the headline's numbers.",
                 numeric=("value", "limit value", "margin", "crank angle", "shell angle θ",
                          "z"), css_class="margins")


def worst_cells_table(indicators: dict[str, Any]) -> Table:
    """The worst cell of each per-cell map: value, where (angle, z) and when."""
    rows = []
    for key, item in indicators.items():
        if not isinstance(item, dict):
            continue
        factor, shown = DISPLAY.get(str(item.get("units")), (1.0, str(item.get("units"))))
        rows.append([key.replace("_", " "), _number(item.get("value"), factor, shown),
                     _angle(item.get("theta_deg")), f"{item.get('z_m', 0.0) * 1e3:+.1f} mm",
                     _angle(item.get("crank_angle_deg"))])
    return Table(["map", "worst value", "angle (shell θ / journal α)", "z", "crank angle"],
                 rows, "Worst cell of each per-cell indicator map over the cycle (shell: "
                 "unrolled shell; journal: in the journal's own frame).",
                 numeric=("worst value", "angle (shell θ / journal α)", "z", "crank angle"))


def _number(value: float | None, factor: float, unit: str, style: str = "{:.4g}") -> str:
    return "–" if value is None else f"{style.format(value * factor)} {unit}"


def _angle(value: float | None) -> str:
    return "–" if value is None else f"{value:.0f}°"
