"""Wear diagram and oil-hole angle (seed 001) against constructed loads."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.loads.diagrams import least_worn_angle, polar_diagram_points, wear_diagram


def test_single_load_wears_exactly_its_sixty_degree_sector():
    angle, wear = wear_diagram(np.array([math.radians(30.0)]), np.array([5.0]), bins=360)
    worn = np.degrees(angle[wear > 0])
    offsets = (np.degrees(angle) - 30.0 + 180.0) % 360.0 - 180.0
    np.testing.assert_array_equal(wear > 0, np.abs(offsets) <= 60.0)
    assert set(np.unique(wear)) == {0.0, 5.0}
    assert worn.size == 120
    # the least-worn zone is centred opposite the load
    assert math.degrees(least_worn_angle(angle, wear)) == pytest.approx(210.0, abs=0.5)


def test_wear_diagram_of_a_symmetric_load_is_symmetric():
    """Loads mirrored about the direction 40° give a wear diagram mirrored about 40°."""
    rng = np.random.default_rng(7)
    half = rng.uniform(-math.pi, math.pi, 200)
    magnitude = rng.uniform(1.0, 10.0, 200)
    axis = math.radians(40.0)
    directions = np.concatenate([axis + half, axis - half])
    angle, wear = wear_diagram(directions, np.concatenate([magnitude, magnitude]), bins=720)
    mirrored = np.interp(np.mod(2 * axis - angle, 2 * math.pi), angle, wear, period=2 * math.pi)
    np.testing.assert_allclose(mirrored, wear, rtol=1e-12)
    # the least-worn angle is a minimum, and so is its mirror image
    hole = least_worn_angle(angle, wear)
    at = lambda a: np.interp(np.mod(a, 2 * math.pi), angle, wear, period=2 * math.pi)  # noqa: E731
    assert at(hole) == pytest.approx(wear.min())
    assert at(2 * axis - hole) == pytest.approx(wear.min())


def test_wear_sum_equals_load_times_sector_fraction():
    """Σ wear over the bins = Σ|R| × (sector width / bin width) (each strip covers 120°)."""
    rng = np.random.default_rng(3)
    directions, magnitude = rng.uniform(0, 2 * math.pi, 50), rng.uniform(0, 3, 50)
    _, wear = wear_diagram(directions, magnitude, bins=3600)
    assert wear.sum() == pytest.approx(magnitude.sum() * 1200, rel=2e-3)


def test_least_worn_angle_picks_the_widest_minimal_arc_across_zero():
    angle = (np.arange(36) + 0.5) * math.radians(10.0)
    wear = np.ones(36)
    wear[[0, 1, 34, 35]] = 0.0  # arc 340°..20° centred on 0°
    wear[10] = 0.0  # a narrower minimal arc
    hole = math.degrees(least_worn_angle(angle, wear))
    assert min(hole, 360.0 - hole) == pytest.approx(0.0, abs=1e-9)


def test_polar_diagram_pole_shift_is_the_rotating_force():
    radial, tangential = np.array([10.0, -3.0]), np.array([0.0, 4.0])
    t, outward, pole = polar_diagram_points(radial, tangential, rotating_force=-2.0)
    # vector from O' to each point = S + K_R = force of the rod on the pin (outward, T)
    np.testing.assert_allclose(outward - pole[1], -radial)
    np.testing.assert_allclose(t, tangential)


def test_conventions_figure_draws_the_three_frames():
    from conrod.plotting.loads_plots import plot_conventions

    figure = plot_conventions()
    texts = " ".join(t.get_text() for t in figure.axes[0].texts)
    for label in ("X (engine)", "x rod", "y rod", "x crank", "θ on the shell"):
        assert label in texts
