"""The opening sections of a run report: the headline exactly as ``conrod run`` printed it
(``summary.json["headline"]``) with the warnings in a box above it, the rigid-vs-elastic
comparison in the columns of Rodin (2004, Table 2) where the run has an elastic big end,
and the cycle summary in engineering units — one unit per quantity, the units of the
headline (µm, MPa, W, l/min, °C)."""

from __future__ import annotations

from typing import Any

from conrod.report.html import Notice, Section, Table

LITRES_PER_MINUTE = 6.0e4
"""m³/s → l/min [-]."""

SUMMARY_ROWS = (
    ("smallest film h_min (outside contact)", "film_h_min_m", 1e6, "µm", "{:.3f}"),
    ("  at crank angle", "film_h_min_crank_angle_deg", 1.0, "deg", "{:.0f}"),
    ("smallest gap over the cycle (with contact)", "h_min_m", 1e6, "µm", "{:.3f}"),
    ("h/σ (film h_min over the combined roughness)", "film_thickness_ratio", 1.0, "-",
     "{:.3g}"),
    ("largest p_max", "p_max_Pa", 1e-6, "MPa", "{:.2f}"),
    ("  at crank angle", "p_max_crank_angle_deg", 1.0, "deg", "{:.0f}"),
    ("cycle mean of h_min, h*", "mean_h_min_m", 1e6, "µm", "{:.3f}"),
    ("cycle mean of p_max, p*", "mean_p_max_Pa", 1e-6, "MPa", "{:.2f}"),
    ("friction power, film", "mean_friction_power_W", 1.0, "W", "{:.1f}"),
    ("friction power, hard contact", "mean_contact_friction_power_W", 1.0, "W", "{:.1f}"),
    ("friction power, boundary (asperities)", "mean_boundary_friction_power_W", 1.0, "W",
     "{:.1f}"),
    ("friction power, total", "mean_total_friction_power_W", 1.0, "W", "{:.1f}"),
    ("side flow, out at the edges", "mean_side_flow_m3_s", LITRES_PER_MINUTE, "l/min",
     "{:.3g}"),
    ("supply flow, into the bearing", "mean_supply_flow_m3_s", LITRES_PER_MINUTE, "l/min",
     "{:.3g}"),
    ("effective temperature (heat balance)", "effective_temperature_C", 1.0, "°C", "{:.1f}"),
    ("viscosity of the final orbit", "viscosity_Pa_s", 1e3, "mPa s", "{:.4g}"),
    ("nominal specific load W_max/(B·D)", "nominal_specific_load_Pa", 1e-6, "MPa", "{:.3g}"),
    ("largest hard-contact force", "max_orbit_contact_force_N", 1e-3, "kN", "{:.3g}"),
    ("cycles integrated (a lead-in by its share)", "cycles", 1.0, "-", "{:g}"),
    ("periodicity error", "periodicity_error", 1.0, "c", "{:.2g}"),
    ("exit code of conrod run", "exit_code", 1.0, "-", "{:.0f}"),
)
"""Cycle-summary rows: label, summary.json key, factor from SI, unit, format."""


def headline_section(summary: dict[str, Any]) -> Section:
    """The warnings box and the headline table, as the terminal showed them."""
    warnings = [str(w) for w in summary.get("warnings") or []]
    if summary.get("converged") is False or summary.get("periodic") is False:
        warnings.insert(0, "the orbit is NOT periodic: the results are for diagnosis only")
    notice = (Notice(f"{len(warnings)} warning(s): conrod run exits "
                     f"{summary.get('exit_code', 4)} (finished with warnings)", warnings)
              if warnings else Notice("No warnings", [], ok=True))
    section = Section("Headline", [notice])
    lines = summary.get("headline") or {}
    if lines:
        section.blocks.append(Table(
            ["", ""], [[label, str(text)] for label, text in lines.items()],
            "The headline conrod run printed (summary.json 'headline').", css_class="headline"))
    return section


def comparison_section(summary: dict[str, Any]) -> Section | None:
    """Rigid vs elastic bore in Rodin's Table 2 columns, over the cycle and the firing
    stroke, and the bore displacement at the elastic h_min; None without a comparison."""
    table = summary.get("comparison")
    if not isinstance(table, dict) or "rigid" not in table:
        return None
    rows = [[meaning, _number(table["rigid"].get(key)), _number(table["elastic"].get(key)),
             _percent(table["difference_percent"].get(key))]
            for key, meaning in table.get("units", {}).items()]
    firing = table.get("firing_stroke") or {}
    if "rigid" in firing:
        for key, meaning in (("h_min_um", "smallest film h_min, firing stroke [µm]"),
                             ("p_max_MPa", "largest p_max, firing stroke [MPa]")):
            rows.append([meaning, _number(firing["rigid"].get(key)),
                         _number(firing["elastic"].get(key)),
                         _percent(firing.get("difference_percent", {}).get(key))])
    section = Section("Rigid and elastic big end", [Table(
        ["quantity [unit]", "rigid", "elastic", "difference [%]"], rows,
        "Rigid and elastic bore in the columns of Rodin (2004, Table 2), over the whole cycle "
        "and over the firing stroke (±90° around firing TDC); difference (elastic − rigid) "
        "/ rigid.", numeric=("rigid", "elastic", "difference [%]"))])
    split = table.get("bore_displacement_at_elastic_h_min")
    if isinstance(split, dict):
        section.blocks.append(
            f"Bore displacement at the elastic h_min (φ = {split['crank_angle_deg']:.0f}°, "
            f"θ = {split['shell_angle_deg']:.0f}°, outward +): "
            f"{split['total_m'] * 1e6:+.2f} µm = film pressure "
            f"{split['pressure_m'] * 1e6:+.2f} µm + rod inertia "
            f"{split['inertia_m'] * 1e6:+.2f} µm.")
    return section


def summary_section(summary: dict[str, Any]) -> Section:
    """The cycle summary in engineering units, with the grid-error estimate."""
    rows = []
    for label, key, factor, unit, shown in SUMMARY_ROWS:
        value = summary.get(key)
        if isinstance(value, int | float) and not isinstance(value, bool):
            rows.append([label, shown.format(value * factor), unit])
    section = Section("Cycle summary", [Table(
        ["quantity", "value", "unit"], rows,
        "Cycle characteristics of summary.json in the units of the headline (the file "
        "holds them in SI units, named in each key).", numeric=("value",))])
    grid = summary.get("grid_error")
    if isinstance(grid, dict):
        section.blocks.append(_grid_table(grid))
    return section


def _grid_table(grid: dict[str, Any]) -> Table:
    sizes = " / ".join(f"{a}×{b}" for a, b in grid.get("grids", []))
    rows = []
    for quantity, unit, key, factor in (("h_min", "µm", "m", 1e6), ("p_max", "MPa", "Pa", 1e-6)):
        item = grid.get(quantity) or {}
        values = " / ".join(f"{v * factor:.4g}" for v in item.get(f"values_{key}", []))
        order = item.get("observed_order")
        rows.append([f"{quantity} at {item.get('crank_angle_deg', 0.0):.0f}° [{unit}]", values,
                     f"{item.get(f'error_{key}', 0.0) * factor:+.3g}",
                     f"{100 * item.get('relative_error', 0.0):+.1f}",
                     "not observed" if order is None else f"{order:.2g}"])
    return Table(["quantity", f"on the grids {sizes}", "grid error", "grid error [%]",
                  "observed order"], rows,
                 "Grid-error estimate: the cycle's extreme on the run grid and two coarser "
                 "grids; Richardson extrapolation from the run grid and the next coarser one "
                 "with the formal order 2 of the finite differences (the error: extrapolated "
                 "minus run-grid value), the observed order from all three (Celik et al. "
                 "2008).", numeric=(f"on the grids {sizes}", "grid error", "grid error [%]"))


def _number(value: Any) -> str:
    return "–" if value is None else f"{value:.4g}"


def _percent(value: Any) -> str:
    return "–" if value is None else f"{value:+.1f}"
