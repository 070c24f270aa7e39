"""Figures of ``conrod run``: one function per figure, each returns a Figure.

* :func:`plot_orbit` — journal-centre orbit inside the clearance circle, crank-angle labels;
  the cycle before the last is dashed, and a non-periodic orbit is flagged in the title;
* :func:`plot_film_thickness_and_pressure` — h_min(φ) and p_max(φ) ([D0] Fig. 3.5.2);
* :func:`plot_friction_and_flow` — friction power and side/supply flow over the cycle;
* :func:`plot_pressure_map` — film pressure p(θ, z) at the crank angle of the largest p_max.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from conrod.results.cycle_results import RunResults

UM = 1e6
LABEL_EVERY_DEG = 60.0


def plot_orbit(results: RunResults) -> Figure:
    """Orbit (x, y) [µm] in the clearance circle, labelled every 60° of crank angle."""
    cycle, c = results.cycle, results.clearance
    fig = Figure(figsize=(6.0, 6.0))
    ax = fig.add_subplot()
    circle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(c * UM * np.cos(circle), c * UM * np.sin(circle), "k-", lw=1.0, label="clearance")
    if results.previous_cycle_eccentricity is not None:
        prev = results.previous_cycle_eccentricity * UM
        ax.plot(prev[0], prev[1], "--", color="0.6", lw=0.8, label="previous cycle")
    x, y = cycle.eccentricity_x * UM, cycle.eccentricity_y * UM
    ax.plot(np.append(x, x[0]), np.append(y, y[0]), "-", color="C0", lw=1.4, label="orbit")
    if np.any(cycle.in_contact):
        ax.plot(x[cycle.in_contact], y[cycle.in_contact], ".", color="C3", ms=3, label="contact")
    step = max(int(round(np.radians(LABEL_EVERY_DEG) / np.diff(cycle.crank_angle[:2])[0])), 1)
    for i in range(0, len(cycle), step):
        ax.plot(x[i], y[i], "o", color="C1", ms=3)
        ax.annotate(f"{cycle.crank_angle_deg[i]:.0f}°", (x[i], y[i]), fontsize=7,
                    xytext=(3, 3), textcoords="offset points")
    ax.set_aspect("equal")
    ax.set_xlabel("e_x [µm] (film frame)")
    ax.set_ylabel("e_y [µm]")
    s = results.summary
    title = f"Journal-centre orbit — {s.film_model}, {s.cycles} cycles"
    if not s.periodic:
        title += f"\nNOT PERIODIC: error {s.periodicity_error:.2g}"
    ax.set_title(title, color="C3" if not s.periodic else "k", fontsize=10)
    ax.legend(loc="upper right", fontsize=7)
    return fig


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
    top.set_ylabel("h_min [µm]")
    top.set_ylim(bottom=0.0)
    bottom.plot(cycle.crank_angle_deg, cycle.p_max / 1e6, color="C1")
    bottom.set_ylabel("p_max [MPa]")
    bottom.set_xlabel("crank angle φ [deg]")
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    fig.suptitle("Minimum film thickness and maximum film pressure", fontsize=10)
    return fig


def plot_friction_and_flow(results: RunResults) -> Figure:
    """Friction power [W] and side/supply flow [l/min] over the cycle."""
    cycle = results.cycle
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(cycle.crank_angle_deg, cycle.friction_power, color="C2")
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
    mesh = ax.pcolormesh(np.degrees(theta), z * 1e3, field.T / 1e6, shading="auto", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="p [MPa]")
    ax.set_xlabel("shell angle θ [deg]")
    ax.set_ylabel("z [mm]")
    phi = np.degrees(results.summary.p_max_crank_angle)
    ax.set_title(f"Film pressure at φ = {phi:.0f}° (largest p_max)", fontsize=10)
    return fig
