"""The discrete problem of one grid level of the Reynolds film and its SOR factor."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.characteristics import FilmGrid
from conrod.film.supply import instant_supply, nearest_theta_index


def optimal_relaxation(grid: FilmGrid) -> float:
    """SOR factor ω = 2/(1 + √(1 − ρ_J²)) of the constant-h model problem [-].

    ρ_J = (a_θ + a_z cos(π/n_z))/(a_θ + a_z), a_θ = 1/(RΔθ)², a_z = 1/Δz² — the slowest
    mode is uniform in θ (periodic) and a half sine in z (Young's theory of SOR).
    """
    a_theta = 1.0 / (grid.radius * grid.d_theta) ** 2
    a_z = 1.0 / grid.d_z**2
    rho = (a_theta + a_z * math.cos(math.pi / grid.n_z)) / (a_theta + a_z)
    return 2.0 / (1.0 + math.sqrt(1.0 - rho * rho))


@dataclass
class DiscreteProblem:
    """Discrete problem of one grid level (arrays in SI units)."""

    grid: FilmGrid
    h: np.ndarray
    h_rate: np.ndarray
    fixed: np.ndarray
    fixed_values: np.ndarray
    cavitation: float = 0.0
    """Cavitation bound of the solved variable (reduced pressure when piezoviscous) [Pa]."""
    coefficients: tuple | None = None
    """(a_E, a_N, b) of the last solve on this level (reused by the characteristics)."""
    journal_holes: np.ndarray | None = None
    """Nodes fed by the journal's oil holes at this instant, bool (None: no journal hole)."""
    conduction: np.ndarray | None = None
    """Conductance thickness h (μ_r/μ)^{1/3} of a viscosity field [m]
    (:mod:`conrod.film.reynolds.viscosity_field`); None: the conductances of h."""
    h_min: float | None = None
    """Smallest film thickness min h [m], where the problem's maker computed it (None: not
    computed)."""

    def min_film_thickness(self) -> float:
        """min h [m], computed once."""
        if self.h_min is None:
            self.h_min = float(self.h.min())
        return self.h_min

    def coarsened(self) -> DiscreteProblem:
        """The same problem on every other node (coinciding nodes, exact subsampling)."""
        g = self.grid
        coarse = FilmGrid(g.radius, g.width, g.n_theta // 2, g.n_z // 2)
        return DiscreteProblem(coarse, self.h[::2, ::2].copy(), self.h_rate[::2, ::2].copy(),
                               self.fixed[::2, ::2].copy(), self.fixed_values[::2, ::2].copy(),
                               self.cavitation, conduction=None if self.conduction is None
                               else self.conduction[::2, ::2].copy())


def dirichlet_regions(grid: FilmGrid, state: FilmState, geometry: BearingGeometry,
                      shell: tuple[np.ndarray, np.ndarray], solved,
                      inlet_line: bool) -> tuple[np.ndarray, np.ndarray, np.ndarray | None]:
    """(Dirichlet mask, values, nodes fed by the journal holes) of ``state``: the ``shell``
    mask and values (edges, grooves, shell holes; not modified), the journal's oil holes
    where ``state.journal_feed`` puts them (:func:`~conrod.film.supply.instant_supply`,
    ``solved(p)`` the solved variable of a pressure [Pa]) and with ``inlet_line`` p = 0 on
    the axial line at the largest gap θ = ψ + π."""
    fixed, values, fed = instant_supply(geometry, grid, state.journal_feed, *shell, solved)
    if inlet_line:
        fixed, values = fixed.copy(), values.copy()
        psi = math.atan2(state.eccentricity_y, state.eccentricity_x)
        column = nearest_theta_index(psi + math.pi, grid)
        fixed[column, :] = True
        values[column, :] = 0.0
    return fixed, values, fed
