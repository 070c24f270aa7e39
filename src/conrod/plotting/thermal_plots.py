"""The film temperature map of a thermal film run, drawn from
:class:`conrod.results.thermal.ThermalFilmResults`."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure


def plot_temperature_map(thermal) -> Figure:
    """T(θ, z) [°C] over shell angle θ [deg] and axial position z [mm], hottest point
    marked; walls and heat flows in the title."""
    fig = Figure(figsize=(8.0, 4.2))
    ax = fig.add_subplot()
    theta = np.degrees(np.append(thermal.theta, thermal.theta[0] + 2 * np.pi))
    field = np.vstack([thermal.temperature, thermal.temperature[:1]])
    mesh = ax.pcolormesh(theta, thermal.z * 1e3, field.T, shading="gouraud", cmap="inferno")
    fig.colorbar(mesh, ax=ax, label="film temperature [°C]")
    t, at_theta, at_z = thermal.hottest
    ax.plot(np.degrees(at_theta), at_z * 1e3, "c+", markersize=12)
    below = -14 if at_z > 0.0 else 6  # inside the axes
    ax.annotate(f"{t:.1f} °C", (np.degrees(at_theta), at_z * 1e3), color="c",
                xytext=(6, below), textcoords="offset points")
    ax.set_xlabel("shell angle θ [deg]")
    ax.set_ylabel("z [mm]")
    ax.set_title(f"journal {thermal.journal_temperature:.1f} °C, shell "
                 f"{thermal.shell_temperature:.1f} °C; heat {thermal.generated:.0f} W → oil "
                 f"{thermal.to_oil:.0f}, journal {thermal.to_journal:.0f}, shell "
                 f"{thermal.to_shell:.0f} W", fontsize=9)
    return fig
