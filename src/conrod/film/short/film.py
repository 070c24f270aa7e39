"""Short-bearing film model (Ocvirk/Dubois, half-Sommerfeld) behind :class:`FilmModel`.

Forces come from the compiled closed form in :mod:`short_bearing_kernel`; the other
characteristics (friction, flow, h_min, p_max) from the same short-bearing pressure.

Friction uses Raimondi & Boyd's convention: Couette shear over the full 360° film
plus the pressure-gradient term, so that (R/c)·f = 2π²S/√(1−ε²) + ε sin φ/2.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numba as nb
import numpy as np

from conrod.film.base import BearingGeometry, FilmResult, FilmState, film_thickness
from conrod.film.capabilities import CompiledKernel, QuasiStaticRequest, refuse_deformation
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.profile import refuse_profile
from conrod.film.short.kernel import (
    ECCENTRICITY_LIMIT,
    short_bearing_force,
    short_bearing_polar,
)


@nb.njit(cache=True)
def kernel_force(x, y, vx, vy, omega_sum, viscosity, params):
    """:func:`short_bearing_force` [N] in the calling convention of
    :class:`~conrod.film.capabilities.CompiledKernel`; params = (R [m], L [m], c [m],
    force factor [-])."""
    fx, fy = short_bearing_force(x, y, vx, vy, omega_sum, viscosity, params[0], params[1],
                                 params[2])
    return params[3] * fx, params[3] * fy


@nb.njit(cache=True)
def radial_damping(eps, viscosity, params):
    """Radial squeeze damping of the short bearing B_rr = π μ R L³ (1 + 2ε²) /
    (2 c³ (1 − ε²)^{5/2}) [N s/m] times the force factor (Hamrock, Fundamentals of Fluid
    Film Lubrication, ch. 10); params as :func:`kernel_force`."""
    radius, width, clearance = params[0], params[1], params[2]
    eps = min(eps, 0.999999)
    return params[3] * (math.pi * viscosity * radius * width**3 * (1.0 + 2.0 * eps * eps)
                        / (2.0 * clearance**3 * (1.0 - eps * eps) ** 2.5))


def start_angle(vx: float, vy: float, x: float, y: float, load_x: float, load_y: float,
                omega_sum: float) -> float:
    """Guess of the active-arc angle α + ψ = β + π/2 [rad] from the squeeze velocity
    v_s = ė − ω̄ × e of a state, or from the load when the state is at rest."""
    mean = 0.5 * omega_sum
    sx, sy = vx + mean * y, vy - mean * x
    if sx or sy:
        return math.atan2(sy, sx) + 0.5 * math.pi
    return math.atan2(load_y, load_x) + 0.5 * math.pi


@dataclass
class ShortBearingFilm:
    """Closed-form short-bearing film.

    geometry : BearingGeometry  Bearing geometry (supply features are ignored: the
        short-bearing theory has ambient pressure on both edges only).
    n_theta, n_z : int  Grid of the pressure field returned on request [-].
    pressure_viscosity : PressureViscosity or None  μ(p) law: the closed form holds for
        the reduced pressure, forces by quadrature (:mod:`conrod.film.short.piezoviscous`).
    """

    geometry: BearingGeometry
    n_theta: int = 144
    n_z: int = 17
    pressure_viscosity: PressureViscosity | None = None
    name: str = "short"

    def __post_init__(self) -> None:
        """The closed form is for a cylindrical bore: a profile is refused."""
        refuse_profile(self.geometry, self.name)

    @classmethod
    def from_settings(cls, geometry: BearingGeometry, settings: Any) -> Any:
        """Short film of ``geometry``; two lands when a full central groove splits it
        (:class:`GroovedShortBearingFilm`). ``settings``: ``[solver]``."""
        if central_groove_width(geometry) > 0.0:
            return GroovedShortBearingFilm.from_geometry(geometry)
        return cls(geometry)

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """θ nodes [rad] (periodic, no duplicate of 2π) and z nodes [m]."""
        theta = np.linspace(0.0, 2.0 * math.pi, self.n_theta, endpoint=False)
        half = 0.5 * self.geometry.width
        return theta, np.linspace(-half, half, self.n_z)

    def initial_history(self) -> None:
        """The short-bearing film has no memory."""
        return None

    def compiled_kernel(self) -> CompiledKernel | None:
        """Closed-form force, Booker's exact massless inversion, radial damping; None with
        a pressure-dependent viscosity (the compiled closed form is isoviscous)."""
        if self.pressure_viscosity is not None:
            return None
        g = self.geometry
        params = (g.radius, g.width, g.radial_clearance, 1.0)
        return CompiledKernel(kernel_force, params, self._quasi_static_cycle, radial_damping)

    def _quasi_static_cycle(self, r: QuasiStaticRequest) -> Any:
        from conrod.film.short.velocity import short_bearing_cycle

        g = self.geometry
        alpha = start_angle(r.vx, r.vy, r.x, r.y, r.load_x[0], r.load_y[0],
                            r.journal_speed[0] + r.shell_speed[0])
        return short_bearing_cycle(
            r.x, r.y, alpha, r.dt, r.load_x, r.load_y, r.journal_speed, r.shell_speed,
            r.record_every, r.viscosity, g.radius, g.width, g.radial_clearance,
            r.contact_radius)

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]; refuses a deformation field."""
        refuse_deformation(state, self.name)
        g = self.geometry
        if self.pressure_viscosity is not None:
            return self._piezoviscous(state)[0]
        return short_bearing_force(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed + state.shell_speed, state.viscosity,
            g.radius, g.width, g.radial_clearance,
)

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """All film characteristics for one state; refuses a deformation field."""
        refuse_deformation(state, self.name)
        g = self.geometry
        c = g.radial_clearance
        ex, ey = state.eccentricity_x, state.eccentricity_y
        e = math.hypot(ex, ey)
        psi = math.atan2(ey, ex) if e > 0.0 else 0.0
        eps = min(e / c, ECCENTRICITY_LIMIT)
        e_rate = (ex * state.velocity_x + ey * state.velocity_y) / e if e > 0 else 0.0
        whirl = (ex * state.velocity_y - ey * state.velocity_x) / (e * e) if e > 0 else 0.0
        omega_sum = state.journal_speed + state.shell_speed
        _, f_t, alpha, speed = short_bearing_polar(
            eps, e_rate / c, whirl, omega_sum, state.viscosity, g.radius, g.width, c
)
        fx, fy = self.force(state)
        extra: dict[str, float] = {}
        if self.pressure_viscosity is not None:
            (fx, fy), f_t, extra = self._piezoviscous(state)
        torque_j, torque_b = self._friction_torques(state, eps, f_t * eps * c)
        couette_excess = self._couette_excess(state, eps, alpha, speed)
        torque_j, torque_b = torque_j - couette_excess, torque_b + couette_excess
        p_peak, p_angle = self._peak_pressure(state, eps, alpha, speed, psi)
        side_flow = g.width * g.radius * c * speed
        sliding = state.journal_speed - state.shell_speed
        result = FilmResult(
            force_x=fx, force_y=fy,
            friction_torque_journal=torque_j, friction_torque_shell=torque_b,
            side_flow=side_flow, supply_flow=0.0,
            min_film_thickness=c * (1.0 - eps), min_film_angle=psi % (2.0 * math.pi),
            max_pressure=p_peak, max_pressure_angle=p_angle,
            cavitated_fraction=0.5 if speed > 0.0 else 0.0,
            friction_power=abs(torque_j * sliding) if sliding else 0.0, extra=extra,
        )
        if with_pressure:
            result.pressure = self.pressure_field(state)
        return result

    # ------------------------------------------------- piezoviscous hooks (q ↔ p)
    def _piezoviscous(self, state: FilmState) -> tuple[tuple[float, float], float, dict]:
        """((F_x, F_y) [N], F_t [N], diagnostics) with pressure-dependent viscosity."""
        from conrod.film.short.piezoviscous import piezoviscous_polar

        g, c = self.geometry, self.geometry.radial_clearance
        ex, ey = state.eccentricity_x, state.eccentricity_y
        e = math.hypot(ex, ey)
        if e > 1.0e-12 * c:
            cos_psi, sin_psi = ex / e, ey / e
            e_rate = (ex * state.velocity_x + ey * state.velocity_y) / e
            whirl = (ex * state.velocity_y - ey * state.velocity_x) / (e * e)
        else:
            v = math.hypot(state.velocity_x, state.velocity_y)
            if v == 0.0:
                return (0.0, 0.0), 0.0, {}
            cos_psi, sin_psi, e_rate, whirl = state.velocity_x / v, state.velocity_y / v, v, 0.0
        f_r, f_t, _, _, extra = piezoviscous_polar(
            e / c, e_rate / c, whirl, state.journal_speed + state.shell_speed,
            state.viscosity, g.radius, g.width, c, self.pressure_viscosity)
        force = (f_r * cos_psi - f_t * sin_psi, f_r * sin_psi + f_t * cos_psi)
        return force, f_t, extra

    def _couette_excess(self, state: FilmState, eps: float, alpha: float,
                        speed: float) -> float:
        """Extra Couette moment of μ(p) − μ₀ on the active arc [N m] (0 when isoviscous)."""
        if self.pressure_viscosity is None:
            return 0.0
        from conrod.film.short.piezoviscous import piezoviscous_couette_excess

        g = self.geometry
        return piezoviscous_couette_excess(
            eps, alpha, speed, state.viscosity, g.radius, g.width, g.radial_clearance,
            state.journal_speed - state.shell_speed, self.pressure_viscosity)

    def _friction_torques(
        self, state: FilmState, eps: float, e_times_ft: float
) -> tuple[float, float]:
        """Shear moments on journal and shell [N m] (full-film Couette + Poiseuille term)."""
        g = self.geometry
        couette = (
            state.viscosity * g.radius**3 * g.width * (state.journal_speed - state.shell_speed)
            * 2.0 * math.pi / (g.radial_clearance * math.sqrt(1.0 - eps * eps))
)
        poiseuille = 0.5 * e_times_ft
        return -couette - poiseuille, couette - poiseuille

    def _peak_pressure(
        self, state: FilmState, eps: float, alpha: float, speed: float, psi: float
) -> tuple[float, float]:
        """Maximum mid-plane pressure [Pa] and its shell angle [rad] (sampled + refined)."""
        if speed == 0.0:
            return 0.0, 0.0
        g = self.geometry
        theta_rel = alpha + math.pi + PEAK_SAMPLES
        shape = -np.sin(theta_rel - alpha) / (1.0 - eps * np.cos(theta_rel)) ** 3
        k = int(np.argmax(shape))
        scale = 3.0 * state.viscosity * speed * g.width**2 / (4.0 * g.radial_clearance**2)
        peak = float(scale * shape[k])
        if self.pressure_viscosity is not None:
            peak = float(self.pressure_viscosity.from_reduced(peak, state.viscosity))
        return peak, float((theta_rel[k] + psi) % (2.0 * math.pi))

    def pressure_field(self, state: FilmState) -> np.ndarray:
        """Short-bearing pressure p(θ, z) [Pa] on :meth:`grid`, cavitated part at 0."""
        g = self.geometry
        theta, z = self.grid()
        h = film_thickness(g, state.eccentricity_x, state.eccentricity_y, theta)
        dh_dtheta = state.eccentricity_x * np.sin(theta) - state.eccentricity_y * np.cos(theta)
        dh_dt = -state.velocity_x * np.cos(theta) - state.velocity_y * np.sin(theta)
        omega_sum = state.journal_speed + state.shell_speed
        source = 6.0 * state.viscosity * (omega_sum * dh_dtheta + 2.0 * dh_dt)
        profile = 0.25 * g.width**2 - z**2
        pressure = np.maximum(-source[:, None] * profile[None, :] / (2.0 * h[:, None] ** 3), 0.0)
        if self.pressure_viscosity is not None:
            pressure = self.pressure_viscosity.from_reduced(pressure, state.viscosity)
        return pressure


PEAK_SAMPLES = np.linspace(0.0, math.pi, 721)
"""Angles past the start of the pressure arc where the peak pressure is sampled [rad]."""


def central_groove_width(geometry: BearingGeometry) -> float:
    """Width [m] of a single full circumferential groove at mid-width, 0 if there is none."""
    grooves = geometry.grooves
    if len(grooves) != 1 or geometry.feed_holes:
        return 0.0
    groove = grooves[0]
    full = groove.extent >= 2.0 * math.pi - 1e-9 and abs(groove.axial_position) < 1e-12
    return groove.width if full else 0.0


@dataclass
class GroovedShortBearingFilm:
    """Short-bearing theory on the two lands beside a full central circumferential groove.

    Each land of width L_l = (L − g)/2 carries the Ocvirk film with ambient (gauge supply)
    pressure at both of its edges, so forces and torques are twice those of one land; half
    of each land's leakage leaves at its outer edge (side flow) and half at the groove edge:
    the supply flow, positive into the film as in :class:`FilmResult`, is minus that.
    """

    geometry: BearingGeometry
    land: Any
    groove_width: float
    name: str = "short"

    @classmethod
    def from_geometry(cls, geometry: BearingGeometry,
                      pressure_viscosity: Any = None) -> GroovedShortBearingFilm:
        """Two-land film of ``geometry`` (with a full central groove)."""
        groove = central_groove_width(geometry)
        land_geometry = dataclasses.replace(
            geometry, width=0.5 * (geometry.width - groove), grooves=(), feed_holes=()
        )
        land = ShortBearingFilm(land_geometry, pressure_viscosity=pressure_viscosity)
        return cls(geometry, land, groove)

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]: both lands."""
        fx, fy = self.land.force(state)
        return 2.0 * fx, 2.0 * fy

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Both lands' characteristics (pressure field over the full width on request)."""
        r = self.land.solve(state, with_pressure=with_pressure)
        leakage = r.side_flow  # two lands x (half of one land's edge flow) each side
        result = dataclasses.replace(
            r, force_x=2.0 * r.force_x, force_y=2.0 * r.force_y,
            friction_torque_journal=2.0 * r.friction_torque_journal,
            friction_torque_shell=2.0 * r.friction_torque_shell,
            friction_power=2.0 * r.friction_power, side_flow=leakage, supply_flow=-leakage,
)
        if with_pressure and r.pressure is not None:
            result.pressure = np.concatenate([r.pressure, r.pressure], axis=1)
        return result

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """θ nodes [rad]; z nodes of both lands [m] (the groove lies between them)."""
        theta, z_land = self.land.grid()
        offset = 0.5 * (self.groove_width + self.land.geometry.width)
        return theta, np.concatenate([z_land - offset, z_land + offset])

    def initial_history(self) -> None:
        """No memory."""
        return None

    def compiled_kernel(self) -> CompiledKernel | None:
        """Twice the land's closed-form force; the land's exact massless inversion (None
        when the lands have a pressure-dependent viscosity)."""
        if self.land.pressure_viscosity is not None:
            return None
        g = self.land.geometry
        return CompiledKernel(kernel_force, (g.radius, g.width, g.radial_clearance, 2.0),
                              self._quasi_static_cycle, radial_damping)

    def _quasi_static_cycle(self, r: QuasiStaticRequest) -> Any:
        """Booker's inversion of one land at twice the viscosity: the force of two equal
        lands, 2 F_land(μ) = F_land(2μ), is linear in μ."""
        return self.land._quasi_static_cycle(dataclasses.replace(r, viscosity=2.0 * r.viscosity))
