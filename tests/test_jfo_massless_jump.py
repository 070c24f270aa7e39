"""The massless mass-conserving orbit where the film force cannot turn with the load.

Where the pressurised film is a strip one row of cells wide, its force points along the
strip for any journal velocity (a damping matrix of rank one) and the massless journal
must jump to a position where more cells fill. The implicit step lands after the jump by
a bracketed search (:mod:`conrod.orbit.content_bracket`); the periodic orbit is checked
against the orbit with mass (whose step never meets a rank-one balance: the mass adds
m/Δt² to every direction) and against plainly repeated cycles.
"""

from __future__ import annotations

import numpy as np
import pytest

from conrod.cases.solver import SolverSection
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.orbit import OrbitProblem
from conrod.orbit.content_bracket import bracketed_balance
from conrod.orbit.periodic import periodic_orbit
from orbit_helpers import fed_bearing_problem

FED_BEARING = {"bore": 0.1082, "width_ratio": 0.3679, "rpm": 3516.0, "clearance": 2.147e-05,
               "supply": 382100.0, "viscosity": 0.01905, "unit_load": 11.43e6}
"""A fed bearing whose massless orbit meets a one-row pressure strip at 36×8 (SI units)."""
SLOW_BEARING = {"bore": 0.1096, "width_ratio": 0.5174, "rpm": 2201.0, "clearance": 1.119e-05,
                "supply": 491500.0, "viscosity": 0.01398, "unit_load": 15.57e6}
"""A fed bearing whose film content settles slowly from cycle to cycle at 36×8."""


def _problem(b: dict) -> OrbitProblem:
    """Central groove fed at the supply pressure; firing pulse on a rotating inertia load."""
    return fed_bearing_problem(b, MassConservingFilm, b["viscosity"])


def _solver(integrator: str, **changes) -> SolverSection:
    settings = {"film": "mass_conserving", "integrator": integrator,
                "quasi_static_step_deg": 1.0, "output_step_deg": 2.0, "max_cycles": 10}
    return SolverSection(**(settings | changes))


def _h_min(problem: OrbitProblem, result) -> float:
    return problem.clearance - float(np.max(np.hypot(result.last.x, result.last.y)))


def test_bracketed_balance_finds_the_root_beyond_a_flat_region():
    """Force F = −(k₁x, k₂ max(y − y_b, 0)): across the load there is no force until
    y > y_b, so every Newton iterate near y = 0 sees a Jacobian of rank one; the root is
    x = W_x/k₁, y = y_b + W_y/k₂ (closed form)."""
    k1, k2, y_b, load = 2.0e9, 5.0e8, 3.0e-6, (300.0, 200.0)

    def residual(x, y):
        force = np.array([-k1 * x, -k2 * max(y - y_b, 0.0)])
        return np.asarray(load) + force, None

    found = bracketed_balance(residual, (1.0e-7, 0.0), load, radius=2.0e-5, clearance=2.0e-5)
    assert found is not None
    assert found.x == pytest.approx(load[0] / k1, rel=1e-8)
    assert found.y == pytest.approx(y_b + load[1] / k2, rel=1e-8)


def test_bracketed_balance_says_none_when_the_root_lies_outside_the_circle():
    """The same force with y_b beyond the contact circle: no balance inside it."""
    def residual(x, y):
        return np.array([300.0 - 2.0e9 * x, 200.0 - 5.0e8 * max(y - 3.0e-5, 0.0)]), None

    assert bracketed_balance(residual, (0.0, 0.0), (300.0, 200.0), radius=2.0e-5,
                             clearance=2.0e-5) is None


@pytest.mark.slow
def test_massless_orbit_through_a_one_row_strip_is_the_orbit_of_vanishing_mass():
    """The massless orbit of a bearing whose film narrows to one row finishes periodic and
    matches the orbit with mass (1 kg, light for a 108 mm big end) within 1 % of h_min."""
    problem = _problem(FED_BEARING)
    massless = periodic_orbit(problem, _solver("quasi_static"))
    with_mass = periodic_orbit(problem, _solver("implicit", massless_start=False))
    assert massless.periodic and with_mass.periodic
    assert _h_min(problem, massless) == pytest.approx(_h_min(problem, with_mass), rel=0.01)


@pytest.mark.slow
def test_content_in_the_cycle_acceleration_reaches_the_orbit_of_repeated_cycles():
    """Anderson mixing with the film content in its state ends on the orbit that plainly
    repeated cycles reach (independent answer: the fixed point of the cycle map), in
    fewer cycles. Bound: repeated cycles contracting by q per cycle stop within
    tol·q/(1 − q) of the fixed point, the mixed run within tol/(1 − q)."""
    tolerance = 2.0e-4
    problem = _problem(SLOW_BEARING)
    plain = periodic_orbit(problem, _solver("quasi_static", accelerate_cycles=False,
                                            periodicity_tolerance=tolerance, max_cycles=16))
    mixed = periodic_orbit(problem, _solver("quasi_static", periodicity_tolerance=tolerance))
    assert plain.periodic and mixed.periodic
    assert mixed.cycles <= plain.cycles // 2
    q = plain.history[-1] / plain.history[-2]
    assert q < 0.6  # the slow but steady contraction the bound assumes
    gap = np.max(np.hypot(mixed.last.x - plain.last.x, mixed.last.y - plain.last.y))
    assert gap <= tolerance * (1.0 + q) / (1.0 - q) * problem.clearance
