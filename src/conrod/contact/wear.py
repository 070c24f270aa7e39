"""Wear of journal and shell from the friction work per surface element ([D4] §4.5),
and the worn shell profile fed back into the film thickness (running-in).

Energy wear law (wear depth proportional to the friction work dissipated per unit area):

.. math:: w_k = k \\, \\frac{A_k}{B R Δθ}, \\qquad Δθ = 2π/N,

with A_k the friction work of element k [J], B the width, R the radius [m] and k the
energy wear coefficient [m³/J] — separate for journal (k_j) and shell (k_b).

The [D4] units. [D4] prints the coefficient's unit as
"micron·mm / ((kg·mm/mm²)·s)" — wear × journal width over (specific work × time).
"Wear = coefficient × work" only balances with wear depth per specific work,
µm/(kgf·mm/mm²); the extra width/time factor of the printout cannot be reconciled and
is read as "per cycle". The edge conversion is
1 µm/(kgf·mm/mm²) = 10⁻⁶ m / (9.80665·10⁻³ J / 10⁻⁶ m²) = 1.0197·10⁻¹⁰ m³/J
(:data:`SEED_WEAR_UNIT_TO_SI`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.contact.friction_work import FrictionWork
from conrod.units import KGF_TO_N, MM_TO_M, UM_TO_M

SEED_WEAR_UNIT_TO_SI = UM_TO_M / (KGF_TO_N * MM_TO_M / MM_TO_M**2)
"""[m^3/J per µm/(kgf·mm/mm²)] converts [D4]'s wear coefficient to SI."""


def element_area(radius: float, width: float, elements: int) -> float:
    """Area B·R·2π/N of one surface element [m²] (radius [m], width [m], N [-])."""
    return width * radius * 2.0 * math.pi / elements


def wear_depth(work: np.ndarray, coefficient: float, radius: float, width: float) -> np.ndarray:
    """Wear depth per element w = k·A/(B R Δθ) [m] for friction work per element A [J],
    energy wear coefficient k [m³/J], radius and width [m]."""
    work = np.asarray(work, dtype=float)
    return coefficient * work / element_area(radius, width, work.size)


@dataclass(frozen=True)
class WearDistribution:
    """Friction work and wear depth per element of journal and shell, for one cycle.

    element_angle : ndarray  Element centre angles (journal-fixed / shell θ) [rad].
    journal_work, shell_work : ndarray  Friction work per element [J].
    journal_wear, shell_wear : ndarray  Wear depth per element per cycle [m].
    """

    element_angle: np.ndarray
    journal_work: np.ndarray
    shell_work: np.ndarray
    journal_wear: np.ndarray
    shell_wear: np.ndarray


def wear_distribution(
    work: FrictionWork, radius: float, width: float,
    journal_coefficient: float, shell_coefficient: float,
) -> WearDistribution:
    """Wear per cycle of each journal and shell element from the friction work
    (radius, width [m]; coefficients [m³/J])."""
    return WearDistribution(
        element_angle=work.element_angle,
        journal_work=work.journal,
        shell_work=work.shell,
        journal_wear=wear_depth(work.journal, journal_coefficient, radius, width),
        shell_wear=wear_depth(work.shell, shell_coefficient, radius, width),
)


def worn_profile_deformation(
    theta: np.ndarray, z: np.ndarray, element_angle: np.ndarray, shell_wear: np.ndarray,
    cycles: float = 1.0,
) -> np.ndarray:
    """Additive film-thickness field δ(θ, z) [m] of a shell worn by ``cycles`` cycles.

    Material removed from the shell opens the gap, so δ = +wear, interpolated periodically
    from the element centres ``element_angle`` [rad] to the film grid ``theta`` [rad] and
    uniform over ``z`` [m] ([D4]'s wear model has no axial variation). Shape
    (len(theta), len(z)), as :class:`conrod.film.base.FilmState` ``deformation`` expects.
    """
    depth = cycles * np.interp(
        np.mod(theta, 2.0 * math.pi), element_angle, shell_wear, period=2.0 * math.pi
)
    return np.repeat(depth[:, None], np.asarray(z).size, axis=1)
