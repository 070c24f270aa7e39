"""Forces of the crank train on the big-end bearing ([D0] §3.4, [D1]).

Signs (``docs/conventions.md``):

* Forces along the cylinder axis (gas P_g, reciprocating inertia P_j, total P_Σ) are
  positive **towards the crank axis** (−X), the textbook convention of [D0] and [D1].
* Rod force S is positive in **compression** (rod pushing the crankpin).
* Radial crank force R (often K) is positive **towards the crank axis**; tangential T is
  positive **in the direction of rotation**. The rod's rotating-mass force P_r = −m_rk r ω²
  (outward, [D1]'s K_R) is included in R.
* ``pin_force`` is the force the rod exerts on the crankpin [N]; the bearing load handed to
  the film (:class:`~conrod.loads.cycle.LoadCycle`) is its negative.

References
----------
[1] [D0] eqs 3.4.1–3.4.3: S = P_Σ / cos β ([D0]'s "/tg(b)" is a typo),
    R = S cos(φ + β) + P_r, T = S sin(φ + β).
[2] [D1] (lecture 16): K_R = −m_rk r ω²; polar diagram of S shifted by K_R.
[3] A.S. Orlin, M.G. Kruglov (eds.), *Dvigateli vnutrennego sgoraniya: dinamika i
    konstruirovanie*, 1980 — two- and three-mass rod models.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.loads.kinematics import rod_angle


def gas_force(gauge_pressure: np.ndarray, bore: float) -> np.ndarray:
    """Gas force on the piston P_g = π D_p² (p − p_amb)/4 [N], towards the crank positive.

    gauge_pressure : ndarray  p − p_ambient [Pa].  bore : float  Cylinder bore D_p [m].
    """
    return 0.25 * math.pi * bore**2 * np.asarray(gauge_pressure, dtype=float)


def reciprocating_inertia_force(mass: float, piston_acceleration: np.ndarray) -> np.ndarray:
    """P_j = −m_j s̈ [N] (towards the crank positive); s̈ from :mod:`kinematics` [m/s²].

    With the series acceleration this is P_j = −m_j r ω² (cos φ + λ cos 2φ).
    """
    return -mass * np.asarray(piston_acceleration, dtype=float)


@dataclass(frozen=True)
class RodMasses:
    """Lumped-mass model of the connecting rod.

    big_end : float  Mass at the big-end centre, rotating with the crankpin m_A [kg].
    small_end : float  Mass at the small-end centre, reciprocating m_B [kg].
    centre : float  Mass left at the centre of mass m_G (0 for the two-mass model) [kg].
    """

    big_end: float
    small_end: float
    centre: float


def two_mass_split(rod_mass: float, rod_length: float, cg_from_big_end: float) -> RodMasses:
    """Two-mass rod (static equivalence): m_A = m L₂/L, m_B = m L₁/L, L₂ = L − L₁ [kg].

    Equivalent to a rigid rod with J_G = m L₁ L₂.
    """
    share = cg_from_big_end / rod_length
    return RodMasses(rod_mass * (1.0 - share), rod_mass * share, 0.0)


def three_mass_split(
    rod_mass: float, rod_length: float, cg_from_big_end: float, inertia: float
) -> RodMasses:
    """Three-mass rod matching mass, centre of mass and J_G (dynamic equivalence) [kg].

    .. math:: m_A = J_G/(L_1 L),\\quad m_B = J_G/(L_2 L),\\quad m_G = m - J_G/(L_1 L_2)

    m_G < 0 when J_G exceeds the two-mass value m L₁ L₂ (still exact).
    """
    l1, l2 = cg_from_big_end, rod_length - cg_from_big_end
    return RodMasses(
        inertia / (l1 * rod_length), inertia / (l2 * rod_length), rod_mass - inertia / (l1 * l2)
)


def rod_force(axial_force: np.ndarray, beta: np.ndarray) -> np.ndarray:
    """Force along the rod S = P_Σ / cos β [N], compression positive ([D0] eq. 3.4.1)."""
    return np.asarray(axial_force) / np.cos(beta)


def crank_forces(
    rod_force_value: np.ndarray, crank_angle: np.ndarray, beta: np.ndarray, rotating_force: float
) -> tuple[np.ndarray, np.ndarray]:
    """Radial R = S cos(φ+β) + P_r and tangential T = S sin(φ+β) [N] ([D0] eqs 3.4.2–3)."""
    radial = rod_force_value * np.cos(crank_angle + beta) + rotating_force
    tangential = rod_force_value * np.sin(crank_angle + beta)
    return radial, tangential


def crank_to_engine(
    radial: np.ndarray, tangential: np.ndarray, crank_angle: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Force on the crankpin in the engine frame (F_X, F_Y) [N] from R (inward +) and T."""
    cos_phi, sin_phi = np.cos(crank_angle), np.sin(crank_angle)
    return -radial * cos_phi - tangential * sin_phi, -radial * sin_phi + tangential * cos_phi


def engine_to_crank(
    force_x: np.ndarray, force_y: np.ndarray, crank_angle: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Engine-frame vector → crank frame (x outward along the crank, y along rotation) [N]."""
    cos_phi, sin_phi = np.cos(crank_angle), np.sin(crank_angle)
    return force_x * cos_phi + force_y * sin_phi, -force_x * sin_phi + force_y * cos_phi


def engine_to_rod(
    force_x: np.ndarray, force_y: np.ndarray, beta: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """Engine-frame vector → rod frame (x big end → small end = (cos β, −sin β), y = z × x) [N]."""
    cos_b, sin_b = np.cos(beta), np.sin(beta)
    return force_x * cos_b - force_y * sin_b, force_x * sin_b + force_y * cos_b


def rigid_rod_pin_force(
    crank_angle: np.ndarray,
    axial_piston_force: np.ndarray,
    rod_cg_acceleration: tuple[np.ndarray, np.ndarray],
    rod_angular_acceleration: np.ndarray,
    *,
    crank_to_rod: float,
    rod_mass: float,
    rod_length: float,
    cg_from_big_end: float,
    rod_inertia: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Force of a rigid rod on the crankpin (F_X, F_Y) [N], engine frame (Newton–Euler).

    The piston pushes the small end with its axial force P (towards the crank +; gas
    plus piston inertia); the rod (mass m, J_G about its centre of mass at L₁ from the
    big end) obeys m a_G = F_A + F_B and J_G α = (r_A − r_G) × F_A + (r_B − r_G) × F_B,
    which gives the small-end side force B_Y and F_A. Exact for any J_G; with
    J_G = m L₁ L₂ it reproduces the two-mass model, otherwise the three-mass model.
    """
    beta = rod_angle(crank_angle, crank_to_rod)
    ux, uy = np.cos(beta), -np.sin(beta)
    acc_x, acc_y = rod_cg_acceleration
    force_b_x = np.asarray(-axial_piston_force, dtype=float)  # piston on rod, along X
    moment = rod_inertia * rod_angular_acceleration + rod_mass * cg_from_big_end * (
        ux * acc_y - uy * acc_x
)
    force_b_y = (moment / rod_length + uy * force_b_x) / ux
    force_a_x = rod_mass * acc_x - force_b_x
    force_a_y = rod_mass * acc_y - force_b_y
    return -force_a_x, -force_a_y
