"""Short-bearing film model (Ocvirk/Dubois, half-Sommerfeld) behind :class:`FilmModel`.

Forces come from the compiled closed form in :mod:`short_bearing_kernel`; the other
characteristics (friction, flow, h_min, p_max) from the same short-bearing pressure.

Friction uses Raimondi & Boyd's convention: Couette shear over the full 360° film
plus the pressure-gradient term, so that (R/c)·f = 2π²S/√(1−ε²) + ε sin φ/2.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.film.base import BearingGeometry, FilmResult, FilmState, film_thickness
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.short_bearing_kernel import (
    ECCENTRICITY_LIMIT,
    short_bearing_force,
    short_bearing_polar,
)


@dataclass
class ShortBearingFilm:
    """Closed-form short-bearing film.

    geometry : BearingGeometry  Bearing geometry (supply features are ignored: the
        short-bearing theory has ambient pressure on both edges only).
    n_theta, n_z : int  Grid of the pressure field returned on request [-].
    pressure_viscosity : PressureViscosity or None  μ(p) law: the closed form holds for
        the reduced pressure, forces by quadrature (:mod:`conrod.film.short_piezoviscous`).
    """

    geometry: BearingGeometry
    n_theta: int = 144
    n_z: int = 17
    pressure_viscosity: PressureViscosity | None = None
    name: str = "short"

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """θ nodes [rad] (periodic, no duplicate of 2π) and z nodes [m]."""
        theta = np.linspace(0.0, 2.0 * math.pi, self.n_theta, endpoint=False)
        half = 0.5 * self.geometry.width
        return theta, np.linspace(-half, half, self.n_z)

    def initial_history(self) -> None:
        """The short-bearing film has no memory."""
        return None

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]."""
        g = self.geometry
        if self.pressure_viscosity is not None:
            return self._piezoviscous(state)[0]
        return short_bearing_force(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed + state.shell_speed, state.viscosity,
            g.radius, g.width, g.radial_clearance,
        )

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """All film characteristics for one state."""
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
        from conrod.film.short_piezoviscous import piezoviscous_polar

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
        from conrod.film.short_piezoviscous import piezoviscous_couette_excess

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
        theta_rel = alpha + math.pi + np.linspace(0.0, math.pi, 721)
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
