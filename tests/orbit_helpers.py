"""Small orbit problems shared by the orbit tests (not a test module)."""

from __future__ import annotations

import math

import numpy as np

from conrod.cases.solver import SolverSection
from conrod.film.base import BearingGeometry
from conrod.film.short_bearing import ShortBearingFilm
from conrod.loads.cycle import LoadCycle
from conrod.orbit import OrbitProblem

SPEED = 2000.0 * 2.0 * math.pi / 60.0
"""Crank = journal speed of the test problems [rad/s]."""


def geometry(width: float = 0.025, diameter: float = 0.05, clearance: float = 25e-6):
    """Automotive-size bearing [m]."""
    return BearingGeometry(diameter=diameter, width=width, radial_clearance=clearance)


def load_cycle(load_x, load_y, *, cycle=4 * math.pi, journal=SPEED, shell=0.0, n=144):
    """LoadCycle from callables of the crank angle [rad] → load [N]."""
    phi = np.linspace(0.0, cycle, n, endpoint=False)
    return LoadCycle(
        phi, load_x(phi) * np.ones(n), load_y(phi) * np.ones(n),
        np.full(n, journal), np.full(n, shell), SPEED, cycle,
    )


def short_problem(loads, *, viscosity=0.01, mass=1.0, film=None, contact_film_thickness=0.0,
                  dry_friction=0.1, **geometry_kwargs):
    """Orbit problem with the short-bearing film (or ``film``)."""
    film = film or ShortBearingFilm(geometry(**geometry_kwargs))
    return OrbitProblem(film, loads, viscosity, mass, mass, dry_friction, contact_film_thickness)


def solver(**kwargs) -> SolverSection:
    """``[solver]`` section with overrides."""
    return SolverSection(**kwargs)


def engine_like_load(peak: float = 2.0e4, base: float = 2.0e3):
    """A firing-like load: rotating inertia part plus a combustion pulse near φ = 0 [N]."""

    def load_x(phi):
        pulse = peak * np.exp(-(((phi + math.pi) % (4 * math.pi) - math.pi) / 0.35) ** 2)
        return pulse - base * np.cos(phi)

    def load_y(phi):
        return base * np.sin(phi)

    return load_x, load_y
