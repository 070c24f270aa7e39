"""Fast quasi-static velocity paths (issue 4 speed): Booker's squeeze reduction for grid
Reynolds films and the compiled table-film loop, checked against the Newton solve they
replace and against the identities they rest on."""

from __future__ import annotations

import math

import numpy as np
import pytest

import conrod.orbit.quasi_static as qs
from conrod.film.base import BearingGeometry, FilmState, Groove
from conrod.film.capabilities import HasCompiledKernel
from conrod.film.reynolds import squeeze as sv
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.orbit import OrbitState
from orbit_helpers import SPEED, engine_like_load, geometry, load_cycle, short_problem

MU = 0.01
STATES = [  # x, y [m], W_x, W_y [N], ω_j, ω_b [rad/s]
    (5e-6, 3e-6, 2000.0, -1000.0, SPEED, 0.0),
    (-15e-6, 12e-6, -8000.0, 15000.0, SPEED, 30.0),
    (20e-6, -10e-6, 30000.0, -5000.0, SPEED, -20.0),
    (0.0, 0.0, 1000.0, 500.0, -SPEED, SPEED),
]


def coarse_film(**kwargs) -> ReynoldsFilm:
    return ReynoldsFilm(kwargs.pop("geometry", geometry()), n_theta=48, n_z=8, **kwargs)


def force(film, x, y, vx, vy, wj=0.0, wb=0.0):
    return np.array(film.force(FilmState(eccentricity_x=x, eccentricity_y=y, velocity_x=vx,
                                         velocity_y=vy, journal_speed=wj, shell_speed=wb,
                                         viscosity=MU)))


def test_squeeze_force_is_homogeneous_of_degree_one():
    film = coarse_film()
    for x, y, *_ in STATES:
        for beta in (0.3, 2.0, -2.5):
            v = 0.01 * np.array([math.cos(beta), math.sin(beta)])
            f1, f2 = force(film, x, y, *v), force(film, x, y, *(2.0 * v))
            np.testing.assert_allclose(f2, 2.0 * f1, rtol=1e-9, atol=1e-9 * np.abs(f2).max())


def test_discrete_wedge_equals_squeeze_in_the_mean_frame():
    """F(e, ė, ω_j, ω_b) = F(e, ė − κ ω̄ × e, 0, 0), κ = sin Δθ/Δθ (central-difference wedge)."""
    film = coarse_film()
    d_theta = 2.0 * math.pi / 48
    kappa = math.sin(d_theta) / d_theta
    for x, y, _, _, wj, wb in STATES:
        mean = 0.5 * kappa * (wj + wb)
        full = force(film, x, y, 0.003, -0.002, wj, wb)
        squeeze = force(film, x, y, 0.003 + mean * y, -0.002 - mean * x)
        np.testing.assert_allclose(full, squeeze, rtol=1e-9, atol=1e-9 * np.abs(full).max())


def _squeeze_solve(film, x, y, wx, wy, wj, wb):
    grid = sv.SqueezeGrid(film, MU)
    radius, d_theta, d_z, c = grid.geometry
    g = (grid.fixed, grid.source_x, grid.source_y, grid.weight_x, grid.weight_y,
         radius, d_theta, d_z, grid.n_coarse, grid.symmetric, grid.stats)
    mean = 0.5 * math.sin(d_theta) / d_theta * (wj + wb)
    return sv.squeeze_velocity(x, y, wx, wy, mean, 0.3, 1.0, grid.pressure, grid.cos_t,
                               grid.sin_t, g, c, c * SPEED, 1e-12, 20000,
                               np.zeros_like(grid.pressure), np.zeros_like(grid.pressure))


@pytest.mark.parametrize("variant", ["symmetric", "groove", "n_z=6"])
def test_squeeze_velocity_equals_newton_and_balances_the_load(variant):
    geo = geometry()
    if variant == "groove":  # an ambient partial groove off the mid-plane: no z-symmetry
        groove = Groove(start_angle=1.0, extent=2.0, width=0.004, axial_position=0.005)
        geo = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6, grooves=(groove,))
    film = coarse_film(geometry=geo)
    if variant == "n_z=6":  # half grid with an odd interval count: full-grid solve
        film = ReynoldsFilm(geo, n_theta=48, n_z=6)
    problem = short_problem(load_cycle(np.cos, np.sin), film=film, viscosity=MU)
    assert problem.kernel is not None and problem.kernel.quasi_static_cycle is not None
    newton = qs._generic_newton(problem, 25e-6 * SPEED)
    for x, y, wx, wy, wj, wb in STATES:
        vx, vy, *_, miss = _squeeze_solve(film, x, y, wx, wy, wj, wb)
        nx, ny, _ = newton(x, y, wx, wy, wj, wb, (0.0, 0.0))
        assert miss < 1e-8
        assert math.hypot(vx - nx, vy - ny) < 1e-6 * math.hypot(nx, ny)
        residual = force(film, x, y, vx, vy, wj, wb) + (wx, wy)
        assert np.hypot(*residual) < 1e-7 * math.hypot(wx, wy)


def test_reduction_not_used_where_it_is_not_exact():
    loads = load_cycle(np.cos, np.sin)
    fed = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6,
                          grooves=(Groove(width=0.003),),
                          supply_pressure=3e5)
    cavitating = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6,
                                 cavitation_pressure=-1e4)
    for geo in (fed, cavitating):
        assert short_problem(loads, film=coarse_film(geometry=geo)).kernel is None
    assert short_problem(loads, film=coarse_film(method="sor")).kernel is None


def _orbit(problem, monkeypatch, fast: bool):
    if not fast:
        monkeypatch.setattr(qs, "compiled_kernel", lambda p: None)
    trajectory = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    monkeypatch.undo()
    return np.array([trajectory.x, trajectory.y])


def test_reynolds_orbit_unchanged_by_the_squeeze_path(monkeypatch):
    loads = load_cycle(*engine_like_load())
    problem = short_problem(loads, film=coarse_film(), viscosity=MU)
    fast, newton = _orbit(problem, monkeypatch, True), _orbit(problem, monkeypatch, False)
    h_fast = problem.clearance - np.hypot(*fast)
    h_newton = problem.clearance - np.hypot(*newton)
    assert np.abs(fast - newton).max() < 1e-7 * problem.clearance
    assert abs(h_fast.min() - h_newton.min()) < 1e-7 * problem.clearance


def test_compiled_table_orbit_balances_the_table_force_and_follows_reynolds(tmp_path):
    """Every recorded velocity of the compiled table loop satisfies F_table + W = 0 (the
    generic Newton on the piecewise-quadratic table fails here: residual 3e-4), and the
    orbit stays within the table's interpolation error of the direct Reynolds orbit."""
    from conrod.film.table.film import TabulatedFilm

    base = coarse_film()
    table = TabulatedFilm(base, cache_dir=tmp_path)
    loads = load_cycle(*engine_like_load())
    problem = short_problem(loads, film=table, viscosity=MU)
    assert qs.compiled_applies(problem)
    run = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    load_x, load_y = loads.load(run.crank_angle)
    for k in np.flatnonzero(run.contact_force == 0.0)[::7]:
        f = table.force(FilmState(eccentricity_x=run.x[k], eccentricity_y=run.y[k],
                                  velocity_x=run.vx[k], velocity_y=run.vy[k], journal_speed=SPEED,
                                  shell_speed=0.0, viscosity=MU))
        assert math.hypot(f[0] + load_x[k], f[1] + load_y[k]) < 1e-8 * math.hypot(
            load_x[k], load_y[k])
    direct = qs.quasi_static_cycle(short_problem(loads, film=base, viscosity=MU),
                                   OrbitState(), 1.0, 2.0)
    gap = np.hypot(run.x - direct.x, run.y - direct.y)
    assert gap.max() < 0.02 * problem.clearance


# ------------------------------------------------- short bearing: Booker's exact inversion
SHORT = (0.01, 0.025, 0.025, 25e-6)  # μ [Pa s], R, L, c [m]
SHORT_STATES = [  # x, y [m], W_x, W_y [N], ω_j, ω_b [rad/s]
    (5e-6, 3e-6, 2000.0, -1000.0, SPEED, 0.0),
    (-15e-6, 12e-6, -8000.0, 15000.0, SPEED, 30.0),
    (0.98 * 25e-6, 0.0, 30000.0, 2000.0, SPEED, 0.0),  # near contact, pressed on the wall
    (0.0, -0.98 * 25e-6, 500.0, 4000.0, SPEED, -40.0),  # near contact, pulled off the wall
    (0.98 * 25e-6 * 0.6, 0.98 * 25e-6 * 0.8, -3000.0, -1000.0, SPEED, 0.0),
    (12e-6, -6e-6, 2500.0, 9000.0, -SPEED, 0.0),  # reversed rotation
    (0.98 * 25e-6 * 0.8, -0.98 * 25e-6 * 0.6, 20000.0, -15000.0, -SPEED, -20.0),
    (0.0, 0.0, 1000.0, 500.0, -SPEED, SPEED),
]


@pytest.mark.parametrize("state", SHORT_STATES)
def test_short_velocity_equals_newton_and_balances_the_load(state):
    from conrod.film.short.kernel import short_bearing_force
    from conrod.film.short.velocity import newton_short_velocity, short_velocity

    x, y, wx, wy, wj, wb = state
    for guess in (0.0, 2.0, -3.0):  # cold starts from anywhere on the circle
        vx, vy, _, residual, _ = short_velocity(x, y, wx, wy, wj, wb, *SHORT, guess)
        nx, ny, newton_residual, _ = newton_short_velocity(
            x, y, wx, wy, wj, wb, *SHORT, 0.0, 0.0, 25e-6 * SPEED)
        assert newton_residual < 1e-10 and residual < 1e-11
        assert math.hypot(vx - nx, vy - ny) <= 1e-8 * math.hypot(nx, ny)
        fx, fy = short_bearing_force(x, y, vx, vy, wj + wb, *SHORT)
        assert math.hypot(fx + wx, fy + wy) < 1e-10 * math.hypot(wx, wy)


def test_short_velocity_without_load_is_the_half_speed_whirl():
    """No load, no film force: ė = ω̄ × e (SPEC pitfall: the whirl carries nothing)."""
    from conrod.film.short.velocity import short_velocity

    vx, vy, *_ = short_velocity(10e-6, -4e-6, 0.0, 0.0, SPEED, 30.0, *SHORT, 1.0)
    mean = 0.5 * (SPEED + 30.0)
    assert (vx, vy) == pytest.approx((mean * 4e-6, mean * 10e-6), rel=1e-15)


@pytest.mark.parametrize("eps", [0.0, 0.4, 0.98])
def test_short_unit_force_direction_derivative_and_homogeneity(eps):
    """dg/dα in closed form (arc-end terms vanish with the pressure) against central
    differences of g; F(v_s) = |v_s| F(v̂_s) in the ω̄ frame (both used by the inversion)."""
    from conrod.film.short.kernel import short_bearing_force
    from conrod.film.short.velocity import unit_force_direction

    h = 1e-3
    for alpha in np.linspace(-3.0, 3.0, 13):
        g_r, g_t, d_r, d_t = unit_force_direction(alpha, eps)
        g = [np.array(unit_force_direction(alpha + k * h, eps)[:2]) for k in (-2, -1, 1, 2)]
        numeric = (g[0] - 8.0 * g[1] + 8.0 * g[2] - g[3]) / (12.0 * h)  # O(h⁴) stencil
        scale = max(math.hypot(g_r, g_t), math.hypot(d_r, d_t))  # rounding ∝ |g|
        assert np.abs(numeric - (d_r, d_t)).max() < 1e-8 * scale
    x, y, mean = eps * 25e-6 * 0.6, -eps * 25e-6 * 0.8, 0.5 * SPEED
    for beta in (0.3, 2.0, -2.5):
        sx, sy = 0.01 * math.cos(beta), 0.01 * math.sin(beta)
        f1 = short_bearing_force(x, y, sx - mean * y, sy + mean * x, SPEED, *SHORT)
        f2 = short_bearing_force(x, y, 3 * sx - mean * y, 3 * sy + mean * x, SPEED, *SHORT)
        np.testing.assert_allclose(f2, 3.0 * np.array(f1), rtol=1e-12,
                                   atol=1e-12 * np.abs(f2).max())


def test_short_force_angle_is_monotone_and_brackets_the_root():
    """The inversion's bracket: φ(α) increases (dφ/dα > 0) and |φ − α − π/2| < π/2."""
    from conrod.film.short.velocity import unit_force_direction

    for eps in (0.0, 0.5, 0.98, 0.9999):
        for alpha in np.linspace(-math.pi, math.pi, 721):
            g_r, g_t, d_r, d_t = unit_force_direction(alpha, eps)
            assert g_r * d_t - g_t * d_r > 0.0
            offset = (math.atan2(g_t, g_r) - alpha - 0.5 * math.pi + math.pi) % (2 * math.pi)
            assert abs(offset - math.pi) < 0.5 * math.pi


def _python_loop(problem, monkeypatch):
    """Orbit of the uncompiled loop: Newton (short bearing) or ``journal_velocity``."""
    monkeypatch.setattr(qs, "compiled_applies", lambda p: False)
    trajectory = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    monkeypatch.undo()
    return trajectory


@pytest.mark.parametrize("journal", [SPEED, -SPEED])
def test_short_orbit_unchanged_by_the_booker_path(monkeypatch, journal):
    loads = load_cycle(*engine_like_load(peak=1.0e5, base=2.0e4), journal=journal)
    problem = short_problem(loads, viscosity=0.001, contact_film_thickness=1e-6)
    assert qs.compiled_applies(problem)
    fast = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    newton = _python_loop(problem, monkeypatch)
    # reaches the contact circle ε = 0.96 at the firing peak (18-20°; before the first
    # output interval from the concentric start was sub-stepped, the first Heun step
    # threw the journal onto the circle at 2° and kept it there to 20°)
    assert np.count_nonzero(newton.contact_force) >= 2
    assert np.abs(fast.x - newton.x).max() < 1e-9 * problem.clearance
    assert np.abs(fast.y - newton.y).max() < 1e-9 * problem.clearance
    np.testing.assert_allclose(fast.contact_force, newton.contact_force, rtol=1e-9,
                               atol=1e-9 * newton.contact_force.max())


def test_mobility_orbit_unchanged_by_the_compiled_loop(monkeypatch):
    """Compiled table loop and compiled contact forces reproduce the Python loop over
    ``MobilityFilm.journal_velocity`` and ``problem.force_function`` (same kernels: to rounding)."""
    from conrod.film.table.mobility import MobilityFilm

    film = MobilityFilm.short_bearing(geometry(), n_eps=20, n_direction=32)
    loads = load_cycle(*engine_like_load(peak=1.0e5, base=2.0e4))
    problem = short_problem(loads, film=film, viscosity=0.001, contact_film_thickness=1e-6)
    assert isinstance(film, HasCompiledKernel) and qs.compiled_applies(problem)
    fast = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    slow = _python_loop(problem, monkeypatch)
    assert np.count_nonzero(slow.contact_force) >= 2  # the firing peak, as above
    for name in ("x", "y", "vx", "vy", "contact_force", "friction_force"):
        reference = getattr(slow, name)
        np.testing.assert_allclose(getattr(fast, name), reference, rtol=1e-12,
                                   atol=1e-12 * np.abs(reference).max())
