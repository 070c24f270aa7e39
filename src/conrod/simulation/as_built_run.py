"""The simulation's bearing geometry as built and warm: ``[housing.assembly]`` and
``[housing.thermal]`` through :mod:`conrod.housing.as_built`."""

from __future__ import annotations

from typing import Any

from conrod.errors import CaseError

GRID_FILMS = ("reynolds", "mass_conserving")
"""Films that take a bore profile (the as-built bore) [-]."""


def as_built(simulation: Any, geometry: Any, film_by_name: bool) -> Any:
    """``geometry`` of ``[bearing]`` as built and warm for ``simulation``: the warm
    clearance, and the housing's static bore shape in the profile of a grid film named by
    the case or the simulation (``film_by_name``; a film object keeps its own geometry)."""
    from conrod.housing.as_built import run_geometry
    from conrod.housing.housing import Housing

    case = simulation.case.model_copy(update={"solver": simulation.solver})
    thermal = case.housing.thermal
    if thermal is not None and thermal.from_film and case.solver.thermal != "film":
        raise CaseError(
            "housing.thermal: no journal_temperature, housing_temperature or "
            f"shell_temperatures with [solver] thermal = {case.solver.thermal!r} (allowed: "
            "give journal_temperature and housing_temperature or shell_temperatures; or "
            "thermal = 'film', whose film gives them)")
    grid = film_by_name and simulation.solver.film in GRID_FILMS
    return run_geometry(geometry, simulation.case.housing, simulation.housing, case, grid,
                        lambda: Housing.from_case(case).warm)


def warm_note(simulation: Any) -> str:
    """`` (warm clearance … µm)`` for the headline's bore with ``[housing.thermal]``, else
    ''."""
    thermal = simulation.case.housing.thermal
    if thermal is None or not thermal.active:
        return ""
    if thermal.from_film:
        return " (warm from the thermal film)"
    return f" (warm clearance {simulation.geometry().radial_clearance * 1e6:.2f} µm)"
