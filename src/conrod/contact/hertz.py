"""Contact stress of the journal in the shell: nominal specific load and Hertz line
contact of a convex cylinder (journal, R₁) in a concave one (shell, R₂) — [D4] §4.4.

Hertz line contact (Johnson, *Contact Mechanics*, 1985, §4.3), load P on length B:

.. math::

    \\frac{1}{R'} = \\frac{1}{R_1} - \\frac{1}{R_2}, \\qquad
    \\frac{1}{E^*} = \\frac{1-ν_1^2}{E_1} + \\frac{1-ν_2^2}{E_2},

    p_0 = \\sqrt{\\frac{P E^*}{π B R'}}, \\qquad a = \\sqrt{\\frac{4 P R'}{π B E^*}}.

[D4]'s eq. 4.4.2 (with the square root its printout lost),
σ = 0.418·√(P E/B·(1/R₁ − 1/R₂)), is this p₀ for ν₁ = ν₂ = 0.3 **if** E is the
"two-material" modulus E = 2E₁E₂/(E₁ + E₂): then E* = E/(2·0.91) and
1/√(2π·0.91) = 0.4182. [D4]'s eq. 4.4.3 instead defines 1/E = 1/E₁ + 1/E₂, half that
modulus; used with 0.418 it gives a stress √2 too small. conrod always uses the exact
p₀ with E* above (:func:`hertz_line_contact_pressure`);
:func:`hertz_stress_seed_form` is the 0.418 form for comparison.

With R₂ − R₁ = c ≪ R₁ (eq. 4.4.4): 1/R' ≈ c/R₁². The contact is then conformal and the
Hertz half-width a is often not small against R₁ (check :func:`hertz_half_width`);
Hertz overestimates the peak pressure of such a contact, which is why it is a
conservative engineering estimate, as in [D4].
"""

from __future__ import annotations

import math

import numpy as np

SEED_HERTZ_CONSTANT = 0.418
"""Constant of [D4] eq. 4.4.2 = 1/√(2π(1 − 0.3²)) rounded [-]."""


def contact_modulus(
    journal_modulus: float, journal_poisson: float, shell_modulus: float, shell_poisson: float
) -> float:
    """Contact (plane-strain composite) modulus E* [Pa]:
    1/E* = (1 − ν₁²)/E₁ + (1 − ν₂²)/E₂ (Johnson 1985, eq. 4.22). Moduli [Pa], ratios [-].
    """
    compliance = (1.0 - journal_poisson**2) / journal_modulus + (
        1.0 - shell_poisson**2
) / shell_modulus
    return 1.0 / compliance


def seed_reduced_modulus(journal_modulus: float, shell_modulus: float) -> float:
    """The [D4]'s reduced modulus E, 1/E = 1/E₁ + 1/E₂ ([D4] eq. 4.4.3) [Pa]."""
    return journal_modulus * shell_modulus / (journal_modulus + shell_modulus)


def nominal_specific_load(load: np.ndarray | float, width: float, diameter: float):
    """Nominal specific load K = P/(B·D) ([D4] eq. 4.4.1) [Pa].

    load [N], width B [m], diameter D [m].
    """
    return np.asarray(load, dtype=float) / (width * diameter)


def relative_curvature(journal_radius: float, shell_radius: float) -> float:
    """1/R' = 1/R₁ − 1/R₂ of a convex journal in a concave shell [1/m]."""
    if shell_radius <= journal_radius:
        raise ValueError("the shell radius must exceed the journal radius (positive clearance)")
    return 1.0 / journal_radius - 1.0 / shell_radius


def hertz_line_contact_pressure(
    load: np.ndarray | float, width: float, journal_radius: float, shell_radius: float,
    modulus: float,
):
    """Peak Hertz pressure p₀ = √(P E*/(π B R')) of the line contact [Pa].

    load P ≥ 0 [N], width B [m], radii R₁ < R₂ [m], contact modulus E* [Pa]
    (:func:`contact_modulus`).
    """
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    curvature = relative_curvature(journal_radius, shell_radius)
    return np.sqrt(load * modulus * curvature / (math.pi * width))


def hertz_half_width(
    load: np.ndarray | float, width: float, journal_radius: float, shell_radius: float,
    modulus: float,
):
    """Half-width a = √(4 P R'/(π B E*)) of the Hertz contact strip [m] (same arguments as
    :func:`hertz_line_contact_pressure`). Hertz theory assumes a ≪ R₁."""
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    curvature = relative_curvature(journal_radius, shell_radius)
    return np.sqrt(4.0 * load / (curvature * math.pi * width * modulus))


def hertz_stress_seed_form(
    load: np.ndarray | float, width: float, journal_radius: float, shell_radius: float,
    modulus: float,
):
    """[D4] eq. 4.4.2: σ = 0.418·√(P E/B·(1/R₁ − 1/R₂)) [Pa] with the modulus E [Pa]
    as given (exact Hertz for ν = 0.3 only with E = 2E₁E₂/(E₁+E₂))."""
    load = np.maximum(np.asarray(load, dtype=float), 0.0)
    curvature = relative_curvature(journal_radius, shell_radius)
    return SEED_HERTZ_CONSTANT * np.sqrt(load * modulus * curvature / width)
