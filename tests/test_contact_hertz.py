"""Hertz line contact and nominal specific load (seed 004 §4.4)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.contact.hertz import (
    contact_modulus,
    hertz_half_width,
    hertz_line_contact_pressure,
    hertz_stress_seed_form,
    nominal_specific_load,
    seed_reduced_modulus,
)


def test_hand_computed_hertz_case():
    """Steel on steel, P = 10 kN, B = 20 mm, R1 = 25 mm, c = 50 µm, by hand:
    E* = 2.1e11/(2·0.91) = 1.153846e11 Pa; 1/R' = 5e-5/(0.025·0.02505) = 0.0798403 1/m;
    p0 = √(1e4 · 1.153846e11 · 0.0798403 / (π · 0.02)) = 38.29 MPa;
    a = √(4 · 1e4 / (0.0798403 · π · 0.02 · 1.153846e11)) = 8.31 mm."""
    modulus = contact_modulus(2.1e11, 0.3, 2.1e11, 0.3)
    assert modulus == pytest.approx(1.153846e11, rel=1e-6)
    pressure = hertz_line_contact_pressure(1.0e4, 0.02, 0.025, 0.02505, modulus)
    assert pressure == pytest.approx(38.29e6, rel=1e-3)
    half_width = hertz_half_width(1.0e4, 0.02, 0.025, 0.02505, modulus)
    assert half_width == pytest.approx(8.31e-3, rel=1e-3)
    # equilibrium of the elliptic Hertz distribution: P/B = π a p0 / 2
    assert math.pi * half_width * pressure / 2.0 == pytest.approx(1.0e4 / 0.02, rel=1e-12)
    assert nominal_specific_load(1.0e4, 0.02, 0.05) == pytest.approx(1.0e7)


def test_seed_0418_form_is_hertz_for_poisson_03_with_two_material_modulus():
    """0.418 = 1/√(2π(1−0.3²)) when E = 2E1E2/(E1+E2) — twice the seed's eq. 4.4.3 modulus."""
    e_journal, e_shell = 2.1e11, 7.0e10
    exact = hertz_line_contact_pressure(
        2.0e4, 0.025, 0.03, 0.03003, contact_modulus(e_journal, 0.3, e_shell, 0.3)
    )
    two_material = 2.0 * seed_reduced_modulus(e_journal, e_shell)
    assert hertz_stress_seed_form(2.0e4, 0.025, 0.03, 0.03003, two_material) == pytest.approx(
        exact, rel=1e-3
    )
    seed_literal = hertz_stress_seed_form(
        2.0e4, 0.025, 0.03, 0.03003, seed_reduced_modulus(e_journal, e_shell)
    )
    assert exact / seed_literal == pytest.approx(math.sqrt(2.0), rel=1e-3)


def test_conformal_limit_and_scaling():
    """1/R1 − 1/R2 → c/R1² for c ≪ R1 (eq. 4.4.4); p0 ∝ √P; zero load gives zero stress."""
    modulus = contact_modulus(2.1e11, 0.3, 7.0e10, 0.33)
    radius, clearance = 0.03, 30e-6
    exact = hertz_line_contact_pressure(1.0e4, 0.025, radius, radius + clearance, modulus)
    approx = math.sqrt(1.0e4 * modulus * clearance / (math.pi * 0.025 * radius**2))
    assert exact == pytest.approx(approx, rel=clearance / radius)
    loads = np.array([0.0, 1.0e3, 4.0e3])
    stress = hertz_line_contact_pressure(loads, 0.025, radius, radius + clearance, modulus)
    assert stress[0] == 0.0 and stress[2] / stress[1] == pytest.approx(2.0)


def test_shell_must_be_larger_than_journal():
    with pytest.raises(ValueError, match="shell radius"):
        hertz_line_contact_pressure(1.0, 0.02, 0.03, 0.03, 1e11)
