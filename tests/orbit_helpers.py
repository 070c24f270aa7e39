"""Small orbit problems shared by the orbit tests (not a test module)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.solver import SolverSection
from conrod.film.base import BearingGeometry
from conrod.film.short.film import ShortBearingFilm
from conrod.loads.cycle import LoadCycle
from conrod.orbit import OrbitProblem
from conrod.orbit.characteristics import cycle_characteristics

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


def fed_bearing_problem(bearing: dict, model, viscosity: float) -> OrbitProblem:
    """A random-plausible fed big end (``bearing``: bore, width_ratio, rpm, clearance,
    supply, unit_load in SI units): central groove fed at the supply pressure, a four-stroke
    load (firing pulse on a rotating inertia load), film ``model`` on a 36×8 grid."""
    from conrod.film.base import Groove

    width = bearing["width_ratio"] * bearing["bore"]
    fed = BearingGeometry(diameter=bearing["bore"], width=width,
                          radial_clearance=bearing["clearance"],
                          grooves=(Groove(width=0.1 * width),),
                          supply_pressure=bearing["supply"])
    omega = bearing["rpm"] * math.pi / 30.0
    phi = np.linspace(0.0, 4 * math.pi, 144, endpoint=False)
    peak = bearing["unit_load"] * bearing["bore"] * width
    firing = np.exp(-(((phi + math.pi) % (4 * math.pi) - math.pi) / 0.3) ** 2)
    loads = LoadCycle(phi, peak * firing - 0.3 * peak * np.cos(phi),
                      -0.12 * peak * np.sin(phi), np.full(144, omega), np.zeros(144), omega,
                      4 * math.pi)
    return OrbitProblem(model(fed, n_theta=36, n_z=8, tolerance=1e-10), loads, viscosity,
                        1.0, 1.0, 0.1, 0.05 * bearing["clearance"])


def assert_settles_at_steady_point(orbit, film, load: float, most_cycles: int = 3) -> None:
    """The orbit under a constant load ``load`` [N] along −x ended at the static equilibrium
    F(e, 0) + W = 0 of ``film`` (scipy fsolve on (ε, attitude)): ε and attitude within
    0.5 %, periodic after at most ``most_cycles`` cycles."""
    from scipy.optimize import fsolve

    from conrod.film.base import FilmState

    c = film.geometry.radial_clearance

    def balance(polar):
        eps, angle = polar
        fx, fy = film.force(FilmState(eccentricity_x=eps * c * math.cos(angle),
                                      eccentricity_y=eps * c * math.sin(angle),
                                      velocity_x=0.0, velocity_y=0.0, journal_speed=SPEED,
                                      shell_speed=0.0, viscosity=0.01))
        return [(fx + load) / load, fy / load]

    eps_ref, angle_ref = fsolve(balance, [0.5, 1.0], xtol=1e-12)
    eps = math.hypot(orbit.last.x[-1], orbit.last.y[-1]) / c
    angle = math.atan2(orbit.last.y[-1], orbit.last.x[-1])
    print(f"orbit eps {eps:.5f} angle {angle:.5f}; equilibrium {eps_ref:.5f} "
          f"{angle_ref:.5f}; cycles {orbit.cycles}")
    assert orbit.periodic and orbit.cycles <= most_cycles
    assert eps == pytest.approx(eps_ref, rel=5e-3)
    assert angle == pytest.approx(angle_ref, rel=5e-3)


def assert_same_periodic_orbit(problem, settings, plain, shot) -> None:
    """Two periodic orbits of ``problem`` agree: both periodic, ``shot``'s error within the
    tolerance of ``settings``; max |Δe|/c ≤ tolerance; h_min within tolerance × c; p_max
    1 %."""
    tolerance = settings.periodicity_tolerance
    assert plain.periodic and shot.periodic
    assert shot.periodicity_error <= tolerance
    gap = np.max(np.hypot(shot.last.x - plain.last.x, shot.last.y - plain.last.y))
    assert gap <= tolerance * problem.clearance
    a = cycle_characteristics(problem, plain.last)
    b = cycle_characteristics(problem, shot.last)
    assert abs(float(np.min(a.h_min)) - float(np.min(b.h_min))) <= tolerance * problem.clearance
    assert float(np.max(b.p_max)) == pytest.approx(float(np.max(a.p_max)), rel=0.01)
