"""Greenwood–Tripp asperity contact for mixed lubrication.

Nominal asperity pressure between two rough surfaces at a mean gap h
(Greenwood & Tripp 1970):

.. math::

    p_a(h) = K E' F_{5/2}(h/σ), \\qquad
    K = \\frac{16\\sqrt2}{15} π (ηβσ)^2 \\sqrt{σ/β},

    F_{5/2}(x) = \\frac{1}{\\sqrt{2π}} \\int_x^∞ (s - x)^{5/2} e^{-s^2/2}\\, ds,

σ combined RMS roughness [m], η summit density [1/m²], β summit radius [m]. E' is taken
as the contact modulus E* of Greenwood–Williamson, 1/E* = (1−ν₁²)/E₁ + (1−ν₂²)/E₂
(:func:`conrod.contact.hertz.contact_modulus`); authors who write E' = 2E* absorb the
factor 2 into K.

F_{5/2} is evaluated from a table of ln F_{5/2} on x ∈ [−10, 9.5] (step 0.005, built at
import by Gauss–Legendre quadrature after the substitution s = x + u², which removes the
root singularity), linear in ln F (relative error < 5·10⁻⁶), with the asymptotic series
F_{5/2}(x) = |x|^{5/2}[1 + 15/(8x²) − 0.1171875/x⁴ − 0.0732421875/x⁶] for x < −10
(deep penetration) and 0 for x > 9.5 (F < 10⁻²¹).

The force on the journal integrates p_a over the shell, h(θ) = c − e cos(θ − ψ):
F = −R L ∫ p_a(h(θ)) (cos θ, sin θ) dθ, which for a rigid round shell is purely radial
(towards the shell centre); a 64-point Gauss–Legendre rule over the arc where
h < 9.5 σ makes it ~2 µs per call.

Limit σ → 0 at fixed ηβσ and σ/β (self-similar surfaces): K stays fixed, so carrying a
given load needs a fixed h/σ and the gap h → 0 — the asperity law becomes the rigid
barrier of hard contact (tested in ``tests/test_contact_asperity.py``).

[1] J.A. Greenwood, J.H. Tripp, "The contact of two nominally flat rough surfaces",
    Proc. IMechE 185 (1970) 625–633.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numba as nb
import numpy as np

from conrod.contact.hertz import contact_modulus
from conrod.errors import CaseError

if TYPE_CHECKING:
    from conrod.cases.case import Case

F52_X_MIN = -10.0
"""Lower end of the tabulated range of h/σ [-]."""
F52_X_MAX = 9.5
"""Upper end of the tabulated range of h/σ; F_{5/2} = 0 beyond [-]."""
F52_STEP = 0.005
"""Table spacing in h/σ [-]."""


def f52_quadrature(x: np.ndarray, nodes: int = 128) -> np.ndarray:
    """F_{5/2}(x) by Gauss–Legendre quadrature (vectorised; used to build the table).

    With s = x + u²: F = (1/√(2π)) ∫₀^U 2u⁶ exp(−(x + u²)²/2) du, U² = max(x, 0) + 10 − x.
    """
    x = np.atleast_1d(np.asarray(x, dtype=float))
    points, weights = np.polynomial.legendre.leggauss(nodes)
    upper = np.sqrt(np.maximum(x, 0.0) + 10.0 - x)
    u = 0.5 * upper[:, None] * (points[None, :] + 1.0)
    integrand = 2.0 * u**6 * np.exp(-0.5 * (x[:, None] + u * u) ** 2)
    return 0.5 * upper * (integrand @ weights) / math.sqrt(2.0 * math.pi)


def _build_log_table() -> np.ndarray:
    count = int(round((F52_X_MAX - F52_X_MIN) / F52_STEP)) + 1
    x = np.linspace(F52_X_MIN, F52_X_MAX, count)
    return np.log(f52_quadrature(x))


LOG_F52 = _build_log_table()
_GL_POINTS, _GL_WEIGHTS = np.polynomial.legendre.leggauss(64)


@nb.njit(cache=True)
def f52(x: float) -> float:
    """Greenwood–Tripp integral F_{5/2}(x) of the gap ratio x = h/σ [-] (compiled)."""
    if x >= F52_X_MAX:
        return 0.0
    if x <= F52_X_MIN:
        inv2 = 1.0 / (x * x)
        series = 1.0 + inv2 * (1.875 + inv2 * (-0.1171875 - 0.0732421875 * inv2))
        return (-x) ** 2.5 * series
    position = (x - F52_X_MIN) / F52_STEP
    index = min(int(position), LOG_F52.size - 2)
    frac = position - index
    return math.exp((1.0 - frac) * LOG_F52[index] + frac * LOG_F52[index + 1])


@nb.njit(cache=True)
def _f52_array(x: np.ndarray) -> np.ndarray:
    out = np.empty(x.size)
    flat = x.ravel()
    for i in range(flat.size):
        out[i] = f52(flat[i])
    return out


def greenwood_tripp_f52(x: np.ndarray | float) -> np.ndarray:
    """F_{5/2}(h/σ) for an array of gap ratios [-] (NumPy in, NumPy out)."""
    values = np.asarray(x, dtype=float)
    return _f52_array(np.ascontiguousarray(values).ravel()).reshape(values.shape)


def roughness_constant(roughness: float, density: float, summit_radius: float) -> float:
    """K = (16√2/15)·π·(ηβσ)²·√(σ/β) [-], σ [m], η [1/m²], β [m]."""
    return (16.0 * math.sqrt(2.0) / 15.0) * math.pi * (density * summit_radius * roughness) ** 2 * (
        math.sqrt(roughness / summit_radius)
)


def asperity_pressure(gap: np.ndarray | float, roughness: float, pressure_scale: float):
    """Nominal asperity pressure p_a = K E' F_{5/2}(h/σ) [Pa] for gap h [m], σ [m] and
    ``pressure_scale`` = K E' [Pa]."""
    return pressure_scale * greenwood_tripp_f52(np.asarray(gap, dtype=float) / roughness)


@nb.njit(cache=True)
def asperity_force(
    ex: float, ey: float, clearance: float, params: tuple[float, float, float, float]
) -> tuple[float, float]:
    """Asperity-contact force on the journal (F_x, F_y) [N] (compiled, for the orbit RHS).

    ex, ey : journal centre relative to the shell centre, film frame [m].
    clearance : radial clearance c [m].
    params : (radius R [m], width L [m], roughness σ [m], pressure scale K E' [Pa]),
        from :meth:`AsperityParameters.kernel_parameters`.
    """
    radius, width, sigma, scale = params
    e = math.hypot(ex, ey)
    if e <= 0.0 or scale <= 0.0:
        return 0.0, 0.0
    cos_edge = (clearance - F52_X_MAX * sigma) / e
    if cos_edge >= 1.0:
        return 0.0, 0.0
    half = math.pi if cos_edge <= -1.0 else math.acos(cos_edge)
    total = 0.0
    for k in range(_GL_POINTS.size):
        angle = half * _GL_POINTS[k]
        gap = clearance - e * math.cos(angle)
        total += _GL_WEIGHTS[k] * f52(gap / sigma) * math.cos(angle)
    radial = scale * radius * width * half * total
    return -radial * ex / e, -radial * ey / e


@nb.njit(cache=True)
def asperity_force_array(
    ex: np.ndarray, ey: np.ndarray, clearance: float, params: tuple[float, float, float, float]
) -> tuple[np.ndarray, np.ndarray]:
    """:func:`asperity_force` for arrays of centre positions (ex, ey) [m] → (F_x, F_y) [N]."""
    fx = np.empty(ex.size)
    fy = np.empty(ex.size)
    for i in range(ex.size):
        fx[i], fy[i] = asperity_force(ex[i], ey[i], clearance, params)
    return fx, fy


@dataclass(frozen=True)
class AsperityParameters:
    """Greenwood–Tripp surface and material parameters.

    roughness : float  Combined RMS roughness σ [m].
    asperity_density : float  Summit density η [1/m²].
    asperity_radius : float  Summit radius β [m].
    modulus : float  Composite modulus E' (= E*) [Pa].
    """

    roughness: float
    asperity_density: float
    asperity_radius: float
    modulus: float

    @classmethod
    def from_case(cls, case: Case) -> AsperityParameters:
        """Parameters from the ``[contact]`` section of a case."""
        section = case.contact
        modulus = contact_modulus(
            section.journal_elastic_modulus, section.journal_poisson_ratio,
            section.shell_elastic_modulus, section.shell_poisson_ratio,
)
        return cls(section.roughness, section.asperity_density, section.asperity_radius, modulus)

    @property
    def roughness_constant(self) -> float:
        """K of Greenwood–Tripp [-]."""
        return roughness_constant(self.roughness, self.asperity_density, self.asperity_radius)

    @property
    def pressure_scale(self) -> float:
        """K E' [Pa]: asperity pressure at F_{5/2} = 1."""
        return self.roughness_constant * self.modulus

    def kernel_parameters(self, radius: float, width: float) -> tuple[float, float, float, float]:
        """Tuple for :func:`asperity_force`: (R [m], L [m], σ [m], K E' [Pa])."""
        return (float(radius), float(width), float(self.roughness), float(self.pressure_scale))


def kernel_parameters(case: Case) -> tuple[float, float, float, float]:
    """``params`` of :func:`asperity_force` for a case with ``[bearing]`` and ``[contact]``."""
    bearing = case.bearing
    if bearing is None:
        raise CaseError("[contact] model = 'greenwood_tripp' needs the [bearing] section")
    parameters = AsperityParameters.from_case(case)
    return parameters.kernel_parameters(0.5 * bearing.diameter, bearing.width)
