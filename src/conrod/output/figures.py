"""Figures of every result type, registered in :func:`conrod.output.registry.figures`
(importing :mod:`conrod.output` registers them; each figure is drawn by a function of
:mod:`conrod.plotting`, imported when the figure is built)."""

from __future__ import annotations

import importlib

from conrod.contact.analysis import ContactResults
from conrod.loads.cycle import LoadCycle
from conrod.loads.engine_loads import EngineLoads
from conrod.mechanism.regimes import SweepRun
from conrod.mechanism.results import MechanismRun
from conrod.output.registry import FigureSpec, figures
from conrod.output.thermal_tables import thermal_outputs
from conrod.results.cycle_results import RunResults
from conrod.results.ehd import ElasticRunResults


def _plots(module: str):
    """The plotting module ``module``, imported when a figure is built (matplotlib is not
    imported by reading results or writing tables)."""
    return importlib.import_module(f"conrod.plotting.{module}")


@figures.register
def _run_figures(results: RunResults) -> tuple[FigureSpec, ...]:
    own = (
        FigureSpec("orbit.png", "Journal-centre orbit",
                   "Journal centre e_x, e_y [µm] in the clearance circle over the last cycle, "
                   "labelled by crank angle [deg]; the cycle before it dashed; the orbit's "
                   "contact circle (on a deforming bore widened by one clearance: the bore "
                   "gives way, the deformed film stops the journal).",
                   lambda: _plots("orbit_plots").plot_orbit(results)),
        FigureSpec("hmin_pmax.png", "Minimum film thickness and peak pressure",
                   "h_min [µm] and p_max [MPa] against crank angle [deg].",
                   lambda: _plots("orbit_plots").plot_film_thickness_and_pressure(results)),
        FigureSpec("friction_flow.png", "Friction power and oil flow",
                   "Friction power of the film and of hard contact [W] and side/supply "
                   "flow [l/min] against crank angle [deg].",
                   lambda: _plots("orbit_plots").plot_friction_and_flow(results)),
        FigureSpec("pressure_map.png", "Film pressure at the largest p_max",
                   "Film pressure p [MPa] over shell angle θ [deg] and axial position z [mm] "
                   "at the crank angle of the largest p_max.",
                   lambda: _plots("orbit_plots").plot_pressure_map(results)),
        FigureSpec("film_thickness_map.png", "Film thickness over shell and cycle",
                   "Film thickness h [µm] over crank angle φ [deg] and shell angle θ [deg] "
                   f"({_bore(results)}), with the contact threshold h_c and the angle of "
                   "h_min.",
                   lambda: _plots("film_maps").plot_film_thickness_map(results)),
        FigureSpec("min_film_envelope.png", "Shell envelope of minimum film thickness",
                   "Smallest film thickness [µm] each shell angle θ [deg] sees over the cycle "
                   f"({_bore(results)}), and the crank angle [deg] where it occurs.",
                   lambda: _plots("film_maps").plot_min_film_envelope(results)),
)
    contact = results.contact
    return (own + signoff_figures(results) + thermal_outputs(results, figures)
            + (figures(contact) if contact is not None and contact.has_contact else ()))


def signoff_figures(results: RunResults) -> tuple[FigureSpec, ...]:
    """The per-cell indicator maps (shell, journal) and the erosion map of a run."""
    signoff = results.signoff
    if signoff is None or signoff.indicators is None:
        return ()
    maps = "largest pressure, pressure range, smallest film thickness (and asperity " \
        "pressure, temperature where computed)"
    return (
        FigureSpec("indicator_maps_shell.png", "Per-cell indicators on the shell",
                   f"Over the cycle at each point of the unrolled shell: {maps} over θ "
                   "[deg] and z [mm]; worst cell marked, limit contours dashed.",
                   lambda: _plots("indicator_plots").plot_indicator_maps(results, "shell")),
        FigureSpec("indicator_maps_journal.png", "Per-cell indicators on the journal",
                   f"The same on the journal in its own frame (it turns): {maps} over the "
                   "journal angle α [deg] and z [mm].",
                   lambda: _plots("indicator_plots").plot_indicator_maps(results, "journal")),
        FigureSpec("erosion_map.png", "Cavitation-erosion indicator",
                   "Largest reformation intensity over the cycle at each shell cell "
                   "[GPa/s] over θ [deg] and z [mm] (mass-conserving film; a labelled "
                   "proxy for the Reynolds film).",
                   lambda: _plots("indicator_plots").plot_erosion_map(results)),
    )


def _bore(results: RunResults) -> str:
    """Which gap a film figure draws, in words."""
    if (results.model or {}).get("housing", "").startswith("elastic"):
        return "gap on the deformed bore, h_rigid + u"
    return "rigid bore"


@figures.register
def _contact_figures(contact: ContactResults) -> tuple[FigureSpec, ...]:
    return (
        FigureSpec("contact_cycle.png", "Contact over the cycle",
                   "Contact (Hertz) stress [MPa] and friction work [J], h_min [µm] with the "
                   "contact intervals shaded and p_max [MPa] against crank angle [deg].",
                   lambda: _plots("contact_plots").plot_contact_cycle(contact)),
        FigureSpec("wear_unrolled.png", "Friction work and wear, unrolled",
                   "Friction work [J] and wear depth [µm] of journal and shell against the "
                   "surface angle [deg].",
                   lambda: _plots("contact_plots").plot_wear_unrolled(contact)),
        FigureSpec("wear_polar.png", "Wear around journal and shell",
                   "Wear depth [µm] of journal and shell around the circumference (polar).",
                   lambda: _plots("contact_plots").plot_wear_polar(contact)),
        FigureSpec("contact_stress_surfaces.png", "Contact stress on the surfaces",
                   "Largest Hertz stress [MPa] each journal and shell element sees over the "
                   "cycle, against the surface angle [deg].",
                   lambda: _plots("contact_plots").plot_contact_stress_surfaces(contact)),
)


@figures.register
def _loads_figures(loads: EngineLoads) -> tuple[FigureSpec, ...]:
    return (
        FigureSpec("polar_load_diagram.png", "Polar load diagram",
                   "Load on the crank pin [kN] in the rod frame, labelled by crank angle [deg].",
                   lambda: _plots("loads_plots").plot_polar_load_diagram(loads)),
        FigureSpec("load_vs_crank_angle.png", "Load over the cycle",
                   "Bearing load components and magnitude [kN] against crank angle [deg].",
                   lambda: _plots("loads_plots").plot_load_over_crank_angle(loads)),
        FigureSpec("wear_diagram.png", "Wear diagram",
                   "Load-weighted wear intensity around the crank pin [kN] and the oil-hole "
                   "angle [deg].",
                   lambda: _plots("loads_plots").plot_wear_diagram(loads)),
)


@figures.register
def _table_load_figures(loads: LoadCycle) -> tuple[FigureSpec, ...]:
    return (
        FigureSpec("polar_load_diagram.png", "Polar load diagram",
                   "Load on the shell [kN] in the bearing frame of the load table, labelled "
                   "by crank angle [deg].",
                   lambda: _plots("loads_plots").plot_table_load_polar(loads)),
        FigureSpec("load_vs_crank_angle.png", "Load over the cycle",
                   "Load components in the bearing frame and magnitude [kN] against crank "
                   "angle [deg].",
                   lambda: _plots("loads_plots").plot_table_load_over_crank_angle(loads)),
    )


@figures.register
def _mechanism_figures(run: MechanismRun) -> tuple[FigureSpec, ...]:
    results = run.results
    return (
        FigureSpec("gaps_and_forces.png", "Gaps and contact forces",
                   "Gap [µm] and contact force [N] of both rod bearings against crank angle "
                   "[deg] over the last cycle.",
                   lambda: _plots("mechanism_plots").plot_gaps_and_forces(results)),
        FigureSpec("journal_orbits.png", "Journal orbits in the clearances",
                   "Journal-centre paths [µm] inside both rod-bearing clearances.",
                   lambda: _plots("mechanism_plots").plot_journal_orbits(results)),
        FigureSpec("impact_velocities.png", "Impact velocities",
                   "Impact velocity [m/s] of every impact against crank angle [deg].",
                   lambda: _plots("mechanism_plots").plot_impacts(results)),
)


@figures.register
def _sweep_figures(run: SweepRun) -> tuple[FigureSpec, ...]:
    return (
        FigureSpec("sweep_map.png", "Impact-velocity ratio over the operating modes",
                   "Ratio of the worn joint's largest impact velocity to the other's [-] over "
                   "crank speed [rpm] and load scale [-].",
                   lambda: _plots("mechanism_plots").plot_sweep_map(run.sweep)),
)


@figures.register
def _elastic_figures(results: ElasticRunResults) -> tuple[FigureSpec, ...]:
    own = (
        FigureSpec("hmin_pmax_rigid_elastic.png", "Rigid and elastic big end",
                   "h_min [µm] and p_max [MPa] against crank angle [deg] on the deforming "
                   "bore and on the rigid bore.",
                   lambda: _plots("ehd_plots").plot_rigid_vs_elastic(results)),
        FigureSpec("deformed_bore.png", "Deformed bore",
                   "Magnified deformed bore and the clearance circle [µm] at the crank "
                   "angles of the largest load and of the smallest h_min.",
                   lambda: _plots("ehd_plots").plot_deformed_bore(results)),
        FigureSpec("deformed_film_maps.png", "Film on the deformed bore",
                   "Film thickness [µm] and pressure [MPa] over θ [deg] and z [mm] at the "
                   "crank angle of the largest p_max, centred on the pressure peak.",
                   lambda: _plots("ehd_plots").plot_deformed_film_maps(results)),
)
    if results.stresses is not None:
        own += (
            FigureSpec("von_mises_film_pressure.png", "Rod stress under the film pressure",
                       "Von Mises stress [MPa] of the rod at the largest load under the "
                       "elastic film pressure.",
                       lambda: _plots("ehd_plots").plot_von_mises(results, "pressure")),
            FigureSpec("von_mises_cosine_load.png", "Rod stress under a cosine load",
                       "Von Mises stress [MPa] of the rod at the largest load under a cosine "
                       "load of the same resultant.",
                       lambda: _plots("ehd_plots").plot_von_mises(results, "cosine")),
)
    return _run_figures(results.elastic) + own + _bore_field_figures(results)


def _bore_field_figures(results: ElasticRunResults) -> tuple[FigureSpec, ...]:
    """u(θ, z) of a housing that deforms along the width (none for a plane housing)."""
    if results.deformation_field is None:
        return ()
    return (FigureSpec("bore_deformation_width.png", "Bore deformation along the width",
                       "Corrected radial bore displacement u [µm] over θ [deg] and z [mm] at "
                       "the largest load and the smallest h_min, whole and less its "
                       "width-mean, and the film thickness h [µm] across the width at the "
                       "angle of the smallest film.",
                       lambda: _plots("bore_field_plots").plot_bore_field(results)),)
