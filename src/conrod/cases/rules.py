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
