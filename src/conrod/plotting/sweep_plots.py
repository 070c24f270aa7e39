"""Figures of a sweep table: one characteristic against one axis, a line per hue value.

How a variant is drawn follows the table's ``status`` and ``h_min_set_by`` columns
(:mod:`conrod.sweep.status`):

* ``ok``: a filled marker on the line of its hue value;
* ``warning`` or ``not_periodic``: a hollow marker off the line (a doubtful result: read
  its warnings before using it);
* on an h_min plot, a variant whose smallest gap is set by hard contact (the journal
  touches the shell, the gap is the contact threshold h_c of the contact model): a
  hollow down-triangle off the line, labelled "hard contact", never a film thickness;
* ``failed``: not drawn (counted in the title).
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

UNIT_SUFFIXES = (
    ("_m3_s", "m³/s"), ("_Pa_s", "Pa s"), ("_kg_m3", "kg/m³"), ("_rad_s", "rad/s"),
    ("_m_s", "m/s"), ("_N_m", "N m"), ("_rpm", "rpm"), ("_Pa", "Pa"), ("_kg", "kg"),
    ("_W", "W"), ("_N", "N"), ("_J", "J"), ("_deg", "deg"), ("_C", "°C"), ("_s", "s"),
    ("_m", "m"),
)
"""Column-name suffix → unit, longest first."""
STATUS_OK = "ok"
STATUS_FAILED = "failed"
"""Values of the table's ``status`` column (:mod:`conrod.sweep.status`)."""
SET_BY_CONTACT = "contact"
"""Value of the table's ``h_min_set_by`` column where hard contact sets the smallest gap."""
CONTACT_SET_COLUMNS = ("h_min_m",)
"""Columns whose value is the contact threshold where the journal touches the shell."""


def column_label(name: str, labels: dict[str, str] | None = None) -> str:
    """Axis label of a table column: ``h_min_m`` → ``h_min [m]``; ``labels`` (column →
    label) first, e.g. ``{"engine.speed_rpm": "engine.speed [rpm]"}``."""
    if labels and name in labels:
        return labels[name]
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix):
            return f"{name[: -len(suffix)]} [{unit}]"
    return name


def sweep_figure(frame, x: str, y: str, hue: str | None = None,
                 labels: dict[str, str] | None = None) -> Figure:
    """``y`` against ``x`` for every variant that has a result; one line per value of
    ``hue`` through the variants with status ``ok`` (see the module docstring)."""
    status = frame.get("status")
    drawn = frame if status is None else frame[status != STATUS_FAILED]
    fig = Figure(figsize=(7.0, 4.4))
    ax = fig.add_subplot()
    groups = [(None, drawn)] if hue is None else list(drawn.groupby(hue, sort=True))
    kinds: set[str] = set()
    for number, (value, group) in enumerate(groups):
        color = f"C{number % 10}"
        kinds |= _draw_group(ax, group.sort_values(x), x, y, color,
                             None if hue is None else _hue_text(column_label(hue, labels),
                                                                value))
    ax.set_xlabel(column_label(x, labels))
    ax.set_ylabel(column_label(y, labels))
    keys = [_marker_key(kind) for kind in _ORDER if kind in kinds] if kinds - {"ok"} else []
    handles = ax.get_legend_handles_labels()[0] + keys
    if handles:
        ax.legend(handles=handles, fontsize=7)
    ax.grid(True, lw=0.3)
    failed = len(frame) - len(drawn)
    if failed:
        ax.set_title(f"{failed} failed variant(s) not drawn", fontsize=8, color="C3")
    fig.subplots_adjust(bottom=0.14)  # the axis label within the canvas
    return fig


def _draw_group(ax, group, x: str, y: str, color: str, label: str | None) -> set[str]:
    """One hue value: the line through its ok variants, the other variants as hollow
    markers; returns the kinds of marker drawn."""
    ok = group["status"] == STATUS_OK if "status" in group else np.ones(len(group), bool)
    contact = np.zeros(len(group), bool)
    if y in CONTACT_SET_COLUMNS and "h_min_set_by" in group:
        contact = (group["h_min_set_by"] == SET_BY_CONTACT).to_numpy()
    film_ok = np.asarray(ok) & ~contact
    doubtful = ~np.asarray(ok) & ~contact
    ax.plot(group[x][film_ok], group[y][film_ok], "o-", ms=4, color=color,
            label=label if film_ok.any() else None)
    ax.plot(group[x][doubtful], group[y][doubtful], "o", ms=6, mfc="none", color=color,
            label=label if doubtful.any() and not film_ok.any() else None)
    ax.plot(group[x][contact], group[y][contact], "v", ms=7, mfc="none", color=color,
            label=label if contact.any() and not (film_ok | doubtful).any() else None)
    return {kind for kind, shown in (("ok", film_ok), ("doubtful", doubtful),
                                     ("contact", contact)) if shown.any()}


_ORDER = ("ok", "doubtful", "contact")


def _marker_key(kind: str) -> Line2D:
    """Legend entry of a marker kind."""
    if kind == "ok":
        return Line2D([], [], marker="o", ms=4, color="0.3", label="status ok")
    if kind == "doubtful":
        return Line2D([], [], marker="o", ms=6, mfc="none", ls="none", color="0.3",
                      label="warning / not periodic (doubtful: see its warnings)")
    return Line2D([], [], marker="v", ms=7, mfc="none", ls="none", color="0.3",
                  label="hard contact: gap = contact threshold h_c, not a film thickness")


def _hue_text(label: str, value) -> str:
    """``engine.speed [rpm]`` and 1000.0 → ``engine.speed = 1000 rpm``."""
    name, _, unit = label.partition(" [")
    return f"{name} = {_short(value)}" + (f" {unit.rstrip(']')}" if unit else "")


def _short(value) -> str:
    return f"{value:.4g}" if isinstance(value, float | np.floating) else str(value)
