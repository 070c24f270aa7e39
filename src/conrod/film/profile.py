"""Bore and shell profiles: the additive film thickness h₀(θ, z) of a bore that is not a
plain cylinder.

Every grid film (Reynolds, mass-conserving, and the elastic films built on them) adds

.. math:: h(θ, z) = c − (e_x + zγ_y)\\cos θ − (e_y − zγ_x)\\sin θ + h_0(θ, z) + δ(θ, z)

with h₀ of :meth:`BoreProfile.field` on its grid, once, when the film is built. θ is the
shell angle in the film frame and z the axial position from mid-width (:mod:`conrod.film.base`).
**The profile is fixed in the film (bearing) frame**: for a big end that is the connecting
rod, so the shell profile turns with the rod, as the shell does. A positive h₀ is more
clearance. ``radial_clearance`` c stays the clearance of the cylindrical bore; the lobed
shapes below keep c as their smallest (assembled) clearance.

Shapes (all optional, summed):

* crush relief at the split: depth d_cr at each joint face (rod/cap joint angles β_j, by
  default ±90°, the split plane perpendicular to the rod axis), falling linearly to 0 over
  the angular extent Δ_cr on both sides: h₀ = d_cr max(0, 1 − |θ − β_j|/Δ_cr);
* end relief or edge chamfer: depth d_e at both edges, falling linearly to 0 over the axial
  length l_e: h₀ = d_e max(0, 1 − (L/2 − |z|)/l_e);
* elliptical (lemon, two-lobe) bore with preload m (0 ≤ m < 1): two lobes of clearance
  c_b = c/(1 − m) centred at α and α + π (``lobe_angle`` α, default 0: the rod axis), each
  lobe's centre moved towards the opposite side by d = m c_b, so
  h₀ = d (1 − |cos(θ − α)|) and the clearance is c on the lobe axis, c_b = c + d across it
  (Lund & Thomsen 1978's two-lobe bearing; their bearing clearance is c_b);
* offset halves: the two halves centred at α and α + π moved along the split by d in
  opposite directions, each converging in +θ (the journal's rotation):
  h₀ = d (1 − sgn(cos(θ − α)) sin(θ − α));
* axial taper t: h₀ = t z/L (the edge z = +L/2 has t more clearance than z = −L/2);
* crown k: h₀ = k (2z/L)² (k more clearance at both edges than at mid-width; negative: a
  barrel that is tighter at the edges);
* out-of-round: Σ a_n cos(n(θ − φ_n)) (n = 2 ovality, 3 trilobe, ...);
* a measured table (:class:`~conrod.film.profile_table.ProfileTable`);
* the as-built bore of an elastic housing (bolt preload, shell crush and thermal distortion,
  :mod:`conrod.housing.assembly`, :mod:`conrod.housing.thermal`), a table on the film
  nodes, uniform in z.

A profile may not close the film of a centred journal: c + min h₀ must stay above 2 % of c.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.errors import CaseError
from conrod.film.profile_table import ProfileTable

__all__ = ["BoreProfile", "Harmonic", "ProfileTable", "profile_field"]

SMALLEST_OPEN_GAP = 0.02
"""Smallest film thickness of the centred journal a profile may leave, share of c [-]."""


@dataclass(frozen=True)
class Harmonic:
    """One out-of-round harmonic a cos(n(θ − φ)).

    order : int  n ≥ 1 [-].  amplitude : float  a [m].  angle : float  φ [rad].
    """

    order: int
    amplitude: float
    angle: float = 0.0


@dataclass(frozen=True, kw_only=True)
class BoreProfile:
    """Parametric and measured bore/shell profile (module docstring), SI units.

    crush_relief_depth : float  d_cr at the joint faces [m].
    crush_relief_extent : float  Δ_cr from each joint face [rad] (≤ π/2).
    joint_angles : tuple  Shell angles of the rod/cap joints β_j [rad].
    end_relief_depth : float  d_e at both edges [m].
    end_relief_length : float  Axial length l_e of the end relief [m].
    preload : float  Elliptical-bore preload m [-] (0: none).
    offset_halves : float  Offset d of the two halves [m] (0: none).
    lobe_angle : float  α, centre of the first lobe / half [rad].
    taper : float  Axial taper t [m].  crown : float  Crown k [m].
    out_of_round : tuple  :class:`Harmonic` terms.
    table : ProfileTable or None  Measured offsets.
    housing_bore : ProfileTable or None  The as-built bore of the housing (uniform in z).
    """

    crush_relief_depth: float = 0.0
    crush_relief_extent: float = 0.0
    joint_angles: tuple[float, ...] = (0.5 * math.pi, 1.5 * math.pi)
    end_relief_depth: float = 0.0
    end_relief_length: float = 0.0
    preload: float = 0.0
    offset_halves: float = 0.0
    lobe_angle: float = 0.0
    taper: float = 0.0
    crown: float = 0.0
    out_of_round: tuple[Harmonic, ...] = ()
    table: ProfileTable | None = None
    housing_bore: ProfileTable | None = None

    def __post_init__(self) -> None:
        """Ranges that keep every shape meaningful (module docstring)."""
        checks = (("crush_relief_depth", self.crush_relief_depth, 0.0, 1e-3, "m"),
                  ("crush_relief_extent", self.crush_relief_extent, 0.0, 0.5 * math.pi, "rad"),
                  ("end_relief_depth", self.end_relief_depth, 0.0, 1e-3, "m"),
                  ("end_relief_length", self.end_relief_length, 0.0, 10.0, "m"),
                  ("preload", self.preload, 0.0, 0.9, "-"),
                  ("offset_halves", self.offset_halves, 0.0, 1e-3, "m"),
                  ("taper", self.taper, -1e-3, 1e-3, "m"),
                  ("crown", self.crown, -1e-3, 1e-3, "m"))
        for name, value, low, high, unit in checks:
            if not (isinstance(value, int | float) and low <= value <= high):
                raise CaseError(f"BoreProfile {name} = {value!r}: out of range (allowed: "
                                f">= {low:g} and <= {high:g} {unit})")
        if (self.crush_relief_depth > 0.0) != (self.crush_relief_extent > 0.0):
            raise CaseError("BoreProfile crush relief: depth and extent go together (allowed: "
                            "both > 0, or both 0)")
        if (self.end_relief_depth > 0.0) != (self.end_relief_length > 0.0):
            raise CaseError("BoreProfile end relief: depth and length go together (allowed: "
                            "both > 0, or both 0)")
        for harmonic in self.out_of_round:
            if not (isinstance(harmonic, Harmonic) and harmonic.order >= 1
                    and abs(harmonic.amplitude) <= 1e-3):
                raise CaseError(f"BoreProfile out_of_round term {harmonic!r}: allowed a "
                                "Harmonic with order >= 1 and |amplitude| <= 0.001 m")

    @property
    def active(self) -> bool:
        """True when some shape or the table is not zero (else the film is a cylinder) [-]."""
        shapes = (self.crush_relief_depth, self.end_relief_depth, self.preload,
                  self.offset_halves, self.taper, self.crown,
                  *(h.amplitude for h in self.out_of_round))
        table = self.table is not None and bool(np.any(np.asarray(self.table.offsets)))
        table = table or (self.housing_bore is not None
                          and bool(np.any(np.asarray(self.housing_bore.offsets))))
        return table or any(value != 0.0 for value in shapes)

    @property
    def smooth_around(self) -> bool:
        """True when h₀ is smooth in θ (no crush relief, lobes, offset halves or a table
        varying in θ): the parabola through three nodes then locates h_min between them [-]."""
        table = self.table
        uniform = table is None or bool(np.all(np.ptp(np.asarray(table.offsets), axis=0) == 0))
        return (self.crush_relief_depth == 0.0 and self.preload == 0.0
                and self.offset_halves == 0.0 and uniform)

    def field(self, theta: np.ndarray, z: np.ndarray, clearance: float,
              width: float) -> np.ndarray:
        """h₀ at the nodes θ [rad] × z [m] of a bearing of radial clearance c and width L
        [m], shape (len θ, len z) [m] (module docstring)."""
        theta = np.asarray(theta, dtype=float)
        z = np.asarray(z, dtype=float)
        around = circumferential(self, theta, clearance)
        along = axial(self, z, width)
        out = around[:, None] + along[None, :]
        if self.table is not None:
            out = out + self.table.field(theta, z, width)
        if self.housing_bore is not None:
            out = out + self.housing_bore.field(theta, z, width)
        return out


def circumferential(profile: BoreProfile, theta: np.ndarray, clearance: float) -> np.ndarray:
    """The parts of h₀ that depend on θ alone [m] (module docstring)."""
    out = np.zeros_like(theta)
    if profile.crush_relief_depth > 0.0:
        for joint in profile.joint_angles:
            distance = np.abs((theta - joint + math.pi) % (2.0 * math.pi) - math.pi)
            out += profile.crush_relief_depth * np.maximum(
                0.0, 1.0 - distance / profile.crush_relief_extent)
    relative = theta - profile.lobe_angle
    if profile.preload > 0.0:
        lift = profile.preload * clearance / (1.0 - profile.preload)
        out += lift * (1.0 - np.abs(np.cos(relative)))
    if profile.offset_halves > 0.0:
        out += profile.offset_halves * (1.0 - np.sign(np.cos(relative)) * np.sin(relative))
    for harmonic in profile.out_of_round:
        out += harmonic.amplitude * np.cos(harmonic.order * (theta - harmonic.angle))
    return out


def axial(profile: BoreProfile, z: np.ndarray, width: float) -> np.ndarray:
    """The parts of h₀ that depend on z alone [m] (module docstring)."""
    out = np.zeros_like(z)
    if profile.end_relief_depth > 0.0:
        inside = 0.5 * width - np.abs(z)
        out += profile.end_relief_depth * np.maximum(
            0.0, 1.0 - inside / profile.end_relief_length)
    if profile.taper:
        out += profile.taper * z / width
    if profile.crown:
        out += profile.crown * (2.0 * z / width) ** 2
    return out


def profile_field(geometry, theta: np.ndarray, z: np.ndarray) -> np.ndarray | None:
    """h₀ of ``geometry.profile`` on the nodes θ × z [m], read-only; None without a profile
    or for one that is zero everywhere (the film then runs exactly as on a cylinder).
    CaseError when the profile closes the film of the centred journal."""
    profile = geometry.profile
    if profile is None:
        return None
    field = profile.field(theta, z, geometry.radial_clearance, geometry.width)
    if not np.any(field):
        return None
    c = geometry.radial_clearance
    smallest = float(field.min())
    if not c + smallest > SMALLEST_OPEN_GAP * c:
        i, j = np.unravel_index(int(np.argmin(field)), field.shape)
        raise CaseError(
            f"bearing profile{' (with the as-built housing bore)' if profile.housing_bore else ''}"
            f": offset {smallest:.3g} m at θ = {math.degrees(theta[i]):.1f} "
            f"deg, z = {z[j]:.4g} m leaves {c + smallest:.3g} m of the radial clearance "
            f"{c:.3g} m for a centred journal (allowed: offset > {-(1 - SMALLEST_OPEN_GAP):g}"
            " x radial_clearance)")
    if np.allclose(field, field[:, ::-1], rtol=0.0, atol=1e-12 * c):
        field = 0.5 * (field + field[:, ::-1])  # exactly even in z: the mid-plane symmetry
    field.setflags(write=False)
    return field


def refuse_profile(geometry, name: str) -> None:
    """CaseError when ``geometry`` carries a profile the film ``name`` cannot honour."""
    if geometry.profile is not None:
        raise CaseError(
            f"film = {name!r} cannot take a bore profile (bearing.profile / "
            "bearing.profile_file / housing.assembly; allowed: a grid film, 'reynolds' or "
            "'mass_conserving')")
