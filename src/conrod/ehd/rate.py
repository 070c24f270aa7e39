"""The bore's deformation rate in the squeeze term of the Reynolds equation.

The squeeze term 12 μ ∂h/∂t of a film on a deforming bore has two parts: the journal's
velocity and the bore's own rate ∂u/∂t. Leaving the second out (Rodin 2004) lets the bore
move into a journal that the massless orbit holds in place, with no film resistance: on a
compliant rod the film then closes within a step and the force balance has no solution.
:class:`RatedFilmState` carries ∂u/∂t and :class:`ReynoldsWithDeformationRate` adds it to
the film-thickness rate (Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994, ch. 7:
∂h/∂t of the transient Reynolds equation includes the surface's normal velocity).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from conrod.film.base import FilmState
from conrod.film.reynolds import ReynoldsFilm


@dataclass(frozen=True)
class RatedFilmState(FilmState):
    """A film state with the rate of its deformation field.

    deformation_rate : ndarray or None  ∂δ/∂t (n_θ, n_z + 1) [m/s] on the film grid.
    """

    deformation_rate: np.ndarray | None = None


@dataclass
class ReynoldsWithDeformationRate(ReynoldsFilm):
    """:class:`ReynoldsFilm` whose squeeze term includes ``RatedFilmState.deformation_rate``."""

    def _problem(self, state: FilmState):
        problem = super()._problem(state)
        rate = getattr(state, "deformation_rate", None)
        if rate is not None:
            problem.h_rate = problem.h_rate + rate
        return problem


def rated(state: FilmState, deformation: np.ndarray, rate: np.ndarray | None) -> FilmState:
    """``state`` with the deformation field and (when given) its rate [m], [m/s]."""
    if rate is None:
        return dataclasses.replace(state, deformation=deformation)
    fields = {f.name: getattr(state, f.name) for f in dataclasses.fields(FilmState)}
    fields["deformation"] = deformation
    return RatedFilmState(**fields, deformation_rate=rate)


def with_deformation_rate(film):
    """The rate-aware version of a plain :class:`ReynoldsFilm` (same settings); other films
    unchanged (their squeeze term keeps the journal's velocity only)."""
    if not isinstance(film, ReynoldsFilm) or isinstance(film, ReynoldsWithDeformationRate):
        return film
    values = {f.name: getattr(film, f.name) for f in dataclasses.fields(film) if f.init}
    return ReynoldsWithDeformationRate(**values)
