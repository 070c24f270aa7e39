"""Film-thickness figures of ``conrod run`` over the shell circumference, drawn from the
film thickness the run holds (:attr:`conrod.results.cycle_results.RunResults.film_thickness`:
on a rigid bore h = c − e_x cos θ − e_y sin θ, on a deforming bore the deformed gap
h_rigid + u the film sees).

* :func:`plot_film_thickness_map` — h(θ, φ) over shell angle and crank angle, the h_c
  contour (rigid bore) and the track of h_min;
* :func:`plot_min_film_envelope` — the shell envelope of minimum film thickness: for each
  shell angle θ the thinnest film it sees over the cycle, min_φ h(θ, φ), and at which φ.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from conrod.results.cycle_results import RunResults

UM = 1e6


def _which_bore(results: RunResults) -> str:
    return "deformed bore" if results.contact_circle_widened else "rigid bore"


def _rigid_threshold(results: RunResults) -> float | None:
    """h_c where the rigid contact circle stops the journal (None on a deforming bore,
    where the deformed film stops it)."""
    return None if results.contact_circle_widened else results.contact_threshold


def plot_film_thickness_map(results: RunResults) -> Figure:
    """h(θ, φ) [µm] over crank angle φ [deg] and shell angle θ [deg]."""
    fig = Figure(figsize=(8.0, 4.2))
    ax = fig.add_subplot()
    if results.film_thickness is None or results.film_angles is None:
        ax.text(0.5, 0.5, "no film thickness field in this result", ha="center")
        return fig
    h, theta = results.film_thickness, np.degrees(results.film_angles)
    phi = results.cycle.crank_angle_deg
    mesh = ax.pcolormesh(phi, theta, h.T * UM, shading="auto", cmap="viridis_r")
    fig.colorbar(mesh, ax=ax, label="film thickness h [µm]")
    h_c = _rigid_threshold(results)
    if h_c and h.min() <= h_c * 1.5:
        ax.contour(phi, theta, h.T * UM, levels=[h_c * UM], colors="C3", linewidths=0.8)
        ax.plot([], [], color="C3", lw=0.8, label=f"h = h_c = {h_c * UM:.2g} µm (contact)")
    ax.plot(phi, np.degrees(np.mod(results.cycle.h_min_angle_shell, 2 * np.pi)), ".",
            color="w", ms=1.5, label="θ of h_min")
    ax.legend(fontsize=7, loc="upper right", framealpha=0.8)
    ax.set_xlabel("crank angle φ [deg]")
    ax.set_ylabel("shell angle θ [deg] (film frame)")
    ax.set_yticks(np.arange(0, 361, 90))
    ax.set_title(f"Film thickness over the shell and the cycle ({_which_bore(results)})",
                 fontsize=10)
    fig.subplots_adjust(bottom=0.14)  # the axis label within the canvas
    return fig


def plot_min_film_envelope(results: RunResults) -> Figure:
    """min over the cycle of h(θ, φ) [µm] against shell angle θ [deg], with the crank angle
    where each shell point sees its thinnest film."""
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    envelope = results.film_envelope()
    if envelope is None:
        top.text(0.5, 0.5, "no film thickness field in this result", ha="center")
        return fig
    theta, smallest, where = envelope
    top.plot(np.degrees(theta), smallest * UM, color="C0", label="min over the cycle")
    h_c = _rigid_threshold(results)
    if h_c:
        top.axhline(h_c * UM, color="C3", ls="--", lw=0.8, label=f"h_c = {h_c * UM:.2g} µm")
    top.set_ylabel("smallest film h [µm]")
    top.set_ylim(bottom=0.0)
    top.legend(fontsize=7)
    bottom.plot(np.degrees(theta), where, ".", ms=2, color="C1")
    bottom.set_ylabel("at crank angle φ [deg]")
    bottom.set_xlabel("shell angle θ [deg] (film frame)")
    bottom.set_xticks(np.arange(0, 361, 45))
    for ax in (top, bottom):
        ax.grid(True, lw=0.3)
    fig.suptitle(f"Shell envelope of minimum film thickness ({_which_bore(results)})",
                 fontsize=10)
    return fig
