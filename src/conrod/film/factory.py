"""Build the film model named in ``[solver] film`` from the registry of model names
(:mod:`conrod.registry`): every model builds itself with ``from_settings``."""

from __future__ import annotations

import dataclasses
from typing import Any

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel
from conrod.film.short.film import GroovedShortBearingFilm, central_groove_width
from conrod.registry import film_class

__all__ = ["GroovedShortBearingFilm", "build_film_model", "central_groove_width"]


def build_film_model(
    case_or_solver: Any, geometry: BearingGeometry, name: str | None = None,
    pressure_viscosity: Any = None,
) -> FilmModel:
    """Film model for ``geometry`` from a :class:`Case` or its ``[solver]`` section.

    ``name`` overrides ``solver.film``. Grid models (reynolds, mass_conserving) take
    ``n_theta``, ``n_z`` and ``film_tolerance``; ``table`` tabulates a Reynolds film on that
    grid; ``mobility`` builds its map from a Reynolds film on that grid; ``short`` with a full
    central groove becomes :class:`GroovedShortBearingFilm`. ``pressure_viscosity``
    (a :class:`~conrod.film.piezoviscosity.PressureViscosity`, default: the case's
    ``[lubricant]`` law) goes to the short and grid films; the map films refuse it.
    """
    solver = getattr(case_or_solver, "solver", case_or_solver)
    film_name = name or solver.film
    law = pressure_viscosity or _case_pressure_viscosity(case_or_solver)
    if law is None:
        return film_class(film_name).from_settings(geometry, solver)
    if film_name in ("table", "mobility"):
        raise CaseError(
            f"solver.film = {film_name!r}: cannot be combined with lubricant.pressure_viscosity "
            f"= {law.law!r} (its maps assume force ∝ μω); use film = 'short', 'reynolds' or "
            "'mass_conserving', or pressure_viscosity = 'none'")
    if film_name == "short" and central_groove_width(geometry) > 0.0:
        return GroovedShortBearingFilm.from_geometry(geometry, law)
    film = film_class(film_name).from_settings(geometry, solver)
    return dataclasses.replace(film, pressure_viscosity=law)


def _case_pressure_viscosity(case_or_solver: Any) -> Any:
    """The case's pressure–viscosity law (None when isoviscous or given a bare solver)."""
    lubricant = getattr(case_or_solver, "lubricant", None)
    return None if lubricant is None else lubricant.pressure_viscosity_law()
