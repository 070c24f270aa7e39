"""Greenwood–Tripp asperity contact: F_{5/2}, force integral, hard-contact limit σ → 0."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate, optimize, special

from conrod.contact.asperity import (
    AsperityParameters,
    asperity_force,
    asperity_pressure,
    f52,
    greenwood_tripp_f52,
)

RADIUS, WIDTH, CLEARANCE = 0.03, 0.025, 30e-6


def _f52_direct(x: float) -> float:
    value, _ = integrate.quad(
        lambda s: (s - x) ** 2.5 * math.exp(-0.5 * s * s), x, np.inf, epsabs=0.0, epsrel=1e-12,
        limit=200,
    )
    return value / math.sqrt(2.0 * math.pi)


@pytest.mark.parametrize("x", [-25.0, -10.3, -9.9987, -4.321, -0.0013, 0.7771, 2.5025, 3.9, 5.5])
def test_f52_against_direct_integration(x):
    """Table + series vs adaptive quadrature of the defining integral (rel. 1e-5)."""
    assert f52(x) == pytest.approx(_f52_direct(x), rel=1e-5)


def test_f52_against_parabolic_cylinder_closed_form():
    """F_{5/2}(x) = Γ(7/2)/√(2π) · exp(−x²/4) · D_{−7/2}(x) (independent closed form)."""
    x = np.linspace(-9.0, 7.0, 777)
    closed = special.gamma(3.5) / math.sqrt(2 * math.pi) * np.exp(-x * x / 4.0) * (
        special.pbdv(-3.5, x)[0]
    )
    np.testing.assert_allclose(greenwood_tripp_f52(x), closed, rtol=1e-5)


def test_f52_monotone_and_continuous_at_range_ends():
    x = np.linspace(-12.0, 9.6, 20001)
    values = greenwood_tripp_f52(x)
    assert np.all(np.diff(values) <= 0.0)
    assert f52(-10.0 - 1e-9) == pytest.approx(f52(-10.0 + 1e-9), rel=1e-7)
    assert f52(9.5) == 0.0 and f52(9.4999) < 1e-20


def _direct_force(ex, ey, params, nodes=200001):
    """Force from a fine uniform θ-grid (periodic trapezoid) of p_a over the shell."""
    radius, width, sigma, scale = params
    theta = np.linspace(0.0, 2 * math.pi, nodes, endpoint=False)
    gap = CLEARANCE - ex * np.cos(theta) - ey * np.sin(theta)
    pressure = asperity_pressure(gap, sigma, scale)
    d_theta = 2 * math.pi / nodes
    return (-radius * width * d_theta * np.sum(pressure * np.cos(theta)),
            -radius * width * d_theta * np.sum(pressure * np.sin(theta)))


@pytest.mark.parametrize("gap_over_sigma", [3.0, 0.5, -2.0])
def test_asperity_force_against_direct_surface_integral(gap_over_sigma):
    params = AsperityParameters(0.4e-6, 5e9, 20e-6, 5.9e10).kernel_parameters(RADIUS, WIDTH)
    e = CLEARANCE - gap_over_sigma * 0.4e-6
    angle = 2.2
    fx, fy = asperity_force(e * math.cos(angle), e * math.sin(angle), CLEARANCE, params)
    gx, gy = _direct_force(e * math.cos(angle), e * math.sin(angle), params)
    assert fx == pytest.approx(gx, rel=1e-6)
    assert fy == pytest.approx(gy, rel=1e-6)
    # purely radial, pointing back towards the shell centre
    assert fx * math.sin(angle) - fy * math.cos(angle) == pytest.approx(0.0, abs=1e-9 * abs(fx))
    assert fx * math.cos(angle) + fy * math.sin(angle) < 0.0


def test_no_force_far_from_the_shell():
    params = AsperityParameters(0.4e-6, 5e9, 20e-6, 5.9e10).kernel_parameters(RADIUS, WIDTH)
    assert asperity_force(0.0, 0.0, CLEARANCE, params) == (0.0, 0.0)
    assert asperity_force(CLEARANCE - 10 * 0.4e-6, 0.0, CLEARANCE, params) == (0.0, 0.0)


def _self_similar(sigma: float) -> tuple[float, float, float, float]:
    """Surfaces with fixed ηβσ = 0.04 and σ/β = 0.02 (K fixed), scaled by σ."""
    beta = sigma / 0.02
    eta = 0.04 / (beta * sigma)
    return AsperityParameters(sigma, eta, beta, 5.9e10).kernel_parameters(RADIUS, WIDTH)


def _radial_force(e: float, params) -> float:
    return -asperity_force(e, 0.0, CLEARANCE, params)[0]


def _gap_carrying(load: float, params, sigma: float) -> float:
    e = optimize.brentq(lambda e: _radial_force(e, params) - load,
                        CLEARANCE - 9.4 * sigma, CLEARANCE + 0.5 * CLEARANCE, xtol=1e-6 * sigma)
    return CLEARANCE - e


def test_sigma_to_zero_becomes_a_rigid_barrier():
    """With K fixed (self-similar surfaces) the gap that carries a 20 kN load vanishes with σ
    (as σ^{5/6}: |h/σ| grows as σ^{-1/6} because the contact arc narrows as √σ), and around
    h = 0 the force jumps from ≪ to ≫ the load within ±1 % of the clearance."""
    load, delta = 2.0e4, 0.01 * CLEARANCE
    sigmas = [1e-6, 1e-7, 1e-8, 1e-9]
    gaps = []
    for sigma in sigmas:
        params = _self_similar(sigma)
        assert params[3] == pytest.approx(_self_similar(1e-6)[3])  # same K E'
        gaps.append(abs(_gap_carrying(load, params, sigma)))
    ratios = np.array(gaps[:-1]) / np.array(gaps[1:])
    assert np.all(ratios > 3.0) and np.all(np.diff(ratios) > 0.0)
    assert ratios[-1] == pytest.approx(10.0 ** (5.0 / 6.0), rel=0.15)  # asymptotic rate
    assert gaps[-1] < 1e-3 * CLEARANCE
    for sigma in sigmas[2:]:
        params = _self_similar(sigma)
        assert _radial_force(CLEARANCE - delta, params) < 1e-6 * load
        assert _radial_force(CLEARANCE + delta, params) > 10.0 * load


def _hard_contact_whirl(load, mass, omega, damping, mu):
    """Hard contact (seed 004 eqs 4.2.3–4.2.9) for a load of constant size whirling at Ω:
    the centre runs on the clearance circle, normal balance P = W cos ψ + m Ω² c, tangential
    W sin ψ + μ P + d Ω c = 0 (journal spinning forward, so friction opposes +t)."""
    def tangential(psi):
        return load * math.sin(psi) + mu * (load * math.cos(psi) + mass * omega**2 * CLEARANCE) + (
            damping * omega * CLEARANCE)
    psi = optimize.brentq(tangential, -math.pi / 2, 0.0, xtol=1e-14)
    return psi, load * math.cos(psi) + mass * omega**2 * CLEARANCE


@pytest.mark.parametrize("sigma", [0.4e-6, 1e-8])
def test_whirling_orbit_contact_force_matches_hard_contact(sigma):
    """Steady whirl in the rotating frame with GT asperity force + friction μ|F_a|, inertia
    and a dashpot: the asperity force equals the hard-contact force and the centre sits on
    the clearance circle to within a few σ."""
    load, mass, omega, damping, mu = 1.5e4, 2.0, 2 * math.pi * 50, 2.0e5, 0.1
    psi_hard, force_hard = _hard_contact_whirl(load, mass, omega, damping, mu)
    params = _self_similar(sigma)

    def residual(q):
        ex, ey = q * CLEARANCE
        fx, fy = asperity_force(ex, ey, CLEARANCE, params)
        e = math.hypot(ex, ey)
        tx, ty = -ey / e, ex / e
        along = mu * math.hypot(fx, fy) + damping * omega * e
        rx = load + fx - along * tx + mass * omega**2 * ex
        ry = fy - along * ty + mass * omega**2 * ey
        return np.array([rx, ry]) / load

    guess = np.array([math.cos(psi_hard), math.sin(psi_hard)])
    solution = optimize.fsolve(residual, guess, xtol=1e-13)
    assert np.max(np.abs(residual(solution))) < 1e-9
    ex, ey = solution * CLEARANCE
    force = math.hypot(*asperity_force(ex, ey, CLEARANCE, params))
    assert abs(math.hypot(ex, ey) - CLEARANCE) < 3.0 * sigma
    assert math.atan2(ey, ex) == pytest.approx(psi_hard, abs=1e-3)
    assert force == pytest.approx(force_hard, rel=1e-3)
