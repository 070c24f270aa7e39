"""Steady-state journal-bearing calculator under Raimondi & Boyd's conditions.

Raimondi & Boyd's full journal bearing [1]: rigid, aligned, isoviscous, journal
rotating at N [rev/s], shell fixed, Swift–Stieber (Reynolds) cavitation at gauge 0,
ambient (gauge 0) pressure on both edges and on an axial **inlet line at the largest
gap** θ = ψ + π, friction with Couette shear over the full 360°.

Dimensionless groups (Raimondi–Boyd school):

* Sommerfeld number S = (R/c)² μN/P, P = W/(2RL) = W/(DL) [-],
* friction variable (R/c)f, f = |M_j|/(R W) [-],
* flow variable Q/(RcNL), Q = circumferential inflow just downstream of the inlet line,
  side-flow ratio Q_s/Q, Q_s = leakage through both edges [-],
* load-to-peak-pressure ratio P/p_max [-],
* peak-pressure angle: from p_max forward to the minimum film (θ_pmax of [1]) [deg],
* film-end angle: from the minimum film forward to the film rupture at the
  mid-plane (θ_p0 of [1]) [deg],
* the eight linearised coefficients K_ij = −∂F_i/∂e_j, C_ij = −∂F_i/∂ė_j in the load
  frame (x along the load, y 90° ahead in the direction of rotation), dimensionless
  K̄ = Kc/W, C̄ = Ccω/W, and in N/m, N s/m in the dimensional mode
  (:mod:`conrod.film.linearised`; the inlet line is held fixed while the journal moves).

Butenschön's So = 1/(2πS) and W̄ = Wc²/(μωR³L) = 1/(πS) are the other schools' numbers.

[1] A.A. Raimondi, J. Boyd, ASLE Trans. 1 (1958) 159–209.
"""

from __future__ import annotations

import importlib
import math
from dataclasses import asdict, dataclass, field, replace
from typing import Literal

import numpy as np
from scipy.optimize import brentq

from conrod.errors import CaseError, ConvergenceError
from conrod.film import characteristics as chars
from conrod.film.base import BearingGeometry, FilmResult, FilmState, Groove, film_thickness
from conrod.film.linearised import linearise
from conrod.film.reynolds.film import FrictionConvention, ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm

SteadyModel = Literal["reynolds", "mass_conserving", "short"]
DEFAULT_GRID = (144, 32)
"""Default (n_theta, n_z) intervals of the steady calculator for ε ≤ 0.9 [-]."""
FINE_GRID = (288, 64)
"""Default grid for ε > 0.9, where the film near h_min needs finer nodes [-]."""


def default_grid(eccentricity: float) -> tuple[int, int]:
    """Grid whose S, (R/c)f, φ, Q are within 0.5 % of the grid-converged values [-]."""
    return DEFAULT_GRID if eccentricity <= 0.9 else FINE_GRID


@dataclass(frozen=True)
class SteadyPoint:
    """Raimondi–Boyd characteristics of one steady operating point (all [-] or [deg])."""

    length_to_diameter: float
    eccentricity: float
    sommerfeld_number: float
    attitude_angle_deg: float
    friction_variable: float
    flow_variable: float
    side_flow_ratio: float
    load_to_peak_pressure_ratio: float
    peak_pressure_angle_deg: float
    film_end_angle_deg: float
    model: str
    friction_convention: str
    coefficients: dict[str, float] = field(default_factory=dict)
    """K_bar_xx … C_bar_yy in the load frame [-] (:mod:`conrod.film.linearised`)."""

    def as_dict(self) -> dict[str, float | str]:
        """Plain flat dictionary (JSON-ready)."""
        return _flat(asdict(self))


def _flat(values: dict) -> dict[str, float | str]:
    """Dictionary with the ``coefficients`` entries moved to the top level."""
    coefficients = values.pop("coefficients", {})
    return {**values, **coefficients}


def load_frame_coefficients(film, state: FilmState, dimensional: bool) -> dict[str, float]:
    """K̄, C̄ [-] (and K [N/m], C [N s/m] when ``dimensional``) in the load frame."""
    values = linearise(film, state).in_load_frame().as_dict()
    if dimensional:
        return values
    return {key: value for key, value in values.items() if "_bar_" in key}


def _unit_geometry(length_to_diameter: float) -> BearingGeometry:
    """Any consistent bearing: R = 1 m, c = 1 mm (the groups do not depend on it)."""
    return BearingGeometry(diameter=2.0, width=2.0 * length_to_diameter, radial_clearance=1e-3)


def _inlet_groove_geometry(geometry: BearingGeometry) -> BearingGeometry:
    """Geometry with the ambient inlet line at θ = π as a full-width axial groove."""
    line = Groove(start_angle=math.pi, extent=1e-9, width=geometry.width)
    return BearingGeometry(diameter=geometry.diameter, width=geometry.width,
                           radial_clearance=geometry.radial_clearance,
                           grooves=(line,))


def make_film(model: SteadyModel, geometry: BearingGeometry, grid: tuple[int, int],
              friction: str = "full_film"):
    """Film model under Raimondi–Boyd conditions; journal centre later placed on +x."""
    n_theta, n_z = grid
    if friction not in ("full_film", "film_fraction"):
        raise CaseError(f"friction = {friction!r}: allowed full_film, film_fraction")
    convention: FrictionConvention = "full_film" if friction == "full_film" else "film_fraction"
    if model == "reynolds":
        return ReynoldsFilm(geometry, n_theta=n_theta, n_z=n_z, friction=convention,
                            ambient_line_at_max_gap=True)
    if model == "short":
        return ShortBearingFilm(geometry)
    if model == "mass_conserving":
        try:
            module = importlib.import_module("conrod.film.mass_conserving.film")
        except ModuleNotFoundError:
            raise CaseError("model = 'mass_conserving': not available in this build "
                            "(allowed: reynolds, short)") from None
        return module.MassConservingFilm(_inlet_groove_geometry(geometry),
                                         n_theta=n_theta, n_z=n_z)
    raise CaseError(f"model = {model!r}: allowed reynolds, mass_conserving, short")


def _film_end_angle(pressure: np.ndarray, grid: chars.FilmGrid) -> float:
    """Mid-plane rupture angle after the minimum film at θ = 0 [rad]; p ~ (θ_e − θ)²
    near a Reynolds rupture, so √p is extrapolated linearly to zero."""
    line = pressure[:, grid.n_z // 2]
    half = grid.n_theta // 2
    positive = line[: half + 1] > 0.0
    if positive.all() or not positive[0]:
        return float("nan")
    last = int(np.argmin(positive)) - 1
    if last < 1:
        return grid.theta[max(last, 0)]
    root_a, root_b = math.sqrt(line[last - 1]), math.sqrt(line[last])
    step = root_b / (root_a - root_b) if root_a > root_b else 1.0
    return float(grid.theta[last] + min(step, 1.0) * grid.d_theta)


def _pressure_grid(film, pressure: np.ndarray | None) -> chars.FilmGrid | None:
    """The model's FilmGrid when it returned a pressure field on it (grid models)."""
    grid = getattr(film, "film_grid", None)
    if isinstance(grid, chars.FilmGrid) and pressure is not None and (
        pressure.shape == (grid.n_theta, grid.n_z + 1)
):
        return grid
    return None


def _flows(film, result: FilmResult, state: FilmState) -> tuple[float, float]:
    """(Q inflow at the inlet line, Q_s side flow) [m^3/s]."""
    pressure = result.pressure
    grid = _pressure_grid(film, pressure)
    if grid is not None and pressure is not None:
        h = film_thickness(film.geometry, state.eccentricity_x, state.eccentricity_y,
                           grid.theta, np.zeros(pressure.shape))
        speed = grid.radius * (state.journal_speed + state.shell_speed)
        inflow = chars.circumferential_flow(pressure, h, grid, grid.n_theta // 2, 1,
                                            speed, state.viscosity)
        return inflow, result.side_flow
    g = film.geometry
    h_max = g.radial_clearance + math.hypot(state.eccentricity_x, state.eccentricity_y)
    inflow = 0.5 * g.radius * state.journal_speed * h_max * g.width
    return float(result.extra.get("inlet_flow_m3_per_s", inflow)), result.side_flow


def raimondi_boyd_point(
    length_to_diameter: float, eccentricity: float, model: SteadyModel = "reynolds",
    grid: tuple[int, int] | None = None, friction: str = "full_film",
) -> SteadyPoint:
    """Raimondi–Boyd characteristics at eccentricity ratio ``eccentricity`` [-]
    (``grid`` = (n_theta, n_z) intervals, None = :func:`default_grid`)."""
    if not 0.0 < eccentricity < 1.0:
        raise CaseError(f"eccentricity = {eccentricity!r}: out of range (allowed: > 0 and < 1)")
    if not 0.0 < length_to_diameter <= 10.0:
        raise CaseError(f"length_to_diameter = {length_to_diameter!r}: "
                        "out of range (allowed: > 0 and <= 10)")
    geometry = _unit_geometry(length_to_diameter)
    film = make_film(model, geometry, grid or default_grid(eccentricity), friction)
    speed_rev = 1.0
    state = FilmState(eccentricity_x=eccentricity * geometry.radial_clearance, eccentricity_y=0.0,
                      journal_speed=2.0 * math.pi * speed_rev, viscosity=1.0)
    if model == "mass_conserving":
        state = FilmState(**{**state.__dict__, "history": film.initial_history()})
    result = film.solve(state, with_pressure=True)
    point = _dimensionless(film, geometry, state, result, length_to_diameter, eccentricity,
                           model, friction)
    return replace(point, coefficients=load_frame_coefficients(film, state, False))


def _dimensionless(film, geometry: BearingGeometry, state: FilmState, result: FilmResult,
                   length_to_diameter: float, eccentricity: float, model: str,
                   friction: str) -> SteadyPoint:
    R, L, c = geometry.radius, geometry.width, geometry.radial_clearance
    speed_rev = state.journal_speed / (2.0 * math.pi)
    load = math.hypot(result.force_x, result.force_y)
    if not load > 0.0:
        raise ConvergenceError("steady film carries no load", where=f"eps = {eccentricity}")
    unit_load = load / (2.0 * R * L)
    inflow, side = _flows(film, result, state)
    pressure = result.pressure
    grid = _pressure_grid(film, pressure)
    if grid is not None and pressure is not None:
        film_end = _film_end_angle(pressure, grid)
    elif model == "short":
        film_end = 0.0  # half-Sommerfeld: the film ends at h_min
    else:
        film_end = float(result.extra.get("film_end_angle_rad", float("nan")))
    return SteadyPoint(
        length_to_diameter=length_to_diameter, eccentricity=eccentricity,
        sommerfeld_number=(R / c) ** 2 * state.viscosity * speed_rev / unit_load,
        attitude_angle_deg=math.degrees(math.atan2(result.force_y, -result.force_x)),
        friction_variable=abs(result.friction_torque_journal) / (c * load),
        flow_variable=inflow / (R * c * speed_rev * L),
        side_flow_ratio=side / inflow,
        load_to_peak_pressure_ratio=unit_load / result.max_pressure,
        peak_pressure_angle_deg=math.degrees((2.0 * math.pi - result.max_pressure_angle)
                                             % (2.0 * math.pi)),
        film_end_angle_deg=math.degrees(film_end),
        model=model,
        friction_convention=friction,
)


@dataclass(frozen=True)
class OperatingPoint:
    """Dimensional steady answer for a given load (Raimondi–Boyd conditions).

    eccentricity : float  Eccentricity ratio ε [-].
    attitude_angle_deg : float  Angle between load line and line of centres [deg].
    min_film_thickness : float  h_min [m].
    max_pressure : float  p_max [Pa].
    friction_torque : float  |M_j| on the journal [N m].
    friction_power : float  Power dissipated, |M_j| ω_j [W].
    side_flow : float  Edge leakage Q_s [m^3/s].
    inlet_flow : float  Inflow Q at the inlet line [m^3/s].
    sommerfeld_number : float  S = (R/c)² μN/P [-].
    """

    eccentricity: float
    attitude_angle_deg: float
    min_film_thickness: float
    max_pressure: float
    friction_torque: float
    friction_power: float
    side_flow: float
    inlet_flow: float
    sommerfeld_number: float
    model: str
    friction_convention: str
    coefficients: dict[str, float] = field(default_factory=dict)
    """K_xx … C_yy [N/m, N s/m] and K_bar_xx … C_bar_yy [-] in the load frame."""

    def as_dict(self) -> dict[str, float | str]:
        """Plain flat dictionary (JSON-ready)."""
        return _flat(asdict(self))


ECCENTRICITY_BRACKET = (1.0e-3, 0.995)
"""Search interval of the eccentricity ratio in :func:`solve_for_load` [-]."""


def solve_for_load(
    load: float, journal_speed: float, viscosity: float, geometry: BearingGeometry,
    model: SteadyModel = "reynolds", grid: tuple[int, int] | None = None,
    friction: str = "full_film",
) -> OperatingPoint:
    """Eccentricity, attitude, h_min, p_max, friction and flows for load W [N], journal
    speed ω_j [rad/s] and viscosity μ [Pa s] — ε from |F(ε)| = W by Brent's method.
    ``grid`` None: :data:`DEFAULT_GRID`, repeated on :data:`FINE_GRID` when ε > 0.9."""
    if grid is None:
        point = solve_for_load(load, journal_speed, viscosity, geometry, model, DEFAULT_GRID,
                               friction)
        if point.eccentricity <= 0.9:
            return point
        grid = FINE_GRID
    for name, value in (("load", load), ("journal_speed", journal_speed),
                        ("viscosity", viscosity)):
        if not value > 0.0:
            raise CaseError(f"{name} = {value!r}: out of range (allowed: > 0)")
    film = make_film(model, geometry, grid, friction)
    c = geometry.radial_clearance

    def state_at(eps: float) -> FilmState:
        return FilmState(eccentricity_x=eps * c, eccentricity_y=0.0, journal_speed=journal_speed,
                         viscosity=viscosity)

    def excess(eps: float) -> float:
        return math.hypot(*film.force(state_at(eps))) - load

    low, high = ECCENTRICITY_BRACKET
    if excess(high) < 0.0:
        raise CaseError(f"load = {load:g}: out of range (allowed: below the film capacity "
                        f"{load + excess(high):.4g} N at eccentricity {high}) N")
    eps = low if excess(low) > 0.0 else brentq(excess, low, high, xtol=1e-10, rtol=1e-10)
    state = state_at(eps)
    result = film.solve(state, with_pressure=True)
    inflow, side = _flows(film, result, state)
    speed_rev = journal_speed / (2.0 * math.pi)
    unit_load = load / (geometry.diameter * geometry.width)
    return OperatingPoint(
        eccentricity=eps,
        attitude_angle_deg=math.degrees(math.atan2(result.force_y, -result.force_x)),
        min_film_thickness=result.min_film_thickness, max_pressure=result.max_pressure,
        friction_torque=abs(result.friction_torque_journal),
        friction_power=abs(result.friction_torque_journal) * journal_speed,
        side_flow=side, inlet_flow=inflow,
        sommerfeld_number=(geometry.radius / c) ** 2 * viscosity * speed_rev / unit_load,
        model=model, friction_convention=friction,
        coefficients=load_frame_coefficients(film, state, True),
    )
