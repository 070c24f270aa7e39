"""One grid level of the Reynolds film solved in place: the coefficients of
:mod:`conrod.film.reynolds.kernel` (with a viscosity field the conductances of its
conductance thickness, :mod:`conrod.film.reynolds.viscosity_field`), then projected
multigrid or SOR to the tolerance."""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.errors import ConvergenceError
from conrod.film.base import FilmState
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds import multigrid as multigrid
from conrod.film.reynolds import viscosity_field as vf
from conrod.film.reynolds.problem import optimal_relaxation


def sweep(film: Any, level: Any, pressure: np.ndarray, state: FilmState, tolerance: float,
          fixed_set: bool = False) -> tuple[int, float]:
    """Solve ``level`` (a :class:`~conrod.film.reynolds.problem.DiscreteProblem`) of
    ``film`` in place on ``pressure`` [Pa] (its Dirichlet values already there when
    ``fixed_set``); (sweeps, last relative change [-]); the coefficients are left in
    ``level.coefficients``. :class:`ConvergenceError` beyond ``film.max_iterations``."""
    symmetric = (film.symmetric and not state.tilted and level.grid.n_z % 4 == 0
                 and (state.deformation is None or (vf.mirror_symmetric(level.h)
                                                    and vf.mirror_symmetric(level.h_rate)))
                 and vf.mirror_symmetric(level.conduction))
    g = level.grid
    a_east, a_north, source = kernel.assemble_coefficients(
        level.h, level.h_rate, g.radius, g.d_theta, g.d_z,
        state.journal_speed + state.shell_speed, state.viscosity)
    h_flow = level.h if level.conduction is None else level.conduction
    if level.conduction is not None:  # a viscosity field: the conductances of h_μ
        a_east, a_north = vf.field_conductances(level.conduction, g)
    level.coefficients = (a_east, a_north, source)
    if not fixed_set:
        pressure[level.fixed] = level.fixed_values[level.fixed]
    if film.method == "multigrid":
        cycles, change = multigrid.solve_on_grid(
            pressure, h_flow, source, level.fixed, g, level.cavitation,
            tolerance, film.max_iterations, symmetric)
        sweeps = cycles * (multigrid.PRE_SWEEPS + multigrid.POST_SWEEPS)
    else:
        omega = film.relaxation if film.relaxation is not None else optimal_relaxation(g)
        sweeps, change = kernel.sor_solve(
            pressure, a_east, a_north, source, level.fixed,
            level.cavitation, omega, tolerance, film.max_iterations)
    if not change <= tolerance:
        raise ConvergenceError(
            f"Reynolds {film.method} on {g.n_theta}x{g.n_z} after {sweeps} sweeps",
            where=f"e = ({state.eccentricity_x:.4g}, {state.eccentricity_y:.4g}) m, "
            f"v = ({state.velocity_x:.4g}, {state.velocity_y:.4g}) m/s",
            residual=change)
    return sweeps, change
