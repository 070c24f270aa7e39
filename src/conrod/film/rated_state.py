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

from dataclasses import dataclass

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
        return state.moved(deformation=deformation)
    return state.moved(RatedFilmState, deformation=deformation, deformation_rate=rate)


def state_rate(state: FilmState) -> np.ndarray | None:
    """The deformation rate a state carries [m/s], None for a plain state."""
    return getattr(state, "deformation_rate", None)
