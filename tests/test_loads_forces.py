"""Engine loads against closed forms, conservation of energy and frame invariance."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.loads import forces
from conrod.loads import kinematics as kin
from conrod.loads.engine_loads import compute_engine_loads
from loads_helpers import ENGINE, trace_case

OMEGA = ENGINE["speed"] * math.pi / 30.0
R = ENGINE["stroke"] / 2
LAM = R / ENGINE["rod_length"]
SHARE = ENGINE["rod_cg_from_big_end"] / ENGINE["rod_length"]
M_RECIP = ENGINE["piston_mass"] + ENGINE["rod_mass"] * SHARE
M_ROT = ENGINE["rod_mass"] * (1 - SHARE)


def test_inertia_only_loads_at_dead_centres(tmp_path):
    """No gas: S(TDC) = −m_j r ω²(1+λ), S(BDC) = +m_j r ω²(1−λ); R adds −m_rk r ω²."""
    loads = compute_engine_loads(trace_case(tmp_path))
    tdc, bdc = 0, 180
    assert loads.gas_force == pytest.approx(0.0, abs=1e-9)
    assert loads.rod_force[tdc] == pytest.approx(-M_RECIP * R * OMEGA**2 * (1 + LAM), rel=1e-12)
    assert loads.rod_force[bdc] == pytest.approx(M_RECIP * R * OMEGA**2 * (1 - LAM), rel=1e-12)
    rotating = -M_ROT * R * OMEGA**2
    assert loads.rotating_inertia_force == pytest.approx(rotating, rel=1e-12)
    assert loads.radial_force[tdc] == pytest.approx(
        -M_RECIP * R * OMEGA**2 * (1 + LAM) + rotating, rel=1e-12
    )
    # at BDC cos(φ+β) = −1: R = −S + P_r
    assert loads.radial_force[bdc] == pytest.approx(
        -M_RECIP * R * OMEGA**2 * (1 - LAM) + rotating, rel=1e-12
    )
    assert loads.tangential_force[[tdc, bdc]] == pytest.approx([0.0, 0.0], abs=1e-9)
    # the load magnitude on the pin at TDC: reciprocating plus rotating parts, both outward
    assert loads.load_magnitude[tdc] == pytest.approx(
        M_RECIP * R * OMEGA**2 * (1 + LAM) + M_ROT * R * OMEGA**2, rel=1e-12
    )


def test_gas_only_rod_force_at_tdc_equals_gas_force(tmp_path):
    """Massless piston/rod: at TDC S = P_g = π D²(p − p_amb)/4 and R = S, T = 0."""
    peak = 8.0e6
    case = trace_case(
        tmp_path,
        pressure=lambda a: 1e5 + peak * np.exp(-((((a + 360) % 720 - 360) / 30) ** 2)),
        piston_mass=1e-9,
        rod_mass=1e-9,
    )
    loads = compute_engine_loads(case)
    gas = math.pi * ENGINE["bore"] ** 2 * peak / 4
    assert loads.gas_force[0] == pytest.approx(gas, rel=1e-12)
    assert loads.rod_force[0] == pytest.approx(gas, rel=1e-9)
    assert loads.radial_force[0] == pytest.approx(gas, rel=1e-9)
    assert loads.load_rod_x[0] == pytest.approx(gas, rel=1e-9)  # journal pressed towards small end
    # away from TDC, massless: S = P_g / cos β and the load is along the rod axis
    # residual inertia of the 1e-9 kg masses is ~1e-5 N
    np.testing.assert_allclose(
        loads.rod_force, loads.gas_force / np.cos(loads.rod_angle), rtol=1e-9, atol=1e-3
    )
    np.testing.assert_allclose(loads.load_rod_y, 0.0, atol=1e-6 * gas)


@pytest.mark.parametrize("inertia", [None, 0.8 * 1.5 * 0.05 * 0.13, 1.3 * 1.5 * 0.05 * 0.13])
def test_energy_balance_of_the_crank_train(tmp_path, inertia):
    """T r ω = P_g ṡ − d/dt(KE piston + rod), KE from kinematics alone (any rod model)."""
    extra = {} if inertia is None else {"rod_inertia": inertia}
    case = trace_case(
        tmp_path,
        pressure=lambda a: 1e5 + 5e6 * np.exp(-((((a + 360) % 720 - 360) / 40) ** 2)),
        **extra,
    )
    step = 0.25
    loads = compute_engine_loads(case, step_deg=step)
    phi = loads.crank_angle
    e = case.engine
    vel = kin.piston_velocity(phi, R, e.rod_length, OMEGA)
    rod_rate = kin.rod_angular_velocity(phi, LAM, OMEGA)
    beta = kin.rod_angle(phi, LAM)
    l1 = e.rod_cg_from_big_end
    v_gx = -R * OMEGA * np.sin(phi) + l1 * np.sin(beta) * rod_rate
    v_gy = R * OMEGA * np.cos(phi) + l1 * np.cos(beta) * rod_rate
    j_g = inertia if inertia is not None else e.rod_mass * l1 * (e.rod_length - l1)
    kinetic = (
        0.5 * e.piston_mass * vel**2
        + 0.5 * e.rod_mass * (v_gx**2 + v_gy**2)
        + 0.5 * j_g * rod_rate**2
    )
    dt = math.radians(step) / OMEGA
    kinetic_rate = (np.roll(kinetic, -1) - np.roll(kinetic, 1)) / (2 * dt)
    crank_power = loads.tangential_force * R * OMEGA
    residual = crank_power - (loads.gas_force * vel - kinetic_rate)
    assert np.max(np.abs(residual)) < 2e-4 * np.max(np.abs(crank_power))


def test_three_mass_reduces_to_two_mass(tmp_path):
    """Rigid-rod (three-mass) path with J = m L₁ L₂ equals the closed-form two-mass path."""
    l1 = ENGINE["rod_cg_from_big_end"]
    j2 = ENGINE["rod_mass"] * l1 * (ENGINE["rod_length"] - l1)
    pressure = lambda a: 1e5 + 6e6 * np.exp(-((((a + 360) % 720 - 360) / 25) ** 2))  # noqa: E731
    two = compute_engine_loads(trace_case(tmp_path, pressure=pressure))
    three = compute_engine_loads(trace_case(tmp_path, pressure=pressure, rod_inertia=j2))
    assert (two.rod_model, three.rod_model) == ("two_mass", "three_mass")
    scale = np.max(two.load_magnitude)
    for name in ("rod_force", "radial_force", "tangential_force", "load_rod_x", "load_rod_y"):
        np.testing.assert_allclose(getattr(three, name), getattr(two, name), atol=1e-10 * scale)
    masses = forces.three_mass_split(ENGINE["rod_mass"], ENGINE["rod_length"], l1, j2)
    assert masses.centre == pytest.approx(0.0, abs=1e-12)


def test_three_mass_split_conserves_mass_centre_and_inertia():
    m, length, l1, j = 2.0, 0.2, 0.06, 0.012
    masses = forces.three_mass_split(m, length, l1, j)
    assert masses.big_end + masses.small_end + masses.centre == pytest.approx(m)
    assert masses.small_end * length + masses.centre * l1 == pytest.approx(m * l1)
    assert masses.big_end * l1**2 + masses.small_end * (length - l1) ** 2 == pytest.approx(j)


def test_load_magnitude_is_frame_invariant(tmp_path):
    case = trace_case(
        tmp_path, pressure=lambda a: 1e5 + 7e6 * np.exp(-((((a + 360) % 720 - 360) / 30) ** 2))
    )
    loads = compute_engine_loads(case, step_deg=2.0)
    for x, y in (
        (loads.load_engine_x, loads.load_engine_y),
        (loads.load_crank_x, loads.load_crank_y),
        (loads.load_rod_x, loads.load_rod_y),
    ):
        np.testing.assert_allclose(np.hypot(x, y), loads.load_magnitude, rtol=1e-12)
    # crank frame load = (R, −T) by the sign conventions
    np.testing.assert_allclose(loads.load_crank_x, loads.radial_force, rtol=1e-12, atol=1e-9)
    np.testing.assert_allclose(loads.load_crank_y, -loads.tangential_force, rtol=1e-12, atol=1e-9)


def test_load_cycle_hand_over_uses_rod_frame_and_relative_speed(tmp_path):
    loads = compute_engine_loads(trace_case(tmp_path))
    cycle = loads.to_load_cycle()
    assert cycle.cycle == pytest.approx(4 * math.pi)
    wx, wy = cycle.load(np.radians(90.0))
    assert (float(wx), float(wy)) == pytest.approx((loads.load_rod_x[90], loads.load_rod_y[90]))
    journal, shell = cycle.speeds(np.array([0.0, math.pi]))
    # ω_j = ω − Ω_rod = ω(1 ± λ) at TDC/BDC (relative speed of the big end)
    assert journal == pytest.approx([OMEGA * (1 + LAM), OMEGA * (1 - LAM)], rel=1e-12)
    assert shell == pytest.approx([0.0, 0.0])


def test_series_kinematics_option_gives_the_textbook_inertia_force(tmp_path):
    """kinematics = "series": P_j = −m_j r ω²(cos φ + λ cos 2φ) exactly (SPEC S1)."""
    loads = compute_engine_loads(trace_case(tmp_path, kinematics="series"))
    phi = loads.crank_angle
    expected = -M_RECIP * R * OMEGA**2 * (np.cos(phi) + LAM * np.cos(2 * phi))
    np.testing.assert_allclose(loads.reciprocating_inertia_force, expected, rtol=1e-12, atol=1e-9)
    exact = compute_engine_loads(trace_case(tmp_path))
    # the two differ by O(λ³) of the inertia force, i.e. a few per mille here
    difference = np.max(np.abs(exact.reciprocating_inertia_force - expected))
    assert 0.0 < difference < LAM**3 * M_RECIP * R * OMEGA**2
