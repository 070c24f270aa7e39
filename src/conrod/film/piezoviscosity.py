"""Pressure-dependent viscosity μ(p) and the reduced pressure that linearises it.

For an isothermal film whose viscosity depends on pressure only, μ = μ₀ g(p), the
reduced pressure (Kirchhoff transform)

.. math:: q(p) = \\int_0^p \\frac{μ_0}{μ(p')}\\,dp'

turns the piezoviscous Reynolds equation ∇·(h³/(12μ(p)) ∇p) = (U/2) ∂h/∂x + ∂h/∂t
exactly into the isoviscous one for q (with μ₀). q is strictly increasing, so Dirichlet
values (q_supply = q(p_supply)), the cavitation bound (q_cav = q(p_cav)) and the
Elrod–Adams complementarity map too; a piezoviscous film is an isoviscous solve in q
followed by the pointwise map p = q⁻¹(q) [1, ch. 4; 2].

Laws (μ₀ [Pa s] the viscosity at gauge pressure 0):

* Barus [3]: g = e^{αp}, q = (1 − e^{−αp})/α, p = −ln(1 − αq)/α.
* Roelands [4]: g = exp[(ln μ₀ + 9.67)((1 + p/p_r)^z − 1)], p_r = 1.96e8 Pa; with
  A = ln μ₀ + 9.67 and a = 1/z, substituting u = A(1 + p/p_r)^z gives the closed form
  q = C [Q(a, A) − Q(a, A(1 + p/p_r)^z)], C = p_r e^A Γ(a)/(z A^a), Q the regularised
  upper incomplete gamma function; the inverse uses Q⁻¹. Its initial pressure-viscosity
  coefficient is α₀ = A z/p_r.

Both laws give a finite q(∞): the isoviscous reduced field may exceed it, where the
piezoviscous pressure would be infinite (the film cannot carry that state). Above the
``limit_pressure`` p_L the viscosity is therefore held at μ(p_L) — a modelling bound
(Barus and Roelands are not meant for the glassy region above ~1 GPa) — which keeps q(p)
and its inverse finite, strictly monotone and C¹, so the map stays exact for that law:
q = q(p_L) + (p − p_L)/g(p_L) above p_L.

[1] B.J. Hamrock, S.R. Schmid, B.O. Jacobson, Fundamentals of Fluid Film Lubrication,
    2nd ed., Marcel Dekker (2004), ch. 4 (viscosity–pressure laws).
[2] D. Dowson, G.R. Higginson, Elasto-Hydrodynamic Lubrication, Pergamon (1966)
    (reduced pressure of the piezoviscous Reynolds equation).
[3] C. Barus, "Isothermals, isopiestics and isometrics relative to viscosity",
    Am. J. Sci. 45 (1893) 87–96.
[4] C.J.A. Roelands, Correlational Aspects of the Viscosity–Temperature–Pressure
    Relationship of Lubricating Oils, PhD thesis, TH Delft (1966).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

import numpy as np

from conrod.errors import CaseError

if TYPE_CHECKING:  # pragma: no cover
    from scipy import interpolate

ROELANDS_REFERENCE_PRESSURE = 1.96e8
"""Roelands' reference pressure p_r [Pa]."""
ROELANDS_LOG_VISCOSITY = 9.67
"""−ln μ_∞ of Roelands' law, μ_∞ = 6.31e-5 Pa s [-]."""
DEFAULT_LIMIT_PRESSURE = 1.0e9
"""Pressure above which the viscosity is held constant by default [Pa]."""

PressureViscosityName = Literal["barus", "roelands"]


def barus_reduced(pressure: np.ndarray, alpha: float) -> np.ndarray:
    """Barus reduced pressure q = (1 − e^{−αp})/α [Pa] (q = p for α = 0)."""
    if alpha == 0.0:
        return np.asarray(pressure, dtype=float).copy()
    return -np.expm1(-alpha * np.asarray(pressure, dtype=float)) / alpha


def barus_pressure(reduced: np.ndarray, alpha: float) -> np.ndarray:
    """Inverse of :func:`barus_reduced`: p = −ln(1 − αq)/α [Pa], for αq < 1."""
    if alpha == 0.0:
        return np.asarray(reduced, dtype=float).copy()
    return -np.log1p(-alpha * np.asarray(reduced, dtype=float)) / alpha


def roelands_exponent(viscosity: float) -> float:
    """A = ln μ₀ + 9.67 of Roelands' law for μ₀ [Pa s] (must be > 0) [-]."""
    exponent = math.log(viscosity) + ROELANDS_LOG_VISCOSITY
    if not exponent > 0.0:
        raise CaseError(f"viscosity = {viscosity:.4g} Pa s: out of range for Roelands' law "
                        f"(allowed: > {math.exp(-ROELANDS_LOG_VISCOSITY):.3g} Pa s)")
    return exponent


def roelands_ratio(pressure: np.ndarray, viscosity: float, index: float,
                   reference: float = ROELANDS_REFERENCE_PRESSURE) -> np.ndarray:
    """Roelands viscosity ratio μ/μ₀ = exp[A((1 + p/p_r)^z − 1)] [-]."""
    a_exp = roelands_exponent(viscosity)
    return np.exp(a_exp * np.expm1(index * np.log1p(np.asarray(pressure) / reference)))


def _roelands_scale(a_exp: float, index: float, reference: float) -> tuple[float, float]:
    """(C, Q(1/z, A)) of the closed-form Roelands reduced pressure."""
    from scipy import special  # imported when a Roelands law is used: 0.1 s of start-up

    a = 1.0 / index
    scale = reference * math.exp(a_exp + special.gammaln(a) - a * math.log(a_exp)) / index
    return scale, float(special.gammaincc(a, a_exp))


def roelands_reduced(pressure: np.ndarray, viscosity: float, index: float,
                     reference: float = ROELANDS_REFERENCE_PRESSURE) -> np.ndarray:
    """Roelands reduced pressure q(p) [Pa] in closed form (incomplete gamma)."""
    from scipy import special

    a_exp = roelands_exponent(viscosity)
    scale, q_zero = _roelands_scale(a_exp, index, reference)
    u = a_exp * np.exp(index * np.log1p(np.asarray(pressure, dtype=float) / reference))
    return scale * (q_zero - special.gammaincc(1.0 / index, u))


def roelands_pressure(reduced: np.ndarray, viscosity: float, index: float,
                      reference: float = ROELANDS_REFERENCE_PRESSURE) -> np.ndarray:
    """Inverse of :func:`roelands_reduced` [Pa], for q below q(∞) = C Q(1/z, A)."""
    from scipy import special

    a_exp = roelands_exponent(viscosity)
    scale, q_zero = _roelands_scale(a_exp, index, reference)
    u = special.gammainccinv(1.0 / index, q_zero - np.asarray(reduced, dtype=float) / scale)
    return reference * np.expm1(np.log(u / a_exp) / index)


TABLE_NODES = 4001
"""Nodes of the cached inverse table of a law without a fast closed-form inverse [-]."""
TABLE_LOWEST_PRESSURE = -1.0e6
"""Lowest pressure of that table (below: the exact, slower inverse) [Pa]."""


@functools.lru_cache(maxsize=64)
def _inverse_table(law: PressureViscosity, viscosity: float) -> interpolate.CubicHermiteSpline:
    """p(q) as a cubic Hermite spline through exact (q(p_k), p_k) with the exact slope
    dp/dq = μ(p_k)/μ₀, p_k uniform on [TABLE_LOWEST_PRESSURE, p_L] (error ~1e-10 p)."""
    from scipy import interpolate  # imported when a table is built: 0.2 s of start-up

    p_nodes = np.linspace(TABLE_LOWEST_PRESSURE, law.limit_pressure, TABLE_NODES)
    q_nodes = law._exact_reduced(p_nodes, viscosity)
    return interpolate.CubicHermiteSpline(q_nodes, p_nodes, law._exact_ratio(p_nodes, viscosity))


@dataclass(frozen=True)
class PressureViscosity:
    """Pressure-viscosity law with a viscosity held constant above ``limit_pressure``.

    law : 'barus' | 'roelands'
    coefficient : float  Barus pressure-viscosity coefficient α [1/Pa].
    roelands_index : float  Roelands pressure index z [-].
    roelands_pressure : float  Roelands reference pressure p_r [Pa].
    limit_pressure : float  p_L: μ(p > p_L) = μ(p_L) [Pa].
    """

    law: PressureViscosityName = "barus"
    coefficient: float = 0.0
    roelands_index: float = 0.6
    roelands_pressure: float = ROELANDS_REFERENCE_PRESSURE
    limit_pressure: float = DEFAULT_LIMIT_PRESSURE

    # ---------------------------------------------------------------- exact law
    def _exact_reduced(self, p: np.ndarray, mu0: float) -> np.ndarray:
        if self.law == "barus":
            return barus_reduced(p, self.coefficient)
        return roelands_reduced(p, mu0, self.roelands_index, self.roelands_pressure)

    def _exact_pressure(self, q: np.ndarray, mu0: float) -> np.ndarray:
        if self.law == "barus":
            return barus_pressure(q, self.coefficient)
        table = _inverse_table(self, float(mu0))
        q = np.asarray(q, dtype=float)
        below = q < table.x[0]
        pressure = table(np.maximum(q, table.x[0]))
        if below.any():
            pressure[below] = roelands_pressure(q[below], mu0, self.roelands_index,
                                                self.roelands_pressure)
        return pressure

    def _exact_ratio(self, p: np.ndarray, mu0: float) -> np.ndarray:
        if self.law == "barus":
            return np.exp(self.coefficient * np.asarray(p, dtype=float))
        return roelands_ratio(p, mu0, self.roelands_index, self.roelands_pressure)

    # ------------------------------------------------------------ bounded law
    def limit(self, mu0: float) -> tuple[float, float]:
        """(q(p_L) [Pa], μ(p_L)/μ₀ [-]) at the limit pressure."""
        p_limit = np.array(self.limit_pressure)
        return (float(self._exact_reduced(p_limit, mu0)),
                float(self._exact_ratio(p_limit, mu0)))

    def viscosity_ratio(self, pressure: np.ndarray, mu0: float) -> np.ndarray:
        """μ(p)/μ₀ [-] (constant above the limit pressure)."""
        return self._exact_ratio(np.minimum(pressure, self.limit_pressure), mu0)

    def to_reduced(self, pressure: np.ndarray, mu0: float) -> np.ndarray:
        """Reduced pressure q(p) [Pa] for μ₀ [Pa s]; strictly increasing in p."""
        p = np.asarray(pressure, dtype=float)
        q_limit, ratio_limit = self.limit(mu0)
        inside = self._exact_reduced(np.minimum(p, self.limit_pressure), mu0)
        return np.where(p <= self.limit_pressure, inside,
                        q_limit + (p - self.limit_pressure) / ratio_limit)

    def from_reduced(self, reduced: np.ndarray, mu0: float) -> np.ndarray:
        """Pressure p(q) [Pa] for μ₀ [Pa s]; finite for every finite q."""
        q = np.asarray(reduced, dtype=float)
        q_limit, ratio_limit = self.limit(mu0)
        below = q < q_limit
        with np.errstate(divide="ignore", invalid="ignore"):  # q(p_L) may round to q(∞)
            inside = self._exact_pressure(np.where(below, q, 0.0), mu0)
        inside = np.minimum(np.where(np.isfinite(inside), inside, self.limit_pressure),
                            self.limit_pressure)
        return np.where(below, inside, self.limit_pressure + (q - q_limit) * ratio_limit)

    def initial_coefficient(self, mu0: float) -> float:
        """Pressure-viscosity coefficient at p = 0, d ln μ/dp [1/Pa]."""
        if self.law == "barus":
            return self.coefficient
        return roelands_exponent(mu0) * self.roelands_index / self.roelands_pressure

    def diagnostics(self, reduced: np.ndarray, pressure: np.ndarray, mu0: float,
                    area_share: float | None = None) -> dict[str, float]:
        """Diagnostics for ``FilmResult.extra`` (units in the key names)."""
        q_limit, _ = self.limit(mu0)
        p_max = float(np.max(pressure)) if np.size(pressure) else 0.0
        limited = (float(np.mean(pressure > self.limit_pressure)) if area_share is None
                   else area_share)
        return {
            "piezoviscous_reduced_to_limit_max": float(np.max(reduced)) / q_limit
            if np.size(reduced) else 0.0,
            "piezoviscous_viscosity_ratio_max": float(self.viscosity_ratio(p_max, mu0)),
            "piezoviscous_limited_node_share": limited,
        }
