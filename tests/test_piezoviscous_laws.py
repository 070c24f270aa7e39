"""Pressure–viscosity laws: closed-form reduced pressures against numerical quadrature,
inverses, the held viscosity above the limit pressure."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from conrod.errors import CaseError
from conrod.film.piezoviscosity import (
    PressureViscosity,
    barus_pressure,
    barus_reduced,
    roelands_pressure,
    roelands_reduced,
)

MU0 = 0.008
PRESSURES = np.array([-1.0e5, 0.0, 3.0e5, 1.0e7, 1.0e8, 4.0e8, 9.0e8])


def quadrature_reduced(law: PressureViscosity, p: float) -> float:
    """q(p) = ∫₀^p μ₀/μ dp' by adaptive quadrature of the law's μ(p)."""
    value, _ = integrate.quad(lambda s: 1.0 / float(law.viscosity_ratio(s, MU0)), 0.0, p,
                              epsabs=0.0, epsrel=1e-13, limit=200)
    return value


@pytest.mark.parametrize("law", [PressureViscosity("barus", coefficient=1.8e-8),
                                 PressureViscosity("roelands", roelands_index=0.65)])
def test_closed_form_reduced_pressure_equals_quadrature(law):
    q = law.to_reduced(PRESSURES, MU0)
    reference = np.array([quadrature_reduced(law, p) for p in PRESSURES])
    assert np.allclose(q, reference, rtol=1e-10, atol=1e-6)


@pytest.mark.parametrize("law", [PressureViscosity("barus", coefficient=2.2e-8),
                                 PressureViscosity("roelands", roelands_index=0.6)])
def test_inverse_round_trip_and_monotone_beyond_limit(law):
    p = np.concatenate([np.linspace(-1e5, 1e9, 2001), [1.5e9, 1e10, 1e12]])
    q_of_p = law.to_reduced(p, MU0)
    back = law.from_reduced(q_of_p, MU0)
    # condition number of p(q): (μ(p)/μ₀)·|q|/|p| (≈ 1e8 at 1 GPa for Barus), times 1e-15
    condition = law.viscosity_ratio(p, MU0) * np.abs(q_of_p) / np.maximum(np.abs(p), 1.0)
    assert np.all(np.abs(back - p) <= (1e-9 + 1e-15 * condition) * np.abs(p) + 1e-3)
    q_limit, ratio = law.limit(MU0)
    q = np.linspace(0.0, 5.0 * q_limit, 5001)
    pressure = law.from_reduced(q, MU0)
    assert np.all(np.isfinite(pressure)) and np.all(np.diff(pressure) > 0.0)
    above = q > q_limit
    slope = np.diff(pressure[above]) / np.diff(q[above])
    assert np.allclose(slope, ratio, rtol=1e-6)  # viscosity held at μ(p_L) above p_L


def test_exact_barus_and_roelands_inverses():
    q = np.linspace(-1e5, 4.9e7, 50)
    assert np.allclose(barus_reduced(barus_pressure(q, 2e-8), 2e-8), q, rtol=1e-12, atol=1e-6)
    p = roelands_pressure(q, MU0, 0.6)
    assert np.allclose(roelands_reduced(p, MU0, 0.6), q, rtol=1e-11, atol=1e-5)


def test_zero_coefficient_is_identity_and_roelands_slope():
    assert np.array_equal(barus_reduced(PRESSURES, 0.0), PRESSURES)
    law = PressureViscosity("roelands", roelands_index=0.6)
    slope = (math.log(MU0) + 9.67) * 0.6 / 1.96e8
    dp = 10.0
    numeric = math.log(float(law.viscosity_ratio(dp, MU0))) / dp
    assert numeric == pytest.approx(slope, rel=1e-6)
    assert law.initial_coefficient(MU0) == pytest.approx(slope, rel=1e-14)


def test_roelands_needs_viscosity_above_its_asymptote():
    with pytest.raises(CaseError, match="Roelands"):
        PressureViscosity("roelands", roelands_index=0.6).to_reduced(1e6, 1e-5)


def test_limit_where_reduced_pressure_rounds_to_its_asymptote():
    """α p_L = 100: q(p_L) equals 1/α in floating point; the inverse stays finite and
    monotone and returns p_L there (no division by zero)."""
    law = PressureViscosity("barus", coefficient=1.0e-7, limit_pressure=1.0e9)
    q_limit, _ = law.limit(MU0)
    assert q_limit == 1.0 / law.coefficient
    q = q_limit * np.array([0.5, 0.999999, 1.0 - 1e-16, 1.0, 1.0 + 1e-12])
    p = law.from_reduced(q, MU0)
    assert np.all(np.isfinite(p)) and np.all(np.diff(p) >= 0.0)
    assert law.from_reduced(q_limit, MU0) == law.limit_pressure
