"""Volume fluxes and dissipation of a solved Reynolds film
(:class:`~conrod.film.thermal.flows.FilmFlows`), the drive of the film's energy equation.

The fluxes are those of the discrete balance of :mod:`conrod.film.reynolds.kernel`: through
the east face Q_e = (U/2) h_e w_j + a_E (p_P − p_E)/(12 μ_r), through the north face
Q_n = a_N (p_P − p_N)/(12 μ_r), U = R(ω_j + ω_b), with the conductances of the solve (of the
conductance thickness with a viscosity field); so they satisfy the solve's mass balance at
every free full-film node. The dissipation takes the local viscosity
(:func:`conrod.film.thermal.flows.shear_dissipation`), full-film Couette shear in the
cavitated zone as the film's ``full_film`` friction convention does.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import numpy as np

from conrod.film.base import FilmState
from conrod.film.supply import edge_mask
from conrod.film.thermal.flows import FilmFlows, shear_dissipation


def film_flows(film: Any, state: FilmState, memory: Any) -> tuple[FilmFlows, np.ndarray]:
    """(:class:`FilmFlows` of ``state``, the solved pressure [Pa]) of a
    :class:`~conrod.film.reynolds.film.ReynoldsFilm` warm-started from ``memory``."""
    problem = film.discrete_problem(state)
    pressure, _ = film.solve_pressure(problem, state, memory)
    a_east, a_north, _ = problem.coefficients
    grid = film.film_grid
    reference = state.viscosity
    surface = grid.radius * (state.journal_speed + state.shell_speed)
    h = problem.h
    weights = grid.axial_weights[None, :]
    h_east = 0.5 * (h + np.roll(h, -1, axis=0))
    east = (0.5 * surface * h_east * weights
            + a_east * (pressure - np.roll(pressure, -1, axis=0)) / (12.0 * reference))
    north = np.zeros(h.shape)
    north[:, :-1] = a_north * (pressure[:, :-1] - pressure[:, 1:]) / (12.0 * reference)
    field = state.viscosity_field if state.viscosity_field is not None else film.viscosity_field
    viscosity = np.full(h.shape, reference) if field is None else field
    sliding = grid.radius * (state.journal_speed - state.shell_speed)
    dissipation = shear_dissipation(pressure, h, viscosity, sliding, grid.radius,
                                    grid.d_theta, grid.axial_weights, grid.d_z)
    supply = problem.fixed & ~edge_mask(grid)
    flows = FilmFlows(east=east, north=north, dissipation=dissipation,
                      area=grid.area_weights, supply=supply,
                      squeeze_power=-float(np.sum(pressure * problem.h_rate * grid.area_weights)))
    pumping = float(np.sum((pressure * flows.net_outflow())[supply]))
    return replace(flows, pumping_power=pumping), pressure
