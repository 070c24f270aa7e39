"""The projected multigrid solves the discrete Swift–Stieber complementarity problem."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.film import reynolds_kernel as kernel
from conrod.film import reynolds_multigrid as multigrid
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds import ReynoldsFilm

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)


@pytest.mark.parametrize("grid", [(72, 16), (288, 64)])
def test_converged_pressure_is_the_complementarity_solution(grid):
    """K p = b on the pressurised free nodes, K p − b ≥ 0 where p = p_cav, p ≥ p_cav
    (the W-cycle path runs at 288×64: four coarse levels)."""
    n_theta, n_z = grid
    film = ReynoldsFilm(GEOMETRY, n_theta=n_theta, n_z=n_z, tolerance=1e-13)
    state = FilmState(eccentricity_x=15e-6, eccentricity_y=5e-6, velocity_x=1e-3, velocity_y=0.0,
                      journal_speed=200.0, viscosity=0.02)
    pressure = film.solve(state, with_pressure=True).pressure
    problem = film._problem(state)
    g = film.film_grid
    a_east, a_north, source = kernel.assemble_coefficients(
        problem.h, problem.h_rate, g.radius, g.d_theta, g.d_z, 200.0, 0.02)
    imbalance = kernel.node_imbalance(pressure, a_east, a_north, source)
    free = ~problem.fixed
    active = free & (pressure > 0.0)
    scale = np.abs(source).max()
    assert pressure.min() >= 0.0
    assert np.abs(imbalance[active]).max() < 1e-8 * scale
    assert imbalance[free & ~active].min() > -1e-8 * scale
    assert 0.2 < active[free].mean() < 0.8  # a real free boundary


def test_w_cycle_from_four_coarse_levels():
    assert multigrid.coarse_levels(288, 32) >= multigrid.W_CYCLE_LEVELS
    assert multigrid.coarse_levels(144, 16) < multigrid.W_CYCLE_LEVELS
