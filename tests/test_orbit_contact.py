"""Hard contact in the orbit (seed 004 §4.1–4.2; issue 5 validation list)."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest

from conrod.orbit import periodic_orbit
from conrod.orbit.contact import (
    contact_acceleration,
    project_onto_circle,
    remove_normal_velocity,
)
from orbit_helpers import engine_like_load, load_cycle, short_problem, solver

CLEARANCE = 25e-6
CONTACT_H = 0.25 * CLEARANCE


def test_projection_and_normal_velocity_removal_follow_seed_equations():
    x, y, projected = project_onto_circle(3.0, 4.0, 2.5)  # Z = 2
    assert projected and (x, y) == pytest.approx((1.5, 2.0))
    vx, vy = remove_normal_velocity(3.0, 4.0, 1.0, 2.0)
    assert vx * 3.0 + vy * 4.0 == pytest.approx(0.0, abs=1e-15)  # V_n = 0 (eq. 4.1.5)
    v_k = 2.0 * 0.6 - 1.0 * 0.8  # eq. 4.1.6 with cos = 0.6, sin = 0.8
    assert (vx, vy) == pytest.approx((-v_k * 0.8, v_k * 0.6))  # eqs 4.1.7–4.1.8


def test_contact_force_is_normal_component_and_friction_opposes_sliding():
    # journal on the circle at 90°, force X = (300, 1000): P_n = 1000, P_k = −300 (eq. 4.2.3–4)
    ax, ay, p_c, p_f = contact_acceleration(
        0.0, 1.0, 0.0, 0.0, 300.0, 1000.0, 2.0, 2.0, 0.1, 1.0, 5.0, True
    )
    assert p_c == pytest.approx(1000.0)  # eq. 4.2.5 (at rest: no centripetal term)
    assert p_f == pytest.approx(100.0)  # eq. 4.2.6
    # sliding speed +5 m/s along t = (−1, 0): friction along +x, K = P_k + P_f = −300 + 100
    assert ax == pytest.approx((300.0 + 100.0) / 2.0) and ay == pytest.approx(0.0, abs=1e-12)


@pytest.mark.parametrize("integrator", ["adaptive", "rk2"])
def test_pressing_without_rotation_gives_contact_force_equal_to_load(integrator):
    load = 5000.0
    direction = math.radians(30.0)
    loads = load_cycle(lambda p: load * math.cos(direction) + 0 * p,
                       lambda p: load * math.sin(direction) + 0 * p,
                       cycle=2 * math.pi, journal=0.0)
    problem = short_problem(loads, contact_film_thickness=CONTACT_H)
    settings = solver(max_cycles=2, min_cycles=2, step_deg=0.001)  # explicit: stiff squeeze
    last = periodic_orbit(problem, settings, integrator=integrator).last
    assert last.in_contact[-1]
    assert last.contact_force[-1] == pytest.approx(load, rel=1e-6)
    assert last.friction_force[-1] == pytest.approx(0.0, abs=1e-6)  # no sliding: sticks
    assert math.atan2(last.y[-1], last.x[-1]) == pytest.approx(direction, abs=1e-6)


@functools.cache
def _contact_orbit(integrator: str, output_step_deg: float = 0.25):
    loads = load_cycle(*engine_like_load(peak=4.0e4, base=3.0e3))
    problem = short_problem(loads, viscosity=0.005, contact_film_thickness=CONTACT_H)
    settings = solver(max_cycles=3, output_step_deg=output_step_deg, step_deg=0.0025)
    return problem, periodic_orbit(problem, settings, integrator=integrator).last


def _intervals(crank_angle, in_contact):
    """(entry, exit) crank angles [deg] of contact, assuming one interval that may wrap."""
    shifted = np.roll(in_contact, -np.argmin(in_contact))  # start outside contact
    angles = np.roll(np.degrees(crank_angle), -np.argmin(in_contact))
    idx = np.flatnonzero(shifted)
    return angles[idx[0]], angles[idx[-1]], np.all(np.diff(idx) == 1)


@pytest.fixture(scope="module", params=["adaptive", "rk2"])
def contact_orbit(request):
    return _contact_orbit(request.param)


def test_no_penetration_anywhere(contact_orbit):
    problem, last = contact_orbit
    z = np.hypot(last.x, last.y) / problem.contact_radius
    assert np.any(last.in_contact)
    assert np.max(z) <= 1.0 + 1e-9


def test_normal_velocity_is_zero_during_contact(contact_orbit):
    problem, last = contact_orbit
    inside = last.in_contact
    normal = (last.x * last.vx + last.y * last.vy) / np.hypot(last.x, last.y)
    scale = problem.clearance * problem.crank_speed
    assert np.max(np.abs(normal[inside])) <= 1e-9 * scale
    assert np.all(last.contact_force[inside] >= 0.0)
    assert np.all(last.contact_force[~inside] == 0.0)


def test_orbit_is_continuous_at_contact_entry_and_exit(contact_orbit):
    problem, last = contact_orbit
    entry, leave, single = _intervals(last.crank_angle, last.in_contact)
    assert single
    step = np.diff(last.crank_angle[:2])[0] / problem.crank_speed
    speed = np.hypot(last.vx, last.vy)
    jumps = np.hypot(np.diff(last.x), np.diff(last.y))
    # every move between samples is explained by the local speed (no jump at entry/exit)
    assert np.all(jumps <= 1.5 * step * np.maximum(speed[1:], speed[:-1]) + 1e-12)


def test_contact_interval_agrees_between_integrators():
    _, adaptive = _contact_orbit("adaptive")
    _, rk2 = _contact_orbit("rk2")
    a = _intervals(adaptive.crank_angle, adaptive.in_contact)
    b = _intervals(rk2.crank_angle, rk2.in_contact)
    print("contact interval adaptive", a[:2], "rk2", b[:2])
    assert a[0] == pytest.approx(b[0], abs=1.0) and a[1] == pytest.approx(b[1], abs=1.0)
    assert adaptive.contact_force.max() == pytest.approx(rk2.contact_force.max(), rel=0.03)
