"""Journal tilt (misalignment) in the grid films: film thickness, tilting moments and their
linearisation against independent answers."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.linearised import linearise_by_differences
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.rated_state import rated
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm

MU, D, L, C, OMEGA = 0.01, 0.05, 0.025, 25e-6, 300.0
GEOMETRY = BearingGeometry(diameter=D, width=L, radial_clearance=C)
TILT = 0.4 * C / (0.5 * L)
"""A tilt that moves the edge by 0.4 c [rad]."""


def state(ex=0.4, ey=0.2, gx=0.0, gy=0.0, **more) -> FilmState:
    return FilmState(eccentricity_x=ex * C, eccentricity_y=ey * C, journal_speed=OMEGA,
                     viscosity=MU, tilt_x=gx, tilt_y=gy, **more)


def generalised(result) -> np.ndarray:
    return np.array([result.force_x, result.force_y, result.moment_x, result.moment_y])


def films():
    return [ReynoldsFilm(GEOMETRY, 48, 16), MassConservingFilm(GEOMETRY, 48, 16, tolerance=1e-12)]


def test_zero_tilt_is_the_aligned_film_bit_for_bit():
    """tilt = 0 given explicitly takes the aligned path: every number identical."""
    for film in films():
        a = film.solve(state(), with_pressure=True)
        b = film.solve(state(gx=0.0, gy=0.0, tilt_rate_x=0.0, tilt_rate_y=0.0),
                       with_pressure=True)
        assert np.array_equal(a.pressure, b.pressure)
        assert (a.force_x, a.force_y, a.moment_x, a.moment_y) == (
            b.force_x, b.force_y, b.moment_x, b.moment_y)


@pytest.mark.parametrize("film", films(), ids=["reynolds", "mass_conserving"])
def test_mirror_symmetry_same_force_opposite_moments(film):
    """h(θ, z; +γ) = h(θ, −z; −γ): +γ and −γ give the same force and opposite moments."""
    plus = generalised(film.solve(state(gx=TILT, gy=-0.3 * TILT)))
    minus = generalised(film.solve(state(gx=-TILT, gy=0.3 * TILT)))
    scale = np.abs(plus).max()
    assert np.allclose(plus[:2], minus[:2], rtol=1e-9, atol=1e-12 * scale)
    assert np.allclose(plus[2:], -minus[2:], rtol=1e-9, atol=1e-12 * scale)
    assert abs(plus[2]) > 1e-3 * abs(plus[0]) * L  # the moments are not trivially zero


@pytest.mark.parametrize("film", films(), ids=["reynolds", "mass_conserving"])
def test_tilted_centred_journal_no_net_force_and_a_restoring_moment(film):
    """Pure misalignment of a centred journal: the film at −z is the film at +z turned by π,
    so the net force vanishes; the moment opposes the tilt (M·γ < 0)."""
    for direction in (0.0, 1.0, 2.5):
        gx, gy = TILT * math.cos(direction), TILT * math.sin(direction)
        result = film.solve(state(0.0, 0.0, gx, gy))
        moment = np.array([result.moment_x, result.moment_y])
        assert math.hypot(result.force_x, result.force_y) < 1e-9 * np.linalg.norm(moment) / L
        assert moment @ np.array([gx, gy]) < 0.0


@pytest.mark.parametrize("film", films(), ids=["reynolds", "mass_conserving"])
def test_moments_are_slice_forces_times_lever_arms(film):
    """M_x = −∫ z F_y(z) dz, M_y = ∫ z F_x(z) dz from the pressure of each axial slice."""
    result = film.solve(state(gx=TILT, gy=0.5 * TILT), with_pressure=True)
    theta, z = film.grid()
    arc = GEOMETRY.radius * 2.0 * math.pi / theta.size
    slice_x = -arc * np.cos(theta) @ result.pressure  # force per unit width [N/m]
    slice_y = -arc * np.sin(theta) @ result.pressure
    width = np.full(z.size, z[1] - z[0])
    width[[0, -1]] *= 0.5
    assert result.moment_x == pytest.approx(-np.sum(z * slice_y * width), rel=1e-10)
    assert result.moment_y == pytest.approx(np.sum(z * slice_x * width), rel=1e-10)
    assert result.force_x == pytest.approx(np.sum(slice_x * width), rel=1e-10)


def test_tilt_is_the_deformation_field_it_describes():
    """The tilt equals the additive field z(γ_x sin θ − γ_y cos θ) and its rate the bore rate
    of the same shape in the squeeze term."""
    base = ReynoldsFilm(GEOMETRY, 48, 16)
    film = base.with_deformation_rate()
    theta, z = film.grid()
    gx, gy, rx, ry = TILT, -0.5 * TILT, 2.0, -1.0
    field = np.multiply.outer(gx * np.sin(theta) - gy * np.cos(theta), z)
    rate = np.multiply.outer(rx * np.sin(theta) - ry * np.cos(theta), z)
    tilted = film.solve(state(gx=gx, gy=gy, tilt_rate_x=rx, tilt_rate_y=ry))
    deformed = film.solve(rated(state(), field, rate))
    assert generalised(tilted) == pytest.approx(generalised(deformed), rel=1e-12)


def test_four_by_four_coefficients_against_finite_differences():
    """The 4 × 4 stiffness and damping of forces and moments by (e, γ) from the active-set
    solve equal central differences of the film's forces and moments."""
    film = ReynoldsFilm(GEOMETRY, 48, 16, tolerance=1e-14)
    at = state(gx=0.5 * TILT, gy=-0.2 * TILT, velocity_x=1e-3, tilt_rate_x=0.02)
    exact = film.sensitivities(at)
    differences = linearise_by_differences(film, at, tilt=True)
    for name in ("full_stiffness", "full_damping"):
        a, b = getattr(exact, name), getattr(differences, name)
        assert np.abs(a - b).max() <= 1e-6 * np.abs(b).max()
    assert np.array_equal(exact.full_stiffness[:2, :2], exact.stiffness)
    assert exact.moment == pytest.approx(differences.moment, rel=1e-12)
    assert set(exact.as_dict(tilt=True)) > set(exact.as_dict())


def test_squeeze_damping_of_forces_and_moments_is_symmetric():
    """Without rotation the squeeze film dissipates q̇ᵀCq̇: the 4 × 4 damping is symmetric, a
    check that the moments are the generalised forces of the tilt angles."""
    film = ReynoldsFilm(GEOMETRY, 48, 16, tolerance=1e-14)
    at = replace(state(gx=0.5 * TILT, gy=-0.2 * TILT, velocity_x=1e-3), journal_speed=0.0)
    damping = film.sensitivities(at).full_damping
    assert np.abs(damping - damping.T).max() <= 1e-10 * np.abs(damping).max()
    assert abs(damping[0, 2]) > 1e-6 * damping[0, 0] * L  # coupled, not trivially zero


def test_films_uniform_along_the_width_refuse_a_tilt():
    with pytest.raises(CaseError, match="cannot take a journal tilt"):
        ShortBearingFilm(GEOMETRY).force(state(gx=TILT))
    with pytest.raises(CaseError, match="tilt_x"):
        state(gx=1.0)


# --------------------------------------------------------------- independent JFO solver
def independent_jfo(h: np.ndarray, inlet: int, speed: float, viscosity: float, radius: float,
                    width: float) -> tuple[np.ndarray, np.ndarray]:
    """Steady JFO (Elrod–Adams p–ϑ) on a vertex grid, written from the flux balance and solved
    by semismooth Newton on the Fischer–Burmeister complementarity of p ≥ 0 and 1 − ϑ ≥ 0:
    (p [Pa], ϑ [-]) with p = 0, ϑ = 1 on the edges and on the inlet column."""
    n, m = h.shape
    dx, dz = radius * 2.0 * math.pi / n, width / (m - 1)
    free = np.ones((n, m), dtype=bool)
    free[:, [0, -1]] = False
    free[inlet] = False
    index = -np.ones((n, m), dtype=int)
    index[free] = np.arange(free.sum())
    k = int(free.sum())
    rows = []
    scale = 6.0 * viscosity * speed * radius * width / C  # a pressure scale [Pa]
    for i in range(n):
        for j in range(1, m - 1):
            if not free[i, j]:
                continue
            row = index[i, j]
            for (a, b, face) in ((i + 1, j, "e"), (i - 1, j, "w"), (i, j + 1, "n"),
                                 (i, j - 1, "s")):
                a %= n
                h_face = 0.5 * (h[i, j] + h[a, b])
                conductance = h_face ** 3 * (dz / dx if face in "ew" else dx / dz)
                rows.append((row, row, conductance, 0.0))
                if free[a, b]:
                    rows.append((row, index[a, b], -conductance, 0.0))
            couette_e = 6.0 * viscosity * speed * radius * 0.5 * (h[i, j] + h[(i + 1) % n, j]) * dz
            couette_w = 6.0 * viscosity * speed * radius * 0.5 * (h[i, j] + h[i - 1, j]) * dz
            rows.append((row, row, 0.0, couette_e))  # upwind: the east face carries ϑ_i
            if free[i - 1, j]:
                rows.append((row, index[i - 1, j], 0.0, -couette_w))
            else:  # the west neighbour is full: its flux is known
                rows.append((row, -1, 0.0, -couette_w))
    known = np.zeros(k)
    entries_p, entries_t = [], []
    for row, col, a_p, a_t in rows:
        if col < 0:
            known[row] += a_t
        else:
            if a_p:
                entries_p.append((row, col, a_p))
            if a_t:
                entries_t.append((row, col, a_t))
    a_p = sp.csr_matrix(([e[2] for e in entries_p], ([e[0] for e in entries_p],
                         [e[1] for e in entries_p])), shape=(k, k))
    a_t = sp.csr_matrix(([e[2] for e in entries_t], ([e[0] for e in entries_t],
                         [e[1] for e in entries_t])), shape=(k, k))
    p, theta = np.zeros(k), np.ones(k)
    for _ in range(200):
        mass = a_p @ p + a_t @ theta + known
        a, b = p / scale, 1.0 - theta
        root = np.sqrt(a * a + b * b)
        fb = a + b - root
        residual = np.concatenate([mass, fb])
        if np.abs(mass).max() <= 1e-14 * np.abs(a_t.diagonal()).max() and np.abs(fb).max() < 1e-14:
            break
        safe = np.where(root > 0.0, root, 1.0)
        d_a = np.where(root > 0.0, 1.0 - a / safe, 1.0 - 1.0 / math.sqrt(2.0))
        d_b = np.where(root > 0.0, 1.0 - b / safe, 1.0 - 1.0 / math.sqrt(2.0))
        jac = sp.bmat([[a_p, a_t], [sp.diags(d_a / scale), sp.diags(-d_b)]], format="csc")
        step = spsolve(jac, -residual)
        lam, norm = 1.0, np.linalg.norm(residual)
        while lam > 1e-6:
            trial_p, trial_t = p + lam * step[:k], theta + lam * step[k:]
            trial = np.concatenate([a_p @ trial_p + a_t @ trial_t + known,
                                    trial_p / scale + (1 - trial_t)
                                    - np.hypot(trial_p / scale, 1 - trial_t)])
            if np.linalg.norm(trial) < norm:
                break
            lam *= 0.5
        p, theta = trial_p, trial_t
    pressure, fraction = np.zeros((n, m)), np.ones((n, m))
    pressure[free], fraction[free] = p, theta
    return pressure, fraction


def test_tilted_steady_jfo_film_against_an_independent_finite_volume_solver():
    """A tilted journal in the steady mass-conserving film (Ausas sweep) against an
    independent finite-volume JFO solver (semismooth Newton on the Fischer–Burmeister
    form): pressure, film fraction, forces and moments."""
    film = MassConservingFilm(GEOMETRY, 36, 8, tolerance=1e-13, max_iterations=200000)
    at = state(0.5, 0.0, 0.6 * TILT, -0.4 * TILT)
    result = film.solve_steady(at, with_pressure=True)
    theta, z = film.grid()
    h = (C - np.multiply.outer(np.cos(theta), at.eccentricity_x + z * at.tilt_y)
         - np.multiply.outer(np.sin(theta), at.eccentricity_y - z * at.tilt_x))
    pressure, fraction = independent_jfo(h, theta.size // 2, OMEGA, MU, GEOMETRY.radius, L)
    assert fraction.min() < 0.9  # a cavitated region exists
    scale = pressure.max()
    assert np.abs(result.pressure - pressure).max() <= 1e-10 * scale
    assert np.abs(film.last_film_fraction - fraction).max() <= 1e-10
    area = GEOMETRY.radius * (2.0 * math.pi / theta.size) * np.where(
        np.isin(np.arange(z.size), [0, z.size - 1]), 0.5, 1.0) * (z[1] - z[0])
    force_x = -np.sum(pressure * np.cos(theta)[:, None] * area)
    moment_x = np.sum(pressure * np.multiply.outer(np.sin(theta), z) * area)
    moment_y = -np.sum(pressure * np.multiply.outer(np.cos(theta), z) * area)
    assert result.force_x == pytest.approx(force_x, rel=1e-10)
    assert result.moment_x == pytest.approx(moment_x, rel=1e-9)
    assert result.moment_y == pytest.approx(moment_y, rel=1e-9)
    assert abs(moment_x) > 1e-3 * abs(force_x) * L
