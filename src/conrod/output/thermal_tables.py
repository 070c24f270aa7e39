"""The table and the figure of the film's temperature field
(:class:`conrod.results.thermal.ThermalFilmResults`), registered once; a run with
``[solver] thermal = "film"`` writes them beside its own (:mod:`conrod.output.tables`,
:mod:`conrod.output.figures`)."""

from __future__ import annotations

import importlib

from conrod.output.registry import FigureSpec, TableSpec, figures, tables
from conrod.results.thermal import ThermalFilmResults
from conrod.results.thermal_maps import ThermalMapsResults


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


@tables.register
def _thermal_map_tables(maps: ThermalMapsResults) -> tuple[TableSpec, ...]:
    return (TableSpec("thermal_maps.csv", "Film temperature maps at chosen crank angles",
                      "Quasi-steady film temperature [°C] at every film grid node, by crank "
                      "angle [deg] (the output row nearest each asked angle), shell angle θ "
                      "[deg] and axial position z [mm], the walls held at their cycle-mean "
                      "temperatures; the hottest point and heat flows [W] of each map are in "
                      "summary.json 'thermal_film' 'maps'.", maps.table),)


@figures.register
def _thermal_map_figures(maps: ThermalMapsResults) -> tuple[FigureSpec, ...]:
    def draw():
        return importlib.import_module("conrod.plotting.thermal_map_plots").plot_temperature_maps(
            maps)

    return (FigureSpec("temperature_maps.png", "Film temperature maps at chosen crank angles",
                       "Quasi-steady film temperature [°C] over shell angle θ [deg] and axial "
                       "position z [mm] at each chosen crank angle [deg], one colour scale, "
                       "the hottest point of each marked; walls at their cycle-mean "
                       "temperatures.", draw),)


def thermal_outputs(results, registry) -> tuple:
    """The tables or figures (``registry``) of a run's temperature field and of its maps at
    chosen crank angles; () without them."""
    parts = (getattr(results, "thermal_film", None), getattr(results, "thermal_maps", None))
    return tuple(spec for part in parts if part is not None for spec in registry(part))
