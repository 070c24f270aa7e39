"""Closed forms for limits and tests: infinitely long (Sommerfeld, Gümbel) and short
(Ocvirk) bearings, wedge and pure squeeze.

Forces are on the journal, in the line-of-centres frame of :mod:`conrod.film.base`:
``radial`` along the journal-centre displacement e, ``tangential`` 90° ahead of it
(positive towards +θ). U = R(ω_j + ω_b) [m/s] is the sum of the surface speeds, ε = e/c.

Long bearing, wedge (Reynolds d/dx(h³ dp/dx) = 6μU dh/dx, p(0) = p(2π) = 0) [1, ch. 8]:

.. math:: F_t/L = \\frac{12πμUR^2 ε}{c^2(2+ε^2)\\sqrt{1-ε^2}}, \\quad F_r = 0
          \\quad\\text{(full Sommerfeld)}

.. math:: F_r/L = -\\frac{12μUR^2 ε^2}{c^2(2+ε^2)(1-ε^2)}, \\quad
          F_t/L = \\frac{6πμUR^2 ε}{c^2(2+ε^2)\\sqrt{1-ε^2}}
          \\quad\\text{(Gümbel, half Sommerfeld)}

Pure squeeze, full film (no cavitation), ė = de/dt [m/s]:

.. math:: F_r^{long}/L = -\\frac{12πμR^3 ė}{c^3(1-ε^2)^{3/2}}, \\qquad
          F_r^{short} = -\\frac{πμRL^3 ė (1+2ε^2)}{c^3(1-ε^2)^{5/2}}

(the short form from p = −6μḣ(L²/4 − z²)/h³ and ∫cos²θ/(1−ε cos θ)³ dθ =
π(1+2ε²)/(1−ε²)^{5/2}).

[1] B.J. Hamrock, S.R. Schmid, B.O. Jacobson, Fundamentals of Fluid Film Lubrication,
    2nd ed., Marcel Dekker (2004), ch. 8 and 10.
"""

from __future__ import annotations

import math


def sommerfeld_long_force(
    eps: float, surface_speed_sum: float, viscosity: float, radius: float, clearance: float
) -> tuple[float, float]:
    """Full-Sommerfeld long bearing: (F_r, F_t) per unit length [N/m]."""
    scale = viscosity * surface_speed_sum * radius**2 / clearance**2
    tangential = 12.0 * math.pi * scale * eps / ((2.0 + eps * eps) * math.sqrt(1.0 - eps * eps))
    return 0.0, tangential


def gumbel_long_force(
    eps: float, surface_speed_sum: float, viscosity: float, radius: float, clearance: float
) -> tuple[float, float]:
    """Half-Sommerfeld (Gümbel) long bearing: (F_r, F_t) per unit length [N/m]."""
    scale = viscosity * surface_speed_sum * radius**2 / clearance**2
    beta = 1.0 - eps * eps
    radial = -12.0 * scale * eps * eps / ((2.0 + eps * eps) * beta)
    tangential = 6.0 * math.pi * scale * eps / ((2.0 + eps * eps) * math.sqrt(beta))
    return radial, tangential


def long_squeeze_force(
    eps: float, eccentricity_rate: float, viscosity: float, radius: float, clearance: float
) -> float:
    """Full-film pure-squeeze radial force per unit length of a long bearing [N/m]."""
    return (-12.0 * math.pi * viscosity * radius**3 * eccentricity_rate
            / (clearance**3 * (1.0 - eps * eps) ** 1.5))


def short_squeeze_force(
    eps: float, eccentricity_rate: float, viscosity: float, radius: float, width: float,
    clearance: float,
) -> float:
    """Full-film pure-squeeze radial force of a short bearing [N]."""
    return (-math.pi * viscosity * radius * width**3 * eccentricity_rate * (1.0 + 2.0 * eps * eps)
            / (clearance**3 * (1.0 - eps * eps) ** 2.5))
