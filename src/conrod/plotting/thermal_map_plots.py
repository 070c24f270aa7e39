"""Small multiples of the film temperature maps at chosen crank angles of a thermal film
run, drawn from :class:`conrod.results.thermal_maps.ThermalMapsResults`."""

from __future__ import annotations

import math

import numpy as np
from matplotlib.figure import Figure

from conrod.plotting.save import fitting_layout


def plot_temperature_maps(maps) -> Figure:
    """T(θ, z) [°C] over shell angle θ [deg] and axial position z [mm] per crank angle, on
    the unrolled shell, one shared colour scale, the hottest point of each marked."""
    count = maps.crank_angle_deg.size
    columns = min(count, 3)
    rows = math.ceil(count / columns)
    fig = Figure(figsize=(4.2 * columns + 1.2, 2.6 * rows + 0.8), layout=fitting_layout())
    axes = np.atleast_1d(fig.subplots(rows, columns, sharex=True, sharey=True, squeeze=False)
                         ).ravel()
    low, high = float(maps.temperature.min()), float(maps.temperature.max())
    theta = np.degrees(np.append(maps.theta, maps.theta[0] + 2 * np.pi))
    z = maps.z * 1e3
    for k, ax in enumerate(axes[:count]):
        field = np.vstack([maps.temperature[k], maps.temperature[k][:1]])
        mesh = ax.pcolormesh(theta, z, field.T, shading="gouraud", cmap="inferno",
                             vmin=low, vmax=high)
        t, at_theta, at_z = maps.hottest(k)
        ax.plot(math.degrees(at_theta), at_z * 1e3, "c+", markersize=10)
        ax.set_title(f"φ = {maps.crank_angle_deg[k]:.0f}°: max {t:.1f} °C at "
                     f"θ = {math.degrees(at_theta):.0f}°", fontsize=9)
    for ax in axes[count:]:
        ax.set_visible(False)
    for ax in axes[(rows - 1) * columns:]:
        ax.set_xlabel("shell angle θ [deg]")
    for ax in axes[::columns]:
        ax.set_ylabel("z [mm]")
    fig.colorbar(mesh, ax=list(axes[:count]), label="film temperature [°C]")
    fig.suptitle(f"walls held at journal {maps.journal_temperature:.1f} °C, shell "
                 f"{maps.shell_temperature:.1f} °C (cycle means)", fontsize=10)
    return fig
