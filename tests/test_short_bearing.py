"""Short-bearing closed form against Ocvirk's formulas and brute-force quadrature."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.film import BearingGeometry, FilmState, ShortBearingFilm
from conrod.film.short.kernel import short_bearing_force

MU, R, L, C = 0.01, 0.025, 0.02, 25e-6


def brute_force(ex, ey, vx, vy, omega_sum, n=200_000):
    """Half-Sommerfeld short-bearing force by direct rectangle-rule quadrature."""
    theta = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    h = C - ex * np.cos(theta) - ey * np.sin(theta)
    source = 6 * MU * (omega_sum * (ex * np.sin(theta) - ey * np.cos(theta))
                       - 2 * (vx * np.cos(theta) + vy * np.sin(theta)))
    axial = np.maximum(0.0, -source * L**3 / (12 * h**3))
    step = theta[1] - theta[0]
    return -R * np.sum(axial * np.cos(theta)) * step, -R * np.sum(axial * np.sin(theta)) * step


@pytest.mark.parametrize("eps", [0.05, 0.3, 0.6, 0.9, 0.97])
def test_steady_forces_match_ocvirk(eps):
    omega = 300.0
    fx, fy = short_bearing_force(eps * C, 0.0, 0.0, 0.0, omega, MU, R, L, C)
    speed = R * omega
    radial = -MU * speed * L**3 * eps**2 / (C**2 * (1 - eps**2) ** 2)
    tangential = math.pi * MU * speed * L**3 * eps / (4 * C**2 * (1 - eps**2) ** 1.5)
    assert fx == pytest.approx(radial, rel=1e-10)
    assert fy == pytest.approx(tangential, rel=1e-10)


@pytest.mark.parametrize(
    "state",
    [
        (10e-6, 5e-6, 0.01, -0.02, 300.0),
        (-3e-6, 20e-6, -0.05, 0.0, -100.0),
        (20e-6, -10e-6, 0.0, 0.0, 300.0),
        (1e-6, 1e-6, 0.2, 0.1, 50.0),
    ],
)
def test_general_state_matches_quadrature(state):
    exact = short_bearing_force(*state, MU, R, L, C)
    approx = brute_force(*state)
    assert exact == pytest.approx(approx, rel=1e-6)


def test_pure_squeeze_closed_form():
    """Concentric journal approaching along x at speed v: p>0 over the half it approaches.

    F = −R ∫ p cos θ = −(μ v R L³ / c³) ∫_{−π/2}^{π/2} cos² θ dθ = −π μ v R L³/(2 c³)."""
    v = 0.01
    fx, fy = short_bearing_force(0.0, 0.0, v, 0.0, 0.0, MU, R, L, C)
    assert fx == pytest.approx(-math.pi * MU * v * R * L**3 / (2 * C**3), rel=1e-10)
    assert abs(fy) < 1e-9 * abs(fx)


def test_counter_rotation_gives_no_wedge_force():
    model = ShortBearingFilm(BearingGeometry(diameter=2 * R, width=L, radial_clearance=C))
    state = FilmState(eccentricity_x=12e-6, eccentricity_y=-4e-6, velocity_x=0.0, velocity_y=0.0,
                      journal_speed=250.0, shell_speed=-250.0, viscosity=MU)
    assert model.force(state) == (0.0, 0.0)


def test_half_speed_whirl_has_no_capacity():
    """A journal whirling at half the journal speed carries no load (Booker)."""
    omega, e = 300.0, 10e-6
    fx, fy = short_bearing_force(e, 0.0, 0.0, 0.5 * omega * e, omega, MU, R, L, C)
    assert (fx, fy) == (0.0, 0.0)


def test_solve_reports_consistent_characteristics():
    model = ShortBearingFilm(BearingGeometry(diameter=2 * R, width=L, radial_clearance=C))
    state = FilmState(eccentricity_x=15e-6, eccentricity_y=0.0, velocity_x=0.0, velocity_y=0.0,
                      journal_speed=300.0, viscosity=MU)
    result = model.solve(state, with_pressure=True)
    assert result.min_film_thickness == pytest.approx(C - 15e-6)
    assert result.min_film_angle == pytest.approx(0.0, abs=1e-12)
    assert result.max_pressure == pytest.approx(result.pressure.max(), rel=2e-3)
    # Side flow of the short bearing: Q = ε c U L (U = R ω)
    assert result.side_flow == pytest.approx(0.6 * C * R * 300.0 * L, rel=1e-12)
    # Friction power equals friction torque times sliding speed
    assert result.friction_power == pytest.approx(abs(result.friction_torque_journal) * 300.0)
