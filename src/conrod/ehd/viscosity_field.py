"""A viscosity field μ(θ, z) [Pa s] in the film on the elastic bore (the thermal film on the
elastic bore, docs/thermal.md).

:class:`~conrod.ehd.film.ElasticFilm` declares
:class:`~conrod.film.capabilities.HasViscosityField` exactly when the film it wraps does (the
Reynolds film): :func:`with_viscosity_field` hands the field to the wrapped film, whose
conductances, shear and exact thickness response take it
(:mod:`conrod.film.reynolds.viscosity_field`, :mod:`conrod.film.reynolds.response`), so the
coupling and the journal's implicit step see it; :func:`film_flows` solves the coupling at a
state from the memory the orbit sampled there and gives the volume fluxes and dissipation of
the wrapped film on the bore so deformed (the bore's rate in the squeeze term as in the
coupling).
"""

from __future__ import annotations

import copy
import dataclasses
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.film.base import FilmState
from conrod.film.rated_state import rated


def with_viscosity_field(film: Any, field: np.ndarray | None) -> Any:
    """A copy of the elastic ``film`` whose wrapped film carries ``field`` [Pa s] (None: the
    scalar viscosity; the wrapped film itself when it already carries none)."""
    if field is None and getattr(film.base, "viscosity_field", None) is None:
        return film
    warm = copy.copy(film)
    warm.base = film.base.with_viscosity_field(field)
    warm.answers = {}  # its step answers' characteristics are its own
    if warm.base.exact_thickness_response() != film.base.exact_thickness_response():
        raise CaseError(f"film = {film.name!r} on an elastic bore: a viscosity field changes "
                        "how its response is taken (allowed: the isoviscous Reynolds film)")
    return warm


def film_flows(film: Any, state: FilmState, memory: Any) -> tuple[Any, Any]:
    """(:class:`~conrod.film.thermal.flows.FilmFlows` of ``state`` on the bore deformed as
    the coupling from ``memory`` finds it, the memory after it)."""
    _, after = film.solve_with_memory(state, memory)
    deformed = rated(state, film.film_field(after.deformation), _rate(film, memory,
                                                                     after.deformation))
    flows, inner = film.base.film_flows(deformed, after.inner)
    return flows, dataclasses.replace(after, inner=inner)


def _rate(film: Any, memory: Any, deformation: np.ndarray) -> np.ndarray | None:
    """The bore's rate ∂u/∂t on the film grid [m/s] the coupling put in the squeeze term
    (None without it)."""
    if not (film.settings.deformation_rate and memory.reference is not None
            and memory.reference_dt > 0.0):
        return None
    return film.film_field((deformation - memory.reference) / memory.reference_dt)
