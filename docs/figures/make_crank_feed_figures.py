"""Figures of the crank-pin oil feed (docs/conventions.md, docs/film.md).

Run from the repository root:

    python docs/figures/make_crank_feed_figures.py [STUDY_CSV ...]

* ``crank_pin_hole_frames.png``: engine, crank and rod frames, the hole at angle α on the
  pin (from the outward crank radius) and its shell angle θ = α + φ + β; beside it θ over
  the cycle for the passenger-car crank (λ = 0.33) from conrod's own feed schedule.
* ``pin_hole_angle_study.png`` (given the tables of
  ``examples/studies/passenger_car_pin_hole_angle.py``, kept in docs/figures/data/): h_min,
  p_max, hole flow and starvation against the hole angle, the wear diagram's angle marked.
"""

from __future__ import annotations

import csv
import math
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from conrod.cases.case import Case  # noqa: E402
from conrod.loads.engine_loads import compute_engine_loads  # noqa: E402
from conrod.loads.oil_feed import journal_turn  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm_crank_fed.toml"
OUT = ROOT / "docs" / "figures"


def _arrow(ax, start, end, text, color="k", offset=(0.0, 0.0)):
    ax.annotate("", xy=end, xytext=start,
                arrowprops={"arrowstyle": "->", "color": color, "lw": 1.4})
    ax.text(end[0] + offset[0], end[1] + offset[1], text, color=color, fontsize=10)


def frames_figure() -> None:
    """Frames and the hole's shell angle (left), θ(φ) over the cycle (right)."""
    phi, alpha, lam = math.radians(50.0), math.radians(60.0), 0.33
    beta = math.asin(lam * math.sin(phi))
    r, pin = 1.0, 0.45
    rod = r / lam  # the small end on the cylinder axis
    centre = np.array([r * math.cos(phi), r * math.sin(phi)])
    fig, (ax, right) = plt.subplots(1, 2, figsize=(11.5, 5.2),
                                    gridspec_kw={"width_ratios": [1.1, 1.0]})
    # engine frame: X towards TDC drawn upwards -> plot (Y, X) as (−x, y) so that the
    # crank turns counter-clockwise seen from the front
    def to_plot(v):
        return np.array([-v[1], v[0]])

    origin = np.zeros(2)
    _arrow(ax, to_plot(origin), to_plot(np.array([0.9, 0.0])), "X (TDC)", "0.4", (0.05, 0.0))
    ax.plot(*to_plot(centre), "ko", ms=3)
    ax.plot([0, to_plot(centre)[0]], [0, to_plot(centre)[1]], "k-", lw=2)
    t = np.linspace(0, 2 * math.pi, 200)
    circle = centre[:, None] + pin * np.vstack([np.cos(t), np.sin(t)])
    ax.plot(*np.array([to_plot(c) for c in circle.T]).T, "k-", lw=1)
    # crank frame at the pin: x_crank outward
    x_crank = np.array([math.cos(phi), math.sin(phi)])
    _arrow(ax, to_plot(centre), to_plot(centre + 0.9 * x_crank), "x_crank", "tab:blue",
           (-0.5, 0.05))
    # rod frame: x_rod towards the small end = (cos β, −sin β)
    x_rod = np.array([math.cos(beta), -math.sin(beta)])
    small_end = centre + rod * x_rod
    ax.plot([to_plot(centre)[0], to_plot(small_end)[0]],
            [to_plot(centre)[1], to_plot(small_end)[1]], "-", color="tab:green", lw=3,
            alpha=0.35)
    _arrow(ax, to_plot(centre), to_plot(centre + 0.9 * x_rod), "x_rod (θ = 0)", "tab:green",
           (-0.55, 0.08))
    hole_dir = np.array([math.cos(phi + alpha), math.sin(phi + alpha)])
    hole = centre + pin * hole_dir
    ax.plot(*to_plot(hole), "o", color="tab:red", ms=9)
    ax.text(*(to_plot(hole) + np.array([0.1, -0.12])), "oil hole", color="tab:red")
    for start, extent, radius, label, color in (
            (phi, alpha, 0.3, "α", "tab:red"), (-beta, phi + alpha + beta, 0.75,
                                                "θ = α + φ + β", "tab:green")):  # noqa: RUF001
        arc = np.linspace(start, start + extent, 60)
        points = centre[:, None] + radius * np.vstack([np.cos(arc), np.sin(arc)])
        ax.plot(*np.array([to_plot(p) for p in points.T]).T, "-", color=color, lw=1.2)
        at = start + (0.5 if label == "α" else 1.0) * extent
        end = centre + (radius + 0.1) * np.array([math.cos(at), math.sin(at)])
        ax.text(*(to_plot(end) + np.array([-0.15 * len(label) / 3, -0.18])), label,
                color=color, fontsize=10)
    arc = np.linspace(0.0, phi, 40)
    ax.plot(*np.array([to_plot(0.35 * np.array([math.cos(a), math.sin(a)]))
                       for a in arc]).T, "k-", lw=1)
    ax.text(*to_plot(0.42 * np.array([math.cos(0.5 * phi), math.sin(0.5 * phi)])), "φ")
    ax.set_aspect("equal")
    ax.set_xlim(-2.2, 1.2)
    ax.set_ylim(-0.6, 3.6)
    ax.axis("off")
    ax.set_title("crank pin hole: angle α on the pin, θ on the shell\n"
                 "(seen from the front, crank turning counter-clockwise)", fontsize=10)
    case = Case.from_toml(CASE)
    loads = compute_engine_loads(case).to_load_cycle()
    angles, turned = journal_turn(loads)
    degrees = np.degrees(angles)
    right.plot(degrees, np.degrees(turned), label="ψ(φ) = ∫(ω_j − ω_b)/ω dφ (conrod)")
    right.plot(degrees, degrees, "k--", lw=0.8, label="φ (a hole turning with the crank "
               "in a fixed shell)")
    right.plot(degrees, 20 * np.degrees(turned - angles), color="tab:green",
               label="20 × (ψ − φ) = 20 β")
    right.set_xlabel("crank angle φ [deg]")
    right.set_ylabel("journal turn ψ in the rod (film) frame [deg]")
    right.set_xlim(0, 720)
    right.grid(alpha=0.3)
    right.legend(fontsize=8, loc="upper left")
    right.set_title("the hole's shell angle θ = α + ψ(φ), passenger-car crank λ = 0.33",
                    fontsize=10)
    fig.tight_layout()
    fig.savefig(OUT / "crank_pin_hole_frames.png", dpi=110)
    plt.close(fig)


def _read(table: Path) -> tuple[str, list[dict]]:
    """(film name from the file name, rows) of a study table."""
    with open(table) as handle:
        rows = list(csv.DictReader(handle))
    return table.stem.removeprefix("pin_hole_angle_").replace("_", "-"), rows


def study_figure(tables: list[Path]) -> None:
    """The pin-hole angle study against the hole angle (one line per film), the wear
    diagram's angle marked."""
    panels = (("h_min_m", 1e6, "film h_min over the cycle [µm]"),
              ("p_max_Pa", 1e-6, "p_max over the cycle [MPa]"),
              ("journal_hole_flow_mean_m3_s", 6e4, "mean flow through the hole [l/min]"),
              ("inlet_film_fraction_min", 1.0, "smallest film fraction at the load zone's "
               "inlet [-]"))
    fig, axes = plt.subplots(2, 2, figsize=(10.5, 7), sharex=True)
    for table in tables:
        film, rows = _read(table)
        angle = np.array([float(r["hole_angle_deg"]) for r in rows])
        for ax, (name, scale, label) in zip(axes.flat, panels, strict=True):
            values = np.array([float(r[name]) * scale for r in rows])
            if np.all(np.isnan(values)):
                continue
            ax.plot(angle, values, "o-", ms=4, label=f"{film} film")
            ax.set_ylabel(label, fontsize=9)
        wear = [float(r["hole_angle_deg"]) for r in rows if r["wear_diagram"] == "1"]
    for ax in axes.flat:
        for value in wear:
            ax.axvline(value, color="tab:red", ls="--", lw=1)
        ax.grid(alpha=0.3)
        ax.set_xticks(np.arange(0, 361, 60))
    axes[1, 1].axhline(0.9, color="0.5", lw=0.8)
    axes[0, 0].legend(fontsize=8)
    for ax in axes[1]:
        ax.set_xlabel("hole angle on the pin from the outward crank radius [deg]")
    fig.suptitle("Passenger-car big end, 2000 rpm, 3 bar gallery: where to drill the crank-pin "
                 "oil hole\n(red dashed: the wear diagram's least-worn angle; grey: the "
                 "starvation limit 0.9)", fontsize=10)
    fig.tight_layout()
    fig.savefig(OUT / "pin_hole_angle_study.png", dpi=110)
    plt.close(fig)


if __name__ == "__main__":
    frames_figure()
    if len(sys.argv) > 1:
        study_figure([Path(name) for name in sys.argv[1:]])
