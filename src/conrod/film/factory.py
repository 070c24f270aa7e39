"""Build the film model named in ``[solver] film`` from the registry of model names
(:mod:`conrod.registry`): every model builds itself with ``from_settings``."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel, FilmResult, FilmState
from conrod.film.capabilities import CompiledKernel
from conrod.registry import film_class


def build_film_model(
    case_or_solver: Any, geometry: BearingGeometry, name: str | None = None,
    pressure_viscosity: Any = None,
) -> FilmModel:
    """Film model for ``geometry`` from a :class:`Case` or its ``[solver]`` section.

    ``name`` overrides ``solver.film``. Grid models (reynolds, mass_conserving) take
    ``n_theta``, ``n_z`` and ``film_tolerance``; ``table`` tabulates a Reynolds film on that
    grid; ``mobility`` builds its map from a Reynolds film on that grid; ``short`` with a full
    central groove becomes :class:`GroovedShortBearingFilm`. ``pressure_viscosity``
    (a :class:`~conrod.film.piezoviscosity.PressureViscosity`, default: the case's
    ``[lubricant]`` law) goes to the short and grid films; the map films refuse it.
    """
    solver = getattr(case_or_solver, "solver", case_or_solver)
    film_name = name or solver.film
    law = pressure_viscosity or _case_pressure_viscosity(case_or_solver)
    if law is None:
        return film_class(film_name).from_settings(geometry, solver)
    if film_name in ("table", "mobility"):
        raise CaseError(
            f"solver.film = {film_name!r}: cannot be combined with lubricant.pressure_viscosity "
            f"= {law.law!r} (its maps assume force ∝ μω); use film = 'short', 'reynolds' or "
            "'mass_conserving', or pressure_viscosity = 'none'")
    if film_name == "short" and central_groove_width(geometry) > 0.0:
        return GroovedShortBearingFilm.from_geometry(geometry, law)
    film = film_class(film_name).from_settings(geometry, solver)
    return dataclasses.replace(film, pressure_viscosity=law)


def _case_pressure_viscosity(case_or_solver: Any) -> Any:
    """The case's pressure–viscosity law (None when isoviscous or given a bare solver)."""
    lubricant = getattr(case_or_solver, "lubricant", None)
    return None if lubricant is None else lubricant.pressure_viscosity_law()


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
    of the leakage leaves at the outer edges (side flow) and half enters from the groove
    (supply flow, with the sign convention 'into the film' of :class:`FilmResult`).
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
        land = film_class("short")(land_geometry, pressure_viscosity=pressure_viscosity)
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
            friction_power=2.0 * r.friction_power, side_flow=leakage, supply_flow=leakage,
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
        """Twice the land's closed-form force; the orbit's generic compiled Newton loop
        (None when the lands have a pressure-dependent viscosity)."""
        from conrod.film.short_bearing import kernel_force, radial_damping

        if self.land.pressure_viscosity is not None:
            return None
        g = self.land.geometry
        return CompiledKernel(kernel_force, (g.radius, g.width, g.radial_clearance, 2.0),
                              None, radial_damping)
