"""Short-bearing film with pressure-dependent viscosity (reduced-pressure map).

The short-bearing Reynolds equation ∂_z(h³ ∂_z p/(12μ(p))) = (U/2) ∂_x h + ∂_t h becomes,
in the reduced pressure q(p) of :mod:`conrod.film.piezoviscosity`, the isoviscous one
∂_z(h³ ∂_z q/(12μ₀)) = (U/2) ∂_x h + ∂_t h, so the short-bearing solution of
:mod:`conrod.film.short.kernel` holds for q:

.. math:: q(θ', z) = -\\frac{3 μ_0 c V \\sin(θ' - α)}{h^3} \\left(\\frac{L^2}{4} - z^2\\right),
          \\qquad p = q^{-1}(q),

on the active arc θ' ∈ (α + π, α + 2π). The force integrals of p are no longer closed
form: Gauss–Legendre quadrature in the Sommerfeld variable γ (the isoviscous integrand is
a trigonometric polynomial in γ, so the rule is exact for it up to round-off) and in z
over the half width (mirror symmetry). Side flow is unchanged: the flux depends on q only.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.short.kernel import (
    ECCENTRICITY_LIMIT,
    short_bearing_polar,
    sommerfeld_angle,
)

ARC_POINTS = 64
"""Gauss–Legendre points along the active arc (in γ) [-]."""
AXIAL_POINTS = 12
"""Gauss–Legendre points over the half width [-]."""


@functools.lru_cache(maxsize=4)
def _gauss(points: int) -> tuple[np.ndarray, np.ndarray]:
    """Gauss–Legendre nodes and weights on [0, 1]."""
    x, w = np.polynomial.legendre.leggauss(points)
    return 0.5 * (x + 1.0), 0.5 * w


def active_arc_field(
    eps: float, alpha: float, speed: float, viscosity: float, width: float, clearance: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Reduced pressure q [Pa] on the quadrature nodes of the active arc and half width,
    with cos θ', sin θ' of the arc nodes [-] and the weights of dθ' dz [m]."""
    ga = sommerfeld_angle(alpha + math.pi, eps)
    gb = sommerfeld_angle(alpha + 2.0 * math.pi, eps)
    s_arc, w_arc = _gauss(ARC_POINTS)
    s_z, w_z = _gauss(AXIAL_POINTS)
    gamma = ga + (gb - ga) * s_arc
    root = math.sqrt(1.0 - eps * eps)
    denominator = 1.0 + eps * np.cos(gamma)
    cos_t = (eps + np.cos(gamma)) / denominator
    sin_t = root * np.sin(gamma) / denominator
    d_theta = (gb - ga) * w_arc * root / denominator
    half = 0.5 * width
    z = half * s_z
    h = clearance * (1.0 - eps * cos_t)
    wave = -(sin_t * math.cos(alpha) - cos_t * math.sin(alpha))
    shape = 3.0 * viscosity * clearance * speed * wave / h**3
    q = np.maximum(shape[:, None] * (half * half - z * z)[None, :], 0.0)
    weights = 2.0 * d_theta[:, None] * (half * w_z)[None, :]
    return q, cos_t, sin_t, weights


def piezoviscous_polar(
    eps: float, eps_rate: float, whirl_rate: float, omega_sum: float, viscosity: float,
    radius: float, width: float, clearance: float, law: PressureViscosity,
) -> tuple[float, float, float, float, dict[str, float]]:
    """(F_r, F_t [N], α [rad], V [1/s], diagnostics) like ``short_bearing_polar``, with
    p = q⁻¹(q) integrated by quadrature; the diagnostics are those of the law."""
    eps = min(eps, ECCENTRICITY_LIMIT)
    _, _, alpha, speed = short_bearing_polar(eps, eps_rate, whirl_rate, omega_sum,
                                             viscosity, radius, width, clearance)
    if speed == 0.0:
        return 0.0, 0.0, 0.0, 0.0, {}
    q, cos_t, sin_t, weights = active_arc_field(eps, alpha, speed, viscosity, width, clearance)
    pressure = law.from_reduced(q, viscosity)
    load = radius * np.sum(pressure * weights, axis=1)
    f_radial = -float(cos_t @ load)
    f_tangential = -float(sin_t @ load)
    extra = law.diagnostics(q, pressure, viscosity)
    return f_radial, f_tangential, alpha, speed, extra


def piezoviscous_couette_excess(
    eps: float, alpha: float, speed: float, viscosity: float, radius: float, width: float,
    clearance: float, sliding: float, law: PressureViscosity,
) -> float:
    """Extra Couette moment ∫∫ (μ(p) − μ₀) R(ω_j − ω_b)/h R² dθ dz over the active arc
    [N m] (``sliding`` = ω_j − ω_b [rad/s])."""
    if speed == 0.0 or sliding == 0.0:
        return 0.0
    q, cos_t, _, weights = active_arc_field(eps, alpha, speed, viscosity, width, clearance)
    excess = viscosity * (law.viscosity_ratio(law.from_reduced(q, viscosity), viscosity) - 1.0)
    h = clearance * (1.0 - eps * cos_t)
    return radius**3 * sliding * float(np.sum(excess / h[:, None] * weights))
