"""The TR-BDF2 orbit integrator with mass against independent answers."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from conrod.orbit import OrbitState, integrate_cycle, periodic_orbit
from orbit_helpers import (
    SPEED,
    assert_settles_at_steady_point,
    engine_like_load,
    geometry,
    load_cycle,
    short_problem,
    solver,
)


def _engine_problem(mass=40.0):
    return short_problem(load_cycle(*engine_like_load(peak=8.0e3)), mass=mass, viscosity=0.006)


def short_bearing_capacity(eps, viscosity, radius, width, clearance, omega_eff):
    """Load capacity of the short bearing at the effective speed ω_eff = ω_j + ω_b − 2Ω
    (Hamrock, Fundamentals of Fluid Film Lubrication, ch. 10; Booker 1965) [N]."""
    u = radius * abs(omega_eff)
    root = math.sqrt(16 * eps**2 + math.pi**2 * (1 - eps**2))
    return viscosity * u * width**3 * eps * root / (4 * clearance**2 * (1 - eps**2) ** 2)


def test_fixed_step_order_is_two():
    """Error-control off (loose tolerances): steps = max_step_deg; error against a Radau
    reference at 1e-10 falls with the square of the step (TR-BDF2 is second order)."""
    problem = _engine_problem()
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    reference = integrate_cycle(
        problem, start, solver(relative_tolerance=1e-10, absolute_tolerance=1e-10,
                               max_step_deg=0.25), "adaptive")
    steps = np.array([1.0, 0.5, 0.25, 0.125])
    errors = []
    for step in steps:
        loose = solver(max_step_deg=step, relative_tolerance=1e-2, absolute_tolerance=1.0)
        traj = integrate_cycle(problem, start, loose, "implicit")
        errors.append(np.max(np.hypot(traj.x - reference.x, traj.y - reference.y)))
    order = np.polyfit(np.log(steps), np.log(errors), 1)[0]
    print(f"implicit order {order:.3f}, errors/c {np.array(errors) / problem.clearance}")
    assert 1.8 < order < 2.3


def test_error_controlled_orbit_agrees_with_tight_radau_reference():
    problem = _engine_problem()
    start = OrbitState(5e-6, 2e-6, 0.0, 0.0)
    reference = integrate_cycle(
        problem, start, solver(relative_tolerance=1e-10, absolute_tolerance=1e-10,
                               max_step_deg=0.25), "adaptive")
    errors = []
    for tolerance in (1e-4, 1e-6):
        traj = integrate_cycle(problem, start, solver(absolute_tolerance=tolerance),
                               "implicit")
        errors.append(np.max(np.hypot(traj.x - reference.x, traj.y - reference.y))
                      / problem.clearance)
    print(f"global error/c at tolerances 1e-4, 1e-6: {errors}")
    # second order with per-step control: global error ∝ tol^(2/3) (factor ~21 here)
    assert errors[0] / errors[1] > 5.0  # measured 9.7
    assert errors[0] < 1e-3 and errors[1] < 2e-5


def test_massless_limit_is_the_quasi_static_orbit():
    settings = solver(max_cycles=3, absolute_tolerance=1e-6, quasi_static_step_deg=0.25)
    differences = []
    for mass in (0.1, 0.01):
        problem = short_problem(load_cycle(*engine_like_load()), mass=mass)
        dynamic = periodic_orbit(problem, settings, integrator="implicit").last
        massless = periodic_orbit(problem, settings, integrator="quasi_static").last
        difference = np.hypot(dynamic.x - massless.x, dynamic.y - massless.y)
        differences.append(np.max(difference) / problem.clearance)
    # same bounds as the adaptive integrator's massless-limit test
    assert differences[1] < differences[0] < 1e-3
    assert differences[1] < 1e-4


@pytest.mark.parametrize("whirl", [0.0, 1.0, -1.0])
def test_rotating_load_settles_at_booker_effective_speed(whirl):
    """A load of constant size rotating at Ω = whirl·ω: in the load frame the journal
    rests where the short bearing at ω_eff = ω − 2Ω carries it (Booker's mobility
    argument); attitude on the side of the sign of ω_eff. Mass 0.05 kg: the centripetal
    force m Ω² e is < 1e-5 of the load."""
    load = 6000.0
    loads = load_cycle(lambda p: load * np.cos(whirl * p), lambda p: load * np.sin(whirl * p),
                       cycle=2 * math.pi)
    problem = short_problem(loads, mass=0.05)
    settings = solver(integrator="implicit", max_cycles=6, min_cycles=3,
                      periodicity_tolerance=1e-5, absolute_tolerance=1e-7)
    orbit = periodic_orbit(problem, settings)
    g = problem.film.geometry
    omega_eff = SPEED * (1.0 - 2.0 * whirl)
    eps = brentq(lambda e: short_bearing_capacity(e, 0.01, g.radius, g.width,
                                                  g.radial_clearance, omega_eff) - load,
                 1e-9, 1 - 1e-9, xtol=1e-14)
    attitude = math.copysign(math.atan(math.pi * math.sqrt(1 - eps**2) / (4 * eps)), omega_eff)
    last = orbit.last
    assert orbit.periodic
    e = np.hypot(last.x, last.y) / g.radial_clearance
    angle = np.angle((last.x + 1j * last.y) * np.exp(-1j * whirl * last.crank_angle))
    assert np.max(np.abs(e / eps - 1.0)) < 1e-4
    assert np.max(np.abs(angle - attitude)) < 1e-4 * abs(attitude) + 1e-6


def test_half_speed_whirl_has_no_capacity():
    """Ω = ω/2 gives ω_eff = 0: only squeeze carries the load, so the journal keeps
    sinking cycle after cycle towards the shell (no steady position)."""
    load = 6000.0
    loads = load_cycle(lambda p: load * np.cos(0.5 * p), lambda p: load * np.sin(0.5 * p),
                       cycle=4 * math.pi)
    problem = short_problem(loads, mass=0.05)
    state, peaks = OrbitState(), []
    for _ in range(3):
        traj = integrate_cycle(problem, state, solver(), "implicit")
        e = np.hypot(traj.x, traj.y) / problem.clearance
        peaks.append(e.max())
        state = traj.end_state
        assert np.all(np.diff(e) > 0.0)
    print("eccentricity at the end of cycles 1-3:", peaks)
    assert peaks[0] < peaks[1] < peaks[2] < 1.0


def test_same_input_same_output_bit_for_bit():
    problem = _engine_problem()
    settings = solver(max_cycles=2)
    first = periodic_orbit(problem, settings, integrator="implicit").last
    second = periodic_orbit(problem, settings, integrator="implicit").last
    for name in ("x", "y", "vx", "vy", "contact_force"):
        assert np.array_equal(getattr(first, name), getattr(second, name))


def test_contact_interval_agrees_with_adaptive():
    """The contact orbit of tests/test_orbit_contact.py: same contact interval (±1°) and
    peak contact force (3 %) as the Radau integrator."""
    loads = load_cycle(*engine_like_load(peak=4.0e4, base=3.0e3))
    problem = short_problem(loads, viscosity=0.005, contact_film_thickness=6.25e-6)
    settings = solver(max_cycles=3, output_step_deg=0.25)
    orbits = [periodic_orbit(problem, settings, integrator=name).last
              for name in ("implicit", "adaptive")]
    intervals = [_intervals(o.crank_angle, o.in_contact) for o in orbits]
    print("contact intervals implicit, adaptive:", intervals)
    assert intervals[0][2] and intervals[1][2]
    assert intervals[0][0] == pytest.approx(intervals[1][0], abs=1.0)
    assert intervals[0][1] == pytest.approx(intervals[1][1], abs=1.0)
    assert orbits[0].contact_force.max() == pytest.approx(orbits[1].contact_force.max(),
                                                          rel=0.03)
    assert np.max(np.hypot(orbits[0].x, orbits[0].y)) <= problem.contact_radius * (1 + 1e-9)


def _intervals(crank_angle, in_contact):
    """(entry, exit) crank angles [deg] of contact, assuming one interval that may wrap."""
    shifted = np.roll(in_contact, -np.argmin(in_contact))  # start outside contact
    angles = np.roll(np.degrees(crank_angle), -np.argmin(in_contact))
    idx = np.flatnonzero(shifted)
    return angles[idx[0]], angles[idx[-1]], np.all(np.diff(idx) == 1)


@pytest.mark.parametrize("name", ["mobility", "table"])
def test_map_films_refuse_a_supply_pressure_naming_the_film_asked(name):
    from conrod.errors import CaseError
    from conrod.film.base import BearingGeometry, Groove
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.film.table.film import TabulatedFilm
    from conrod.film.table.mobility import MobilityFilm

    fed = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6,
                          grooves=(Groove(width=0.004),),
                          supply_pressure=3e5)
    with pytest.raises(CaseError, match=f"film '{name}'.*use film 'reynolds'"):
        if name == "mobility":
            MobilityFilm(fed)
        else:
            TabulatedFilm(ReynoldsFilm(fed, n_theta=16, n_z=8))


@pytest.mark.parametrize(("massless_start", "most_cycles"), [(True, 3), (False, 4)])
def test_constant_load_on_reynolds_film_settles_at_the_steady_point(massless_start,
                                                                    most_cycles):
    """Default integrator (auto → implicit), from the periodic massless orbit or the
    concentric position (the default): the orbit with mass ends at the static equilibrium
    F(e, 0) + W = 0 found by a root solver on the same film (scipy fsolve), ε and attitude
    within 0.5 %, after at most three cycles with mass from the massless start, four from
    the concentric one (the slowly spiralling orbit of a constant load: periodicity errors
    0.56, 0.037, 5e-4, 7e-6)."""
    from conrod.film.reynolds.film import ReynoldsFilm

    load = 5000.0
    film = ReynoldsFilm(geometry(width=0.05), n_theta=36, n_z=8)
    loads = load_cycle(lambda p: load + 0 * p, lambda p: 0 * p, cycle=2 * math.pi, n=12)
    problem = short_problem(loads, film=film)
    orbit = periodic_orbit(problem, solver(max_cycles=most_cycles, min_cycles=2,
                                           periodicity_tolerance=1e-4,
                                           massless_start=massless_start))
    assert_settles_at_steady_point(orbit, film, load, most_cycles)


def test_a_failed_free_flight_names_what_to_change_for_the_film():
    """The piezoviscous Reynolds film on the shipped 2000 rpm case makes the implicit step
    collapse (force steep in the journal velocity): the message says so and names the
    isoviscous film, not a tolerance that would not help."""
    from conrod.film.piezoviscosity import PressureViscosity
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.orbit.implicit import _failure_hint

    law = PressureViscosity(law="barus", coefficient=1.5e-8)
    piezo = ReynoldsFilm(geometry(), n_theta=12, n_z=4, pressure_viscosity=law)
    assert "pressure_viscosity = 'none'" in _failure_hint(piezo)
    assert "relative_tolerance" in _failure_hint(ReynoldsFilm(geometry(), n_theta=12, n_z=4))
