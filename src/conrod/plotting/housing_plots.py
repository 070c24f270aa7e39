"""Figures of the elastic housing: the mesh, the deformed bore under unit cosine loads
(raw and rigid-body corrected), the inertia deformation at TDC and BDC, and von Mises maps.
One function per figure; each returns a matplotlib Figure."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.tri import Triangulation

from conrod.housing.stresses import StressField

MICRO = 1.0e6


def _triangulation(structure) -> Triangulation:
    mesh = structure.model.fe_mesh.mesh
    corners = mesh.doflocs[:, : int(mesh.t.max()) + 1]
    return Triangulation(corners[0], corners[1], mesh.t.T)


def housing_mesh_figure(structure) -> Figure:
    """The FE mesh (corner nodes) with the big-end bore and the clamped nodes highlighted."""
    figure = Figure(figsize=(11.0, 4.6))
    axes = figure.subplots()
    axes.triplot(_triangulation(structure), lw=0.3, color="0.55")
    mesh = structure.model.fe_mesh.mesh
    bore = mesh.facets[:, structure.model.fe_mesh.boundaries["big_end_bore"]]
    for a, b in bore.T:
        axes.plot(mesh.doflocs[0, [a, b]], mesh.doflocs[1, [a, b]], color="tab:red", lw=1.6)
    clamp = structure.model.basis.doflocs[:, structure.model.clamp_dofs]
    axes.plot(clamp[0], clamp[1], ".", ms=2.5, color="tab:blue", label="clamped nodes")
    axes.plot([], [], color="tab:red", label="big-end bore (film nodes)")
    axes.set_aspect("equal")
    axes.set_xlabel("x_rod (towards the small end) [m]")
    axes.set_ylabel("y_rod [m]")
    n_el, n_dof = mesh.t.shape[1], structure.model.n_dofs
    axes.set_title(f"Housing mesh: {n_el} six-node triangles, {n_dof} unknowns")
    axes.legend(loc="upper right", fontsize=8)
    figure.subplots_adjust(bottom=0.13)  # the axis label within the canvas
    return figure


def _bore_outline(axes, angles, radius, displacement, scale, **style) -> None:
    closed = np.append(angles, angles[0])
    r = radius + scale * np.append(displacement, displacement[0])
    axes.plot(r * np.cos(closed), r * np.sin(closed), **style)


def _magnification(radius: float, fields: list[np.ndarray]) -> float:
    """Scale that draws the largest |u| as 15 % of the radius [-] (rounded)."""
    largest = max(max(float(np.abs(f).max()) for f in fields), 1e-30)
    scale = 0.15 * radius / largest
    return float(10 ** np.floor(np.log10(scale)) * (5 if scale / 10 ** np.floor(
        np.log10(scale)) >= 5 else 2 if scale / 10 ** np.floor(np.log10(scale)) >= 2 else 1))


def bore_deformation_figure(results) -> Figure:
    """Magnified bore under the cosine test loads (±90°) of a housing study
    (:class:`conrod.results.housing.HousingResults`): raw (clamped model) and rigid-body
    corrected, each with its own scale."""
    housing = results.housing
    figure = Figure(figsize=(10.0, 10.0))
    panels = figure.subplots(2, 2).ravel()
    raw_scale = _magnification(housing.radius, [case.raw for case in results.bore])
    corrected_scale = _magnification(housing.radius, [case.corrected for case in results.bore])
    for axes, case in zip(panels, results.bore, strict=True):
        _bore_outline(axes, housing.angles, housing.radius, np.zeros_like(case.raw), 0.0,
                      color="0.7", lw=1.0, label="undeformed")
        _bore_outline(axes, housing.angles, housing.radius, case.raw, raw_scale,
                      color="tab:orange", label=f"raw (clamped) × {raw_scale:.0f}")
        _bore_outline(axes, housing.angles, housing.radius, case.corrected, corrected_scale,
                      color="tab:blue", label=f"corrected ({housing.correction}) × "
                      f"{corrected_scale:.0f}")
        theta = case.direction
        axes.annotate("", xy=(0.6 * housing.radius * np.cos(theta),
                              0.6 * housing.radius * np.sin(theta)), xytext=(0, 0),
                      arrowprops={"arrowstyle": "->", "color": "k"})
        axes.set_aspect("equal")
        axes.set_title(f"{case.label}: corrected range "
                       f"{np.ptp(case.corrected) * MICRO:.1f} µm", fontsize=9)
        axes.set_xticks([])
        axes.set_yticks([])
    panels[0].legend(fontsize=7, loc="lower left")
    figure.suptitle(f"Bore under a {results.test_load / 1e3:.0f} kN cosine load (±90°); "
                    "x_rod to the right, towards the small end")
    return figure


def inertia_deformation_figure(results) -> Figure:
    """Radial bore displacement from the rod's own inertia at TDC and BDC, raw and
    corrected, against θ (:class:`conrod.results.housing.HousingResults`)."""
    figure = Figure(figsize=(9.0, 4.5))
    axes = figure.subplots()
    theta_deg = np.degrees(results.housing.angles)
    for case, color in zip(results.inertia, ("tab:red", "tab:blue"), strict=False):
        axes.plot(theta_deg, case.raw * MICRO, "--", color=color, label=f"{case.label} raw")
        axes.plot(theta_deg, case.corrected * MICRO, color=color,
                  label=f"{case.label} corrected")
    axes.set_xlabel("shell angle θ [deg] (0 = towards the small end)")
    axes.set_ylabel("radial displacement, outward + [µm]")
    axes.set_xlim(0, 360)
    axes.grid(alpha=0.3)
    axes.legend(fontsize=8)
    axes.set_title("Inertia deformation of the bore (superposition of base fields)")
    figure.subplots_adjust(bottom=0.13)  # the axis label within the canvas
    return figure


def von_mises_figure(structure, field: StressField, title: str) -> Figure:
    """Von Mises stress per element [MPa] with the maximum marked."""
    figure = Figure(figsize=(11.0, 4.6))
    axes = figure.subplots()
    image = axes.tripcolor(_triangulation(structure), facecolors=field.von_mises / 1e6,
                           cmap="inferno", shading="flat")
    x, y = field.maximum_location
    axes.plot(x, y, "c*", ms=12, label=f"max {field.maximum / 1e6:.0f} MPa")
    figure.colorbar(image, ax=axes, label="von Mises [MPa]")
    axes.set_aspect("equal")
    axes.set_xlabel("x_rod [m]")
    axes.set_ylabel("y_rod [m]")
    axes.set_title(title)
    axes.legend(loc="upper right", fontsize=8)
    return figure


def assembled_bore_figure(results) -> Figure:
    """The assembled bore, magnified (raw and as the film sees it), and the pressure across
    the joint as assembled and its smallest over the cycle
    (:class:`conrod.results.housing.HousingResults` with an ``assembly``)."""
    report, housing = results.assembly, results.housing
    joint = report.joint_stress is not None
    figure = Figure(figsize=(12.0 if joint else 6.5, 5.6))
    panels = figure.subplots(1, 2 if joint else 1, squeeze=False).ravel()
    axes = panels[0]
    scale = _magnification(housing.radius, [report.raw, report.profile])
    _bore_outline(axes, report.angles, housing.radius, np.zeros_like(report.raw), 0.0,
                  color="0.7", lw=1.0, label="round")
    _bore_outline(axes, report.angles, housing.radius, report.raw, scale, color="tab:orange",
                  label=f"raw (clamped) × {scale:.0f}")
    _bore_outline(axes, report.angles, housing.radius, report.profile, scale,
                  color="tab:blue", label=f"film profile h₀ × {scale:.0f}")
    axes.set_aspect("equal")
    axes.set_xticks([])
    axes.set_yticks([])
    axes.legend(fontsize=7, loc="lower left")
    axes.set_title(f"Assembled bore: preload {report.bolt_preload / 1e3:.0f} kN per bolt, crush "
                   f"pressure {report.crush_pressure / 1e6:.1f} MPa\nout-of-round "
                   f"{report.out_of_roundness * MICRO:.1f} µm (x_rod to the right)", fontsize=9)
    if joint:
        _joint_panel(panels[1], report)
    return figure


def _joint_panel(axes, report) -> None:
    for side, color in ((1.0, "tab:blue"), (-1.0, "tab:red")):
        on = report.joint_side == side
        name = "+y" if side > 0 else "−y"
        distance = report.joint_distance[on] * 1e3
        axes.plot(distance, -report.joint_stress[on] / 1e6, color=color,
                  label=f"side {name}, assembled")
        if report.cycle_max_stress is not None:
            axes.plot(distance, -report.cycle_max_stress[on] / 1e6, "--", color=color,
                      label=f"side {name}, smallest over the cycle")
    axes.axhline(0.0, color="k", lw=0.8)
    axes.set_xlabel("distance from the bore centre along the split line [mm]")
    axes.set_ylabel("pressure across the joint [MPa] (< 0: opens)")
    axes.grid(alpha=0.3)
    axes.legend(fontsize=7)
    opens = report.joint_opens
    verdict = "" if opens is None else (" — opens over the cycle" if opens
                                        else " — stays closed over the cycle")
    axes.set_title(f"Bonded rod/cap joint{verdict}", fontsize=9)


def housing_temperature_figure(structure, warm) -> Figure:
    """The housing's conduction temperature [°C] at the mesh corners
    (:class:`conrod.housing.thermal.WarmBore` with ``corner_temperature``), contoured."""
    figure = Figure(figsize=(11.0, 4.6))
    axes = figure.subplots()
    triangulation = _triangulation(structure)
    image = axes.tricontourf(triangulation, warm.corner_temperature, levels=20, cmap="inferno")
    axes.tricontour(triangulation, warm.corner_temperature, levels=10, colors="w",
                    linewidths=0.4)
    figure.colorbar(image, ax=axes, label="temperature [°C]")
    axes.set_aspect("equal")
    axes.set_xlabel("x_rod (towards the small end) [m]")
    axes.set_ylabel("y_rod [m]")
    axes.set_title(f"Housing temperature: big-end mean {warm.housing_temperature:.1f} °C, "
                   f"shell side {warm.shell_temperature:.1f} °C, crankcase "
                   f"{warm.section.ambient_temperature:g} °C")
    return figure
