"""Journal-centre orbit over the cycle: equations of motion, integrators, hard contact,
periodicity loop and heat balance ([D0] §3, [D4] §4.1–4.2)."""

from conrod.orbit.periodic import PeriodicOrbit, integrate_cycle, periodic_orbit
from conrod.orbit.problem import OrbitProblem, OrbitState, initial_state

__all__ = [
    "OrbitProblem", "OrbitState", "PeriodicOrbit", "initial_state", "integrate_cycle",
    "periodic_orbit",
]
