"""Short-bearing (Ocvirk/Dubois) film forces in closed form, with squeeze and
half-Sommerfeld (Gümbel) cavitation — compiled, ~1 µs per call.

Derivation (frame and signs as in :mod:`conrod.film.base`)
-----------------------------------------------------------
With the line-of-centres angle ψ, θ' = θ − ψ, ε = e/c and the squeeze rates ė, eψ̇,
dropping ∂p/∂θ against ∂p/∂z turns the Reynolds equation into
h³ ∂²p/∂z² = G(θ'), with

.. math:: G = 6μ c\\,[ε(ω_j+ω_b-2\\dot ψ)\\sin θ' - 2\\dot ε \\cos θ'] = 6 μ c V \\sin(θ'-α),

V = √((ε ω_eff)² + (2ε̇)²), tan α = 2ε̇/(ε ω_eff) (Booker's ω_eff = ω_j + ω_b − 2ψ̇).
With p = 0 at z = ±L/2, p = −G (L²/4 − z²)/(2h³); keeping only p > 0 (half-Sommerfeld)
the active arc is θ' ∈ (α+π, α+2π). The force integrals over that arc become exact
trigonometric polynomials under the Sommerfeld substitution
cos θ' = (ε + cos γ)/(1 + ε cos γ) [1], so no quadrature is needed.

Steady check: α = 0 gives the classical F_t = π μ U L³ ε / (4c²(1−ε²)^{3/2}) and
F_r = −μ U L³ ε²/(c²(1−ε²)²) with U = R ω [2].

[1] A. Sommerfeld, Z. Math. Phys. 50 (1904) 97–155.
[2] B.J. Hamrock, Fundamentals of Fluid Film Lubrication, 2nd ed., ch. 10 (2004).
"""

from __future__ import annotations

import math

import numba as nb

ECCENTRICITY_LIMIT = 1.0 - 1.0e-6
"""Largest eccentricity ratio the kernel evaluates; larger values are clamped [-]."""


@nb.njit(cache=True)
def sommerfeld_angle(theta: float, eps: float) -> float:
    """Continuous Sommerfeld variable γ(θ): cos θ = (ε + cos γ)/(1 + ε cos γ) [rad]."""
    k = math.sqrt((1.0 + eps) / (1.0 - eps))
    turns = math.floor(theta / (2.0 * math.pi) + 0.5)
    reduced = theta - 2.0 * math.pi * turns
    return 2.0 * math.atan2(k * math.sin(0.5 * reduced), math.cos(0.5 * reduced)) + (
        2.0 * math.pi * turns
)


@nb.njit(cache=True)
def active_arc_integrals(alpha: float, eps: float) -> tuple[float, float, float]:
    """∫cos²θ'/(1−ε cos θ')³, ∫sin²θ'/(…)³, ∫sinθ' cosθ'/(…)³ over θ' ∈ (α+π, α+2π)."""
    ga = sommerfeld_angle(alpha + math.pi, eps)
    gb = sommerfeld_angle(alpha + 2.0 * math.pi, eps)
    d_gamma = gb - ga
    d_sin = math.sin(gb) - math.sin(ga)
    d_sin2 = math.sin(2.0 * gb) - math.sin(2.0 * ga)
    d_cos = math.cos(gb) - math.cos(ga)
    d_sinsq = math.sin(gb) ** 2 - math.sin(ga) ** 2
    k_cc = eps * eps * d_gamma + 2.0 * eps * d_sin + 0.5 * d_gamma + 0.25 * d_sin2
    k_ss = 0.5 * d_gamma - 0.25 * d_sin2
    k_sc = -eps * d_cos + 0.5 * d_sinsq
    beta = 1.0 - eps * eps
    return k_cc / beta**2.5, k_ss / beta**1.5, k_sc / beta**2


@nb.njit(cache=True)
def short_bearing_polar(
    eps: float, eps_rate: float, whirl_rate: float, omega_sum: float,
    viscosity: float, radius: float, width: float, clearance: float,
) -> tuple[float, float, float, float]:
    """Radial F_r and tangential F_t film force on the journal [N] in the line-of-centres
    frame, with the active-arc angle α [rad] and the squeeze-wedge speed V [1/s].

    eps [-], eps_rate dε/dt [1/s], whirl_rate dψ/dt [rad/s], omega_sum ω_j + ω_b [rad/s],
    viscosity [Pa s], radius R, width L, clearance c [m].
    """
    eps = min(eps, ECCENTRICITY_LIMIT)
    wedge = eps * (omega_sum - 2.0 * whirl_rate)
    squeeze = 2.0 * eps_rate
    speed = math.hypot(wedge, squeeze)
    if speed == 0.0:
        return 0.0, 0.0, 0.0, 0.0
    alpha = math.atan2(squeeze, wedge)
    j_cc, j_ss, j_sc = active_arc_integrals(alpha, eps)
    scale = radius * viscosity * speed * width**3 / (2.0 * clearance * clearance)
    ca = math.cos(alpha)
    sa = math.sin(alpha)
    f_radial = scale * (ca * j_sc - sa * j_cc)
    f_tangential = scale * (ca * j_ss - sa * j_sc)
    return f_radial, f_tangential, alpha, speed


@nb.njit(cache=True)
def short_bearing_force(
    ex: float, ey: float, vx: float, vy: float, omega_sum: float,
    viscosity: float, radius: float, width: float, clearance: float,
) -> tuple[float, float]:
    """Film force on the journal (F_x, F_y) [N] for journal-centre position (ex, ey) [m]
    and velocity (vx, vy) [m/s] relative to the shell, ω_j + ω_b = ``omega_sum`` [rad/s].
    """
    e = math.hypot(ex, ey)
    tiny = 1.0e-12 * clearance
    if e > tiny:
        cos_psi = ex / e
        sin_psi = ey / e
        e_rate = vx * cos_psi + vy * sin_psi
        whirl = (vy * cos_psi - vx * sin_psi) / e
    else:
        v = math.hypot(vx, vy)
        if v == 0.0:
            return 0.0, 0.0
        cos_psi = vx / v
        sin_psi = vy / v
        e_rate = v
        whirl = 0.0
    f_r, f_t, _, _ = short_bearing_polar(
        e / clearance, e_rate / clearance, whirl, omega_sum, viscosity, radius, width, clearance
)
    return f_r * cos_psi - f_t * sin_psi, f_r * sin_psi + f_t * cos_psi
