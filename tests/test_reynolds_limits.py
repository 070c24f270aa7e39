"""Finite-difference Reynolds film against closed forms, limits, order and symmetry."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.errors import CaseError, ConvergenceError, FilmThicknessError
from conrod.film.base import BearingGeometry, FeedHole, FilmModel, FilmState
from conrod.film.long_bearing import (
    gumbel_long_force,
    long_squeeze_force,
    short_squeeze_force,
    sommerfeld_long_force,
)
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.kernel import short_bearing_force

MU, D, C = 0.02, 0.1, 1.0e-4
R = 0.5 * D
OMEGA = 200.0
NO_CAVITATION = -1.0e30


def geometry(length_to_diameter: float, **kwargs) -> BearingGeometry:
    return BearingGeometry(diameter=D, width=length_to_diameter * D, radial_clearance=C, **kwargs)


def relative(a: float, b: float) -> float:
    return abs(a - b) / abs(b)


def test_implements_film_model_interface():
    film = ReynoldsFilm(geometry(1.0), n_theta=36, n_z=8)
    assert isinstance(film, FilmModel)
    theta, z = film.grid()
    result = film.solve(FilmState(eccentricity_x=0.3 * C, eccentricity_y=0.0, journal_speed=OMEGA,
                                  viscosity=MU),
                        with_pressure=True)
    assert result.pressure.shape == (theta.size, z.size) == (36, 9)
    assert film.initial_history() is None
    assert film.name == "reynolds"


def test_short_bearing_limit_error_decreases():
    """As L/D → 0 the FD force tends to the Ocvirk closed form (error ~ (L/D)²)."""
    errors = []
    for ratio in (1 / 4, 1 / 8, 1 / 16):
        state = FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.2 * C, journal_speed=OMEGA,
                          viscosity=MU)
        fd = ReynoldsFilm(geometry(ratio), n_theta=144, n_z=16).force(state)
        closed = short_bearing_force(0.5 * C, 0.2 * C, 0, 0, OMEGA, MU, R, ratio * D, C)
        errors.append(math.dist(fd, closed) / math.hypot(*closed))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 0.01


LONG_RATIOS = (2.0, 4.0, 8.0)


def assert_end_effect_vanishes(errors: list[float]) -> None:
    """Error shrinks with L/D at the rate of an end effect, ∝ D/L (fitted slope ≈ −1)."""
    assert errors[0] > errors[1] > errors[2]
    slope = np.polyfit(np.log(LONG_RATIOS), np.log(errors), 1)[0]
    assert -1.15 < slope < -0.85


def test_long_bearing_limit_full_sommerfeld():
    """Without cavitation the force per length tends to Sommerfeld's as L/D grows."""
    eps = 0.4
    exact = sommerfeld_long_force(eps, R * OMEGA, MU, R, C)
    errors = []
    for ratio in LONG_RATIOS:
        film = ReynoldsFilm(geometry(ratio, cavitation_pressure=NO_CAVITATION),
                            n_theta=72, n_z=int(16 * ratio))
        fx, fy = film.force(FilmState(eccentricity_x=eps * C, eccentricity_y=0.0,
                                      journal_speed=OMEGA, viscosity=MU))
        errors.append(relative(fy / (ratio * D), exact[1]))
        assert abs(fx) < 1e-6 * abs(fy)
    assert_end_effect_vanishes(errors)


def test_long_bearing_limit_gumbel():
    """Dropping the negative pressures of the full film tends to Gümbel's forces."""
    eps = 0.5
    exact = gumbel_long_force(eps, R * OMEGA, MU, R, C)
    errors = []
    for ratio in LONG_RATIOS:
        film = ReynoldsFilm(geometry(ratio, cavitation_pressure=NO_CAVITATION),
                            n_theta=144, n_z=int(16 * ratio))
        state = FilmState(eccentricity_x=eps * C, eccentricity_y=0.0, journal_speed=OMEGA,
                          viscosity=MU)
        pressure = np.maximum(film.solve(state, with_pressure=True).pressure, 0.0)
        theta, _ = film.grid()
        grid = film.film_grid
        fx = -grid.integrate(pressure * np.cos(theta)[:, None]) / (ratio * D)
        fy = -grid.integrate(pressure * np.sin(theta)[:, None]) / (ratio * D)
        errors.append(math.dist((fx, fy), exact) / math.hypot(*exact))
    assert_end_effect_vanishes(errors)


@pytest.mark.parametrize("eps", [0.0, 0.5])
def test_pure_squeeze_short_and_long(eps):
    """No rotation, full film: radial squeeze force against both closed forms."""
    rate = 1.0e-3
    state = FilmState(eccentricity_x=eps * C, eccentricity_y=0.0, velocity_x=rate, viscosity=MU)
    short = ReynoldsFilm(geometry(1 / 16, cavitation_pressure=NO_CAVITATION), n_z=16)
    exact_short = short_squeeze_force(eps, rate, MU, R, D / 16, C)
    assert relative(short.force(state)[0], exact_short) < 0.01
    errors = []
    for ratio in LONG_RATIOS:
        long = ReynoldsFilm(geometry(ratio, cavitation_pressure=NO_CAVITATION),
                            n_theta=72, n_z=int(16 * ratio))
        exact_long = long_squeeze_force(eps, rate, MU, R, C) * ratio * D
        fx, fy = long.force(state)
        assert abs(fy) < 1e-6 * abs(fx)
        errors.append(relative(fx, exact_long))
    assert_end_effect_vanishes(errors)


def test_counter_rotation_has_no_wedge_action():
    """ω_j = −ω_b: zero force at rest, and the pure-squeeze force when moving."""
    film = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16)
    still = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.1 * C, journal_speed=OMEGA,
                      shell_speed=-OMEGA, viscosity=MU)
    assert film.force(still) == (0.0, 0.0)
    moving = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.1 * C, velocity_x=-1e-3,
                       velocity_y=5e-4,
                       journal_speed=OMEGA, shell_speed=-OMEGA, viscosity=MU)
    squeeze_only = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.1 * C, velocity_x=-1e-3,
                             velocity_y=5e-4, viscosity=MU)
    reference = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16).force(squeeze_only)
    assert film.force(moving) == pytest.approx(reference, rel=1e-5)


def test_mirror_state_gives_mirrored_force():
    """Reflection y → −y (θ → −θ) reverses ω and mirrors position, velocity and force."""
    film = ReynoldsFilm(geometry(0.8), n_theta=72, n_z=16)
    state = FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.3 * C, velocity_x=2e-3,
                      velocity_y=-1e-3,
                      journal_speed=OMEGA, shell_speed=20.0, viscosity=MU)
    mirror = FilmState(eccentricity_x=0.5 * C, eccentricity_y=-0.3 * C, velocity_x=2e-3,
                       velocity_y=1e-3,
                       journal_speed=-OMEGA, shell_speed=-20.0, viscosity=MU)
    fx, fy = film.force(state)
    mx, my = ReynoldsFilm(geometry(0.8), n_theta=72, n_z=16).force(mirror)
    assert mx == pytest.approx(fx, rel=1e-5)
    assert my == pytest.approx(-fy, rel=1e-5)


def test_second_order_convergence_full_film():
    """Grid refinement of a smooth full-film case: fitted order of the force error ≈ 2."""
    g = geometry(1.0, cavitation_pressure=NO_CAVITATION)
    state = FilmState(eccentricity_x=0.3 * C, eccentricity_y=0.1 * C, velocity_x=1e-3,
                      journal_speed=OMEGA, viscosity=MU)
    reference = ReynoldsFilm(g, n_theta=576, n_z=128).force(state)
    sizes = [(36, 8), (72, 16), (144, 32)]
    errors = [math.dist(ReynoldsFilm(g, n_theta=n, n_z=m).force(state), reference)
              for n, m in sizes]
    spacing = [1.0 / n for n, _ in sizes]
    order = np.polyfit(np.log(spacing), np.log(errors), 1)[0]
    assert 1.8 < order < 2.3


def test_warm_start_matches_cold_and_is_cheaper():
    film = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16)
    first = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.0, journal_speed=OMEGA, viscosity=MU)
    second = FilmState(eccentricity_x=0.61 * C, eccentricity_y=0.01 * C, journal_speed=OMEGA,
                       viscosity=MU)
    _, memory = film.solve_with_memory(first, film.initial_memory())  # warm start held
    warm, _ = film.solve_with_memory(second, memory)  # by the caller, not the model
    cold = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16, warm_start=False).solve(second)
    assert warm.extra["warm_start"] == 1.0 and cold.extra["warm_start"] == 0.0
    assert warm.force_y == pytest.approx(cold.force_y, rel=2e-5)
    assert warm.force_x == pytest.approx(cold.force_x, rel=2e-5)


def test_petroff_limit_of_friction_torque():
    """ε → 0: M_j = −2πμR³Lω/c (Petroff), and journal + shell moments balance e×F."""
    film = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16)
    result = film.solve(FilmState(eccentricity_x=1e-4 * C, eccentricity_y=0.0, journal_speed=OMEGA,
                                  viscosity=MU))
    petroff = 2.0 * math.pi * MU * R**3 * D * OMEGA / C
    assert result.friction_torque_journal == pytest.approx(-petroff, rel=1e-6)
    assert result.friction_torque_shell == pytest.approx(petroff, rel=1e-6)


def test_uniform_deformation_equals_larger_clearance():
    film = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16, tolerance=1e-12)
    theta, z = film.grid()
    extra = 2.0e-5
    state = FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.0, journal_speed=OMEGA, viscosity=MU,
                      deformation=np.full((theta.size, z.size), extra))
    wider = ReynoldsFilm(BearingGeometry(diameter=D, width=D, radial_clearance=C + extra),
                         n_theta=72, n_z=16, tolerance=1e-12)
    same = FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.0, journal_speed=OMEGA, viscosity=MU)
    assert film.force(state) == pytest.approx(wider.force(same), rel=1e-9)


def test_film_fraction_friction_below_full_film():
    state = FilmState(eccentricity_x=0.7 * C, eccentricity_y=0.0, journal_speed=OMEGA, viscosity=MU)
    full = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16).solve(state)
    partial = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16, friction="film_fraction").solve(state)
    assert full.cavitated_fraction > 0.2
    assert abs(partial.friction_torque_journal) < abs(full.friction_torque_journal)
    assert partial.force_x == pytest.approx(full.force_x, rel=1e-12)


def test_bad_inputs_raise_readable_errors():
    with pytest.raises(CaseError, match="n_theta"):
        ReynoldsFilm(geometry(1.0), n_theta=35)
    film = ReynoldsFilm(geometry(1.0), n_theta=36, n_z=8)
    with pytest.raises(FilmThicknessError, match="film thickness"):  # a state, not input
        film.force(FilmState(eccentricity_x=1.01 * C, eccentricity_y=0.0, journal_speed=OMEGA,
                             viscosity=MU))
    with pytest.raises(CaseError, match="deformation shape"):
        film.force(FilmState(eccentricity_x=0.1 * C, eccentricity_y=0.0, journal_speed=OMEGA,
                             viscosity=MU,
                             deformation=np.zeros((3, 3))))
    stingy = ReynoldsFilm(geometry(1.0), n_theta=36, n_z=8, max_iterations=3)
    with pytest.raises(ConvergenceError, match="sweeps"):
        stingy.force(FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.0, journal_speed=OMEGA,
                               viscosity=MU))


def test_multigrid_and_sor_agree():
    """Two independent solvers of the same discrete problem (with cavitation)."""
    state = FilmState(eccentricity_x=0.7 * C, eccentricity_y=-0.2 * C, velocity_x=1e-3,
                      journal_speed=OMEGA, viscosity=MU)
    g = geometry(0.5, feed_holes=(FeedHole(angle=1.0, diameter=0.01),), supply_pressure=1e5)
    multigrid = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10).solve(state)
    sor = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10, method="sor").solve(state)
    assert multigrid.extra["multigrid"] == 1.0 and sor.extra["multigrid"] == 0.0
    assert multigrid.force_x == pytest.approx(sor.force_x, rel=1e-7)
    assert multigrid.force_y == pytest.approx(sor.force_y, rel=1e-7)
    assert multigrid.side_flow == pytest.approx(sor.side_flow, rel=1e-6)


def test_mid_plane_symmetry_shortcut_matches_full_grid():
    """Solving z ≤ 0 with a mirror plane equals the full-width solve (symmetric hole)."""
    g = geometry(0.5, feed_holes=(FeedHole(angle=2.5, diameter=0.008),), supply_pressure=2e5)
    state = FilmState(eccentricity_x=0.7 * C, eccentricity_y=-0.2 * C, velocity_x=1e-3,
                      journal_speed=OMEGA, viscosity=MU)
    half = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10).solve(state, with_pressure=True)
    full = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10,
                        use_symmetry=False).solve(state, with_pressure=True)
    assert np.max(np.abs(half.pressure - full.pressure)) < 1e-8 * full.max_pressure
    assert half.pressure == pytest.approx(half.pressure[:, ::-1], abs=1e-12 * full.max_pressure)
    assert half.side_flow == pytest.approx(full.side_flow, rel=1e-8)


def test_warm_started_force_is_smooth_enough_for_jacobians():
    """An implicit integrator differentiates F with tiny steps (~1e-8 of the state): the
    warm-started solver must resolve them. Forward differences at δ = 1e-8 c agree with a
    central difference at δ = 1e-4 c (the curvature error of which is ~1e-8)."""
    film = ReynoldsFilm(geometry(1.0), n_theta=72, n_z=16)
    base = dict(velocity_x=2e-4, journal_speed=OMEGA, viscosity=MU)
    f0 = np.array(film.force(FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.1 * C, **base)))
    tiny = 1e-8 * C
    forward = (np.array(film.force(FilmState(eccentricity_x=0.6 * C + tiny,
                                             eccentricity_y=0.1 * C, **base))) - f0) / tiny
    wide = 1e-4 * C
    plus = np.array(film.force(FilmState(eccentricity_x=0.6 * C + wide,
                                         eccentricity_y=0.1 * C, **base)))
    minus = np.array(film.force(FilmState(eccentricity_x=0.6 * C - wide,
                                          eccentricity_y=0.1 * C, **base)))
    central = (plus - minus) / (2 * wide)
    assert np.linalg.norm(forward - central) < 1e-3 * np.linalg.norm(central)


def test_symmetry_shortcut_on_a_bore_deformed_alike_over_the_width(monkeypatch):
    """A bore displacement that is the same at every z (a 2-D housing) keeps the problem
    mirror-symmetric: solved on z ≤ 0, equal to the full-width solve; a displacement that
    differs between the halves is solved on the full width."""
    from conrod.film.reynolds import sweep as sweep_module

    taken = []
    solve_on_grid = sweep_module.multigrid.solve_on_grid

    def spied(*args):
        taken.append(args[-1])
        return solve_on_grid(*args)

    monkeypatch.setattr(sweep_module.multigrid, "solve_on_grid", spied)
    g = geometry(0.5)
    theta = np.linspace(0.0, 2.0 * np.pi, 72, endpoint=False)
    row = 0.2 * C * np.cos(theta - 0.4)
    alike = np.repeat(row[:, None], 17, axis=1)
    uneven = alike + 0.05 * C * np.linspace(-1.0, 1.0, 17)[None, :]
    base = dict(eccentricity_x=0.5 * C, eccentricity_y=-0.2 * C, velocity_x=1e-3,
                journal_speed=OMEGA, viscosity=MU)
    for deformation, symmetric in ((alike, True), (uneven, False)):
        state = FilmState(deformation=deformation, **base)
        taken.clear()
        half = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10).solve(
            state, with_pressure=True)
        assert taken == [symmetric]
        full = ReynoldsFilm(g, n_theta=72, n_z=16, tolerance=1e-10,
                            use_symmetry=False).solve(state, with_pressure=True)
        assert np.max(np.abs(half.pressure - full.pressure)) < 1e-8 * full.max_pressure
