"""The discrete problem of one grid level of the Reynolds film and its SOR factor."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.film.characteristics import FilmGrid


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

    def coarsened(self) -> DiscreteProblem:
        """The same problem on every other node (coinciding nodes, exact subsampling)."""
        g = self.grid
        coarse = FilmGrid(g.radius, g.width, g.n_theta // 2, g.n_z // 2)
        return DiscreteProblem(coarse, self.h[::2, ::2].copy(), self.h_rate[::2, ::2].copy(),
                               self.fixed[::2, ::2].copy(), self.fixed_values[::2, ::2].copy(),
                               self.cavitation)
