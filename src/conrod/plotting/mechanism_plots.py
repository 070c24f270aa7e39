"""Figures of the clearance mechanism. One function per figure → Figure."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from conrod.mechanism.regimes import SweepResults
from conrod.mechanism.results import JOINT_NAMES, MechanismResults
from conrod.plotting.save import POINTS_PER_INCH, fitting_layout, fitting_pad

LABELS = {"big_end": "big end (crank pin)", "small_end": "small end (piston pin)"}
UM = 1.0e6


def _cycle_degrees(results: MechanismResults, angles: np.ndarray) -> np.ndarray:
    return np.degrees(np.mod(angles, results.cycle_length))


def plot_gaps_and_forces(results: MechanismResults) -> Figure:
    """Gap −δ [µm] and contact force [kN] of both joints, piston deviation [µm], last cycle."""
    mask = results.last_cycle()
    angle = np.degrees(results.crank_angle[mask] - (results.cycles - 1) * results.cycle_length)
    figure = Figure(figsize=(8.0, 8.0))
    axes = figure.subplots(3, 1, sharex=True)
    for index, name in enumerate(JOINT_NAMES):
        axes[0].plot(angle, results.gap[index, mask] * UM, label=LABELS[name], lw=0.9)
        axes[1].plot(angle, results.contact_force[index, mask] / 1e3, label=LABELS[name], lw=0.9)
    axes[0].axhline(0.0, color="k", lw=0.5)
    deviation = results.piston_position[mask] - results.piston_position_rigid[mask]
    axes[2].plot(angle, deviation * UM, color="C2", lw=0.9)
    axes[0].set_ylabel("gap −δ [µm]\n(< 0: contact)")
    axes[1].set_ylabel("contact force R [kN]")
    axes[2].set_ylabel("piston − rigid\nslider-crank [µm]")
    axes[2].set_xlabel("crank angle from firing TDC [deg]")
    axes[2].set_xlim(0.0, 720.0)
    axes[2].set_xticks(np.arange(0.0, 721.0, 90.0))
    axes[0].legend(loc="upper right", fontsize=8)
    for ax in axes:
        ax.grid(alpha=0.3)
    return figure


def plot_journal_orbits(results: MechanismResults) -> Figure:
    """Journal centre relative to the shell centre in the rod frame, with the worn outline."""
    mask = results.last_cycle()
    figure = Figure(figsize=(9.0, 4.8), layout=fitting_layout())
    axes = figure.subplots(1, 2)
    for index, name in enumerate(JOINT_NAMES):
        ax = axes[index]
        angles, radii = results.clearance_outline[name]
        ax.plot(radii * np.sin(angles) * UM, radii * np.cos(angles) * UM, "k-", lw=0.8,
                label="free-play outline (δ = 0)")
        along, across = results.journal_offset[index][:, mask]
        ax.plot(across * UM, along * UM, lw=0.7, color=f"C{index}", label="journal centre")
        ax.set_aspect("equal")
        ax.set_title(LABELS[name], fontsize=10)
        ax.set_xlabel("across the rod [µm]")
        ax.set_ylabel("along the rod, towards the small end [µm]")
        ax.grid(alpha=0.3)
    axes[0].legend(loc="lower right", fontsize=7)
    return figure


def plot_impacts(results: MechanismResults) -> Figure:
    """Impact velocity at every contact entry vs crank angle in its cycle (settled cycles)."""
    impacts = results.settled_impacts()
    figure = Figure(figsize=(8.0, 3.8))
    ax = figure.subplots()
    for index, name in enumerate(JOINT_NAMES):
        keep = impacts.joint == index
        angle = _cycle_degrees(results, impacts.crank_angle[keep])
        ax.vlines(angle, 0.0, impacts.velocity[keep], color=f"C{index}", lw=1.0)
        ax.plot(angle, impacts.velocity[keep], "o", color=f"C{index}", ms=4, label=LABELS[name])
    ax.set_xlim(0.0, 720.0)
    ax.set_xticks(np.arange(0.0, 721.0, 90.0))
    ax.set_xlabel("crank angle from firing TDC [deg]")
    ax.set_ylabel("impact velocity [m/s]")
    ax.set_ylim(bottom=0.0)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    figure.subplots_adjust(bottom=0.15)  # the axis label within the canvas
    return figure


def plot_sweep_map(sweep: SweepResults) -> Figure:
    """Max impact velocity of each joint and the worn joint's excess Δv over speed × load;
    the most informative mode marked, with the joint that drives it."""
    figure = Figure(figsize=(14.0, 4.4), layout=fitting_layout())
    axes = figure.subplots(1, 3)
    panels = [(sweep.max_velocity[0], "max impact velocity, big end [m/s]"),
              (sweep.max_velocity[1], "max impact velocity, small end [m/s]"),
              (sweep.excess, f"Δv = v({JOINT_NAMES[sweep.worn_joint]}) − v(other) [m/s]")]
    best = sweep.best()
    for ax, (values, title) in zip(axes, panels, strict=True):
        points = ax.scatter(sweep.speed_rpm, sweep.load_scale, c=values, s=160, marker="s",
                            cmap="viridis")
        figure.colorbar(points, ax=ax)
        ax.plot(best["speed_rpm"], best["load_scale"], "r*", ms=14,
                label=f"most informative (driven by the {best['driven_by'].replace('_', ' ')})")
        ax.set_title(title, fontsize=9)
        ax.set_xlabel("crank speed [rpm]")
        ax.set_ylabel("load (gas pressure scale) [-]")
        ax.grid(alpha=0.3)
    type_size = 8.0  # [pt]; the legend as far from the canvas edge as the layout's axes
    figure.legend(*axes[2].get_legend_handles_labels(), loc="outside lower center",
                  fontsize=type_size, borderaxespad=fitting_pad() * POINTS_PER_INCH / type_size)
    return figure
