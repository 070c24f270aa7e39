"""Figures of an elastohydrodynamic run (:class:`conrod.results.ehd.ElasticRunResults`).

* :func:`plot_rigid_vs_elastic` — h_min(φ) and p_max(φ), rigid and elastic on one axis each;
* :func:`plot_deformed_bore` — magnified deformed bore and the clearance circle at the
  crank angles of the largest load and of the smallest h_min;
* :func:`plot_deformed_film_maps` — film thickness and pressure over θ and z on the deformed
  bore at the crank angle of the largest p_max, θ centred on the pressure peak;
* :func:`plot_von_mises` — rod von Mises stress at the largest load under the elastic film
  pressure or under the cosine load of the same resultant.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

UM, MPA = 1e6, 1e-6


def plot_rigid_vs_elastic(results) -> Figure:
    """h_min [µm] and p_max [MPa] against crank angle [deg], rigid and elastic bore."""
    fig = Figure(figsize=(8.0, 5.5))
    top, bottom = fig.subplots(2, 1, sharex=True)
    elastic = results.cycle
    top.plot(elastic.crank_angle_deg, elastic.h_min * UM, color="C3", label="elastic")
    bottom.plot(elastic.crank_angle_deg, elastic.p_max * MPA, color="C3", label="elastic")
    if results.rigid is not None:
        rigid = results.rigid.cycle
        top.plot(rigid.crank_angle_deg, rigid.h_min * UM, "--", color="C0", label="rigid")
        bottom.plot(rigid.crank_angle_deg, rigid.p_max * MPA, "--", color="C0", label="rigid")
    top.set_ylabel("h_min [µm]")
    bottom.set_ylabel("p_max [MPa]")
    bottom.set_xlabel("crank angle [deg]")
    top.set_title("Rigid and elastic big end", fontsize=10)
    for ax in (top, bottom):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    return fig


def _magnification(clearance: float, deformation: np.ndarray) -> float:
    """Scale drawing the largest |u| at 10 % of the radius-free plot (clearance units)."""
    largest = float(np.max(np.abs(deformation))) or clearance
    return max(round(0.5 * clearance / largest), 1)


def plot_deformed_bore(results) -> Figure:
    """Clearance circle around the journal and the deformed bore (magnified, in µm about
    the bore centre) at the largest load and at the smallest h_min."""
    cycle, c = results.cycle, results.clearance
    rows = {"largest load": results.peak_load_index, "smallest h_min": int(np.argmin(
        cycle.h_min))}
    fig = Figure(figsize=(10.0, 5.0))
    axes = fig.subplots(1, 2)
    theta = np.append(results.bore_angles, results.bore_angles[0])
    scale = _magnification(c, results.deformation[list(rows.values())])
    for ax, (label, i) in zip(axes, rows.items(), strict=True):
        u = np.append(results.deformation[i], results.deformation[i][0])
        radius = (c + scale * u) * UM
        ax.plot(c * UM * np.cos(theta), c * UM * np.sin(theta), "k--", lw=0.8,
                label="rigid bore (clearance circle)")
        ax.plot(radius * np.cos(theta), radius * np.sin(theta), color="C3", lw=1.4,
                label=f"deformed bore, u × {scale:g}")
        ex, ey = cycle.eccentricity_x[i] * UM, cycle.eccentricity_y[i] * UM
        ax.plot(ex, ey, "o", color="C0", ms=4, label="journal centre")
        ax.set_aspect("equal")
        ax.set_title(f"{label}: φ = {cycle.crank_angle_deg[i]:.0f}°, h_min = "
                     f"{cycle.h_min[i] * UM:.2f} µm", fontsize=9)
        ax.set_xlabel("x [µm] (film frame)")
        ax.legend(fontsize=7, loc="lower left")
    axes[0].set_ylabel("y [µm]")
    return fig


def _centred(theta_deg: np.ndarray, field: np.ndarray, centre_deg: float):
    """θ shifted to centre ± 180° and the field rolled to match (no split at 0°/360°)."""
    shift = int(np.argmin(np.abs((theta_deg - centre_deg + 180.0) % 360.0 - 180.0)))
    n = len(theta_deg)
    order = (np.arange(n) + shift - n // 2) % n
    unrolled = np.unwrap(np.radians(theta_deg[order]))
    return np.degrees(unrolled), field[order]


def plot_deformed_film_maps(results) -> Figure:
    """Film thickness h [µm] and pressure p [MPa] over θ [deg] and z [mm] on the deformed
    bore at the crank angle of the largest p_max, θ centred on the pressure peak (the
    thickness the run holds at the bore nodes, alike at every z of the 2-D housing)."""
    elastic = results.elastic
    fig = Figure(figsize=(10.0, 4.5))
    axes = fig.subplots(1, 2)
    if elastic.pressure_at_p_max is None or elastic.film_thickness is None:
        axes[0].text(0.5, 0.5, "no pressure field", ha="center")
        return fig
    theta, z = elastic.pressure_grid
    cycle = elastic.cycle
    i = int(np.argmax(cycle.p_max))
    pressure = elastic.pressure_at_p_max
    peak = np.degrees(theta[np.unravel_index(np.argmax(pressure), pressure.shape)[0]])
    if results.deformation_field is not None:  # a bore that deforms along the width
        nodes, thickness_map = np.degrees(theta), results.gap_field(i)
    else:
        nodes = np.degrees(elastic.film_angles[:-1])  # without the closing 360° point
        thickness_map = np.repeat(elastic.film_thickness[i, :-1][:, None], len(z), axis=1)
    for ax, (angles_deg, field, label, cmap) in zip(axes, (
            (nodes, thickness_map * UM, "film thickness h [µm]", "viridis"),
            (np.degrees(theta), pressure * MPA, "pressure p [MPa]", "inferno")), strict=True):
        angles, rolled = _centred(angles_deg, field, peak)
        mesh = ax.pcolormesh(angles, z * 1e3, rolled.T, shading="auto", cmap=cmap)
        fig.colorbar(mesh, ax=ax, label=label)
        ax.set_xlabel("θ [deg] (centred on the pressure peak)")
        ax.set_title(f"{label.split(' [')[0]} at φ = {cycle.crank_angle_deg[i]:.0f}°",
                     fontsize=9)
    axes[0].set_ylabel("z [mm]")
    fig.subplots_adjust(bottom=0.13)  # the axis labels within the canvas
    return fig


def plot_von_mises(results, scheme: str) -> Figure:
    """Rod von Mises stress [MPa] at the largest load, ``scheme`` 'pressure' (elastic film
    pressure on the bore) or 'cosine' (the same resultant as a cosine load), as the run
    computed them (``results.stresses``)."""
    from conrod.plotting.housing_plots import von_mises_figure

    angle = float(results.cycle.crank_angle_deg[results.peak_load_index])
    title = {"pressure": "elastic film pressure", "cosine": "cosine load, same resultant"}
    return von_mises_figure(results.housing.structure, results.stresses[scheme],
                            f"Von Mises at φ = {angle:.0f}° (largest load): {title[scheme]}")
