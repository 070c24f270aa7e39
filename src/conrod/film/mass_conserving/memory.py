"""What a mass-conserving film remembers between instants, and the discrete fields of one
solve (:mod:`conrod.film.mass_conserving.film`)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

FULL = 1.0 - 1.0e-9
"""Film fraction above which a node counts as full [-]."""


@dataclass(frozen=True)
class MassConservingMemory:
    """What a mass-conserving film remembers between instants (never modified in place).

    fraction : ndarray  Film fraction ϑ(θ, z) on the grid, 1 = full film [-].
    pressure : ndarray or None  Last shifted pressure p̃ = p − p_cav, the warm start of the
        next solve [Pa]; None: start from p̃ = −p_cav.
    thickness : ndarray or None  Film thickness h at the instant of ``fraction`` [m], set by
        an implicit content step (:meth:`MassConservingFilm.content_step`); None otherwise.
    hole_fill, held_fill : float  Content change over that step of the nodes the
        journal's holes (all supply features) hold at its end, per second [m³/s]: oil they
        gave besides their flux (:func:`conrod.film.mass_conserving.step.content_step`).
    """

    fraction: np.ndarray
    pressure: np.ndarray | None = None
    thickness: np.ndarray | None = None
    hole_fill: float = 0.0
    held_fill: float = 0.0


@dataclass
class FilmFields:
    """Discrete fields of one solve (cell-balance form, all scaled by 12μ).

    h : film thickness at the nodes [m];  a_east, a_north : face conductances [m³];
    couette_east : 6μ U h_e Δz [Pa m³];  squeeze : 12μ Δx Δz ∂h/∂t [Pa m³];
    edge, supply : Dirichlet masks;  fixed_pressure : p̃ on Dirichlet nodes [Pa];
    fed : nodes fed by the journal's oil holes at this instant (in ``supply``), or None.
    """

    h: np.ndarray
    a_east: np.ndarray
    a_north: np.ndarray
    couette_east: np.ndarray
    squeeze: np.ndarray
    edge: np.ndarray
    supply: np.ndarray
    fixed_pressure: np.ndarray
    has_deformation: bool = False
    fed: np.ndarray | None = None

    @property
    def free(self) -> np.ndarray:
        """Nodes whose pressure is solved for."""
        return ~(self.edge | self.supply)
