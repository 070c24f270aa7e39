"""A viscosity field μ(θ, z) in the Reynolds film (conrod.film.reynolds.viscosity_field):
the scalar answer from a uniform field, a uniform field of another viscosity against the
scalar at that viscosity, and a circumferentially varying field on a long bearing against
the one-dimensional Reynolds equation integrated by quadrature."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.capabilities import HasViscosityField
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.flight import flight_kernel

MU = 0.01
GEOMETRY = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6)


def _state(**extra) -> FilmState:
    return FilmState(eccentricity_x=12e-6, eccentricity_y=-9e-6, velocity_x=0.004,
                     velocity_y=0.001, journal_speed=300.0, viscosity=MU, **extra)


def test_reynolds_film_declares_the_capability():
    assert isinstance(ReynoldsFilm(GEOMETRY, n_theta=48, n_z=8), HasViscosityField)


def test_uniform_field_equal_to_the_viscosity_reproduces_the_scalar_answer():
    film = ReynoldsFilm(GEOMETRY, n_theta=48, n_z=8)
    scalar = film.solve(_state(), with_pressure=True)
    uniform = np.full(film.deformation_shape(), MU)
    by_state = film.solve(_state(viscosity_field=uniform), with_pressure=True)
    carried = film.with_viscosity_field(uniform).solve(_state(), with_pressure=True)
    for result in (by_state, carried):
        assert np.array_equal(result.pressure, scalar.pressure)  # bit for bit
        assert (result.force_x, result.force_y) == (scalar.force_x, scalar.force_y)
        assert result.side_flow == scalar.side_flow
        assert result.friction_power == pytest.approx(scalar.friction_power, rel=1e-13)


def test_uniform_field_in_the_compiled_flight_kernel_is_the_scalar_answer():
    film = ReynoldsFilm(GEOMETRY, n_theta=48, n_z=8)
    uniform = film.with_viscosity_field(np.full(film.deformation_shape(), MU))
    answers = []
    for f in (film, uniform):
        kernel = flight_kernel(f, None, 1e-10)
        answers.append(kernel.jacobian(12e-6, -9e-6, 0.004, 0.001, 300.0, MU, kernel.params))
    assert np.array_equal(answers[0][0], answers[1][0])
    assert np.array_equal(answers[0][1], answers[1][1])


def test_uniform_field_of_another_viscosity_is_the_scalar_answer_at_it():
    film = ReynoldsFilm(GEOMETRY, n_theta=48, n_z=8)
    doubled = film.solve(_state(viscosity_field=np.full(film.deformation_shape(), 2 * MU)))
    reference = film.solve(FilmState(eccentricity_x=12e-6, eccentricity_y=-9e-6,
                                     velocity_x=0.004, velocity_y=0.001,
                                     journal_speed=300.0, viscosity=2 * MU))
    assert doubled.force_x == pytest.approx(reference.force_x, rel=1e-10)
    assert doubled.force_y == pytest.approx(reference.force_y, rel=1e-10)
    assert doubled.friction_power == pytest.approx(reference.friction_power, rel=1e-10)
    kernel = flight_kernel(film.with_viscosity_field(np.full(film.deformation_shape(), 2 * MU)),
                           None, 1e-12)
    fx, fy = kernel.force(12e-6, -9e-6, 0.004, 0.001, 300.0, MU, kernel.params)
    assert (fx, fy) == pytest.approx((reference.force_x, reference.force_y), rel=1e-9)


def _long_bearing_pressure(theta, h, mu, speed, radius):
    """Full-film (Sommerfeld) long-bearing pressure with μ(θ): dp/dx = 6Uμ(h − h*)/h³,
    x = Rθ, h* from periodicity; trapezoidal quadrature on a fine grid [Pa]."""
    fine = np.linspace(0.0, 2 * np.pi, 20001)
    hf = np.interp(fine, theta, h, period=2 * np.pi)
    muf = np.interp(fine, theta, mu, period=2 * np.pi)
    def integral(f):
        return np.concatenate([[0.0], np.cumsum(0.5 * (f[1:] + f[:-1]) * np.diff(fine))])
    a, b = integral(muf / hf**2), integral(muf / hf**3)
    h_star = a[-1] / b[-1]
    p = 6.0 * speed * radius**2 * (a - h_star * b)  # dp/dθ = R dp/dx, U = ωR
    return np.interp(theta, fine, p)


def test_circumferential_field_on_a_long_bearing_matches_the_one_dimensional_equation():
    geometry = BearingGeometry(diameter=0.05, width=1.0, radial_clearance=25e-6,
                               cavitation_pressure=-1e12)
    film = ReynoldsFilm(geometry, n_theta=144, n_z=64)
    theta, _ = film.grid()
    mu = MU * (1.0 + 0.5 * np.cos(theta - 1.0))  # a hot and a cold side
    field = np.repeat(mu[:, None], film.n_z + 1, axis=1)
    state = FilmState(eccentricity_x=10e-6, eccentricity_y=0.0, journal_speed=300.0,
                      viscosity=MU, viscosity_field=field)
    result = film.solve(state, with_pressure=True)
    h = 25e-6 - 10e-6 * np.cos(theta)
    expected = _long_bearing_pressure(theta, h, mu, 300.0, 0.025)
    middle = result.pressure[:, film.n_z // 2]
    expected = expected - expected.mean() + middle.mean()  # gauge level: the edges' ambient
    assert np.max(np.abs(middle - expected)) < 0.01 * np.max(np.abs(expected))
    scalar = film.solve(FilmState(eccentricity_x=10e-6, eccentricity_y=0.0,
                                  journal_speed=300.0, viscosity=MU), with_pressure=True)
    change = np.max(np.abs(middle - scalar.pressure[:, film.n_z // 2]))
    assert change > 0.1 * np.max(np.abs(expected))  # the field matters


def test_bad_fields_are_refused_in_one_line():
    film = ReynoldsFilm(GEOMETRY, n_theta=48, n_z=8)
    with pytest.raises(CaseError, match="viscosity_field shape"):
        film.solve(_state(viscosity_field=np.full((10, 3), MU)))
    with pytest.raises(CaseError, match="viscosity_field"):
        _state(viscosity_field=np.full(film.deformation_shape(), -MU))
