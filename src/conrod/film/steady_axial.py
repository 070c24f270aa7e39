"""Steady operating point of a bearing that is not a plain aligned cylinder: a bore/shell
profile (:mod:`conrod.film.profile`), a tilted journal (:mod:`conrod.film.tilt`) or a load in
a given direction.

Raimondi & Boyd's conditions (:mod:`conrod.film.steady`) put the load line anywhere because
a cylindrical bore is the same in every direction. A profiled bore is not, so the load is a
vector: W [N] at the angle α in the film frame (the direction in which it presses the
journal, θ measured from +x towards +y), and the journal centre e (two unknowns) solves

.. math:: F(e; γ) + W = 0

by a damped Newton iteration with the film's exact stiffness (the active-set linearisation,
:mod:`conrod.film.linearised`), the tilt γ held. The film is the finite-length Reynolds film
(Swift–Stieber cavitation at the geometry's cavitation pressure, the edges, grooves and holes
of the geometry at their pressures; no inlet line). The answer carries the moments of the
film on the journal and the 4 × 4 coefficient set of forces and moments by (e, γ).
"""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field

import numpy as np

from conrod.errors import CaseError, ConvergenceError, FilmThicknessError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.steady import DEFAULT_GRID

ITERATIONS = 60
"""Most Newton iterations of :func:`solve_for_load_vector` [-]."""
LARGEST_STEP = 0.2
"""Largest move of the journal centre per iteration, share of the clearance [-]."""


@dataclass(frozen=True)
class AxialOperatingPoint:
    """Steady answer for a load vector on a profiled bore or a tilted journal (SI units).

    eccentricity_x, eccentricity_y : float  Journal centre at mid-width [m].
    eccentricity : float  |e|/c [-].  load_angle_deg : float  α [deg].
    tilt_x, tilt_y : float  Held tilt γ [rad].
    min_film_thickness : float  h_min [m].  min_film_axial_position : float  Its z [m].
    edge_min_film_thickness : float  Smallest h on the edges z = ±L/2 [m].
    max_pressure : float  p_max [Pa].  moment_x, moment_y : float  Moments on the journal
    about the bearing centre [N m].  friction_power : float  [W].  side_flow : float
    [m^3/s].  coefficients : dict  K_xx … C_gygy of the 4 × 4 set (film frame; units in
    :mod:`conrod.film.linearised`).
    """

    eccentricity_x: float
    eccentricity_y: float
    eccentricity: float
    load_angle_deg: float
    tilt_x: float
    tilt_y: float
    min_film_thickness: float
    min_film_axial_position: float
    edge_min_film_thickness: float
    max_pressure: float
    moment_x: float
    moment_y: float
    friction_power: float
    side_flow: float
    model: str = "reynolds"
    coefficients: dict[str, float] = field(default_factory=dict)

    def as_dict(self) -> dict[str, float | str]:
        """Plain flat dictionary (JSON-ready), the coefficients at the top level."""
        values = asdict(self)
        coefficients = values.pop("coefficients")
        return {**values, **coefficients}


def solve_for_load_vector(load: float, load_angle: float, journal_speed: float,
                          viscosity: float, geometry: BearingGeometry, *,
                          tilt: tuple[float, float] = (0.0, 0.0),
                          grid: tuple[int, int] | None = None) -> AxialOperatingPoint:
    """The journal position and the film's characteristics under the load W [N] pressing at
    ``load_angle`` α [rad] (film frame), journal speed ω_j [rad/s], viscosity μ [Pa s], with
    the tilt (γ_x, γ_y) [rad] held (module docstring)."""
    for name, value in (("load", load), ("journal_speed", journal_speed),
                        ("viscosity", viscosity)):
        if not (math.isfinite(value) and value > 0.0):
            raise CaseError(f"{name} = {value!r}: out of range (allowed: finite, > 0)")
    n_theta, n_z = grid or DEFAULT_GRID
    film = ReynoldsFilm(geometry, n_theta=n_theta, n_z=n_z)
    c = geometry.radial_clearance
    target = -load * np.array([math.cos(load_angle), math.sin(load_angle)])  # F = −W

    def at(e: np.ndarray) -> FilmState:
        return FilmState(eccentricity_x=float(e[0]), eccentricity_y=float(e[1]),
                         journal_speed=journal_speed, viscosity=viscosity,
                         tilt_x=float(tilt[0]), tilt_y=float(tilt[1]))

    e = _newton(film, at, target, 0.5 * c * np.array([math.cos(load_angle),
                                                      math.sin(load_angle)]), load)
    state = at(e)
    result = film.solve(state)
    lin = film.sensitivities(state)
    return AxialOperatingPoint(
        eccentricity_x=float(e[0]), eccentricity_y=float(e[1]),
        eccentricity=float(np.hypot(*e)) / c, load_angle_deg=math.degrees(load_angle),
        tilt_x=float(tilt[0]), tilt_y=float(tilt[1]),
        min_film_thickness=result.min_film_thickness,
        min_film_axial_position=result.min_film_axial_position,
        edge_min_film_thickness=float(result.edge_min_film_thickness
                                      if result.edge_min_film_thickness is not None
                                      else result.min_film_thickness),
        max_pressure=result.max_pressure, moment_x=result.moment_x, moment_y=result.moment_y,
        friction_power=abs(result.friction_power), side_flow=result.side_flow,
        coefficients=lin.as_dict(tilt=True))


def _newton(film: ReynoldsFilm, at, target: np.ndarray, start: np.ndarray,
            load: float) -> np.ndarray:
    """e [m] with F(e) = ``target`` [N]: Newton with the exact stiffness, each step at most
    :data:`LARGEST_STEP` c, halved while the residual does not fall or the film closes."""
    c = film.geometry.radial_clearance
    e, residual = start, _residual(film, at, start, target)
    for _ in range(ITERATIONS):
        norm = float(np.linalg.norm(residual))
        if norm <= 1e-9 * load:
            return e
        stiffness = film.sensitivities(at(e)).stiffness  # K = −∂F/∂e
        step = np.linalg.solve(stiffness, residual)  # F + K⁻¹… : Δe = K⁻¹ (F − target)
        step *= min(1.0, LARGEST_STEP * c / float(np.linalg.norm(step)))
        for _ in range(30):
            trial = e + step
            trial_residual = _residual(film, at, trial, target)
            if trial_residual is not None and np.linalg.norm(trial_residual) < norm:
                e, residual = trial, trial_residual
                break
            step *= 0.5
        else:
            break
    raise ConvergenceError("steady load balance on the profiled or tilted bearing: no journal "
                           "position carries the load (try a smaller load or tilt)",
                           where=f"load {load:g} N",
                           residual=float(np.linalg.norm(residual)) / load)


def _residual(film: ReynoldsFilm, at, e: np.ndarray, target: np.ndarray):
    """F(e) − target [N], None where the film closes."""
    try:
        return np.array(film.force(at(e))) - target
    except (FilmThicknessError, CaseError):
        return None
