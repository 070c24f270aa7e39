"""The fields an elastic film declares on its grid
(:class:`~conrod.film.capabilities.HasFilmFields`): the bore deformation and, from the film
it wraps, its film fraction and its own declared fields."""

from __future__ import annotations

import dataclasses
from typing import Any

from conrod.film.base import FilmState
from conrod.film.capabilities import FilmField, HasFilmFields, HasMixableContent


def elastic_fields(film: Any, state: FilmState, memory: Any) -> dict[str, FilmField]:
    """The bore deformation δ(θ, z) [m] of ``memory`` on the film grid, the inner film's
    film fraction ϑ [-] when it has a content, and what the inner film declares."""
    deformation = film.film_field(memory.deformation)
    fields = {"deformation": FilmField(deformation, "m", "bore deformation (outward +)")}
    base, shape = film.base, film.base.deformation_shape()
    if isinstance(base, HasMixableContent) and memory.inner is not None:
        fraction = base.content_vector(memory.inner).reshape(shape)
        fields["film_fraction"] = FilmField(fraction, "1", "film fraction")
    if isinstance(base, HasFilmFields):
        deformed = dataclasses.replace(state, deformation=deformation)
        fields.update(base.film_fields(deformed, memory.inner))
    return fields
