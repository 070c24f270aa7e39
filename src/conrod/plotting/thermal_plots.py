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
    fig.subplots_adjust(bottom=0.14)  # the axis label within the canvas
    return fig


def plot_warm_bore(thermal) -> Figure:
    """The bore warm from the film (:class:`conrod.results.thermal.FilmWarmBore`): the
    shell-side temperature T_b(θ) [°C] beside the film's axial mean, and the thermal bore
    profile h₀(θ) [µm] over shell angle θ [deg]."""
    warm = thermal.warm_bore
    fig = Figure(figsize=(8.0, 5.2))
    top, bottom = fig.subplots(2, 1, sharex=True)
    theta = np.degrees(np.append(warm.angles, 2 * np.pi))
    weights = np.ones(thermal.z.size)
    weights[[0, -1]] = 0.5
    film = thermal.temperature @ weights / weights.sum()
    top.plot(np.degrees(np.append(thermal.theta, 2 * np.pi)), np.append(film, film[0]),
             color="tab:orange", label="film, axial mean T̄(θ)")
    shell = np.append(warm.shell_side_temperature, warm.shell_side_temperature[0])
    top.plot(theta, shell, color="tab:red", label="shell side T_b(θ)")
    top.axhline(warm.journal_temperature, color="tab:blue", ls="--", label="journal")
    top.set_ylabel("temperature [°C]")
    top.legend(fontsize=8)
    if warm.profile is not None:
        bottom.plot(theta, np.append(warm.profile, warm.profile[0]) * 1e6, color="k")
        bottom.set_ylabel("thermal bore profile h₀ [µm]")
    else:
        bottom.text(0.5, 0.5, "rigid bore: round (clearance change only)", ha="center",
                    transform=bottom.transAxes)
    bottom.set_xlabel("shell angle θ [deg]")
    shape = "" if warm.out_of_round is None else (
        f", thermal out-of-round {warm.out_of_round * 1e6:.2f} µm")
    top.set_title(f"bore warm from the film: clearance {warm.clearance_change * 1e6:+.2f} µm"
                  f"{shape}, housing {warm.housing_temperature:.1f} °C", fontsize=9)
    return fig
