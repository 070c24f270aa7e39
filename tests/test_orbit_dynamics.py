"""Orbit integrators against independent answers (issue 4 validation list)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from conrod.orbit import OrbitState, integrate_cycle, periodic_orbit
from orbit_helpers import SPEED, engine_like_load, geometry, load_cycle, short_problem, solver


def short_bearing_steady(load, viscosity, radius, width, clearance, omega):
    """Closed-form steady ε and attitude angle of the short bearing (Hamrock ch. 10)."""
    u = radius * omega

    def capacity(eps):
        root = math.sqrt(16 * eps**2 + math.pi**2 * (1 - eps**2))
        return viscosity * u * width**3 * eps * root / (4 * clearance**2 * (1 - eps**2) ** 2)

    eps = brentq(lambda e: capacity(e) - load, 1e-9, 1 - 1e-9, xtol=1e-14)
    return eps, math.atan(math.pi * math.sqrt(1 - eps**2) / (4 * eps))


@pytest.mark.parametrize("integrator", ["adaptive", "quasi_static", "rk2"])
def test_constant_load_settles_at_steady_short_bearing_solution(integrator):
    load = 6000.0
    loads = load_cycle(lambda p: load + 0 * p, lambda p: 0 * p, cycle=2 * math.pi)
    mass = 20.0 if integrator == "rk2" else 1.0
    problem = short_problem(loads, mass=mass)
    settings = solver(integrator=integrator, step_deg=0.05, max_cycles=8, min_cycles=3,
                      periodicity_tolerance=1e-6)
    orbit = periodic_orbit(problem, settings)
    g = problem.film.geometry
    eps, attitude = short_bearing_steady(load, 0.01, g.radius, g.width, g.radial_clearance, SPEED)
    last = orbit.last
    assert orbit.periodic
    assert np.hypot(last.x[-1], last.y[-1]) / g.radial_clearance == pytest.approx(eps, rel=1e-4)
    assert math.atan2(last.y[-1], last.x[-1]) == pytest.approx(attitude, rel=1e-4)


def _engine_problem(mass=40.0):
    return short_problem(load_cycle(*engine_like_load(peak=8.0e3)), mass=mass, viscosity=0.006)


def test_rk2_converges_with_second_order_and_agrees_with_adaptive():
    problem = _engine_problem()
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    reference = integrate_cycle(
        problem, start, solver(relative_tolerance=1e-10, absolute_tolerance=1e-10,
                               max_step_deg=0.25), "adaptive",
    )
    steps = np.array([0.2, 0.1, 0.05, 0.025])
    errors = []
    for step in steps:
        traj = integrate_cycle(problem, start, solver(step_deg=step), "rk2")
        errors.append(np.max(np.hypot(traj.x - reference.x, traj.y - reference.y)))
    order = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    print(f"rk2 order {order:.3f}, error at 0.025 deg {errors[-1] / problem.clearance:.2e} c")
    assert 1.8 < order < 2.2
    assert errors[-1] / problem.clearance < 1e-4


def test_quasi_static_is_the_massless_limit_of_the_dynamic_orbit():
    settings = solver(max_cycles=3, relative_tolerance=1e-7, absolute_tolerance=1e-6,
                      quasi_static_step_deg=0.25)
    differences = []
    for mass in (0.1, 0.01):
        problem = short_problem(load_cycle(*engine_like_load()), mass=mass)
        dynamic = periodic_orbit(problem, settings).last
        massless = periodic_orbit(problem, settings, integrator="quasi_static").last
        difference = np.hypot(dynamic.x - massless.x, dynamic.y - massless.y)
        differences.append(np.max(difference) / problem.clearance)
    # measured: 2.0e-4 (0.1 kg), 5.6e-5 (0.01 kg; floor set by the 0.25° quasi-static step)
    assert differences[1] < differences[0] < 1e-3
    assert differences[1] < 1e-4


@pytest.mark.slow
def test_short_and_finite_difference_orbits_converge_as_bearing_gets_shorter():
    reynolds = pytest.importorskip("conrod.film.reynolds.film")
    differences = []
    for width in (0.025, 0.0125, 0.00625):
        g = geometry(width=width)
        scale = (width / 0.025) ** 3  # same eccentricities: capacity ∝ L³
        loads = load_cycle(*engine_like_load(peak=1.2e4 * scale, base=1.5e3 * scale), n=72,
                           cycle=2 * math.pi)
        settings = solver(integrator="quasi_static", quasi_static_step_deg=2.0,
                          output_step_deg=2.0, max_cycles=1, min_cycles=1)
        short = periodic_orbit(short_problem(loads, width=width), settings).last
        fd_film = reynolds.ReynoldsFilm(g, n_theta=72, n_z=10)
        fd = periodic_orbit(short_problem(loads, film=fd_film), settings).last
        differences.append(np.max(np.hypot(short.x - fd.x, short.y - fd.y)) / g.radial_clearance)
    print("max |e_short - e_fd|/c for L/D = 0.5, 0.25, 0.125:", differences)
    assert differences[0] > differences[1] > differences[2]
    assert differences[2] < 0.02


def test_periodicity_loop_reports_non_periodic_orbits():
    problem = _engine_problem(mass=40.0)
    orbit = periodic_orbit(problem, solver(max_cycles=1, min_cycles=1))
    assert not orbit.periodic  # the first cycle from the concentric start does not close
    assert orbit.cycles == 1 and 1e-3 < orbit.periodicity_error < math.inf
    mixed = periodic_orbit(problem, solver(max_cycles=1, min_cycles=1,
                                           periodic_accelerator="anderson"))
    assert not mixed.periodic
    assert mixed.cycles == 1 and math.isinf(mixed.periodicity_error)


def test_rk2_refuses_a_step_beyond_its_stability_limit():
    from conrod.errors import CaseError

    loads = load_cycle(lambda p: 6000.0 + 0 * p, lambda p: 0 * p, cycle=2 * math.pi)
    with pytest.raises(CaseError, match=r"solver.step_deg = 0.05: too large"):
        integrate_cycle(short_problem(loads, mass=1.0), OrbitState(), solver(step_deg=0.05), "rk2")
