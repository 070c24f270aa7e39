"""Figures of the report drawn from a results folder's tables (``cycle.csv``, wear tables).

The report uses these when a run folder holds no figure files (sweep variants are written
without figures), and always for the load diagram (``conrod run`` writes none). Every
function takes a pandas DataFrame with the file's engineering column names and returns a
Figure; :func:`png_bytes` turns a Figure into PNG bytes for embedding.
"""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import numpy as np  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402

from conrod.plotting.save import figure_bytes  # noqa: E402

UM = 1e6
KN = 1e-3
MPA = 1e-6
LPM = 6.0e4
"""m^3/s → l/min."""


def png_bytes(figure: Figure, dpi: int = 110) -> bytes:
    """The figure as PNG bytes at ``dpi`` [dots per inch], cut to its tight box and drawn
    once where it fits its canvas (:func:`conrod.plotting.save.figure_bytes`), then closed."""
    import matplotlib.pyplot as plt

    drawn = figure_bytes(figure, "png", dpi=dpi)
    plt.close(figure)
    return drawn


def load_diagram_figure(cycle) -> Figure:
    """Polar diagram of the load on the bearing (film frame) [kN] and its magnitude vs φ."""
    fig = Figure(figsize=(10.0, 4.6))
    polar, line = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1.0, 1.4]})
    fx, fy = cycle["load_x_N"] * KN, cycle["load_y_N"] * KN
    phi = cycle["crank_angle_deg"]
    polar.plot(np.append(fx, fx.iloc[0]), np.append(fy, fy.iloc[0]), color="C0", lw=1.2)
    polar.plot([0.0], [0.0], "k+", ms=8)
    for i in range(0, len(phi), max(len(phi) // 8, 1)):
        polar.annotate(f"{phi.iloc[i]:.0f}°", (fx.iloc[i], fy.iloc[i]), fontsize=7,
                       xytext=(3, 3), textcoords="offset points")
    polar.set_aspect("equal", adjustable="datalim")
    polar.set_xlabel("load x [kN] (film frame)")
    polar.set_ylabel("load y [kN]")
    polar.set_title("polar load diagram", fontsize=10)
    line.plot(phi, np.hypot(fx, fy), color="C0")
    line.set_xlabel("crank angle φ [deg]")
    line.set_ylabel("|load| [kN]")
    line.set_title("load magnitude over the cycle", fontsize=10)
    for ax in (polar, line):
        ax.grid(True, lw=0.3)
    fig.subplots_adjust(bottom=0.13)  # the axis labels within the canvas
    return fig


def _column(cycle, name: str):
    """A cycle.csv column by its name, or by the name older conrod versions wrote (without
    the unit suffix)."""
    if name in cycle:
        return cycle[name]
    return cycle[name.removesuffix("_m").removesuffix("_1")]


def orbit_from_table(cycle) -> Figure:
    """Journal-centre orbit [µm] in the clearance circle (c = |e|/ε from the table)."""
    x, y = _column(cycle, "eccentricity_x_m") * UM, _column(cycle, "eccentricity_y_m") * UM
    eps = _column(cycle, "eccentricity_ratio_1").to_numpy()
    radius = np.hypot(x, y).to_numpy()
    usable = eps > 1e-6
    fig = Figure(figsize=(5.6, 5.6))
    ax = fig.add_subplot()
    if usable.any():
        c = float(np.median(radius[usable] / eps[usable]))
        circle = np.linspace(0.0, 2.0 * np.pi, 361)
        ax.plot(c * np.cos(circle), c * np.sin(circle), "k-", lw=1.0, label="clearance")
    ax.plot(np.append(x, x.iloc[0]), np.append(y, y.iloc[0]), color="C0", lw=1.4, label="orbit")
    ax.set_aspect("equal")
    ax.set_xlabel("e_x [µm] (film frame)")
    ax.set_ylabel("e_y [µm]")
    ax.legend(loc="upper right", fontsize=7)
    ax.grid(True, lw=0.3)
    return fig


def hmin_pmax_from_table(cycle) -> Figure:
    """h_min(φ) [µm] and p_max(φ) [MPa] over the cycle."""
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(cycle["crank_angle_deg"], cycle["h_min_m"] * UM, color="C0")
    top.set_ylabel("h_min [µm]")
    top.set_ylim(bottom=0.0)
    bottom.plot(cycle["crank_angle_deg"], cycle["p_max_Pa"] * MPA, color="C1")
    bottom.set_ylabel("p_max [MPa]")
    bottom.set_xlabel("crank angle φ [deg]")
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    return fig


def friction_flow_from_table(cycle) -> Figure:
    """Friction power [W] and side/supply flow [l/min] over the cycle."""
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(cycle["crank_angle_deg"], cycle["friction_power_W"], color="C2")
    top.set_ylabel("friction power [W]")
    bottom.plot(cycle["crank_angle_deg"], cycle["side_flow_m3_s"] * LPM, label="side flow")
    bottom.plot(cycle["crank_angle_deg"], cycle["supply_flow_m3_s"] * LPM, label="supply flow")
    bottom.set_ylabel("flow [l/min]")
    bottom.set_xlabel("crank angle φ [deg]")
    bottom.legend(fontsize=7)
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    return fig


def contact_wear_from_tables(cycle, wear_journal=None, wear_shell=None) -> Figure:
    """Contact force [kN] over the cycle and wear per cycle [nm] on journal and shell."""
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1)
    top.plot(cycle["crank_angle_deg"], cycle["contact_force_N"] * KN, color="C3")
    top.set_xlabel("crank angle φ [deg]")
    top.set_ylabel("contact force [kN]")
    for table, name in ((wear_journal, "journal"), (wear_shell, "shell")):
        if table is not None:
            bottom.plot(table["angle_deg"], table["wear_m"] * 1e9, label=name)
    bottom.set_xlabel("surface angle [deg]")
    bottom.set_ylabel("wear per cycle [nm]")
    if bottom.lines:
        bottom.legend(fontsize=7)
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    fig.tight_layout()
    return fig
