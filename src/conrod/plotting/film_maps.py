"""Film-thickness figures of ``conrod run`` over the shell circumference (rigid bore:
h(θ, φ) = c − e_x(φ) cos θ − e_y(φ) sin θ, film frame, :func:`conrod.film.base.film_thickness`).

* :func:`plot_film_thickness_map` — h(θ, φ) over shell angle and crank angle, the h_c
  contour and the track of h_min;
* :func:`plot_min_film_envelope` — the shell envelope of minimum film thickness: for each
  shell angle θ the thinnest film it sees over the cycle, min_φ h(θ, φ), and at which φ.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from conrod.results.cycle_results import RunResults

UM = 1e6
SHELL_POINTS = 361
"""Shell angles of the maps, 0..360° [-]."""


def film_thickness_over_cycle(results: RunResults) -> tuple[np.ndarray, np.ndarray]:
    """(shell angles θ [rad], h(φ, θ) [m] of shape (n_φ, n_θ)) of the rigid bore."""
    cycle = results.cycle
    theta = np.linspace(0.0, 2.0 * np.pi, SHELL_POINTS)
    h = (results.clearance - cycle.eccentricity_x[:, None] * np.cos(theta)[None, :]
         - cycle.eccentricity_y[:, None] * np.sin(theta)[None, :])
    return theta, h


def _contact_threshold(results: RunResults) -> float | None:
    settings = results.settings or {}
    value = settings.get("contact_film_thickness")
    return float(value) if value else None


def plot_film_thickness_map(results: RunResults) -> Figure:
    """h(θ, φ) [µm] over crank angle φ [deg] and shell angle θ [deg]."""
    theta, h = film_thickness_over_cycle(results)
    phi = results.cycle.crank_angle_deg
    fig = Figure(figsize=(8.0, 4.2))
    ax = fig.add_subplot()
    mesh = ax.pcolormesh(phi, np.degrees(theta), h.T * UM, shading="auto", cmap="viridis_r")
    fig.colorbar(mesh, ax=ax, label="film thickness h [µm]")
    h_c = _contact_threshold(results)
    if h_c is not None and h.min() <= h_c * 1.5:
        ax.contour(phi, np.degrees(theta), h.T * UM, levels=[h_c * UM], colors="C3",
                   linewidths=0.8)
        ax.plot([], [], color="C3", lw=0.8, label=f"h = h_c = {h_c * UM:.2g} µm (contact)")
    ax.plot(phi, np.degrees(np.mod(results.cycle.h_min_angle_shell, 2 * np.pi)), ".",
            color="w", ms=1.5, label="θ of h_min")
    ax.legend(fontsize=7, loc="upper right", framealpha=0.8)
    ax.set_xlabel("crank angle φ [deg]")
    ax.set_ylabel("shell angle θ [deg] (film frame)")
    ax.set_yticks(np.arange(0, 361, 90))
    ax.set_title("Film thickness over the shell and the cycle (rigid bore)", fontsize=10)
    return fig


def plot_min_film_envelope(results: RunResults) -> Figure:
    """min over the cycle of h(θ, φ) [µm] against shell angle θ [deg], with the crank angle
    where each shell point sees its thinnest film."""
    theta, h = film_thickness_over_cycle(results)
    envelope, where = h.min(axis=0), results.cycle.crank_angle_deg[h.argmin(axis=0)]
    fig = Figure(figsize=(8.0, 5.0))
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(np.degrees(theta), envelope * UM, color="C0", label="min over the cycle")
    h_c = _contact_threshold(results)
    if h_c is not None:
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
    fig.suptitle("Shell envelope of minimum film thickness", fontsize=10)
    return fig
