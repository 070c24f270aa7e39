"""Figures of the loads stage: polar load diagram, load vs crank angle, wear diagram,
and the frames/sign-convention sketch of ``docs/conventions.md``. One function per
figure; each returns a matplotlib Figure (save it with :func:`save_figure`).
"""

from __future__ import annotations

import math
from typing import cast

import numpy as np
from matplotlib.figure import Figure
from matplotlib.projections.polar import PolarAxes

from conrod.loads.diagrams import polar_diagram_points
from conrod.loads.engine_loads import EngineLoads

KN = 1.0e-3


def _label_angles(axes, x: np.ndarray, y: np.ndarray, angle_deg: np.ndarray, every: float,
                  span: float | None = None) -> None:
    """Mark the points at multiples of ``every`` degrees; label those not crowding others
    (closer than 5 % of ``span``, default the extent of the finite points; NaN points are
    not drawn)."""
    marks = np.isclose(np.mod(angle_deg + 1e-9, every), 0.0, atol=1e-6) & np.isfinite(x + y)
    axes.plot(x[marks], y[marks], "o", ms=3, color="k")
    if span is None:
        finite = np.isfinite(x + y)
        span = max(float(np.ptp(x[finite])), float(np.ptp(y[finite]))) if finite.any() else 0.0
    span = max(span, 1e-300)
    placed: list[tuple[float, float]] = [(0.0, 0.0)]  # keep the pole O readable
    for xi, yi, ai in zip(x[marks], y[marks], angle_deg[marks], strict=True):
        if min(math.hypot(xi - px, yi - py) for px, py in placed) < 0.05 * span:
            continue
        placed.append((float(xi), float(yi)))
        axes.annotate(f"{ai:.0f}°", (xi, yi), textcoords="offset points", xytext=(4, 3), fontsize=7)


def plot_polar_load_diagram(loads: EngineLoads) -> Figure:
    """Polar diagram of the rod force S on the crankpin with poles O and O' ([D1])."""
    tangential, outward, pole_shift = polar_diagram_points(
        loads.radial_force, loads.tangential_force, loads.rotating_inertia_force
)
    figure = Figure(figsize=(13.0, 6.5))
    axes, zoom = figure.subplots(1, 2, gridspec_kw={"width_ratios": [1.0, 0.8]})
    axes.plot(
        np.append(tangential, tangential[0]) * KN,
        np.append(outward, outward[0]) * KN,
        lw=1.2,
        color="C0",
        label="tip of S (and of R from O')",
)
    _label_angles(axes, tangential * KN, outward * KN, loads.crank_angle_deg, 30.0)
    _mark_poles(axes, pole_shift)
    axes.axhline(0.0, color="0.7", lw=0.6)
    axes.axvline(0.0, color="0.7", lw=0.6)
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("T, tangential force on the crankpin (+ along rotation) [kN]")
    axes.set_ylabel("radial force of S on the crankpin (+ outward along the crank) [kN]")
    axes.set_title(
        "Polar load diagram of the crankpin (crank frame)\n"
        "O' shifted from O by the rotating-mass force "
        f"K_R = {-loads.rotating_inertia_force * KN:.2f} kN outward",
        fontsize=10,
)
    axes.legend(loc="upper right", fontsize=8)
    axes.grid(True, lw=0.3)
    _zoom_on_low_loads(zoom, tangential * KN, outward * KN, loads.crank_angle_deg, pole_shift)
    return figure


def _mark_poles(axes, pole) -> None:
    """Pole O of the S diagram and pole O' shifted by the rotating-mass force ([D1])."""
    axes.plot(0.0, 0.0, "s", color="C3")
    axes.annotate("O", (0.0, 0.0), xytext=(-12, -4), textcoords="offset points", color="C3")
    axes.plot(pole[0] * KN, pole[1] * KN, "D", color="C2")
    axes.annotate("O'", (pole[0] * KN, pole[1] * KN), xytext=(-14, -10),
                  textcoords="offset points", color="C2")


def _zoom_on_low_loads(axes, x: np.ndarray, y: np.ndarray, angle_deg: np.ndarray, pole) -> None:
    """Zoom on the gas-exchange part of the diagram (1.5 x the median |S|)."""
    radius = np.hypot(x, y)
    extent = 1.5 * float(np.median(radius))
    near = radius <= extent
    axes.plot(np.append(x, x[0]), np.append(y, y[0]), lw=1.0, color="C0")
    _label_angles(axes, np.where(near, x, np.nan), np.where(near, y, np.nan), angle_deg, 30.0,
                  span=2.0 * extent)
    _mark_poles(axes, pole)
    axes.set_xlim(-extent, extent)
    axes.set_ylim(-extent, extent)
    axes.set_aspect("equal")
    axes.set_title("zoom on the low loads", fontsize=10)
    axes.set_xlabel("T [kN]")
    axes.set_ylabel("radial force of S, outward + [kN]")
    axes.grid(True, lw=0.3)


def plot_load_over_crank_angle(loads: EngineLoads) -> Figure:
    """|R|(φ) with its mean, and the components R, T, gas force (unrolled polar diagram)."""
    figure = Figure(figsize=(9.0, 6.0))
    top, bottom = figure.subplots(2, 1, sharex=True)
    angle = loads.crank_angle_deg
    mean = float(np.mean(loads.load_magnitude))
    top.plot(angle, loads.load_magnitude * KN, color="C0", label="|R| resultant on the crankpin")
    top.axhline(mean * KN, color="C3", ls="--", label=f"mean R = {mean * KN:.2f} kN")
    top.set_ylabel("load magnitude [kN]")
    top.legend(fontsize=8)
    bottom.plot(angle, loads.gas_force * KN, color="0.5", lw=0.9, label="gas force P_g")
    bottom.plot(angle, -loads.radial_force * KN, color="C1",
                label="radial −R (+ outward along the crank, as in the polar diagram)")
    bottom.plot(angle, loads.tangential_force * KN, color="C2", label="tangential T (+ rotation)")
    bottom.set_ylabel("force [kN]")
    bottom.set_xlabel("crank angle φ from firing TDC [deg]")
    bottom.legend(fontsize=8, ncol=3)
    for axes in (top, bottom):
        axes.grid(True, lw=0.3)
        axes.set_xticks(np.arange(0, 721, 90))
        axes.set_xlim(0.0, 720.0)
    figure.suptitle("Big-end bearing load over the cycle")
    return figure


def plot_wear_diagram(loads: EngineLoads) -> Figure:
    """Journal wear diagram ([D1]) in the crank frame with the oil-hole direction."""
    angle, wear = loads.wear()
    hole = loads.oil_hole_angle()
    figure = Figure(figsize=(6.5, 6.5))
    axes = cast(PolarAxes, figure.add_subplot(projection="polar"))
    axes.set_theta_zero_location("N")  # outward crank radius drawn upwards
    axes.set_theta_direction(1)  # counter-clockwise = direction of rotation
    relative = wear / max(float(wear.max()), 1e-300)
    radius = 1.0 + 0.6 * relative
    axes.fill_between(
        np.append(angle, angle[0]),
        1.0,
        np.append(radius, radius[0]),
        color="C0",
        alpha=0.5,
        label="wear strips (∝ load, ±60°)",
)
    axes.plot(np.linspace(0, 2 * math.pi, 361), np.ones(361), color="k", lw=1.0)
    axes.annotate(
        "",
        xy=(hole, 1.7),
        xytext=(hole, 0.0),
        arrowprops={"arrowstyle": "->", "color": "C3", "lw": 1.5},
)
    axes.set_rmax(1.75)
    axes.set_yticks([])
    axes.set_title(
        "Crankpin wear diagram (journal, crank frame)\n0° = outward crank radius, angles along "
        f"rotation; oil hole at {math.degrees(hole):.1f}°",
        fontsize=10,
)
    axes.legend(loc="lower left", fontsize=8, bbox_to_anchor=(-0.1, -0.1))
    return figure


def plot_conventions() -> Figure:
    """Sketch of the engine, crank and rod frames, angles and force signs (for the docs)."""
    phi, lam, r = math.radians(50.0), 0.3, 1.0
    length = r / lam
    beta = math.asin(lam * math.sin(phi))
    pin = np.array([r * math.cos(phi), r * math.sin(phi)])
    small = np.array([r * math.cos(phi) + length * math.cos(beta), 0.0])
    figure = Figure(figsize=(8.0, 8.0))
    axes = figure.add_subplot()
    axes.plot([0, pin[0]], [0, pin[1]], color="k", lw=3)
    axes.plot([pin[0], small[0]], [pin[1], small[1]], color="0.4", lw=6, alpha=0.6)
    axes.add_patch(_circle(pin, 0.35, "C0"))
    axes.add_patch(_circle((0.0, 0.0), 1.0, "0.8", fill=False))
    axes.plot([small[0] - 0.6, small[0] + 0.9], [0.45, 0.45], color="k")
    axes.plot([small[0] - 0.6, small[0] + 0.9], [-0.45, -0.45], color="k")
    axes.add_patch(_piston(small))
    _arrow(axes, (0, 0), (4.6, 0), "X (engine), towards TDC", "k")
    _arrow(axes, (0, 0), (0, 1.8), "Y (engine)", "k")
    u = (small - pin) / length
    v = np.array([-u[1], u[0]])
    _arrow(axes, pin, pin + 1.2 * u, "x rod (to small end)", "C0")
    _arrow(axes, pin, pin + 1.2 * v, "y rod = z × x", "C0")
    e_r = pin / r
    _arrow(axes, pin, pin + 0.9 * e_r, "x crank (outward)", "C2")
    _arrow(axes, pin, pin + 0.9 * np.array([-e_r[1], e_r[0]]), "y crank\n(rotation)", "C2")
    _crank_angle_arc(axes, phi)
    axes.annotate("β (sin β = λ sin φ);\nrod orientation is −β", (1.3, -0.85), fontsize=9)
    axes.annotate("θ on the shell: from x rod towards y rod", (1.0, 1.75), fontsize=9, color="C0")
    _arrow(
        axes,
        small + np.array([0.3, 0.8]),
        small + np.array([-0.5, 0.8]),
        "P_g, P_Σ > 0 towards the crank",
        "C3",
)
    axes.annotate(
        "φ: crank angle from firing TDC, CCW (= rotation) positive\n"
        "S > 0: rod in compression;  R > 0 towards the crank axis;  T > 0 along rotation\n"
        "W (load on the journal, film frame) = −(force of the rod on the crankpin)",
        (-1.5, -1.75),
        fontsize=9,
)
    axes.set_aspect("equal")
    axes.set_xlim(-1.6, 5.2)
    axes.set_ylim(-1.8, 2.2)
    axes.axis("off")
    axes.set_title("conrod frames and signs (crank at φ = 50°, λ = 0.3)")
    return figure


def _crank_angle_arc(axes, phi: float) -> None:
    arc = np.linspace(0.0, phi, 30)
    axes.plot(0.45 * np.cos(arc), 0.45 * np.sin(arc), color="k", lw=0.8)
    axes.annotate("φ", (0.5 * math.cos(phi / 2), 0.5 * math.sin(phi / 2)), fontsize=11)


def _piston(small):
    from matplotlib.patches import Rectangle

    return Rectangle((small[0] - 0.25, -0.42), 0.7, 0.84, color="0.6", alpha=0.5)


def _circle(centre, radius: float, color: str, fill: bool = True):
    from matplotlib.patches import Circle

    return Circle(tuple(centre), radius, color=color, fill=fill, alpha=0.35 if fill else 1.0)


def _arrow(axes, start, end, label: str, color: str) -> None:
    axes.annotate(
        "",
        xy=tuple(end),
        xytext=tuple(start),
        arrowprops={"arrowstyle": "->", "color": color, "lw": 1.5},
)
    axes.annotate(
        label, tuple(end), fontsize=8, color=color, xytext=(3, 3), textcoords="offset points"
)


def plot_table_load_polar(loads) -> Figure:
    """Polar load diagram of a load table in the bearing (film) frame: the tip of the load
    vector pressing the journal on the shell [kN], labelled by crank angle."""
    x, y = loads.load_x * KN, loads.load_y * KN
    angle = np.degrees(loads.crank_angle)
    figure = Figure(figsize=(6.5, 6.5))
    axes = figure.subplots()
    axes.plot(np.append(x, x[0]), np.append(y, y[0]), lw=1.2, color="C0",
              label="tip of the load on the shell")
    axes.plot(0.0, 0.0, "s", color="C3")
    marks = np.arange(np.ceil(angle[0] / 30.0) * 30.0, angle[-1] + 1e-9, 30.0) + 0.0  # no -0
    _label_angles(axes, np.interp(marks, angle, x), np.interp(marks, angle, y), marks, 30.0,
                  span=max(float(np.ptp(x)), float(np.ptp(y))))
    axes.axhline(0.0, color="0.7", lw=0.6)
    axes.axvline(0.0, color="0.7", lw=0.6)
    axes.set_aspect("equal", adjustable="datalim")
    axes.set_xlabel("F_x, bearing (film) frame [kN]")
    axes.set_ylabel("F_y [kN]")
    axes.set_title("Polar load diagram (bearing frame, from the load table)", fontsize=10)
    axes.legend(loc="upper right", fontsize=8)
    axes.grid(True, lw=0.3)
    return figure


def plot_table_load_over_crank_angle(loads) -> Figure:
    """Load components and magnitude [kN] of a load table against crank angle [deg]."""
    angle = np.degrees(loads.crank_angle)
    figure = Figure(figsize=(9.0, 4.5))
    axes = figure.subplots()
    axes.plot(angle, np.hypot(loads.load_x, loads.load_y) * KN, color="C0", label="|F|")
    axes.plot(angle, loads.load_x * KN, color="C1", label="F_x (bearing frame)")
    axes.plot(angle, loads.load_y * KN, color="C2", label="F_y (bearing frame)")
    axes.set_xlabel("crank angle φ [deg]")
    axes.set_ylabel("load [kN]")
    axes.legend(fontsize=8)
    axes.grid(True, lw=0.3)
    figure.subplots_adjust(bottom=0.13)  # the axis label within the canvas
    return figure
