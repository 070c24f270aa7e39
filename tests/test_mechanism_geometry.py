"""Worn-shell contact geometry and contact law (seed 003) against closed forms."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.mechanism.geometry import (
    contact_force,
    damping_coefficient,
    penetration,
    penetration_rate,
    shell_radius,
    shell_radius_slope,
    shell_semi_axes,
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
