"""The orbit with mass on grid films (compiled Reynolds free flight) and the accelerated
periodic orbit, against independent answers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.orbit import OrbitState, integrate_cycle, periodic_orbit
from conrod.orbit.acceleration import AndersonMixing
from conrod.orbit.progress import reporting
from orbit_helpers import (
    SPEED,
    assert_settles_at_steady_point,
    engine_like_load,
    geometry,
    load_cycle,
    short_problem,
    solver,
)


def _reynolds(n_theta=24, n_z=8, **geometry_kwargs):
    return ReynoldsFilm(geometry(**geometry_kwargs), n_theta=n_theta, n_z=n_z)


@pytest.mark.parametrize("feed", ["none", "groove", "hole off the mid-plane"])
def test_compiled_force_and_jacobian_equal_the_film_and_its_adjoint(feed):
    """The compiled kernel's force equals the film's own solve (nested grids, full grid,
    Python assembly of the source) and its forward-difference Jacobian the adjoint
    sensitivities on the converged active set (conrod.film.linearised): unfed, a 120°
    groove at 0.3 MPa (mid-plane symmetric, half grid) and a feed hole 4 mm off the
    mid-plane (full grid)."""
    from conrod.film.base import FeedHole, Groove
    from conrod.film.linearised import linearise_reynolds
    from conrod.film.reynolds.flight import flight_kernel, reynolds_force, reynolds_jacobian

    supply = {"none": {},
              "groove": {"grooves": (Groove(2.0, 2.1, 0.004),), "supply_pressure": 3e5},
              "hole off the mid-plane": {"feed_holes": (FeedHole(2.5, 0.004, 0.004),),
                                         "supply_pressure": 3e5}}[feed]
    g = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6, **supply)
    film = ReynoldsFilm(g, n_theta=48, n_z=16)
    kernel = flight_kernel(film, None, 1e-12)
    c = g.radial_clearance
    rng = np.random.default_rng(3)
    for _ in range(4):
        eps, angle = rng.uniform(0.2, 0.85), rng.uniform(0, 2 * math.pi)
        state = FilmState(eccentricity_x=eps * c * math.cos(angle),
                          eccentricity_y=eps * c * math.sin(angle),
                          velocity_x=rng.normal() * c * SPEED * 0.3,
                          velocity_y=rng.normal() * c * SPEED * 0.3,
                          journal_speed=SPEED, shell_speed=0.0, viscosity=0.01)
        args = (state.eccentricity_x, state.eccentricity_y, state.velocity_x,
                state.velocity_y, SPEED, 0.01, kernel.params)
        expected = np.array(film.force(state))
        assert np.allclose(reynolds_force(*args), expected, rtol=1e-7, atol=0.0)
        _, jacobian = reynolds_jacobian(*args)
        adjoint = linearise_reynolds(film, state)
        reference = np.hstack(adjoint.force_jacobian)
        scale = np.abs(reference).max(axis=1, keepdims=True)
        assert np.max(np.abs(jacobian - reference) / scale) < 2e-3


def test_the_compiled_path_is_taken_and_agrees_with_the_python_path():
    """Same cycle through the compiled kernel and through the film's Python interface
    (finite-difference-free adjoint Jacobian, film solved at 1e-12): equal within the
    integrator's tolerance."""
    from conrod.orbit import implicit

    problem = short_problem(load_cycle(*engine_like_load(peak=6e3)), film=_reynolds(),
                            mass=2.0)
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    settings = solver()
    compiled = integrate_cycle(problem, start, settings, "implicit")
    original = implicit.HasFlightKernel
    try:
        implicit.HasFlightKernel = type("Nothing", (), {})
        python = integrate_cycle(problem, start, settings, "implicit")
    finally:
        implicit.HasFlightKernel = original
    difference = np.max(np.hypot(compiled.x - python.x, compiled.y - python.y))
    print(f"compiled vs python path: {difference / problem.clearance:.2e} c")
    assert difference < 1e-3 * problem.clearance


@pytest.mark.slow
def test_reynolds_orbit_with_mass_is_second_order():
    """TR-BDF2 on the Reynolds film with steps fixed by max_step_deg (tolerance 1e-5, at
    which the error control does not shorten steps of 1° … 0.25°) against a reference at
    1e-10 and 0.1°: the error falls with the square of the step (fitted order 1.7–2.3;
    measured 1.9)."""
    problem = short_problem(load_cycle(*engine_like_load(peak=6e3)), film=_reynolds(),
                            mass=2.0)
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    reference = integrate_cycle(problem, start, solver(
        relative_tolerance=1e-10, absolute_tolerance=1e-10, max_step_deg=0.1), "implicit")
    steps = np.array([1.0, 0.5, 0.25])
    errors = []
    for step in steps:
        traj = integrate_cycle(problem, start, solver(
            relative_tolerance=1e-5, absolute_tolerance=1e-5, max_step_deg=step), "implicit")
        errors.append(np.max(np.hypot(traj.x - reference.x, traj.y - reference.y)))
    order = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    print(f"error/c {np.array(errors) / problem.clearance}, order {order:.3f}")
    assert 1.7 < order < 2.3


def test_reynolds_massless_limit_is_the_quasi_static_orbit():
    """Mass → 0: the orbit with mass tends to the massless (quasi-static) orbit on the same
    Reynolds film, the difference shrinking with the mass."""
    settings = solver(max_cycles=3, absolute_tolerance=1e-6, quasi_static_step_deg=0.25)
    differences = []
    for mass in (0.1, 0.01):
        problem = short_problem(load_cycle(*engine_like_load(peak=6e3)), film=_reynolds(),
                                mass=mass)
        dynamic = periodic_orbit(problem, settings, integrator="implicit").last
        massless = periodic_orbit(problem, settings, integrator="quasi_static").last
        difference = np.hypot(dynamic.x - massless.x, dynamic.y - massless.y)
        differences.append(np.max(difference) / problem.clearance)
    print(f"max |e_mass - e_massless|/c at 0.1, 0.01 kg: {differences}")
    assert differences[1] < differences[0] < 1e-3
    assert differences[1] < 1e-4


@pytest.mark.parametrize(("massless_start", "most_cycles"), [(True, 3), (False, 4)])
def test_table_film_constant_load_settles_at_the_steady_point(massless_start, most_cycles):
    """Default integrator on the tabulated Reynolds film: the orbit ends at the static
    equilibrium F(e, 0) + W = 0 of the same table (scipy fsolve), ε and attitude within
    0.5 %, after at most three cycles with mass from the massless start, four from the
    concentric one (the default)."""
    from conrod.film.table.film import TabulatedFilm

    film = TabulatedFilm(ReynoldsFilm(geometry(width=0.05), n_theta=36, n_z=8))
    load = 5000.0
    loads = load_cycle(lambda p: load + 0 * p, lambda p: 0 * p, cycle=2 * math.pi, n=12)
    problem = short_problem(loads, film=film)
    orbit = periodic_orbit(problem, solver(max_cycles=most_cycles, periodicity_tolerance=1e-4,
                                           massless_start=massless_start))
    assert_settles_at_steady_point(orbit, film, load, most_cycles)


def test_anderson_mixing_solves_a_linear_map_in_few_cycles():
    """x → A x + b with a slowly contracting A (spectral radius 0.9): plain repetition
    needs ~90 iterations to 1e-10, the mixing (depth 3 on a 2-d map, a secant method)
    reaches the fixed point (A − I)⁻¹(−b) from numpy.linalg.solve in far fewer."""
    a = np.array([[0.6, 0.5], [-0.4, 0.7]])
    b = np.array([0.3, -0.1])
    exact = np.linalg.solve(np.eye(2) - a, b)
    mixing = AndersonMixing(limit=1e9)
    x, count = np.zeros(2), 0
    while np.linalg.norm(a @ x + b - x) >= 1e-10 and count < 50:
        image = a @ x + b
        proposal = mixing.propose(x, image)
        x = image if proposal is None else proposal
        count += 1
    plain, plain_count = np.zeros(2), 0
    while np.linalg.norm(a @ plain + b - plain) >= 1e-10 and plain_count < 10000:
        plain = a @ plain + b
        plain_count += 1
    print(f"anderson {count}, plain {plain_count} iterations")
    assert np.allclose(x, exact, atol=1e-9)
    assert count <= 6 < plain_count


@pytest.mark.parametrize("film", ["short", "reynolds"])
def test_accelerated_orbit_equals_the_repeated_cycles_in_fewer_cycles(film):
    """From the concentric start under a constant load (the slowly decaying spiral into
    the equilibrium): the Anderson-accelerated orbit equals the plainly repeated one
    within the periodicity tolerance and needs fewer cycles."""
    loads = load_cycle(lambda p: 5000.0 + 0 * p, lambda p: 0 * p, cycle=2 * math.pi, n=12)
    chosen = None if film == "short" else ReynoldsFilm(geometry(width=0.05), n_theta=24,
                                                        n_z=8)
    problem = short_problem(loads, film=chosen, mass=5.0, width=0.05)
    orbits = {}
    for accelerate in (False, True):
        settings = solver(max_cycles=12, massless_start=False, accelerate_cycles=accelerate)
        orbits[accelerate] = periodic_orbit(problem, settings)
    plain, fast = orbits[False], orbits[True]
    difference = np.max(np.hypot(plain.last.x - fast.last.x, plain.last.y - fast.last.y))
    print(f"{film}: plain {plain.cycles} cycles {plain.history}, accelerated "
          f"{fast.cycles} cycles {fast.history}; difference {difference / 25e-6:.2e} c")
    assert plain.periodic and fast.periodic
    assert fast.cycles < plain.cycles
    assert difference <= 1e-3 * problem.clearance


def test_in_cycle_reports_do_not_change_the_orbit():
    """On a grid film the implicit integrator reports increasing crank angles every 30°
    up to the cycle's end, and the orbit is bit for bit the same with and without a
    listener."""
    problem = short_problem(load_cycle(*engine_like_load(peak=6e3)), film=_reynolds(),
                            mass=2.0)
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    angles: list[float] = []
    with reporting(angles.append):
        heard = integrate_cycle(problem, start, solver(), "implicit")
    silent = integrate_cycle(problem, start, solver(), "implicit")
    assert np.all(np.diff(angles) > 0.0) and angles[-1] == pytest.approx(4 * math.pi)
    assert len(angles) == 24
    assert np.array_equal(heard.x, silent.x) and np.array_equal(heard.vy, silent.vy)


def test_massless_grid_orbit_reports_its_crank_angle_every_30_degrees():
    """The massless orbit on a fed grid film (its Python step loop) reports the crank
    angle in the cycle too (the progress display moves within a cycle), without changing
    the orbit."""
    from conrod.film.base import Groove

    fed = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6,
                          grooves=(Groove(2.0, 2.1, 0.004),), supply_pressure=3e5)
    problem = short_problem(load_cycle(*engine_like_load(peak=6e3)),
                            film=ReynoldsFilm(fed, n_theta=24, n_z=8), mass=2.0)
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    settings = solver(quasi_static_step_deg=2.0, output_step_deg=2.0)
    angles: list[float] = []
    with reporting(angles.append):
        heard = integrate_cycle(problem, start, settings, "quasi_static")
    silent = integrate_cycle(problem, start, settings, "quasi_static")
    assert np.all(np.diff(angles) > 0.0) and len(angles) == 23  # 30°, 60°, …, 690°
    assert np.allclose(np.diff(angles), math.radians(30.0))
    assert np.array_equal(heard.x, silent.x) and np.array_equal(heard.y, silent.y)
