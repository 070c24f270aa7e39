"""Crank-slider kinematics against independent answers (closed forms, Taylor order, FD)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.loads import kinematics as kin

R, L, OMEGA = 0.05, 0.16, 300.0


def test_exact_displacement_matches_geometry():
    """s = r + L − X_p with the pin on the axis: |crankpin − piston pin| = L exactly."""
    phi = np.linspace(0.0, 4.0 * math.pi, 721)
    s = kin.piston_displacement(phi, R, L)
    piston_x = R + L - s
    distance = np.hypot(piston_x - R * np.cos(phi), -R * np.sin(phi))
    np.testing.assert_allclose(distance, L, rtol=1e-13)


def test_series_displacement_error_is_third_order_in_lambda():
    """Seed-003 series vs exact: error → r λ³ sin⁴φ / 8 (Taylor), slope 3 in log-log."""
    phi = np.linspace(0.0, 2.0 * math.pi, 361)
    lambdas = np.array([0.05, 0.1, 0.2])
    errors = []
    for lam in lambdas:
        exact = kin.piston_displacement(phi, R, R / lam)
        series = kin.piston_displacement_series(phi, R, R / lam)
        errors.append(np.max(np.abs(exact - series)))
    slope = np.polyfit(np.log(lambdas), np.log(errors), 1)[0]
    assert slope == pytest.approx(3.0, abs=0.05)
    assert errors[0] / (R * lambdas[0] ** 3) == pytest.approx(1.0 / 8.0, rel=0.01)


@pytest.mark.parametrize("exact", [True, False])
def test_velocity_and_acceleration_are_derivatives_of_displacement(exact):
    """Central finite differences of s(φ) (independent of the analytic derivatives)."""
    phi = np.linspace(0.1, 12.0, 50)
    h = 1e-4
    if exact:
        disp, vel, acc = kin.piston_displacement, kin.piston_velocity, kin.piston_acceleration
    else:
        disp = kin.piston_displacement_series
        vel, acc = kin.piston_velocity_series, kin.piston_acceleration_series
    s_plus, s0, s_minus = disp(phi + h, R, L), disp(phi, R, L), disp(phi - h, R, L)
    fd_velocity = OMEGA * (s_plus - s_minus) / (2 * h)
    fd_acceleration = OMEGA**2 * (s_plus - 2 * s0 + s_minus) / h**2
    np.testing.assert_allclose(vel(phi, R, L, OMEGA), fd_velocity, rtol=1e-7, atol=1e-9)
    np.testing.assert_allclose(acc(phi, R, L, OMEGA), fd_acceleration, rtol=1e-5, atol=1e-3)


def test_acceleration_at_dead_centres_is_closed_form():
    """Exact and series: s̈(TDC) = r ω²(1 + λ), s̈(BDC) = −r ω²(1 − λ)."""
    lam = R / L
    for accel in (kin.piston_acceleration, kin.piston_acceleration_series):
        tdc, bdc = accel(np.array([0.0, math.pi]), R, L, OMEGA)
        assert tdc == pytest.approx(R * OMEGA**2 * (1 + lam), rel=1e-12)
        assert bdc == pytest.approx(-R * OMEGA**2 * (1 - lam), rel=1e-12)


def test_rod_angular_velocity_and_acceleration_match_finite_differences():
    """Ω_rod = −dβ/dt and its rate, against FD of β(φ) = asin(λ sin φ)."""
    lam, h = R / L, 1e-4
    phi = np.linspace(0.0, 2 * math.pi, 37)
    beta = lambda p: kin.rod_angle(p, lam)  # noqa: E731
    fd_rate = -OMEGA * (beta(phi + h) - beta(phi - h)) / (2 * h)
    fd_accel = -(OMEGA**2) * (beta(phi + h) - 2 * beta(phi) + beta(phi - h)) / h**2
    np.testing.assert_allclose(kin.rod_angular_velocity(phi, lam, OMEGA), fd_rate, atol=1e-6)
    np.testing.assert_allclose(
        kin.rod_angular_acceleration(phi, lam, OMEGA), fd_accel, rtol=1e-5, atol=1e-2
    )


def test_rod_centre_of_mass_acceleration_matches_finite_differences():
    """a_G from the analytic formula vs FD of r_G = pin + L₁ (cos β, −sin β)."""
    lam, l1, h = R / L, 0.045, 1e-4
    phi = np.linspace(0.0, 2 * math.pi, 25)

    def position(p):
        b = kin.rod_angle(p, lam)
        return R * np.cos(p) + l1 * np.cos(b), R * np.sin(p) - l1 * np.sin(b)

    (xp, yp), (x0, y0), (xm, ym) = position(phi + h), position(phi), position(phi - h)
    ax, ay = kin.rod_centre_of_mass_acceleration(phi, R, L, l1, OMEGA)
    np.testing.assert_allclose(ax, OMEGA**2 * (xp - 2 * x0 + xm) / h**2, rtol=1e-5, atol=1e-2)
    np.testing.assert_allclose(ay, OMEGA**2 * (yp - 2 * y0 + ym) / h**2, rtol=1e-5, atol=1e-2)
