"""Sign-off figures of ``conrod run``: the per-cell indicator maps on the unrolled shell and
on the journal, each with its worst cell marked (and the limit contour where a limit is
given), and the cavitation-erosion map — drawn from what
:class:`conrod.results.margins.SignOff` holds; nothing is computed here."""

from __future__ import annotations

import math
import textwrap

import numpy as np
from matplotlib.figure import Figure

DISPLAY = {"Pa": (1e-6, "MPa"), "m": (1e6, "µm"), "degC": (1.0, "°C"), "Pa/s": (1e-9, "GPa/s")}
"""Unit of a map → (factor, engineering unit) of its colour scale."""
LIMIT_OF_MAP = {"max_pressure": "max_pressure", "pressure_range": "pressure_range",
                "min_film_thickness": "min_film_thickness",
                "max_asperity_pressure": "asperity_pressure",
                "max_temperature": "max_temperature"}
"""Indicator map → the ``[limits]`` key drawn as its contour."""
CMAPS = {"min_film_thickness": "viridis_r", "erosion": "magma"}
TITLE_CHARACTERS = 85
"""Longest line of the erosion map's title (9 pt type, as wide as the axes) [characters]."""


def plot_indicator_maps(results, frame: str = "shell") -> Figure:
    """Every indicator map of ``results.signoff`` in ``frame`` ('shell' or 'journal'): the
    indicator over angle [deg] and axial position z [mm], the worst cell marked."""
    signoff = results.signoff
    indicators = None if signoff is None else signoff.indicators
    maps = [] if indicators is None else [m for m in indicators.maps if m.frame == frame]
    columns = 2
    rows = max(1, math.ceil(len(maps) / columns))
    fig = Figure(figsize=(10.0, 2.9 * rows + 0.4))
    if not maps:
        fig.add_subplot().text(0.5, 0.5, "no per-cell indicators in this result", ha="center")
        return fig
    limits = {m.name: m.limit for m in signoff.margins}
    for n, item in enumerate(maps):
        _draw_map(fig.add_subplot(rows, columns, n + 1), fig, item, indicators,
                  limits.get(LIMIT_OF_MAP.get(item.name, "")))
    where = ("unrolled shell, θ in the film frame" if frame == "shell"
             else "journal in its own frame (α: angle on the journal)")
    fig.suptitle(f"Per-cell indicators over the cycle — {where}; ✕ worst cell", fontsize=10)
    fig.tight_layout()
    return fig


def plot_erosion_map(results) -> Figure:
    """The cavitation-erosion indicator on the shell [GPa/s] over θ [deg] and z [mm]."""
    signoff = results.signoff
    indicators = None if signoff is None else signoff.indicators
    fig = Figure(figsize=(8.0, 3.4))
    ax = fig.add_subplot()
    if indicators is None or indicators.erosion is None:
        note = "no erosion indicator" if indicators is None else indicators.erosion_note
        ax.text(0.5, 0.5, note, ha="center", wrap=True)
        return fig
    _draw_map(ax, fig, indicators.erosion, indicators, None)
    ax.set_title(textwrap.fill(f"Cavitation erosion: {indicators.erosion.long_name}",
                               TITLE_CHARACTERS), fontsize=9)
    fig.subplots_adjust(bottom=0.17, top=0.84)  # the axis label and title within the canvas
    return fig


def _draw_map(ax, fig, item, indicators, limit) -> None:
    factor, unit = DISPLAY.get(item.units, (1.0, item.units))
    theta, z = np.degrees(indicators.theta), indicators.z * 1e3
    values = item.values * factor
    mesh = ax.pcolormesh(theta, z, values.T, shading="nearest",
                         cmap=CMAPS.get(item.name, "viridis"))
    fig.colorbar(mesh, ax=ax, label=f"[{unit}]")
    if limit is not None and values.min() < limit * factor < values.max():
        ax.contour(theta, z, values.T, levels=[limit * factor], colors="w", linewidths=1.0,
                   linestyles="--")
        ax.plot([], [], "w--", label=f"limit {limit * factor:.3g} {unit}")
    ax.plot(math.degrees(item.worst_theta) % 360.0, item.worst_z * 1e3, "x", color="C3",
            ms=9, mew=2, label=(f"worst {item.worst_value * factor:.4g} {unit} at "
                                f"{math.degrees(item.worst_crank_angle):.0f}°"))
    ax.legend(fontsize=7, loc="upper right", framealpha=0.8)
    angle = "θ (shell)" if item.frame == "shell" else "α (journal)"
    ax.set_xlabel(f"{angle} [deg]")
    ax.set_ylabel("z [mm]")
    ax.set_xticks(np.arange(0, 361, 90))
    ax.set_title(item.long_name, fontsize=9)
