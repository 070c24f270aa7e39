"""Mobility method: numerically computed map against direct Reynolds solves; the
short-bearing (Booker) mobility's error against the same solves shrinks as L/D → 0."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.table.mobility import MobilityFilm


def load_residuals(model: MobilityFilm, direct: ReynoldsFilm, n: int, seed: int) -> np.ndarray:
    """|F_direct(e, ė_mobility) + W|/|W| at random (ε ≤ 0.9, load, speeds)."""
    c = model.geometry.radial_clearance
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        eps = rng.uniform(0.05, 0.9)
        psi, load_angle = rng.uniform(-math.pi, math.pi, size=2)
        load = rng.uniform(1e3, 3e4)
        ex, ey = eps * c * math.cos(psi), eps * c * math.sin(psi)
        wx, wy = load * math.cos(load_angle), load * math.sin(load_angle)
        vx, vy = model.journal_velocity(ex, ey, wx, wy, 300.0, 20.0, 0.01)
        fx, fy = direct.force(FilmState(eccentricity_x=ex, eccentricity_y=ey, velocity_x=vx,
                                        velocity_y=vy, journal_speed=300.0, shell_speed=20.0,
                                        viscosity=0.01))
        out.append(math.hypot(fx + wx, fy + wy) / load)
    return np.asarray(out)


@pytest.mark.slow
def test_numerical_mobility_against_direct_reynolds(tmp_path):
    """Default map (24 ε × 48 directions) from ReynoldsFilm 48×8 (coarse for test time).

    The velocities it predicts reproduce the load through direct solves on the same grid:
    measured RMS 0.9 %, max 3.7 % (one of 20 points; on 144×32 the max is 0.6 %). On a coarse
    grid the discrete cavitation boundary jumps from node to node, so the map is only
    piecewise smooth; bounds: RMS < 1.5 %, max < 5 %."""
    geometry = BearingGeometry(diameter=0.05, width=0.05, radial_clearance=2.5e-5)
    model = MobilityFilm(geometry, n_theta=48, n_z=8, cache_dir=tmp_path)
    residual = load_residuals(model, ReynoldsFilm(geometry, n_theta=48, n_z=8), 20, seed=1)
    assert np.sqrt(np.mean(residual**2)) < 0.015
    assert residual.max() < 0.05


def test_short_bearing_mobility_error_shrinks_with_slenderness():
    """Booker's short-bearing mobility vs direct Reynolds (72×16): median load error
    measured 32 % at L/D = 1, 12 % at 0.5, 4 % at 0.25 — it must fall as L/D → 0."""
    medians = []
    for ratio in (1.0, 0.25):
        geometry = BearingGeometry(diameter=0.05, width=0.05 * ratio, radial_clearance=2.5e-5)
        short = MobilityFilm.short_bearing(geometry)
        direct = ReynoldsFilm(geometry, n_theta=72, n_z=16)
        medians.append(float(np.median(load_residuals(short, direct, 12, seed=2))))
    assert medians[1] < 0.08
    assert medians[1] < 0.3 * medians[0]


def test_half_speed_whirl_and_zero_load():
    """No load ⇒ the journal turns with ω̄ (ė = ω̄ × e); mobility of an exact squeeze inverse."""
    geometry = BearingGeometry(diameter=0.05, width=0.0125, radial_clearance=2.5e-5)
    short = MobilityFilm.short_bearing(geometry)
    vx, vy = short.journal_velocity(1e-5, 0.0, 0.0, 0.0, 200.0, 0.0, 0.02)
    assert (vx, vy) == pytest.approx((0.0, 100.0 * 1e-5))
    vx, vy = short.journal_velocity(1e-5, 0.5e-5, 800.0, -300.0, 200.0, 50.0, 0.02)
    fx, fy = short.force(FilmState(eccentricity_x=1e-5, eccentricity_y=0.5e-5, velocity_x=vx,
                                   velocity_y=vy, journal_speed=200.0, shell_speed=50.0,
                                   viscosity=0.02))
    assert (fx, fy) == pytest.approx((-800.0, 300.0), rel=1e-9)
