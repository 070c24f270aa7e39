"""Rules that relate fields of different sections, checked when the case is read.

Each rule raises :class:`~conrod.errors.CaseError` (a ``ValueError``, so pydantic reports
it like any field error) naming the field, the value, the allowed range and the unit,
before any computation starts.
"""

from __future__ import annotations

from typing import Any

from conrod.cases.base import range_error


def check_case(case: Any, solver: Any = None) -> None:
    """Cross-section rules of a :class:`~conrod.cases.case.Case`.

    solver : SolverSection or None  The ``[solver]`` section actually used (e.g. with
        command-line overrides); default ``case.solver``.
    """
    solver = case.solver if solver is None else solver
    bearing = case.bearing
    if bearing is not None:
        bearing.check_features_inside_width()
    if bearing is not None and bearing.radial_clearance is not None:
        clearance = bearing.radial_clearance
        if solver.contact_film_thickness >= clearance:
            raise range_error("solver.contact_film_thickness", solver.contact_film_thickness,
                              f">= 0 and < bearing.radial_clearance = {clearance:g}", "m")
    _check_table_with_engine(case)


def _check_table_with_engine(case: Any) -> None:
    """A ``[load]`` table beside ``[engine]``: the table gives the bearing load and
    ``[engine]`` only the crank train (the rod's inertia deformation of an elastic big end),
    so both must turn at one speed."""
    engine, table = case.engine, case.load
    if engine is None or table is None:
        return
    if abs(engine.speed - table.speed) > 1e-9 * engine.speed:
        raise range_error("engine.speed", engine.speed,
                          f"= load.speed = {table.speed:g} (the [load] table gives the bearing "
                          "load, [engine] the crank train of the rod's inertia)", "rpm")
    if table.cycle_deg != 720:
        raise range_error("load.cycle_deg", table.cycle_deg,
                          "720 with [engine] (a four-stroke crank train)", "deg")

