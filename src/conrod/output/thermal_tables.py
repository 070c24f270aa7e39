"""The table and the figure of the film's temperature field
(:class:`conrod.results.thermal.ThermalFilmResults`), registered once; a run with
``[solver] thermal = "film"`` writes them beside its own (:mod:`conrod.output.tables`,
:mod:`conrod.output.figures`)."""

from __future__ import annotations

import importlib

from conrod.output.registry import FigureSpec, TableSpec, figures, tables
from conrod.results.thermal import ThermalFilmResults


@tables.register
def _thermal_tables(thermal: ThermalFilmResults) -> tuple[TableSpec, ...]:
    return (TableSpec("thermal_film.csv", "Film temperature field",
                      "Cycle-mean film temperature [°C] at every film grid node, by shell "
                      "angle θ [deg] and axial position z [mm] (thermal film); the wall "
                      "temperatures and heat flows are in summary.json 'thermal_film'.",
                      thermal.table),)


@figures.register
def _thermal_figures(thermal: ThermalFilmResults) -> tuple[FigureSpec, ...]:
    def draw():
        return importlib.import_module("conrod.plotting.thermal_plots").plot_temperature_map(
            thermal)

    own = (FigureSpec("temperature_map.png", "Film temperature map",
                      "Cycle-mean film temperature [°C] over shell angle θ [deg] and axial "
                      "position z [mm], the hottest point marked; wall temperatures and "
                      "heat flows [W] in the title.", draw),)
    if thermal.warm_bore is None:
        return own
    return own + (FigureSpec(
        "warm_bore.png", "Bore warm from the film",
        "Shell-side temperature T_b(θ) [°C] with the film's axial mean and the journal's, "
        "and the thermal bore profile h₀ [µm] over shell angle θ [deg]; clearance change "
        "and out-of-roundness [µm] in the title.",
        lambda: importlib.import_module("conrod.plotting.thermal_plots").plot_warm_bore(
            thermal)),)


def thermal_outputs(results, registry) -> tuple:
    """The tables or figures (``registry``) of a run's temperature field; () without one."""
    thermal = getattr(results, "thermal_film", None)
    return () if thermal is None else registry(thermal)
