"""Inertia deformation of the rod by superposition (Rodin 2004, eqs. 4–6).

In the rod frame (origin at the big-end centre, x towards the small end; see
docs/conventions.md) the d'Alembert force per unit mass on the material point (x, y) of a
rigid rod is

.. math::
    b_x = ω^2 r \\cos(φ + β) + Ω^2 x + \\dot Ω y, \\qquad
    b_y = ω^2 r \\sin(φ + β) + Ω^2 y - \\dot Ω x

(crank speed ω, crank radius r, rod angular velocity Ω = −dβ/dt and acceleration
dΩ/dt from :mod:`conrod.loads.kinematics`; constant ω). It is a combination of four
time-independent body-force fields, whose displacements are computed once:

=====  ===========================  =====================
base   body force per unit mass     coefficient c_k(φ)
=====  ===========================  =====================
0      (1, 0)                       ω² r cos(φ + β)  [m/s²]
1      (0, 1)                       ω² r sin(φ + β)  [m/s²]
2      (x, y)                       Ω²               [1/s²]
3      (y, −x)                      dΩ/dt            [1/s²]
=====  ===========================  =====================

so that u_inertia(φ) = Σ_k c_k(φ) U_k. The seed combines ρx along x and ρy along y into one
load case in the same way.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.loads.kinematics import rod_angle, rod_angular_acceleration, rod_angular_velocity

BASE_FIELD_NAMES = ("acceleration_x", "acceleration_y", "angular_velocity_squared",
                    "angular_acceleration")
"""Names of the four inertia base fields, in order."""

BASE_FIELD_UNITS = ("m per m/s^2", "m per m/s^2", "m per 1/s^2", "m per 1/s^2")
"""Units of the base fields (displacement per unit coefficient)."""


def base_accelerations(x: np.ndarray, y: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """The four body forces per unit mass of the table above at points (x, y) [m]."""
    one, zero = np.ones_like(x), np.zeros_like(x)
    return [(one, zero), (zero, one), (x, y), (y, -x)]


@dataclass(frozen=True)
class CrankKinematics:
    """Crank train seen by the rod: ω [rad/s], r [m], λ = r/L [-]."""

    crank_speed: float
    crank_radius: float
    crank_to_rod: float

    def coefficients(self, crank_angle: float) -> np.ndarray:
        """c_k(φ) of the four base fields at crank angle φ [rad] (units in the table).

        Scalar form of :mod:`conrod.loads.kinematics` (it runs at every deformation update):
        sin β = λ sin φ, Ω = −ω λ cos φ / cos β, dΩ/dt = ω² λ (1 − λ²) sin φ / cos³ β.
        """
        lam, omega = self.crank_to_rod, self.crank_speed
        sin_phi, cos_phi = math.sin(crank_angle), math.cos(crank_angle)
        sin_beta = lam * sin_phi
        cos_beta = math.sqrt(1.0 - sin_beta * sin_beta)
        centripetal = omega * omega * self.crank_radius
        rod_rate = -omega * lam * cos_phi / cos_beta
        rod_acceleration = omega * omega * lam * (1.0 - lam * lam) * sin_phi / cos_beta**3
        return np.array([centripetal * (cos_phi * cos_beta - sin_phi * sin_beta),
                         centripetal * (sin_phi * cos_beta + cos_phi * sin_beta),
                         rod_rate * rod_rate, rod_acceleration])

    def body_force(self, crank_angle: float):
        """The full d'Alembert body force per unit mass b(x, y) at φ (direct, no split; uses
        :mod:`conrod.loads.kinematics`, so it also checks :meth:`coefficients`)."""
        beta = float(rod_angle(crank_angle, self.crank_to_rod))
        centripetal = self.crank_speed**2 * self.crank_radius
        omega = float(rod_angular_velocity(crank_angle, self.crank_to_rod, self.crank_speed))
        alpha = float(rod_angular_acceleration(crank_angle, self.crank_to_rod, self.crank_speed))

        def acceleration(x: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
            return (centripetal * np.cos(crank_angle + beta) + omega**2 * x + alpha * y,
                    centripetal * np.sin(crank_angle + beta) + omega**2 * y - alpha * x)

        return acceleration


def rigid_rod_load_difference(case, mass_properties: dict[str, float]) -> dict[str, float]:
    """Bearing load with the FE rod's distributed mass versus the two-mass model.

    Both use the FE rod's mass m and centre of mass L₁ (in place of the case's); the
    distributed (rigid-body) model also uses its moment of inertia J_G — the dynamically
    equivalent three-mass rod of :mod:`conrod.loads.forces` — the two-mass model ignores
    it. Returns the largest difference of |W| over the cycle [N], relative to |W| there and
    to the peak load [-], and its crank angle [deg].
    """
    from conrod.cases.base import validate_section
    from conrod.cases.engine import EngineSection
    from conrod.loads.engine_loads import compute_engine_loads

    data = case.engine.model_dump()
    data.update(rod_mass=mass_properties["mass"], rod_cg_from_big_end=mass_properties["x"])
    loads = []
    for inertia in (mass_properties["inertia"], None):
        engine = validate_section(EngineSection, {**data, "rod_inertia": inertia}, "engine")
        loads.append(compute_engine_loads(case.model_copy(update={"engine": engine})))
    distributed, two_mass = (item.load_magnitude for item in loads)
    difference = np.abs(distributed - two_mass)
    worst = int(np.argmax(difference / np.maximum(two_mass, 1.0e-30)))
    return {
        "max_load_difference_N": float(difference.max()),
        "max_relative_difference": float(difference[worst] / two_mass[worst]),
        "at_crank_angle_deg": float(np.degrees(loads[1].crank_angle[worst])),
        "max_difference_over_peak_load": float(difference.max() / two_mass.max()),
    }
