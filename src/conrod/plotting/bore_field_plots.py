"""The bore of a housing that deforms along the width (a 3-D compliance):
:func:`plot_bore_field` draws u(θ, z) and the film thickness across the width from
:class:`conrod.results.ehd.ElasticRunResults` (``deformation_field``, ``gap_field``,
``mean_gap``)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from conrod.plotting.save import fitting_layout

UM, MM = 1e6, 1e3


def plot_bore_field(results) -> Figure:
    """Corrected radial bore displacement u(θ, z) [µm] over the shell angle θ [deg] and the
    axial position z [mm] at the largest load and at the smallest h_min — whole, and less
    its width-mean ū(θ) (the part that varies along the width) — and across the width at
    the angle of the smallest film: h(z) [µm] on the bore deformed along the width against
    h(z) on the bore deformed by its width-mean (what a plane housing of the same mean
    deformation would give). The profile holds the film nodes' values; the h_min of
    cycle.csv is refined between nodes by a parabola in θ."""
    cycle = results.cycle
    rows = {"largest load": results.peak_load_index,
            "smallest h_min": int(np.argmin(cycle.h_min))}
    theta_deg = np.degrees(results.bore_angles)
    z_mm = results.axial_positions * MM
    fig = Figure(figsize=(15.0, 7.5), layout=fitting_layout())
    axes = fig.subplot_mosaic([["whole 0", "along 0", "profile"],
                               ["whole 1", "along 1", "profile"]],
                              width_ratios=(1.0, 1.0, 0.75))
    whole = [results.deformation_field[i] * UM for i in rows.values()]
    along = [field - results.deformation[i][:, None] * UM
             for field, i in zip(whole, rows.values(), strict=True)]
    for key, fields, label in (("whole", whole, "u [µm] (outward +)"),
                               ("along", along, "u − ū(θ) [µm]: along the width")):
        limit = max(float(np.max(np.abs(field))) for field in fields) or 1.0
        for k, ((name, i), field) in enumerate(zip(rows.items(), fields, strict=True)):
            ax = axes[f"{key} {k}"]
            mesh = ax.pcolormesh(theta_deg, z_mm, field.T, shading="auto", cmap="RdBu_r",
                                 vmin=-limit, vmax=limit)
            ax.set_title(f"{name}: φ = {cycle.crank_angle_deg[i]:.0f}°, "
                         f"h_min = {cycle.h_min[i] * UM:.2f} µm", fontsize=9)
            ax.set_xlabel("θ [deg] (film frame)")
            ax.set_ylabel("z [mm] from the mid-plane")
        fig.colorbar(mesh, ax=[axes[f"{key} 0"], axes[f"{key} 1"]], label=label,
                     shrink=0.8)
    _width_profile(axes["profile"], results, rows["smallest h_min"], z_mm)
    return fig


def _width_profile(ax, results, index: int, z_mm: np.ndarray) -> None:
    gap = results.gap_field(index)
    row = int(np.argmin(gap.min(axis=1)))
    cycle, theta = results.cycle, results.bore_angles[row]
    mean = results.mean_gap(index)[row]
    ax.plot(z_mm, gap[row] * UM, "o-", color="C3", ms=3,
            label="bore deformed along the width (film nodes)")
    ax.plot(z_mm, np.full(len(z_mm), mean * UM), "--", color="C0",
            label="bore deformed by its width-mean")
    for end in (0, -1):
        ax.annotate(f"{gap[row, end] * UM:.2f}", (z_mm[end], gap[row, end] * UM),
                    textcoords="offset points", xytext=(0, 6), ha="center", fontsize=7)
    ax.set_xlabel("z [mm] from the mid-plane")
    ax.set_ylabel("film thickness h [µm]")
    ax.set_title(f"across the width at θ = {np.degrees(theta):.0f}° "
                 f"(φ = {cycle.crank_angle_deg[index]:.0f}°)", fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
