"""Worn-shell contact geometry and contact law (seed 003) against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import minimize_scalar

from conrod.mechanism.geometry import (
    contact_force,
    damping_coefficient,
    exact_contact,
    penetration,
    penetration_rate,
    shell_radius,
    shell_radius_slope,
    shell_semi_axes,
    support_penetration,
)

D = 0.048


def test_shell_radius_lies_on_the_ellipse_with_the_right_axes():
    major, minor, ecc = shell_semi_axes(D, 120e-6, 60e-6)
    assert major == pytest.approx((D + 120e-6) / 2, rel=1e-15)
    assert minor == pytest.approx((D + 60e-6) / 2, rel=1e-15)
    angles = np.linspace(0.0, 2 * np.pi, 73)
    radii = np.array([shell_radius(a, minor, ecc) for a in angles])
    x, y = radii * np.cos(angles), radii * np.sin(angles)
    np.testing.assert_allclose((x / major) ** 2 + (y / minor) ** 2, 1.0, rtol=1e-13)
    assert shell_radius(0.0, minor, ecc) == pytest.approx(major, rel=1e-14)
    assert shell_radius(math.pi / 2, minor, ecc) == pytest.approx(minor, rel=1e-14)


def test_shell_radius_slope_matches_finite_difference():
    _, minor, ecc = shell_semi_axes(D, 200e-6, 50e-6)
    step = 1e-6
    for angle in np.linspace(-3.0, 3.0, 13):
        numeric = (shell_radius(angle + step, minor, ecc)
                   - shell_radius(angle - step, minor, ecc)) / (2 * step)
        assert shell_radius_slope(angle, minor, ecc) == pytest.approx(numeric, rel=1e-6, abs=1e-15)


def test_circular_shell_penetration_is_direction_independent():
    _, minor, ecc = shell_semi_axes(D, 80e-6, 80e-6)
    assert ecc == 0.0
    offset = 45e-6
    values = [penetration(offset * math.cos(t), offset * math.sin(t), rod, D, minor, ecc, gamma)
              for t in np.linspace(0, 2 * np.pi, 17)
              for rod in (0.0, 1.0, math.pi)
              for gamma in (0.0, 0.7)]
    ulps_of_radius = 8 * np.spacing(D / 2)  # round-off of (r + D/2) − p
    assert np.ptp(values) <= ulps_of_radius
    np.testing.assert_allclose(values, offset - 40e-6, rtol=0, atol=ulps_of_radius)


def test_elliptical_penetration_follows_the_rod_and_ellipse_angle():
    """Rotating the journal offset with the rod leaves δ unchanged; along the major axis
    the free play is Δmax/2, along the minor axis Δmin/2."""
    _, minor, ecc = shell_semi_axes(D, 120e-6, 60e-6)
    gamma, rod = 0.3, 2.0
    major_dir, minor_dir = rod + gamma, rod + gamma + math.pi / 2
    assert penetration(60e-6 * math.cos(major_dir), 60e-6 * math.sin(major_dir), rod, D, minor,
                       ecc, gamma) == pytest.approx(0.0, abs=1e-15)
    assert penetration(30e-6 * math.cos(minor_dir), 30e-6 * math.sin(minor_dir), rod, D, minor,
                       ecc, gamma) == pytest.approx(0.0, abs=1e-15)
    a = penetration(50e-6, 10e-6, 0.4, D, minor, ecc, gamma)
    turn = 1.1
    b = penetration(50e-6 * math.cos(turn) - 10e-6 * math.sin(turn),
                    50e-6 * math.sin(turn) + 10e-6 * math.cos(turn), 0.4 + turn, D, minor, ecc,
                    gamma)
    assert a == pytest.approx(b, abs=1e-16)


def test_penetration_rate_is_the_time_derivative_of_penetration():
    _, minor, ecc = shell_semi_axes(D, 150e-6, 70e-6)

    def path(t):
        return (40e-6 + 8e-6 * t, -20e-6 + 15e-6 * t * t, 0.3 + 0.4 * t)

    t, step = 0.6, 1e-6
    depth = [penetration(*path(t + s), D, minor, ecc, 0.2) for s in (-step, step)]
    dx, dy, rod = path(t)
    radial, rate = penetration_rate(dx, dy, 8e-6, 30e-6 * t, rod, 0.4, minor, ecc, 0.2)
    assert rate == pytest.approx((depth[1] - depth[0]) / (2 * step), rel=1e-6)
    assert radial == pytest.approx((dx * 8e-6 + dy * 30e-6 * t) / math.hypot(dx, dy), rel=1e-12)


def test_contact_law_hertz_damping_and_clipping():
    assert contact_force(-1e-9, 5.0, 1e13, 1.5, 1e5) == (0.0, 0.0)
    normal, elastic = contact_force(2e-6, 0.0, 1e13, 1.5, 1e5)
    assert elastic == pytest.approx(1e13 * (2e-6) ** 1.5, rel=1e-14)
    assert normal == elastic
    assert contact_force(2e-6, 0.1, 1e13, 1.5, 1e5)[0] == pytest.approx(elastic + 1e4, rel=1e-14)
    assert contact_force(2e-6, -10.0, 1e13, 1.5, 1e5)[0] == 0.0  # no adhesive pull
    assert damping_coefficient(0.1, 1e13, 0.25) == pytest.approx(2 * 0.1 * math.sqrt(2.5e12))


OFFSETS = [(61e-6, 3e-6), (20e-6, 31e-6), (-40e-6, 25e-6), (5e-6, -29e-6), (10e-6, 10e-6)]


@pytest.mark.parametrize("u, v", OFFSETS)
def test_exact_penetration_is_the_largest_half_plane_violation(u, v):
    major, minor, _ = shell_semi_axes(D, 120e-6, 60e-6)
    angles = np.linspace(0.0, 2 * np.pi, 400_001)
    support = np.sqrt((major * np.cos(angles)) ** 2 + (minor * np.sin(angles)) ** 2)
    brute = np.max(u * np.cos(angles) + v * np.sin(angles) - support + D / 2)
    depth, _ = support_penetration(u, v, D, major, minor)
    assert depth == pytest.approx(brute, abs=1e-14)


def test_exact_contact_journal_touches_the_ellipse_when_penetration_is_zero():
    """Independent geometry: on δ = 0 the nearest ellipse point is exactly D/2 from the
    journal centre, along the returned contact normal."""
    major, minor, _ = shell_semi_axes(D, 120e-6, 70e-6)
    for direction in (0.3, 1.2, 2.5):
        low, high = 0.0, 1e-4
        for _ in range(80):
            middle = 0.5 * (low + high)
            inside = support_penetration(middle * math.cos(direction),
                                         middle * math.sin(direction), D, major, minor)[0] < 0
            low, high = (middle, high) if inside else (low, middle)
        centre = np.array([low * math.cos(direction), low * math.sin(direction)])
        normal_angle = support_penetration(*centre, D, major, minor)[1]
        t = minimize_scalar(lambda s, c=centre: math.hypot(major * math.cos(s) - c[0],
                                                           minor * math.sin(s) - c[1]),
                            bounds=(normal_angle - 0.5, normal_angle + 0.5), method="bounded",
                            options={"xatol": 1e-12})
        assert t.fun == pytest.approx(D / 2, abs=1e-12)
        point = np.array([major * math.cos(t.x), minor * math.sin(t.x)])
        towards = (point - centre) / np.linalg.norm(point - centre)
        assert towards @ [math.cos(normal_angle), math.sin(normal_angle)] == pytest.approx(
            1.0, abs=1e-6)


def test_exact_contact_rates_and_lever_are_derivatives_of_the_penetration():
    major, minor, _ = shell_semi_axes(D, 150e-6, 90e-6)
    gamma, step = 0.2, 1e-6

    def path(t):
        return 50e-6 + 8e-6 * t, -30e-6 + 15e-6 * t * t, 0.3 + 0.4 * t

    def depth_at(t, extra_rod=0.0):
        dx, dy, rod = path(t)
        return exact_contact(dx, dy, 0.0, 0.0, rod + extra_rod, 0.0, D, major, minor, gamma)[0]

    t = 0.6
    dx, dy, rod = path(t)
    _, _, _, rate, lever = exact_contact(dx, dy, 8e-6, 30e-6 * t, rod, 0.4, D, major, minor,
                                         gamma)
    numeric_rate = (depth_at(t + step) - depth_at(t - step)) / (2 * step)
    assert rate == pytest.approx(numeric_rate, rel=1e-6)
    numeric_turn = (depth_at(t, step) - depth_at(t, -step)) / (2 * step)
    assert -lever == pytest.approx(numeric_turn, rel=1e-6)


def test_exact_and_seed_geometry_coincide_for_circular_shells():
    major, minor, ecc = shell_semi_axes(D, 80e-6, 80e-6)
    for angle in np.linspace(0.0, 6.0, 9):
        dx, dy = 45e-6 * math.cos(angle), 45e-6 * math.sin(angle)
        exact = exact_contact(dx, dy, 3e-6, -2e-6, 0.7, 0.1, D, major, minor, 0.4)
        seed = penetration_rate(dx, dy, 3e-6, -2e-6, 0.7, 0.1, minor, ecc, 0.4)
        assert exact[0] == pytest.approx(penetration(dx, dy, 0.7, D, minor, ecc, 0.4), abs=1e-17)
        assert exact[3] == pytest.approx(seed[1], rel=1e-9)
        assert exact[4] == pytest.approx(0.0, abs=1e-15)
