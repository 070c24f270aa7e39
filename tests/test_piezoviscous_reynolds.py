"""Piezoviscous Reynolds and mass-conserving films against independent answers.

The reference is a test-only solver of the piezoviscous finite-volume equations
(scipy.sparse direct solves inside a Picard iteration on μ(p)): it never uses the
reduced pressure q(p); its face mobilities are the mean of μ₀/μ(p) between the two node
pressures, integrated by Gauss–Legendre quadrature of the law's μ(p).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import sparse
from scipy.sparse import linalg

from conrod.film.base import BearingGeometry, FilmState, Groove
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.reynolds.film import ReynoldsFilm

MU0, D, L, C = 0.01, 0.05, 0.02, 2.5e-5
R = 0.5 * D
FULL_FILM = -1.0e9  # cavitation bound far below every pressure: full-film (Sommerfeld) film
BARUS = PressureViscosity("barus", coefficient=2.0e-8)


def full_film_geometry(supply: float = 0.0) -> BearingGeometry:
    grooves = (Groove(width=0.002),) if supply else ()
    return BearingGeometry(diameter=D, width=L, radial_clearance=C, grooves=grooves,
                           supply_pressure=supply,
                           cavitation_pressure=FULL_FILM)


def loaded_state(eps: float = 0.6, omega: float = 400.0) -> FilmState:
    return FilmState(eccentricity_x=eps * C * math.cos(0.4), eccentricity_y=eps * C * math.sin(0.4),
                     velocity_x=2e-4,
                     journal_speed=omega, viscosity=MU0)


# ----------------------------------------------------------- independent reference
def mean_mobility(p_a: np.ndarray, p_b: np.ndarray, law: PressureViscosity) -> np.ndarray:
    """(1/(p_b − p_a)) ∫ μ₀/μ(p) dp between the node pressures (8-point Gauss–Legendre)."""
    x, w = np.polynomial.legendre.leggauss(8)
    mid, half = 0.5 * (p_a + p_b), 0.5 * (p_b - p_a)
    samples = mid[..., None] + half[..., None] * x
    return (1.0 / law.viscosity_ratio(samples, MU0)) @ (0.5 * w)


def picard_reference(film: ReynoldsFilm, state: FilmState, law: PressureViscosity):
    """Piezoviscous pressure [Pa] by Picard iteration on μ(p) with sparse direct solves."""
    g, n_t, n_z = film.geometry, film.n_theta, film.n_z + 1
    theta = np.arange(n_t) * 2.0 * math.pi / n_t
    d_z, arc = L / film.n_z, R * 2.0 * math.pi / n_t
    h = (C - state.eccentricity_x * np.cos(theta) - state.eccentricity_y * np.sin(theta))
    h = np.repeat(h[:, None], n_z, axis=1)
    h_rate = np.repeat((-state.velocity_x * np.cos(theta))[:, None], n_z, axis=1)
    width = np.full(n_z, d_z)
    width[[0, -1]] *= 0.5
    h_e = 0.5 * (h + np.roll(h, -1, axis=0))
    h_w = np.roll(h_e, 1, axis=0)
    h_n = 0.5 * (h[:, :-1] + h[:, 1:])
    a_e = h_e**3 * width / arc
    a_n = h_n**3 * arc / d_z
    b = -12.0 * MU0 * width * (0.5 * R * state.journal_speed * (h_e - h_w) + h_rate * arc)
    fixed = film._edges | film._supply
    fixed_value = np.where(film._supply, g.supply_pressure, 0.0)
    index = np.arange(n_t * n_z).reshape(n_t, n_z)
    p = fixed_value.copy()
    for _ in range(200):
        m_e = a_e * mean_mobility(p, np.roll(p, -1, axis=0), law)
        m_n = a_n * mean_mobility(p[:, :-1], p[:, 1:], law)
        rows, cols, vals = [], [], []
        diag = np.zeros((n_t, n_z))
        for coeff, here, there in (
            (m_e, index, np.roll(index, -1, axis=0)),
            (np.roll(m_e, 1, axis=0), index, np.roll(index, 1, axis=0)),
        ):
            rows.append(here.ravel()), cols.append(there.ravel()), vals.append(-coeff.ravel())
            diag += coeff
        rows += [index[:, :-1].ravel(), index[:, 1:].ravel()]
        cols += [index[:, 1:].ravel(), index[:, :-1].ravel()]
        vals += [-m_n.ravel(), -m_n.ravel()]
        diag[:, :-1] += m_n
        diag[:, 1:] += m_n
        matrix = sparse.coo_matrix((np.concatenate(vals), (np.concatenate(rows),
                                    np.concatenate(cols))), shape=(p.size, p.size)).tolil()
        matrix.setdiag(diag.ravel())
        rhs = b.ravel().copy()
        for k in np.flatnonzero(fixed.ravel()):
            matrix.rows[k], matrix.data[k] = [k], [1.0]
            rhs[k] = fixed_value.ravel()[k]
        new = linalg.spsolve(matrix.tocsr(), rhs).reshape(p.shape)
        change = np.max(np.abs(new - p)) / np.max(np.abs(new))
        p = p + 0.5 * (new - p)  # under-relaxed: plain Picard oscillates when αp ~ 1
        if change < 1e-12:
            return p
    raise AssertionError("Picard reference did not converge")


# ------------------------------------------------------------------------- tests
@pytest.mark.parametrize("supply", [0.0, 2.0e6])
def test_barus_full_film_matches_picard_reference(supply):
    """The reduced-pressure solve equals the directly iterated piezoviscous solve to 1e-6
    (field and load), with a strong effect."""
    film = ReynoldsFilm(full_film_geometry(supply), n_theta=96, n_z=24, pressure_viscosity=BARUS)
    state = loaded_state(0.6, omega=2500.0)
    result = film.solve(state, with_pressure=True)
    reference = picard_reference(film, state, BARUS)
    scale = np.max(np.abs(reference))
    assert BARUS.coefficient * scale > 0.15  # max αp = 0.66 without supply, 0.16 fed
    assert np.max(np.abs(result.pressure - reference)) <= 1e-6 * scale
    area = R * 2.0 * math.pi / 96 * film.film_grid.axial_weights
    fx = -float(np.sum(reference * np.cos(film.film_grid.theta)[:, None] * area))
    fy = -float(np.sum(reference * np.sin(film.film_grid.theta)[:, None] * area))
    assert result.force_x == pytest.approx(fx, rel=1e-6)
    assert result.force_y == pytest.approx(fy, rel=1e-6)
    iso = ReynoldsFilm(full_film_geometry(supply), n_theta=96, n_z=24).solve(state)
    assert abs(result.force_x - iso.force_x) > 0.05 * abs(iso.force_x)


def test_vanishing_coefficient_reproduces_isoviscous_film_to_round_off():
    geometry = BearingGeometry(diameter=D, width=L, radial_clearance=C)
    state = loaded_state(0.8)
    iso = ReynoldsFilm(geometry, n_theta=72, n_z=16).solve(state, with_pressure=True)
    tiny = PressureViscosity("barus", coefficient=1.0e-30)
    piezo = ReynoldsFilm(geometry, n_theta=72, n_z=16, pressure_viscosity=tiny).solve(
        state, with_pressure=True)
    assert np.max(np.abs(piezo.pressure - iso.pressure)) <= 1e-12 * iso.max_pressure
    assert piezo.force_x == pytest.approx(iso.force_x, rel=1e-12)
    assert piezo.side_flow == pytest.approx(iso.side_flow, rel=1e-12)
    assert piezo.friction_torque_journal == pytest.approx(iso.friction_torque_journal,
                                                          rel=1e-12)


def _load(film: ReynoldsFilm, state: FilmState) -> float:
    result = film.solve(state)
    return math.hypot(result.force_x, result.force_y)


def _order(law: PressureViscosity | None) -> float:
    state = loaded_state(0.6)
    grids = [(24, 6), (48, 12), (96, 24)]
    finest = _load(ReynoldsFilm(full_film_geometry(), 384, 96, pressure_viscosity=law), state)
    errors = [abs(_load(ReynoldsFilm(full_film_geometry(), n_t, n_z, pressure_viscosity=law),
                        state) - finest) for n_t, n_z in grids]
    spacing = [1.0 / n_t for n_t, _ in grids]
    return float(np.polyfit(np.log(spacing), np.log(errors), 1)[0])


def test_grid_convergence_order_unchanged_by_piezoviscosity():
    iso, piezo = _order(None), _order(BARUS)
    assert iso == pytest.approx(2.0, abs=0.3)
    assert piezo == pytest.approx(iso, abs=0.25)


def test_roelands_and_barus_agree_at_low_pressure():
    """Same initial slope α₀ = (ln μ₀ + 9.67) z/p_r: at low pressure the films differ by a
    small fraction of their common departure from the isoviscous film."""
    roelands = PressureViscosity("roelands", roelands_index=0.6)
    barus = PressureViscosity("barus", coefficient=roelands.initial_coefficient(MU0))
    assert barus.coefficient == pytest.approx((math.log(MU0) + 9.67) * 0.6 / 1.96e8, rel=1e-12)
    geometry, state = BearingGeometry(diameter=D, width=L,
                                      radial_clearance=C), loaded_state(0.5, omega=150.0)
    forces = {}
    for name, law in (("iso", None), ("barus", barus), ("roelands", roelands)):
        result = ReynoldsFilm(geometry, 72, 16, pressure_viscosity=law).solve(state)
        forces[name] = np.array([result.force_x, result.force_y])
    assert barus.coefficient * 2e6 < 0.05  # low pressure: p_max ≈ 2 MPa
    effect = np.linalg.norm(forces["barus"] - forces["iso"])
    assert effect > 1e-3 * np.linalg.norm(forces["iso"])
    assert np.linalg.norm(forces["roelands"] - forces["barus"]) < 0.05 * effect


def test_mass_conserving_full_film_equals_reynolds_film():
    """Without a broken film the JFO film is the Swift–Stieber one, also in q."""
    geometry = BearingGeometry(diameter=D, width=L, radial_clearance=C,
                               grooves=(Groove(width=0.002),), supply_pressure=3e5)
    state = loaded_state(0.7)
    reynolds = ReynoldsFilm(geometry, 72, 16, pressure_viscosity=BARUS).solve(state)
    jfo = MassConservingFilm(geometry, 72, 16, tolerance=1e-11,
                             pressure_viscosity=BARUS).solve(state)
    assert jfo.force_x == pytest.approx(reynolds.force_x, rel=1e-7)
    assert jfo.force_y == pytest.approx(reynolds.force_y, rel=1e-7)
    assert jfo.max_pressure == pytest.approx(reynolds.max_pressure, rel=1e-3)
    assert jfo.extra["piezoviscous_viscosity_ratio_max"] > 1.05


def test_flows_balance_and_shear_uses_pressure_viscosity():
    """Fed, steady, full film: supply flow = side flow (the flux depends on q only); the
    Couette shear grows with μ(p)."""
    geometry = full_film_geometry(1.0e6)
    state = FilmState(eccentricity_x=0.5 * C, eccentricity_y=0.0, journal_speed=300.0,
                      viscosity=MU0)
    iso = ReynoldsFilm(geometry, 96, 24).solve(state)
    piezo = ReynoldsFilm(geometry, 96, 24, pressure_viscosity=BARUS).solve(state)
    assert piezo.supply_flow == pytest.approx(piezo.side_flow, rel=1e-9)
    assert abs(piezo.friction_torque_shell) > abs(iso.friction_torque_shell)


def test_pressure_beyond_the_asymptote_stays_finite_and_is_reported():
    """A state whose isoviscous reduced field exceeds 1/α: finite monotone pressures,
    diagnostics in ``extra``, no NaN."""
    law = PressureViscosity("barus", coefficient=2.5e-8, limit_pressure=1.0e9)
    state = loaded_state(0.95, omega=600.0)
    geometry = BearingGeometry(diameter=D, width=L, radial_clearance=C)
    result = ReynoldsFilm(geometry, 72, 16, pressure_viscosity=law).solve(
        state, with_pressure=True)
    assert np.all(np.isfinite(result.pressure))
    assert result.extra["piezoviscous_reduced_to_limit_max"] > 1.0
    assert result.extra["piezoviscous_limited_node_share"] > 0.0
    assert result.max_pressure > law.limit_pressure


def test_piezoviscous_jfo_transient_conserves_mass():
    """Whirling journal over one period with a ruptured and re-formed film: the change of
    the film content equals ∫(supply − side flow) dt within 1 % (flows are exact in q)."""
    law = PressureViscosity("barus", coefficient=1.0e-7)  # strong: max αp ≈ 0.4
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5,
                               supply_pressure=2e5, grooves=(
        Groove(start_angle=math.radians(170), extent=math.radians(20), width=0.005),))
    model = MassConservingFilm(geometry, n_theta=48, n_z=8, pressure_viscosity=law)
    period, steps = 0.1, 400
    dt, w, c = period / steps, 2 * math.pi / period, 2.5e-5

    def state(t, history):
        return FilmState(eccentricity_x=c * (0.3 + 0.4 * math.sin(w * t)),
                         eccentricity_y=0.3 * c * math.cos(w * t),
                         velocity_x=0.4 * c * w * math.cos(w * t),
                         velocity_y=-0.3 * c * w * math.sin(w * t),
                         journal_speed=200.0, viscosity=0.02, history=history)

    history = model.initial_history()
    first = model.solve(state(0.0, history))
    net, lowest, strongest = 0.0, 1.0, 0.0
    for k in range(steps):
        a = model.solve(state(k * dt, history))
        trial = np.clip(history + dt * a.history_rate, 0.0, 1.0)
        b = model.solve(state((k + 1) * dt, trial))
        history = np.clip(history + 0.5 * dt * (a.history_rate + b.history_rate), 0.0, 1.0)
        net += 0.5 * dt * (a.supply_flow - a.side_flow + b.supply_flow - b.side_flow)
        lowest = min(lowest, float(history.min()))
        strongest = max(strongest, law.coefficient * a.max_pressure)
    change = (model.solve(state(period, history)).extra["film_content_m3"]
              - first.extra["film_content_m3"])
    assert lowest < 0.5 and strongest > 0.2
    assert abs(change - net) < 0.01 * abs(net)
