"""Figures of ``conrod run``: one function per figure, each returns a Figure.

* :func:`plot_orbit` — journal-centre orbit inside the clearance circle, crank-angle labels;
  the cycle before the last is dashed, and a non-periodic orbit is flagged in the title;
* :func:`plot_film_thickness_and_pressure` — h_min(φ) and p_max(φ) ([D0] Fig. 3.5.2);
* :func:`plot_friction_and_flow` — friction power and side/supply flow over the cycle;
* :func:`plot_pressure_map` — film pressure p(θ, z) at the crank angle of the largest p_max,
  the θ window centred on the peak (never split across 0°/360°).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.transforms import offset_copy

from conrod.plotting.save import POINTS_PER_INCH, fitting_pad
from conrod.results.cycle_results import RunResults
from conrod.results.summary import contact_friction_power

UM = 1e6
LABEL_EVERY_DEG = 60.0
TITLE_LINE_PT, TITLE_GAP_PT = 12.0, 13.0
"""Height of a line of the orbit's title (10 pt type) and the space under and over the
title [pt]: the legend sits that far above the axes."""


def plot_orbit(results: RunResults) -> Figure:
    """Orbit (x, y) [µm] in the clearance circle, with the orbit's contact circle (c − h_c;
    on a deforming bore widened by one clearance, said in the legend and the title), the
    load direction at the peak load, and crank-angle labels that do not overlap."""
    cycle, c = results.cycle, results.clearance
    fig = Figure(figsize=(6.4, 6.4))
    ax = fig.add_subplot()
    circle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(c * UM * np.cos(circle), c * UM * np.sin(circle), "k-", lw=1.0,
            label="clearance c (rigid bore)")
    reach = _contact_circle(ax, results, circle)
    if results.previous_cycle_eccentricity is not None:
        prev = results.previous_cycle_eccentricity * UM
        ax.plot(prev[0], prev[1], "--", color="0.6", lw=0.8, label="previous cycle")
    x, y = cycle.eccentricity_x * UM, cycle.eccentricity_y * UM
    ax.plot(np.append(x, x[0]), np.append(y, y[0]), "-", color="C0", lw=1.4, label="orbit")
    if np.any(cycle.in_contact):
        ax.plot(x[cycle.in_contact], y[cycle.in_contact], ".", color="C3", ms=3, label="contact")
    _load_arrow(ax, cycle, c * UM)
    _angle_labels(ax, cycle, x, y, c * UM)
    ax.set_aspect("equal")
    limit = max(1.35 * c, 1.1 * reach, 1.1 * float(np.max(np.hypot(x, y))) / UM) * UM
    ax.set_xlim(-limit, limit)
    ax.set_ylim(-limit, limit)
    ax.set_xlabel("e_x [µm] (film frame)")
    ax.set_ylabel("e_y [µm]")
    s = results.summary
    title = f"Journal-centre orbit — {s.film_model}, {s.cycles:g} cycles"
    if results.contact_circle_widened:
        title += "\ndeforming bore: the journal may pass the rigid clearance circle"
    if not s.periodic:
        title += f"\nNOT PERIODIC: error {s.periodicity_error:.2g}"
    ax.set_title(title, color="C3" if not s.periodic else "k", fontsize=10)
    _legend_above_title(fig, ax, title.count("\n") + 1)
    return fig


def _legend_above_title(fig: Figure, ax, title_lines: int) -> None:
    """The legend centred over the title, and the axes lowered until both lie
    :func:`conrod.plotting.save.fitting_pad` below the top of the canvas (so that the
    figure is drawn once; no layout engine, which costs a third of a drawing)."""
    above = TITLE_GAP_PT + TITLE_LINE_PT * title_lines  # [pt] over the axes
    legend = ax.legend(loc="lower center", fontsize=6.5, bbox_to_anchor=(0.5, 1.0),
                       bbox_transform=offset_copy(ax.transAxes, fig=fig, units="points",
                                                  y=above), borderaxespad=0.0, ncols=2,
                       frameon=False)
    room = above + legend.get_window_extent().height / fig.dpi * POINTS_PER_INCH \
        + fitting_pad() * POINTS_PER_INCH  # [pt] from the top of the axes to the canvas's
    fig.subplots_adjust(top=1.0 - room / (fig.get_figheight() * POINTS_PER_INCH))


def _contact_circle(ax, results: RunResults, circle: np.ndarray) -> float:
    """Draw the orbit's contact circle; return its radius [m] (the clearance without one)."""
    radius, h_c = results.contact_radius, results.contact_threshold or 0.0
    if radius is None:
        radius = results.clearance - h_c
    if radius <= 0.0 or (h_c == 0.0 and not results.contact_circle_widened):
        return results.clearance  # the clearance circle itself
    if results.contact_circle_widened:
        label = (f"contact circle of the deforming bore, 2c − h_c = {radius * UM:.3g} µm:\nthe "
                 "bore gives way, the deformed film stops the journal")
    else:
        label = f"contact circle c − h_c (h_c = {h_c * UM:.2g} µm)"
    ax.plot(radius * UM * np.cos(circle), radius * UM * np.sin(circle), ":", color="C3",
            lw=0.9, label=label)
    return radius


def _load_arrow(ax, cycle, radius: float) -> None:
    """The direction of the load pressing the journal, at the crank angle of the peak load."""
    load = np.hypot(cycle.load_x, cycle.load_y)
    i = int(np.argmax(load))
    if load[i] <= 0.0:
        return
    ux, uy = cycle.load_x[i] / load[i], cycle.load_y[i] / load[i]
    ax.annotate("", xy=(0.9 * radius * ux, 0.9 * radius * uy), xytext=(0.0, 0.0),
                arrowprops={"arrowstyle": "-|>", "color": "C2", "lw": 1.2})
    ax.plot([], [], color="C2", label=f"peak load {load[i] / 1e3:.3g} kN at "
            f"φ = {cycle.crank_angle_deg[i]:.0f}° (direction)")


def _angle_labels(ax, cycle, x: np.ndarray, y: np.ndarray, radius: float) -> None:
    """Crank-angle labels every LABEL_EVERY_DEG, pushed radially outwards and skipped when
    they would sit closer than 12 % of the clearance to a label already drawn."""
    step = max(int(round(np.radians(LABEL_EVERY_DEG) / np.diff(cycle.crank_angle[:2])[0])), 1)
    placed: list[tuple[float, float]] = []
    for i in range(0, len(cycle), step):
        ax.plot(x[i], y[i], "o", color="C1", ms=3)
        norm = max(float(np.hypot(x[i], y[i])), 1e-12)
        lx, ly = x[i] + 0.12 * radius * x[i] / norm, y[i] + 0.12 * radius * y[i] / norm
        if any(np.hypot(lx - px, ly - py) < 0.12 * radius for px, py in placed):
            continue
        placed.append((lx, ly))
        ax.annotate(f"{cycle.crank_angle_deg[i]:.0f}°", (x[i], y[i]), xytext=(lx, ly),
                    fontsize=7, ha="center", va="center",
                    arrowprops={"arrowstyle": "-", "color": "0.6", "lw": 0.4})


def plot_film_thickness_and_pressure(results: RunResults) -> Figure:
    """h_min(φ) [µm] and p_max(φ) [MPa] over the cycle ([D0] Fig. 3.5.2)."""
    cycle = results.cycle
    fig = Figure(figsize=(8.0, 5.5))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(cycle.crank_angle_deg, cycle.h_min * UM, color="C0")
    if np.any(cycle.in_contact):
        top.fill_between(cycle.crank_angle_deg, 0, cycle.h_min.max() * UM,
                         where=cycle.in_contact, color="C3", alpha=0.2, label="contact")
        top.legend(fontsize=7)
    h_c = (results.settings or {}).get("contact_film_thickness")
    if h_c:
        top.axhline(h_c * UM, color="C3", ls="--", lw=0.8,
                    label=f"contact threshold h_c = {h_c * UM:.2g} µm")
        top.legend(fontsize=7)
    top.set_ylabel("h_min [µm]")
    top.set_ylim(bottom=0.0)
    bottom.plot(cycle.crank_angle_deg, cycle.p_max / 1e6, color="C1")
    bottom.set_ylabel("p_max [MPa]")
    _exhaust_note(bottom, results)
    bottom.set_xlabel("crank angle φ [deg]")
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    fig.suptitle("Minimum film thickness and maximum film pressure", fontsize=10)
    return fig


def _exhaust_note(ax, results: RunResults) -> None:
    """Mark the exhaust opening of the parametric gas-pressure model ([D3] §2): the cylinder
    pressure steps there from expansion to exhaust pressure, and so does every load."""
    opening = (results.model or {}).get("exhaust_opening_deg")
    if opening is None:
        return
    ax.axvline(float(opening), color="0.5", ls=":", lw=0.8)
    ax.annotate("exhaust opens: step of the\ngas-pressure model", (float(opening), 1.0),
                xycoords=("data", "axes fraction"), xytext=(4, -4), textcoords="offset points",
                fontsize=7, va="top", color="0.35")


def plot_friction_and_flow(results: RunResults) -> Figure:
    """Friction power [W] and side/supply flow [l/min] over the cycle."""
    cycle = results.cycle
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    contact = contact_friction_power(cycle)
    top.plot(cycle.crank_angle_deg, cycle.friction_power, color="C2", label="film")
    if np.any(contact > 0.0):
        top.plot(cycle.crank_angle_deg, contact, color="C3", label="hard contact μ P_c |V|")
        top.plot(cycle.crank_angle_deg, cycle.friction_power + contact, color="k", lw=0.8,
                 ls="--", label="total")
    top.legend(fontsize=7)
    top.set_ylabel("friction power [W]")
    to_lpm = 6.0e4
    bottom.plot(cycle.crank_angle_deg, cycle.side_flow * to_lpm, label="side flow")
    bottom.plot(cycle.crank_angle_deg, cycle.supply_flow * to_lpm, label="supply flow")
    bottom.set_ylabel("flow [l/min]")
    bottom.set_xlabel("crank angle φ [deg]")
    bottom.legend(fontsize=7)
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    return fig


def plot_pressure_map(results: RunResults) -> Figure:
    """Film pressure p(θ, z) [MPa] at the crank angle of the largest p_max."""
    fig = Figure(figsize=(8.0, 3.8))
    ax = fig.add_subplot()
    if results.pressure_at_p_max is None or results.pressure_grid is None:
        ax.text(0.5, 0.5, "no pressure field from this film model", ha="center")
        return fig
    theta, z = results.pressure_grid
    field = results.pressure_at_p_max
    if field.shape != (theta.size, z.size):
        z = np.linspace(z[0], z[-1], field.shape[1])
        theta = np.linspace(theta[0], theta[-1], field.shape[0])
    theta_deg, field = centred_on_peak(np.degrees(theta), field)
    mesh = ax.pcolormesh(theta_deg, z * 1e3, field.T / 1e6, shading="auto", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="p [MPa]")
    ax.set_xlim(theta_deg[0], theta_deg[-1])
    ax.set_xlabel("shell angle θ [deg] (centred on the peak; add 360° to negative angles)")
    ax.set_ylabel("z [mm]")
    phi = np.degrees(results.summary.p_max_crank_angle)
    ax.set_title(f"Film pressure at φ = {phi:.0f}° (largest p_max)", fontsize=10)
    fig.subplots_adjust(bottom=0.15)  # the axis label within the canvas
    return fig


def centred_on_peak(theta_deg: np.ndarray, field: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(θ [deg], field) rolled around the circumference so that the peak of ``field``
    (shape (n_θ, n_z)) sits in the middle of a 360° window, θ_peak − 180° … θ_peak + 180°;
    a duplicated 360° node is dropped first."""
    if theta_deg.size > 1 and np.isclose(theta_deg[-1] - theta_deg[0], 360.0):
        theta_deg, field = theta_deg[:-1], field[:-1]
    n = theta_deg.size
    peak = int(np.unravel_index(np.argmax(field), field.shape)[0])
    shift = n // 2 - peak
    rolled = np.roll(field, shift, axis=0)
    angles = np.roll(theta_deg, shift)
    centre = theta_deg[peak]
    angles = (angles - centre + 180.0) % 360.0 + centre - 180.0
    return angles, rolled
