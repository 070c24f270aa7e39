"""A tilted journal in the orbit: prescribed tilt and tilt as two more degrees of freedom,
with mass and massless, against the steady calculator and symmetry."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.steady_axial import solve_for_load_vector
from conrod.loads.tilt import JournalTilt, PeriodicTable
from conrod.orbit import OrbitProblem, OrbitState, integrate_cycle, periodic_orbit
from orbit_helpers import SPEED, geometry, load_cycle, short_problem, solver

WIDTH, C = 0.025, 25e-6
LEVER = 0.5 * WIDTH
LOAD = (2000.0, 700.0)
"""Constant load [N] of the steady tests."""


def problem(tilt: JournalTilt, *, mass=1.0, grid=(36, 8), load=LOAD, **film_kwargs):
    loads = load_cycle(lambda p: load[0] + 0 * p, lambda p: load[1] + 0 * p, cycle=2 * math.pi)
    film = ReynoldsFilm(geometry(width=WIDTH), n_theta=grid[0], n_z=grid[1], **film_kwargs)
    return OrbitProblem(film, loads, 0.01, mass, mass, tilt=tilt)


def prescribed(gx=0.0, gy=0.0, table=None) -> JournalTilt:
    return JournalTilt(lever=LEVER, crank_speed=SPEED, prescribed=table, constant=(gx, gy))


def free(offset=0.0, inertia=(0.0, 0.0), moment=(0.0, 0.0)) -> JournalTilt:
    return JournalTilt(lever=LEVER, crank_speed=SPEED, free=True, inertia=inertia,
                       constant_moment=moment, load_offset=offset)


def settle(orbit_problem, integrator="quasi_static", cycles=3, **settings):
    return periodic_orbit(orbit_problem, solver(max_cycles=cycles, min_cycles=cycles,
                                                integrator=integrator, **settings)).last


def test_prescribed_tilt_settles_at_the_steady_point_of_the_steady_calculator():
    """Constant load and tilt, massless orbit: the journal comes to rest where the steady
    calculator for a load vector with the same tilt puts it (same film, same grid)."""
    gx, gy = 0.2 * C / LEVER, -0.1 * C / LEVER
    last = settle(problem(prescribed(gx, gy)))
    steady = solve_for_load_vector(math.hypot(*LOAD), math.atan2(LOAD[1], LOAD[0]), SPEED,
                                   0.01, geometry(width=WIDTH), tilt=(gx, gy), grid=(36, 8))
    assert last.x[-1] == pytest.approx(steady.eccentricity_x, abs=1e-6 * C)
    assert last.y[-1] == pytest.approx(steady.eccentricity_y, abs=1e-6 * C)
    assert np.abs(last.tilt[:, :2] - [gx, gy]).max() == 0.0


def test_free_tilt_balances_the_moment_of_an_offset_load():
    """The load acting 3 mm off mid-width tilts the free journal until the film's moment
    balances a(−W_y, W_x); the steady calculator at that tilt agrees on the position."""
    offset = 0.003
    tilt = free(offset=offset)
    orbit_problem = problem(tilt)
    last = settle(orbit_problem)
    gx, gy = last.tilt[-1, :2]
    assert math.hypot(gx, gy) > 1e-5  # the journal does tilt
    steady = solve_for_load_vector(math.hypot(*LOAD), math.atan2(LOAD[1], LOAD[0]), SPEED,
                                   0.01, geometry(width=WIDTH), tilt=(gx, gy), grid=(36, 8))
    expected = np.array(tilt.moment_at(0.0, LOAD))
    assert [steady.moment_x, steady.moment_y] == pytest.approx(-expected, rel=1e-5)
    assert last.x[-1] == pytest.approx(steady.eccentricity_x, abs=1e-6 * C)


def test_mirror_symmetric_tilts_give_the_same_orbit():
    """+γ and −γ (prescribed): the same orbit, the film mirrored about the mid-plane."""
    plus = integrate_cycle(problem(prescribed(2e-4, -1e-4)), OrbitState(), solver(
        integrator="implicit"))
    minus = integrate_cycle(problem(prescribed(-2e-4, 1e-4)), OrbitState(), solver(
        integrator="implicit"))
    assert np.abs(plus.x - minus.x).max() < 1e-6 * C
    assert np.abs(plus.y - minus.y).max() < 1e-6 * C


def test_free_tilt_without_moment_stays_aligned():
    """A symmetric film and no external moment: the free journal stays aligned (γ to
    round-off) and moves as with a prescribed zero tilt."""
    aligned = integrate_cycle(problem(prescribed()), OrbitState(), solver(integrator="implicit"))
    loose = integrate_cycle(problem(free(inertia=(0.01, 0.01))), OrbitState(),
                            solver(integrator="implicit"))
    assert LEVER * np.abs(loose.tilt[:, :2]).max() < 1e-6 * C  # round-off of the solves
    assert np.abs(loose.x - aligned.x).max() < 1e-6 * C


def test_with_mass_approaches_the_massless_orbit():
    """Small masses and inertias: the orbit with mass tends to the massless one."""
    tilt = free(offset=0.002, inertia=(1e-6, 1e-6))
    massless = settle(problem(tilt), "quasi_static", 2)
    light = settle(problem(tilt, mass=1e-3), "implicit", 2)
    assert np.abs(light.x - massless.x).max() < 2e-3 * C
    assert np.abs(light.tilt[:, 1] - massless.tilt[:, 1]).max() < 2e-3 * np.abs(
        massless.tilt[:, 1]).max()


def test_tilt_table_is_a_periodic_spline():
    """A tilt table over the cycle: values at the nodes, continuous periodic rate."""
    angles = np.linspace(0.0, 2 * math.pi, 12, endpoint=False)
    values = np.column_stack([1e-4 * np.sin(angles), 5e-5 * np.cos(2 * angles)])
    tilt = prescribed(table=PeriodicTable(angles, values, 2 * math.pi))
    for k in (0, 5, 11):
        gx, gy, _, _ = tilt.tilt_at(angles[k])
        assert (gx, gy) == pytest.approx(tuple(values[k]), abs=1e-18)
    start, end = tilt.tilt_at(0.0), tilt.tilt_at(2 * math.pi - 1e-12)
    assert start[2] == pytest.approx(end[2], rel=1e-6)  # periodic rate
    assert start[2] == pytest.approx(SPEED * 1e-4, rel=0.05)  # ≈ ω d(sin)/dφ at 0


def test_films_and_integrators_that_cannot_take_a_tilt_refuse_it():
    loads = load_cycle(lambda p: 5000.0 + 0 * p, lambda p: 0 * p, cycle=2 * math.pi)
    short = replace(short_problem(loads), tilt=prescribed(1e-4))
    with pytest.raises(CaseError, match="cannot take a journal tilt"):
        integrate_cycle(short, OrbitState(), solver(integrator="implicit"))
    with pytest.raises(CaseError, match="rk2"):
        integrate_cycle(problem(prescribed(1e-4)), OrbitState(), solver(integrator="rk2",
                                                                         step_deg=0.01))
    asperity = replace(problem(prescribed(1e-4)), asperity=(0.025, 0.025, 4e-7, 1e9))
    with pytest.raises(CaseError, match="greenwood_tripp"):
        integrate_cycle(asperity, OrbitState(), solver(integrator="implicit"))


def test_compiled_flight_of_the_tilted_journal_equals_its_fixed_steps():
    """The compiled TR-BDF2 orbit of a tilted journal (error-controlled) and the fixed BDF2
    steps of the same problem give the same periodic orbit, position and tilt, within the
    fixed step's error; the compiled kernel's forces and moments are the film's."""
    from conrod.orbit.implicit_step import implicit_step_cycle
    from conrod.orbit.tilt_flight import applies

    loads = load_cycle(lambda p: 2000.0 + 1500.0 * np.cos(p), lambda p: 800.0 * np.sin(p),
                       cycle=2 * math.pi)
    film = ReynoldsFilm(geometry(width=WIDTH), n_theta=36, n_z=8)
    orbit_problem = OrbitProblem(film, loads, 0.01, 1.0, 1.0,
                                 tilt=free(offset=0.002, inertia=(2e-4, 2e-4)))
    assert applies(orbit_problem)
    compiled = periodic_orbit(orbit_problem, solver(max_cycles=4, integrator="implicit",
                                                    periodicity_tolerance=1e-5)).last
    fixed = compiled
    for _ in range(2):
        fixed = implicit_step_cycle(orbit_problem, fixed.end_state, 0.25, 1.0, with_mass=True)
    assert np.abs(fixed.x - compiled.x).max() < 2e-5 * C
    assert np.abs(fixed.tilt[:, 1] - compiled.tilt[:, 1]).max() < 1e-4 * np.abs(
        compiled.tilt[:, 1]).max()
    kernel = film.tilt_flight_kernel(None, 1e-12)
    state = replace(film_state_at(compiled, 40), viscosity=0.01)
    q = kernel.force(state.eccentricity_x, state.eccentricity_y, state.tilt_x, state.tilt_y,
                     state.velocity_x, state.velocity_y, state.tilt_rate_x, state.tilt_rate_y,
                     SPEED, 0.01, kernel.params)
    result = film.solve(state)
    assert q == pytest.approx([result.force_x, result.force_y, result.moment_x,
                               result.moment_y], rel=1e-9, abs=1e-9)


def film_state_at(trajectory, i):
    from conrod.film.base import FilmState

    gx, gy, rx, ry = trajectory.tilt[i]
    return FilmState(eccentricity_x=float(trajectory.x[i]), eccentricity_y=float(trajectory.y[i]),
                     velocity_x=float(trajectory.vx[i]), velocity_y=float(trajectory.vy[i]),
                     journal_speed=SPEED, tilt_x=float(gx), tilt_y=float(gy),
                     tilt_rate_x=float(rx), tilt_rate_y=float(ry))
