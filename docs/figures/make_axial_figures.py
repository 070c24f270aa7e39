"""Figures of docs/conventions.md (journal tilt) and docs/film.md (bore profiles).

Run from the repository root:  python docs/figures/make_axial_figures.py
Writes docs/figures/tilt_convention.png and docs/figures/bore_profiles.png from the film
code itself (conrod.film.tilt, conrod.film.profile), so the pictures show what is computed.
"""

from __future__ import annotations

import math
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from conrod.film.base import BearingGeometry, FilmState  # noqa: E402
from conrod.film.profile import BoreProfile  # noqa: E402
from conrod.film.reynolds.film import ReynoldsFilm  # noqa: E402

HERE = Path(__file__).resolve().parent


def tilt_convention() -> None:
    """Side views of a tilted journal (γ_y > 0 in the x–z plane, γ_x > 0 in the y–z plane)
    and the film thickness and pressure of a centred journal tilted about x."""
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2))
    width, gap = 1.0, 0.25
    z = np.linspace(-0.5 * width, 0.5 * width, 5)
    for ax, (label, axis, offset) in zip(axes[:2], (
            ("x–z plane: tilt γ_y > 0 moves the axis at +z towards +x", "x", 1.0),
            ("y–z plane: tilt γ_x > 0 moves the axis at +z towards −y", "y", -1.0)),
            strict=True):
        ax.axhline(gap, color="0.4", lw=3)
        ax.axhline(-gap, color="0.4", lw=3)
        tilt = 0.08
        ax.plot(z, offset * tilt * z, "C0", lw=2, label="journal axis")
        ax.plot(z, offset * tilt * z + 0.75 * gap, "C0--", lw=1)
        ax.plot(z, offset * tilt * z - 0.75 * gap, "C0--", lw=1)
        ax.annotate("", xy=(0.5, 0.0), xytext=(-0.5, 0.0),
                    arrowprops={"arrowstyle": "->", "color": "k"})
        ax.text(0.52, 0.01, "z", fontsize=11)
        ax.annotate("", xy=(0.0, 0.45), xytext=(0.0, -0.45),
                    arrowprops={"arrowstyle": "->", "color": "k"})
        ax.text(0.02, 0.42, axis, fontsize=11)
        ax.set_title(label, fontsize=9)
        ax.set_xlim(-0.6, 0.6)
        ax.set_ylim(-0.5, 0.5)
        ax.set_xticks([-0.5, 0.0, 0.5], ["−L/2", "0", "+L/2"])
        ax.set_yticks([])
        ax.text(-0.55, gap + 0.03, "shell", fontsize=8)
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6)
    film = ReynoldsFilm(geometry, 72, 16)
    tilt = 0.5 * 25e-6 / 0.0125
    result = film.solve(FilmState(eccentricity_x=0.0, eccentricity_y=0.0, journal_speed=300.0,
                                  viscosity=0.01, tilt_x=tilt), with_pressure=True)
    theta, z = film.grid()
    image = axes[2].pcolormesh(np.degrees(theta), z * 1e3, result.pressure.T / 1e6,
                               shading="auto", cmap="viridis")
    fig.colorbar(image, ax=axes[2], label="p [MPa]")
    axes[2].set_xlabel("θ [deg] (shell, from +x towards +y)")
    axes[2].set_ylabel("z [mm]")
    axes[2].set_title(f"centred journal, γ_x = {tilt * 1e3:.1f} mrad: M_x = "
                      f"{result.moment_x:.2f} N m, M_y = {result.moment_y:.2f} N m,\n"
                      f"|F| = {math.hypot(result.force_x, result.force_y):.1e} N", fontsize=8)
    fig.suptitle("Journal tilt: h = c − (e_x + zγ_y) cos θ − (e_y − zγ_x) sin θ + h₀ + δ; "
                 "right-handed rotations about the film's x and y axes")
    fig.tight_layout()
    fig.savefig(HERE / "tilt_convention.png", dpi=110)


def bore_profiles() -> None:
    """h₀(θ) and h₀(z) of the parametric shapes."""
    c, width = 25e-6, 0.025
    theta = np.linspace(0.0, 2.0 * math.pi, 721)
    z = np.linspace(-0.5 * width, 0.5 * width, 201)
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4))
    for label, profile in (
            ("crush relief 10 µm, 20° (joints ±90°)",
             BoreProfile(crush_relief_depth=10e-6, crush_relief_extent=math.radians(20))),
            ("elliptical, preload 0.5", BoreProfile(preload=0.5)),
            ("offset halves 8 µm", BoreProfile(offset_halves=8e-6))):
        left.plot(np.degrees(theta), profile.field(theta, z[:1], c, width)[:, 0] * 1e6,
                  label=label)
    left.set_xlabel("θ [deg] (film frame; joints of a big end at 90° and 270°)")
    left.set_ylabel("h₀ [µm] (+ = more clearance)")
    left.legend(fontsize=8)
    for label, profile in (("end relief 6 µm over 3 mm",
                            BoreProfile(end_relief_depth=6e-6, end_relief_length=0.003)),
                           ("taper 4 µm", BoreProfile(taper=4e-6)),
                           ("crown 3 µm", BoreProfile(crown=3e-6))):
        right.plot(z * 1e3, profile.field(theta[:1], z, c, width)[0] * 1e6, label=label)
    right.set_xlabel("z [mm] (from mid-width)")
    right.set_ylabel("h₀ [µm]")
    right.legend(fontsize=8)
    fig.suptitle(f"Bore and shell profiles (c = {c * 1e6:.0f} µm, L = {width * 1e3:.0f} mm), "
                 "fixed in the bearing frame")
    fig.tight_layout()
    fig.savefig(HERE / "bore_profiles.png", dpi=110)


if __name__ == "__main__":
    tilt_convention()
    bore_profiles()
