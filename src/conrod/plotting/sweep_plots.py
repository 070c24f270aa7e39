"""Figures of a sweep table: one characteristic against one axis, a line per hue value."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

UNIT_SUFFIXES = (
    ("_m3_s", "m³/s"), ("_Pa_s", "Pa s"), ("_m_s", "m/s"), ("_N_m", "N m"), ("_Pa", "Pa"),
    ("_W", "W"), ("_N", "N"), ("_J", "J"), ("_deg", "deg"), ("_C", "°C"), ("_s", "s"),
    ("_m", "m"),
)
"""Column-name suffix → unit, longest first."""


def column_label(name: str, units: dict[str, str] | None = None) -> str:
    """Axis label of a table column: ``h_min_m`` → ``h_min [m]``; axis keys get ``units``."""
    if units and name in units:
        return f"{name} [{units[name]}]" if units[name] else name
    for suffix, unit in UNIT_SUFFIXES:
        if name.endswith(suffix):
            return f"{name[: -len(suffix)]} [{unit}]"
    return name


def sweep_figure(frame, x: str, y: str, hue: str | None = None,
                 units: dict[str, str] | None = None) -> Figure:
    """``y`` against ``x`` for the finished variants; one line per value of ``hue``."""
    ok = frame[frame["status"] == "ok"] if "status" in frame else frame
    fig = Figure(figsize=(7.0, 4.4))
    ax = fig.add_subplot()
    groups = [(None, ok)] if hue is None else list(ok.groupby(hue, sort=True))
    for value, group in groups:
        group = group.sort_values(x)
        label = None if hue is None else f"{hue} = {_short(value)}"
        ax.plot(group[x], group[y], "o-", ms=4, label=label)
    ax.set_xlabel(column_label(x, units))
    ax.set_ylabel(column_label(y, units))
    if hue is not None and len(groups) > 0:
        ax.legend(fontsize=7, title=column_label(hue, units), title_fontsize=7)
    ax.grid(True, lw=0.3)
    failed = len(frame) - len(ok)
    if failed:
        ax.set_title(f"{failed} failed variant(s) not shown", fontsize=8, color="C3")
    return fig


def _short(value) -> str:
    return f"{value:.4g}" if isinstance(value, float | np.floating) else str(value)
