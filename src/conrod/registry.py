"""The one registry of model names: film models and orbit integrators.

The case schema (``[solver] film`` / ``integrator``), the film factory, the orbit and the
CLI all read these names from here. A name maps to ``"module:Class"``; the module is only
imported when the model is chosen, so a heavy model never slows the others. Each film class
builds itself from the ``[solver]`` settings with ``from_settings(geometry, settings)``.
"""

from __future__ import annotations

import importlib
from typing import Any, Literal, get_args

from conrod.errors import CaseError

FilmName = Literal["short", "mobility", "reynolds", "mass_conserving", "table"]
IntegratorName = Literal["auto", "adaptive", "implicit", "rk2", "quasi_static"]

FILM_MODELS: dict[str, str] = {
    "short": "conrod.film.short.film:ShortBearingFilm",
    "mobility": "conrod.film.table.mobility:MobilityFilm",
    "reynolds": "conrod.film.reynolds.film:ReynoldsFilm",
    "mass_conserving": "conrod.film.mass_conserving.film:MassConservingFilm",
    "table": "conrod.film.table.film:TabulatedFilm",
}
"""Film name → class (each has ``from_settings(geometry, settings)``)."""

INTEGRATORS: dict[str, str] = {
    "auto": "conrod.orbit.integrators:AutomaticIntegrator",
    "adaptive": "conrod.orbit.integrators:AdaptiveIntegrator",
    "implicit": "conrod.orbit.integrators:ImplicitIntegrator",
    "rk2": "conrod.orbit.integrators:HeunIntegrator",
    "quasi_static": "conrod.orbit.integrators:QuasiStaticIntegrator",
}
"""Integrator name → class (each has ``cycle(problem, state, settings)``)."""

FILM_NAMES: tuple[str, ...] = get_args(FilmName)
INTEGRATOR_NAMES: tuple[str, ...] = get_args(IntegratorName)


def _load(kind: str, registry: dict[str, str], name: str) -> Any:
    if name not in registry:
        raise CaseError(f"solver.{kind} = {name!r}: unknown (allowed: {', '.join(registry)})")
    module, attribute = registry[name].split(":")
    return getattr(importlib.import_module(module), attribute)


def film_class(name: str) -> Any:
    """The film model class registered as ``name``."""
    return _load("film", FILM_MODELS, name)


def integrator(name: str) -> Any:
    """A new integrator registered as ``name``."""
    return _load("integrator", INTEGRATORS, name)()
