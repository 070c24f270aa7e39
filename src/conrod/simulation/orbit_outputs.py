"""What a run computes from its converged orbit besides the characteristics: the heat
balance with every friction, the pressure field at the largest p_max, the film thickness
over shell and cycle, the asperity force of a film that carries it, the cycle before the
last (used by :class:`conrod.simulation.simulation.Simulation`)."""

from __future__ import annotations

import numpy as np

from conrod.film.capabilities import CarriesAsperityContact
from conrod.orbit.heat_balance import effective_temperature
from conrod.orbit.periodic import PeriodicOrbit
from conrod.orbit.problem import OrbitProblem
from conrod.results.cycle_results import CycleResults
from conrod.results.summary import contact_friction_power


def heat_balance_temperature(cycle: CycleResults, lubricant, boundary_power: float = 0.0
                              ) -> float | None:
    """T_eff [°C] from the mean friction power of the film, of hard contact and of the
    asperities (boundary friction, cycle mean ``boundary_power`` [W]) and the mean side
    flow of the cycle."""
    friction = (cycle.friction_power.mean() + contact_friction_power(cycle).mean()
                + boundary_power)
    return effective_temperature(
        float(friction), float(cycle.side_flow.mean()),
        lubricant.supply_temperature, lubricant.density_at(lubricant.supply_temperature),
        lubricant.specific_heat,
    )


def pressure_map(problem: OrbitProblem, cycle: CycleResults, film_memory: list | None = None):
    """(pressure field p(θ, z) [Pa], grid (θ [rad], z [m])) at the crank angle of the
    largest p_max, with the film memory sampled there (film fraction ϑ of a
    mass-conserving film); (None, None) for a film without a pressure field."""
    i = int(cycle.p_max.argmax())
    state = problem.row_state(cycle, i)
    session = problem.session(film_memory[i] if film_memory else None)
    field = session.accepted(state, with_pressure=True).pressure
    if field is None:
        return None, None
    return field, problem.film.grid()


def film_asperity_force(problem: OrbitProblem, cycle: CycleResults,
                         film_memory: list | None) -> np.ndarray | None:
    """The asperity force at each output angle of a film that carries it on its own
    (deformed) gap [N], from one film solve per angle with the memory sampled there; None
    for a film that does not (the rigid shell's is computed from the orbit)."""
    film = problem.film
    if not (isinstance(film, CarriesAsperityContact) and film.carries_asperity()
            and film_memory):
        return None
    from conrod.ehd.cycle import asperity_forces

    return asperity_forces(problem, cycle, film_memory)


def rigid_film_thickness(cycle: CycleResults, clearance: float, points: int = 361
                         ) -> tuple[np.ndarray, np.ndarray]:
    """(shell angles θ [rad], 0 … 2π, ``points`` of them; film thickness
    h(φ, θ) = c − e_x cos θ − e_y sin θ of the rigid bore at each output angle (n_out,
    ``points``) [m])."""
    theta = np.linspace(0.0, 2.0 * np.pi, points)
    h = (clearance - cycle.eccentricity_x[:, None] * np.cos(theta)[None, :]
         - cycle.eccentricity_y[:, None] * np.sin(theta)[None, :])
    return theta, h


def previous_cycle(orbit: PeriodicOrbit) -> np.ndarray | None:
    if orbit.previous is None:
        return None
    return np.vstack([orbit.previous.x, orbit.previous.y])
