"""Crank-slider kinematics: exact closed form and the series form of [D3].

Frame (``docs/conventions.md``): engine frame X along the cylinder axis from the
crank axis towards TDC, crank rotating counter-clockwise (positive) at constant ω,
crank angle φ from firing TDC. The crankpin (big-end centre) is at r(cos φ, sin φ),
the piston pin at (X_p, 0) (no pin offset). The rod obliquity β is defined by

.. math:: \\sin β = λ \\sin φ,  \\qquad λ = r / L

so the rod axis from big end to small end is u = (cos β, −sin β): the rod's
orientation angle in the engine frame is −β and its angular velocity Ω_rod = −dβ/dt.

Piston displacement from TDC s = r + L − X_p (positive towards the crank).

References
----------
[1] [D3] (Kulayev), §2: S = r[1 − cos α + λ(1 − cos 2α)/4].
[2] J.B. Heywood, *Internal Combustion Engine Fundamentals*, McGraw-Hill 1988, §2.2
    (exact slider-crank relations).
"""

from __future__ import annotations

import numpy as np

ArrayLike = np.ndarray | float


def rod_angle(crank_angle: ArrayLike, crank_to_rod: float) -> np.ndarray:
    """Rod obliquity β [rad] from sin β = λ sin φ (φ crank angle [rad], λ = r/L [-])."""
    return np.arcsin(crank_to_rod * np.sin(crank_angle))


def rod_angle_derivatives(
    crank_angle: ArrayLike, crank_to_rod: float
) -> tuple[np.ndarray, np.ndarray]:
    """dβ/dφ [-] and d²β/dφ² [-] at constant crank speed.

    .. math:: β' = λ \\cos φ / \\cos β, \\qquad β'' = -λ (1 - λ^2) \\sin φ / \\cos^3 β
    """
    cos_beta = np.cos(rod_angle(crank_angle, crank_to_rod))
    first = crank_to_rod * np.cos(crank_angle) / cos_beta
    second = -crank_to_rod * (1.0 - crank_to_rod**2) * np.sin(crank_angle) / cos_beta**3
    return first, second


def rod_angular_velocity(
    crank_angle: ArrayLike, crank_to_rod: float, crank_speed: float
) -> np.ndarray:
    """Rod angular velocity Ω_rod = −dβ/dt [rad/s] in the engine frame (CCW positive).

    crank_speed : float  Crank angular velocity ω [rad/s].
    """
    return -crank_speed * rod_angle_derivatives(crank_angle, crank_to_rod)[0]


def rod_angular_acceleration(
    crank_angle: ArrayLike, crank_to_rod: float, crank_speed: float
) -> np.ndarray:
    """Rod angular acceleration dΩ_rod/dt = −d²β/dt² [rad/s²] at constant ω [rad/s]."""
    return -(crank_speed**2) * rod_angle_derivatives(crank_angle, crank_to_rod)[1]


def piston_displacement(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float
) -> np.ndarray:
    """Exact piston displacement from TDC s [m], positive towards the crank.

    .. math:: s = r (1 - \\cos φ) + L \\left(1 - \\sqrt{1 - λ^2 \\sin^2 φ}\\right)
    """
    lam = crank_radius / rod_length
    return crank_radius * (1.0 - np.cos(crank_angle)) + rod_length * (
        1.0 - np.sqrt(1.0 - (lam * np.sin(crank_angle)) ** 2)
)


def piston_velocity(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float, crank_speed: float
) -> np.ndarray:
    """Exact piston velocity ds/dt [m/s] (towards the crank positive).

    .. math:: \\dot s = r ω (\\sin φ + \\sin φ \\, λ \\cos φ / \\cos β)
    """
    lam = crank_radius / rod_length
    beta_rate = rod_angle_derivatives(crank_angle, lam)[0]
    beta = rod_angle(crank_angle, lam)
    return crank_speed * (
        crank_radius * np.sin(crank_angle) + rod_length * np.sin(beta) * beta_rate
)


def piston_acceleration(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float, crank_speed: float
) -> np.ndarray:
    """Exact piston acceleration d²s/dt² [m/s²] (towards the crank positive).

    .. math:: \\ddot s = ω^2 [r \\cos φ + L(\\cos β \\, β'^2 + \\sin β \\, β'')]
    """
    lam = crank_radius / rod_length
    beta = rod_angle(crank_angle, lam)
    first, second = rod_angle_derivatives(crank_angle, lam)
    return crank_speed**2 * (
        crank_radius * np.cos(crank_angle)
        + rod_length * (np.cos(beta) * first**2 + np.sin(beta) * second)
)


def piston_displacement_series(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float
) -> np.ndarray:
    """[D3] series piston displacement s [m]; error r λ³ sin⁴φ / 8 + O(λ⁵).

    .. math:: s = r \\left[1 - \\cos φ + \\frac{λ}{4}(1 - \\cos 2φ)\\right]
    """
    lam = crank_radius / rod_length
    return crank_radius * (
        1.0 - np.cos(crank_angle) + 0.25 * lam * (1.0 - np.cos(2.0 * crank_angle))
)


def piston_velocity_series(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float, crank_speed: float
) -> np.ndarray:
    """Series piston velocity [m/s]: ṡ = r ω (sin φ + λ sin 2φ / 2)."""
    lam = crank_radius / rod_length
    return (
        crank_radius * crank_speed * (np.sin(crank_angle) + 0.5 * lam * np.sin(2.0 * crank_angle))
)


def piston_acceleration_series(
    crank_angle: ArrayLike, crank_radius: float, rod_length: float, crank_speed: float
) -> np.ndarray:
    """Series piston acceleration [m/s²]: s̈ = r ω² (cos φ + λ cos 2φ) ([D0]/001 P_j)."""
    lam = crank_radius / rod_length
    return crank_radius * crank_speed**2 * (np.cos(crank_angle) + lam * np.cos(2.0 * crank_angle))


def rod_centre_of_mass_acceleration(
    crank_angle: ArrayLike,
    crank_radius: float,
    rod_length: float,
    cg_from_big_end: float,
    crank_speed: float,
) -> tuple[np.ndarray, np.ndarray]:
    """Acceleration (a_X, a_Y) [m/s²] of the rod's centre of mass, engine frame.

    r_G = r(cos φ, sin φ) + L₁(cos β, −sin β), differentiated twice at constant ω.
    """
    lam = crank_radius / rod_length
    beta = rod_angle(crank_angle, lam)
    first, second = rod_angle_derivatives(crank_angle, lam)
    w2 = crank_speed**2
    pin_x = -crank_radius * w2 * np.cos(crank_angle)
    pin_y = -crank_radius * w2 * np.sin(crank_angle)
    axis_x = -np.sin(beta) * second - np.cos(beta) * first**2
    axis_y = -np.cos(beta) * second + np.sin(beta) * first**2
    return pin_x + cg_from_big_end * w2 * axis_x, pin_y + cg_from_big_end * w2 * axis_y
