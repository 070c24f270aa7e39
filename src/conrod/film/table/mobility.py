"""Booker's mobility method with a numerically computed mobility map.

Normalisation (derived from :mod:`conrod.film.table.kernel`)
------------------------------------------------------------
In the frame turning at ω̄ = (ω_j + ω_b)/2 the film is a pure squeeze film, so a journal
carrying the load W (F_film = −W, quasi-static, massless) moves with

.. math:: \\dot{\\mathbf e} = \\frac{c^3 |W|}{μ R^3 L} \\mathbf M(ε, χ)
          + \\bar ω \\times \\mathbf e,

where **M** is the dimensionless mobility vector, here M = v_s μR³L/(c³|W|): its magnitude
|M| = 1/|f̄(ε, β)| and its direction β (from the line of centres) solve
φ(ε, β) = χ, with χ the angle of the film force −W from the line of centres and f̄ the
dimensionless squeeze force of the table. Booker's own scaling [1] uses (c/R)² and L/D
differently; only the product above matters. A load turning at ω̄ with a steady
eccentricity gives ė = 0 — the half-speed whirl with no film capacity (a known pitfall).

The map f̄(ε, β) comes from any base film model (default: the finite-difference
:class:`~conrod.film.reynolds.film.ReynoldsFilm`) through
:class:`~conrod.film.table.film.TabulatedFilm` (disk-cached).
``MobilityFilm.short_bearing(geometry)`` uses the closed-form short-bearing squeeze force
instead — Booker's classical short-bearing mobility — for comparison.

[1] J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution",
    J. Basic Eng. 87 (1965) 537–546.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmModel, FilmResult, FilmState
from conrod.film.capabilities import CompiledKernel
from conrod.film.table.film import TabulatedFilm
from conrod.film.table.kernel import inverse_direction, mobility_velocity, unit_force


@dataclass
class MobilityFilm:
    """Mobility-method film: quasi-static journal velocity from the load, and forces.

    geometry : BearingGeometry  Bearing (rotation-invariant, see :func:`check_tabulable`).
    n_theta, n_z : int  Grid of the default Reynolds base model [-].
    n_eps, n_direction : int  Mobility-map nodes in ε and squeeze direction [-].
    eccentricity_max : float  Largest tabulated eccentricity ratio [-].
    base : FilmModel or None  Model the map is computed from (None: ReynoldsFilm).
    cache_dir : path or None  Disk cache of the map (None: ``~/.cache/conrod/tables``).
    """

    geometry: BearingGeometry
    n_theta: int = 72
    n_z: int = 16
    n_eps: int = 28
    n_direction: int = 48
    eccentricity_max: float = 0.995
    base: FilmModel | None = None
    cache_dir: str | Path | None = None
    use_cache: bool = True
    name: str = "mobility"
    table: TabulatedFilm = field(init=False, repr=False)

    def __post_init__(self) -> None:
        from conrod.film.table.film import check_tabulable

        if not isinstance(self.geometry, BearingGeometry):
            raise CaseError(f"MobilityFilm: geometry = {type(self.geometry).__name__}: a "
                            "conrod.BearingGeometry is required")
        check_tabulable(self.geometry, self.name)
        if self.base is None:
            from conrod.film.reynolds.film import ReynoldsFilm

            self.base = ReynoldsFilm(self.geometry, n_theta=self.n_theta, n_z=self.n_z)
        self.table = TabulatedFilm(
            self.base, n_eps=self.n_eps, n_direction=self.n_direction,
            eccentricity_max=self.eccentricity_max, cache_dir=self.cache_dir,
            use_cache=self.use_cache,
)

    @classmethod
    def from_settings(cls, geometry: BearingGeometry, settings: Any) -> MobilityFilm:
        """Map of a Reynolds film on the ``[solver]`` grid ``n_theta`` × ``n_z``."""
        return cls(geometry, n_theta=int(settings.n_theta), n_z=int(settings.n_z))

    @classmethod
    def short_bearing(cls, geometry: BearingGeometry, **kwargs: Any) -> MobilityFilm:
        """Booker's short-bearing mobility (closed-form squeeze force, densely tabulated)."""
        from conrod.film.short.film import ShortBearingFilm

        options = {"n_eps": 48, "n_direction": 96, "use_cache": False} | kwargs
        return cls(geometry, base=ShortBearingFilm(geometry), **options)

    # ------------------------------------------------------------- interface
    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """Grid of the base model [rad], [m]."""
        return self.table.grid()

    def initial_history(self) -> None:
        """Memoryless."""
        return None

    def compiled_kernel(self) -> CompiledKernel:
        """The map's compiled force and exact massless inverse (those of its table)."""
        return self.table.compiled_kernel()

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N] from the mobility map (forward use)."""
        return self.table.force(state)

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Interpolated characteristics (see :meth:`TabulatedFilm.solve`)."""
        return self.table.solve(state, with_pressure=with_pressure)

    # ------------------------------------------------------------ mobility
    def mobility(self, eccentricity_ratio: float, load_angle: float) -> tuple[float, float]:
        """Mobility vector (|M| [-], direction β from the line of centres [rad]).

        load_angle : angle χ of the film force (−W) from the line of centres [rad].
        """
        t = self.table
        beta = inverse_direction(eccentricity_ratio, load_angle, t.s_step, t.tables["turning"])
        f_r, f_t = unit_force(eccentricity_ratio, beta, t.s_step,
                              t.tables["log_magnitude"], t.tables["turning"])
        return 1.0 / math.hypot(f_r, f_t), beta

    def journal_velocity(
        self, ex: float, ey: float, load_x: float, load_y: float,
        journal_speed: float, shell_speed: float, viscosity: float,
) -> tuple[float, float]:
        """Quasi-static journal-centre velocity (v_x, v_y) [m/s] for the external load W [N]
        pressing the journal at position (e_x, e_y) [m]; speeds [rad/s], viscosity [Pa s]."""
        t = self.table
        return mobility_velocity(
            ex, ey, load_x, load_y, journal_speed + shell_speed, viscosity, t.force_scale,
            self.geometry.radial_clearance, t.s_step, t.tables["log_magnitude"],
            t.tables["turning"],
)
