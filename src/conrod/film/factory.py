"""Build the film model named in ``[solver] film`` (lazy imports: a model's module is only
imported when chosen, so an unfinished or heavy model never slows the others)."""

from __future__ import annotations

import importlib
from typing import Any

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel

FILM_MODELS = {
    "short": ("conrod.film.short_bearing", "ShortBearingFilm"),
    "reynolds": ("conrod.film.reynolds", "ReynoldsFilm"),
    "mass_conserving": ("conrod.film.mass_conserving", "MassConservingFilm"),
    "mobility": ("conrod.film.mobility", "MobilityFilm"),
    "table": ("conrod.film.table", "TabulatedFilm"),
}
"""Film name → (module, class)."""

_GRID_MODELS = ("reynolds", "mass_conserving")


def _film_class(name: str) -> Any:
    if name not in FILM_MODELS:
        raise CaseError(
            f"solver.film = {name!r}: unknown film model (allowed: {', '.join(FILM_MODELS)})"
        )
    module_name, class_name = FILM_MODELS[name]
    try:
        module = importlib.import_module(module_name)
    except ModuleNotFoundError as error:
        if error.name == module_name:
            raise CaseError(
                f"solver.film = {name!r}: this film model is not available yet"
            ) from None
        raise
    return getattr(module, class_name)


def _grid_kwargs(solver: Any) -> dict[str, int]:
    if solver is None:
        return {}
    return {"n_theta": int(solver.n_theta), "n_z": int(solver.n_z)}


def build_film_model(
    case_or_solver: Any, geometry: BearingGeometry, name: str | None = None
) -> FilmModel:
    """Film model for ``geometry`` from a :class:`Case` or its ``[solver]`` section.

    ``name`` overrides ``solver.film``. Grid models (reynolds, mass_conserving) receive
    ``n_theta``, ``n_z``; ``table`` wraps the short-bearing model (its fast base) unless the
    table class chooses otherwise.
    """
    solver = getattr(case_or_solver, "solver", case_or_solver)
    film_name = name or getattr(solver, "film", "short")
    cls = _film_class(film_name)
    if film_name in _GRID_MODELS:
        return _construct(cls, geometry, _grid_kwargs(solver))
    if film_name == "table":
        base = _film_class("short")(geometry)
        return cls(base)
    return cls(geometry)


def _construct(cls: Any, geometry: BearingGeometry, kwargs: dict[str, int]) -> FilmModel:
    try:
        return cls(geometry, **kwargs)
    except TypeError:
        return cls(geometry)
