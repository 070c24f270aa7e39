"""Component objects of the clearance mechanism: joints, crank train, initial state.

Layer 2 of the package: small frozen dataclasses holding SI parameters that pack
themselves into the flat parameter vector read by :mod:`conrod.mechanism.kernel`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from conrod.mechanism import kernel as k
from conrod.mechanism.geometry import damping_coefficient, shell_radius, shell_semi_axes

ROD_INERTIA_FACTOR = 0.175
"""[D3]: J_c2 = 0.175·m₂·L² when the rod inertia is unknown [-]."""


@dataclass(frozen=True)
class ClearanceJoint:
    """One rod bearing with a worn elliptical shell ([D3] symbols).

    diameter : float  Journal/pin diameter D (big end) or d (small end) [m].
    clearance_max : float  Diametral clearance along the major axis Δmax [m].
    clearance_min : float  Diametral clearance along the minor axis Δmin [m].
    ellipse_angle : float  Major axis to rod axis γ [rad].
    contact_stiffness : float  c [N/m^α].
    contact_exponent : float  α [-].
    damping_factor : float  μ in β = 2 μ √(c m_eff) [-].
    friction_coefficient : float  f [-].
    damping_scale : float  Extra factor on β ([D3]: 0.3 at the small end) [-].
    """

    diameter: float
    clearance_max: float
    clearance_min: float
    ellipse_angle: float = 0.0
    contact_stiffness: float = 1.0e13
    contact_exponent: float = 1.5
    damping_factor: float = 0.1
    friction_coefficient: float = 0.0
    damping_scale: float = 1.0

    @property
    def radial_clearance_min(self) -> float:
        """Smallest radial clearance Δmin/2 [m]."""
        return 0.5 * self.clearance_min

    @property
    def clearance_along_rod(self) -> float:
        """Radial clearance along the rod axis p(γ) − D/2 [m] (Δmax/2 for γ = 0)."""
        _, minor, eccentricity_sq = shell_semi_axes(
            self.diameter, self.clearance_max, self.clearance_min)
        return shell_radius(self.ellipse_angle, minor, eccentricity_sq) - 0.5 * self.diameter

    def block(self, effective_mass: float, exact: bool = False) -> np.ndarray:
        """The joint's entries of the kernel parameter vector (β from ``effective_mass``
        [kg]; ``exact`` selects the exact ellipse–circle contact instead of [D3]'s)."""
        major, minor, eccentricity_sq = shell_semi_axes(
            self.diameter, self.clearance_max, self.clearance_min)
        damping = self.damping_scale * damping_coefficient(
            self.damping_factor, self.contact_stiffness, effective_mass)
        return np.array([self.diameter, minor, eccentricity_sq, self.ellipse_angle,
                         self.contact_stiffness, self.contact_exponent, damping,
                         self.friction_coefficient, major, 1.0 if exact else 0.0])


@dataclass(frozen=True)
class CrankTrain:
    """Slider-crank of [D3].

    crank_radius : float  R [m]; rod_length : float  L [m];
    rod_cg_from_big_end : float  L₁ [m]; rod_mass : float  m₂ [kg];
    rod_inertia : float  J_c2 about the centre of mass [kg m²];
    piston_mass : float  m₃ [kg]; crank_speed : float  ω₁ [rad/s].
    """

    crank_radius: float
    rod_length: float
    rod_cg_from_big_end: float
    rod_mass: float
    rod_inertia: float
    piston_mass: float
    crank_speed: float

    @classmethod
    def with_seed_inertia(cls, **kwargs: float) -> CrankTrain:
        """Build with J_c2 = 0.175 m₂ L² ([D3]) [kg m²]."""
        inertia = ROD_INERTIA_FACTOR * kwargs["rod_mass"] * kwargs["rod_length"] ** 2
        return cls(rod_inertia=inertia, **kwargs)

    @property
    def big_end_mass(self) -> float:
        """[D3] mass in β₂: m₂ L₁/L [kg]."""
        return self.rod_mass * self.rod_cg_from_big_end / self.rod_length

    @property
    def small_end_mass(self) -> float:
        """[D3] mass in β₁: m₂ (L − L₁)/L [kg]."""
        return self.rod_mass * (self.rod_length - self.rod_cg_from_big_end) / self.rod_length


@dataclass(frozen=True)
class Mechanism:
    """Crank train + both joints + friction regularisation; packs the kernel vector.

    friction_velocity : float  Sliding speed below which friction is smoothed,
        F = f R v/√(v² + v₀²) [m/s].
    contact_geometry : str  "seed": penetration along the line of centres
        δ = r + D/2 − p(ϕ), force through the shell centre ([D3]); "exact": largest
        violation of the shell's supporting half-planes, force along the contact normal
        (see :func:`conrod.mechanism.geometry.exact_contact`).
    """

    crank: CrankTrain
    big_end: ClearanceJoint
    small_end: ClearanceJoint
    friction_velocity: float = 1.0e-3
    contact_geometry: str = "seed"

    def parameters(self) -> np.ndarray:
        """Flat parameter vector of :mod:`conrod.mechanism.kernel` (SI)."""
        p = np.zeros(k.PARAMETER_COUNT)
        c = self.crank
        p[k.CRANK_RADIUS], p[k.ROD_LENGTH], p[k.ROD_CG] = (
            c.crank_radius, c.rod_length, c.rod_cg_from_big_end)
        p[k.ROD_MASS], p[k.ROD_INERTIA], p[k.PISTON_MASS] = c.rod_mass, c.rod_inertia, c.piston_mass
        p[k.CRANK_SPEED], p[k.FRICTION_VELOCITY] = c.crank_speed, self.friction_velocity
        exact = self.contact_geometry == "exact"
        p[k.BIG_END:k.BIG_END + k.BLOCK_SIZE] = self.big_end.block(c.big_end_mass, exact)
        p[k.SMALL_END:k.SMALL_END + k.BLOCK_SIZE] = self.small_end.block(c.small_end_mass, exact)
        return p

    def at_speed(self, crank_speed: float) -> Mechanism:
        """Copy running at another crank speed ω₁ [rad/s]."""
        return replace(self, crank=replace(self.crank, crank_speed=crank_speed))


def static_deflection(force: float, stiffness: float, exponent: float) -> float:
    """[D3]: δ = |F/c|^{1/α} [m] for a contact force F [N]."""
    return abs(force / stiffness) ** (1.0 / exponent)


def seed_initial_state(mechanism: Mechanism, gas_force_at_tdc: float) -> np.ndarray:
    """Approximate initial state at firing TDC ([D3], 'vector of initial conditions').

    Inertia forces P_i3 = m₃ R ω²(1 + R/L), P_i2 = m₂ R ω²(1 + 0.35 R/L); static
    deflections δ₁ = |(P_i3 − P(0))/c₁|^{1/α₁}, δ₂ = |(P_i3 + P_i2 − P(0))/c₂|^{1/α₂}.
    [D3] puts the journals Δmax/2 (here the clearance along the rod axis, equal
    for γ = 0) plus δ from the shell centre, against the crank-side of their shells (gas force
    wins); here the side follows the sign of the net force, so a motored or
    high-speed start (inertia wins) begins against the head-side instead.
    The work state W starts at 0 [J].
    """
    c = mechanism.crank
    R, L, L1, w2 = c.crank_radius, c.rod_length, c.rod_cg_from_big_end, c.crank_speed**2
    inertia_piston = c.piston_mass * R * w2 * (1.0 + R / L)
    inertia_rod = c.rod_mass * R * w2 * (1.0 + 0.35 * R / L)
    small_net = inertia_piston - gas_force_at_tdc
    big_net = inertia_piston + inertia_rod - gas_force_at_tdc
    small, big = mechanism.small_end, mechanism.big_end
    offset_small = math.copysign(1.0, -small_net) * (
        small.clearance_along_rod
        + static_deflection(small_net, small.contact_stiffness, small.contact_exponent))
    offset_big = math.copysign(1.0, -big_net) * (
        big.clearance_along_rod
        + static_deflection(big_net, big.contact_stiffness, big.contact_exponent))
    return np.array([
        L1 + R - offset_big, 0.0,
        0.0, R * (L - L1) / L,
        math.pi, -R / L,
        L + R - offset_big - offset_small, 0.0,
        0.0,
    ])
