"""A film state with the rate of its deformation field: the bore's rate in the squeeze term.

The squeeze term 12 μ ∂h/∂t of a film on a deforming bore has two parts: the journal's
velocity and the bore's own rate ∂u/∂t. Leaving the second out (Rodin 2004) lets the bore
move into a journal that the massless orbit holds in place, with no film resistance: on a
compliant rod the film then closes within a step and the force balance has no solution.
:class:`RatedFilmState` carries ∂u/∂t; a film built ``with_deformation_rate()``
(:class:`~conrod.film.capabilities.SupportsDeformationRate`) adds it to its film-thickness
rate (Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994, ch. 7: ∂h/∂t of the
transient Reynolds equation includes the surface's normal velocity).
"""

from __future__ import annotations

import dataclasses
import functools
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.film.base import FilmState


@dataclass(frozen=True)
class RatedFilmState(FilmState):
    """A film state with the rate of its deformation field.

    deformation_rate : ndarray or None  ∂δ/∂t (n_θ, n_z + 1) [m/s] on the film grid.
    """

    deformation_rate: np.ndarray | None = None


def rated(state: FilmState, deformation: np.ndarray, rate: np.ndarray | None) -> FilmState:
    """``state`` with the deformation field and (when given) its rate [m], [m/s]."""
    if rate is None:
        return moved(state, deformation=deformation)
    return moved(state, RatedFilmState, deformation=deformation, deformation_rate=rate)


UNCHECKED_FIELDS = frozenset({"eccentricity_x", "eccentricity_y", "velocity_x", "velocity_y",
                              "deformation", "deformation_rate"})
"""The fields of a film state that :func:`moved` changes: those its check
(``FilmState.__post_init__``) does not read [-]."""


def moved(state: FilmState, kind: type[FilmState] | None = None, **changes: Any) -> FilmState:
    """``state`` with ``changes`` to fields its check does not read (:data:`UNCHECKED_FIELDS`:
    the journal's position and velocity, the deformation field and its rate), as a ``kind``
    (default: ``state``'s class, which takes no field ``state`` lacks unless ``changes``
    gives it); the other fields are taken over as they were checked when ``state`` was
    made. ~1.5 µs against ~10 µs for a new state: an elastic implicit step makes two per
    film solve."""
    kind = kind or type(state)
    if not changes.keys() <= UNCHECKED_FIELDS:
        raise ValueError(f"moved film state: {sorted(changes.keys() - UNCHECKED_FIELDS)} are "
                         f"checked fields (allowed: {sorted(UNCHECKED_FIELDS)}); make a new "
                         "state")
    new = object.__new__(kind)
    new.__dict__.update(state.__dict__)
    new.__dict__.update(changes)
    if kind is not type(state) and not field_names(kind) <= new.__dict__.keys():
        raise ValueError(f"moved film state: a {kind.__name__} needs "
                         f"{sorted(field_names(kind) - new.__dict__.keys())}")
    return new


@functools.cache
def field_names(kind: type) -> frozenset[str]:
    """The names of the dataclass fields of ``kind`` [-]."""
    return frozenset(item.name for item in dataclasses.fields(kind))


def state_rate(state: FilmState) -> np.ndarray | None:
    """The deformation rate a state carries [m/s], None for a plain state."""
    return getattr(state, "deformation_rate", None)
