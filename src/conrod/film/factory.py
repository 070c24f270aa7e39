"""Build the film model named in ``[solver] film`` from the registry of model names
(:mod:`conrod.registry`): every model builds itself with ``from_settings``."""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.film.base import BearingGeometry, FilmModel, FilmResult, FilmState
from conrod.film.capabilities import CompiledKernel
from conrod.registry import film_class


def build_film_model(
    case_or_solver: Any, geometry: BearingGeometry, name: str | None = None
) -> FilmModel:
    """Film model for ``geometry`` from a :class:`Case` or its ``[solver]`` section.

    ``name`` overrides ``solver.film``. Grid models (reynolds, mass_conserving) take
    ``n_theta``, ``n_z`` and ``film_tolerance``; ``table`` tabulates a Reynolds film on that
    grid; ``mobility`` builds its map from a Reynolds film on that grid; ``short`` with a full
    central groove becomes :class:`GroovedShortBearingFilm`.
    """
    solver = getattr(case_or_solver, "solver", case_or_solver)
    return film_class(name or solver.film).from_settings(geometry, solver)


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
    def from_geometry(cls, geometry: BearingGeometry) -> GroovedShortBearingFilm:
        """Two-land film of ``geometry`` (with a full central groove)."""
        groove = central_groove_width(geometry)
        land_geometry = dataclasses.replace(
            geometry, width=0.5 * (geometry.width - groove), grooves=(), feed_holes=()
)
        from conrod.film.short_bearing import ShortBearingFilm

        return cls(geometry, ShortBearingFilm(land_geometry), groove)

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

    def compiled_kernel(self) -> CompiledKernel:
        """Twice the land's closed-form force; the orbit's generic compiled Newton loop."""
        from conrod.film.short_bearing import kernel_force, radial_damping

        g = self.land.geometry
        return CompiledKernel(kernel_force, (g.radius, g.width, g.radial_clearance, 2.0),
                              None, radial_damping)
