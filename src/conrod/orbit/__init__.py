"""Journal-centre orbit over the cycle: equations of motion, integrators, hard contact,
film memory held by the integrator, periodicity loop and heat balance ([D0] §3,
[D4] §4.1–4.2)."""

from conrod.orbit.integrators import (
    AdaptiveIntegrator,
    HeunIntegrator,
    Integrator,
    QuasiStaticIntegrator,
)
from conrod.orbit.memory import FilmSession
from conrod.orbit.periodic import PeriodicOrbit, integrate_cycle, periodic_orbit
from conrod.orbit.problem import OrbitProblem, OrbitState, initial_state

__all__ = [
    "AdaptiveIntegrator", "FilmSession", "HeunIntegrator", "Integrator", "OrbitProblem",
    "OrbitState", "PeriodicOrbit", "QuasiStaticIntegrator", "initial_state", "integrate_cycle",
    "periodic_orbit",
]
