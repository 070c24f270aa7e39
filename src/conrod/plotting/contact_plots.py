"""Contact figures ([D4]): Fig. 4.3.2 — contact stress and friction work, h_min with
the contact intervals shaded, p_max, against crank angle; Fig. 4.5.1 — friction work and
wear around journal and shell (unrolled and polar). One function per figure; each takes
:class:`conrod.contact.analysis.ContactResults` and returns a Figure."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure


def _shade_intervals(axis, intervals, cycle_deg: float) -> None:
    for start, end in intervals:
        for offset in (0.0, -cycle_deg):  # wrapping intervals show at both ends
            axis.axvspan(math.degrees(start) + offset, math.degrees(end) + offset,
                         color="tab:red", alpha=0.15, lw=0)


def plot_contact_cycle(contact) -> Figure:
    """[D4] Fig. 4.3.2: Hertz contact stress and cumulative friction work (top),
    h_min with the contact intervals shaded (middle), p_max (bottom) vs crank angle."""
    phi = np.degrees(contact.crank_angle)
    cycle_deg = float(phi[-1] - phi[0] + np.median(np.diff(phi)))
    figure = Figure(figsize=(8.0, 8.0))
    top, middle, bottom = figure.subplots(3, 1, sharex=True)
    stress_line, = top.plot(phi, contact.hertz_stress / 1e6, color="tab:red",
                            label="Hertz stress [MPa] (left axis)")
    top.set_ylabel("contact stress [MPa]", color="tab:red")
    top.tick_params(axis="y", colors="tab:red")
    work_axis = top.twinx()
    work_line, = work_axis.plot(phi, contact.work.cumulative, color="tab:blue",
                                label="cumulative friction work [J] (right axis)")
    work_axis.set_ylabel("friction work [J]", color="tab:blue")
    work_axis.tick_params(axis="y", colors="tab:blue")
    top.legend(handles=[stress_line, work_line], fontsize=7, loc="center right")
    top.set_title(f"Contact ({contact.model}); friction work {contact.work.total:.3g} J/cycle")
    middle.plot(phi, contact.h_min * 1e6, color="k")
    middle.set_ylabel("h_min [µm]")
    bottom.plot(phi, contact.p_max / 1e6, color="k")
    bottom.set_ylabel("p_max [MPa]")
    bottom.set_xlabel("crank angle [deg]")
    for axis in (top, middle, bottom):
        _shade_intervals(axis, contact.intervals, cycle_deg)
        axis.set_xlim(phi[0], phi[0] + cycle_deg)
        axis.grid(alpha=0.3)
    figure.tight_layout()
    return figure


def plot_wear_unrolled(contact) -> Figure:
    """[D4] Fig. 4.5.1: friction work and wear per element of the journal (curves 1, 2)
    and of the shell (curves 3, 4) against the surface angle."""
    wear = contact.wear
    angle = np.degrees(wear.element_angle)
    figure = Figure(figsize=(8.0, 6.0))
    axes = figure.subplots(2, 1, sharex=True)
    rows = (("journal (angle from journal mark)", wear.journal_work, wear.journal_wear),
            ("shell (film-frame θ)", wear.shell_work, wear.shell_wear))
    for axis, (name, work, depth) in zip(axes, rows, strict=True):
        axis.plot(angle, work, color="tab:blue", label="friction work")
        axis.set_ylabel("friction work [J]", color="tab:blue")
        wear_axis = axis.twinx()
        wear_axis.plot(angle, depth * 1e9, color="tab:red", ls="--", label="wear")
        wear_axis.set_ylabel("wear per cycle [nm]", color="tab:red")
        axis.set_title(name)
        axis.grid(alpha=0.3)
    axes[-1].set_xlabel("surface angle [deg]")
    axes[-1].set_xlim(0.0, 360.0)
    figure.tight_layout()
    return figure


def plot_wear_polar(contact) -> Figure:
    """Friction work around journal and shell as polar diagrams (radius ∝ work)."""
    wear = contact.wear
    closed = np.append(wear.element_angle, wear.element_angle[0])
    figure = Figure(figsize=(9.0, 4.5))
    for index, (name, work) in enumerate(
        (("journal", wear.journal_work), ("shell", wear.shell_work)), start=1
):
        axis = figure.add_subplot(1, 2, index, projection="polar")
        axis.set_title(f"{name}: friction work per element [J]")
        if not np.any(work > 0.0):  # no contact: say so instead of drawing a disc
            axis.set_rlim(0.0, 1.0)
            axis.set_yticklabels([])
            axis.text(0.5, 0.5, "no friction work\n(no contact)", ha="center", va="center",
                      transform=axis.transAxes, fontsize=9)
            continue
        closed_work = np.append(work, work[0])
        axis.plot(closed, closed_work, color="tab:blue")
        axis.fill(closed, closed_work, color="tab:blue", alpha=0.2)
        axis.set_rlim(0.0, 1.05 * float(work.max()))
    figure.tight_layout(pad=2.0)  # [font sizes]: the polar labels and titles within the canvas
    return figure


def plot_contact_stress_surfaces(contact) -> Figure:
    """[D4] Fig. 4.4.1: largest Hertz contact stress seen by each element of the journal
    and of the shell over the cycle."""
    angle = np.degrees(contact.wear.element_angle)
    figure = Figure(figsize=(8.0, 4.0))
    axis = figure.subplots()
    axis.plot(angle, contact.journal_stress / 1e6, label="journal (angle from journal mark)")
    axis.plot(angle, contact.shell_stress / 1e6, label="shell (film-frame θ)", ls="--")
    axis.set_xlabel("surface angle [deg]")
    axis.set_ylabel("max contact stress [MPa]")
    axis.set_xlim(0.0, 360.0)
    axis.grid(alpha=0.3)
    axis.legend()
    figure.tight_layout()
    return figure
