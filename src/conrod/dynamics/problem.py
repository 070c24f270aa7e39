"""The orbit problem: film model, load cycle, masses and contact circle (seed 000 §3.1).

Equation of motion of the journal centre relative to the shell in the film frame, with the
crank angle φ as independent variable (dt = dφ/ω, seed 000 eqs 3.1.3–3.1.6):

.. math:: \\frac{dx}{dφ} = \\frac{v_x}{ω},\\quad
          \\frac{dv_x}{dφ} = \\frac{W_x(φ) + F_x(x, y, v_x, v_y)}{m_x ω}

(likewise for y), W the load pressing the journal on the shell, F the film force on the
journal (F + W = 0 at equilibrium). The seed writes the same with the bearing centre relative
to the journal, hence its R − P signs.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numba as nb
import numpy as np

from conrod.film.base import FilmModel, FilmState
from conrod.film.short_bearing import ShortBearingFilm
from conrod.film.short_bearing_kernel import short_bearing_force
from conrod.loads.cycle import LoadCycle

ForceFunction = Callable[[float, float, float, float, float, float], tuple[float, float]]


@dataclass(frozen=True)
class OrbitState:
    """Journal-centre state carried from cycle to cycle.

    x, y : float  Position relative to the shell centre [m].
    vx, vy : float  Velocity [m/s].
    in_contact : bool  Journal on the contact circle [-].
    film_history : ndarray or None  Film memory (mass-conserving film fraction) [-].
    """

    x: float = 0.0
    y: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    in_contact: bool = False
    film_history: np.ndarray | None = None


@dataclass(frozen=True)
class OrbitProblem:
    """Everything the integrators need.

    film : FilmModel  Film model.
    loads : LoadCycle  Load and surface speeds over the cycle.
    viscosity : float  Dynamic viscosity μ [Pa s].
    mass_x, mass_y : float  Moving masses along film x and y [kg].
    dry_friction : float  Dry friction coefficient μ_dry [-].
    contact_film_thickness : float  h at which hard contact starts [m].
    asperity : tuple or None  Greenwood–Tripp parameters (R [m], L [m], σ [m], K E' [Pa]) of
        :func:`conrod.contact.asperity.asperity_force`, added to the film force when given.
    """

    film: FilmModel
    loads: LoadCycle
    viscosity: float
    mass_x: float
    mass_y: float
    dry_friction: float = 0.1
    contact_film_thickness: float = 0.0
    asperity: tuple[float, float, float, float] | None = None

    @property
    def clearance(self) -> float:
        """Radial clearance c [m]."""
        return self.film.geometry.radial_clearance

    @property
    def contact_radius(self) -> float:
        """Radius of the contact circle r_c = c − h_c [m]."""
        return self.clearance - self.contact_film_thickness

    @property
    def crank_speed(self) -> float:
        """Crank angular velocity ω [rad/s]."""
        return self.loads.crank_speed

    @property
    def is_short_bearing(self) -> bool:
        """True when the compiled short-bearing fast path applies."""
        return (type(self.film) is ShortBearingFilm and self.asperity is None
                and self.film.pressure_viscosity is None)

    def with_viscosity(self, viscosity: float) -> OrbitProblem:
        """Same problem with another viscosity [Pa s]."""
        return OrbitProblem(
            self.film, self.loads, viscosity, self.mass_x, self.mass_y,
            self.dry_friction, self.contact_film_thickness, self.asperity,
        )

    @property
    def has_history(self) -> bool:
        """True for films with memory (mass-conserving): advanced in lock-step, see
        :class:`FilmHistory`."""
        return self.film.initial_history() is not None

    def force_function(self, history: FilmHistory | None = None) -> ForceFunction:
        """(x, y, vx, vy, ω_j, ω_b) → film force (F_x, F_y) [N] for this film and viscosity;
        films with memory read the current ``history.field``."""
        if self.asperity is not None:
            return _with_asperity(self._film_force(history), self.clearance, self.asperity)
        return self._film_force(history)

    def _film_force(self, history: FilmHistory | None) -> ForceFunction:
        mu, film = self.viscosity, self.film
        if type(film) is ShortBearingFilm and film.pressure_viscosity is None:
            g = film.geometry
            radius, width, c = g.radius, g.width, g.radial_clearance

            def short(x: float, y: float, vx: float, vy: float, wj: float, wb: float):
                return short_bearing_force(x, y, vx, vy, wj + wb, mu, radius, width, c)

            return short

        def generic(x: float, y: float, vx: float, vy: float, wj: float, wb: float):
            field = history.field if history is not None else None
            state = FilmState(x, y, vx, vy, wj, wb, mu, history=field)
            fx, fy = film.force(state)
            return float(fx), float(fy)

        return generic

    def output_angles(self, step_deg: float) -> np.ndarray:
        """Output crank angles over one cycle from 0, last point excluded [rad]."""
        count = max(int(round(np.degrees(self.loads.cycle) / step_deg)), 4)
        return np.linspace(0.0, self.loads.cycle, count, endpoint=False)


def _with_asperity(film_force: ForceFunction, clearance: float, params) -> ForceFunction:
    """Film force plus the Greenwood–Tripp asperity force (H5's compiled kernel)."""
    from conrod.contact.asperity import asperity_force

    def total(x: float, y: float, vx: float, vy: float, wj: float, wb: float):
        fx, fy = film_force(x, y, vx, vy, wj, wb)
        ax, ay = asperity_force(x, y, clearance, params)
        return fx + ax, fy + ay

    return total


class FilmHistory:
    """Film memory (e.g. the film fraction ϑ of the mass-conserving model) advanced in
    lock-step with a fixed-step integrator: after each accepted step of length dt [s],
    ϑ ← clip(ϑ + dt ∂ϑ/∂t, 0, 1) with ∂ϑ/∂t from the film at the step start (explicit Euler,
    first order in time; the model's transport limit dt |ω_j + ω_b|/2 ≤ Δθ must hold)."""

    def __init__(self, film: FilmModel, field: np.ndarray | None = None):
        self.film = film
        self.field = film.initial_history() if field is None else field

    def advance(self, state: FilmState, dt: float) -> None:
        """One explicit step from ``state`` (its history is replaced by the current field)."""
        if self.field is None:
            return
        rate = self.film.solve(_with_history(state, self.field)).history_rate
        if rate is not None:
            self.field = np.clip(self.field + dt * rate, 0.0, 1.0)


def _with_history(state: FilmState, field: np.ndarray) -> FilmState:
    return FilmState(
        state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
        state.journal_speed, state.shell_speed, state.viscosity, state.deformation, field,
    )


@nb.njit(cache=True)
def periodic_sample(phi: float, angles: np.ndarray, table: np.ndarray, cycle: float) -> np.ndarray:
    """Row of ``table`` linearly interpolated at ``phi`` [rad]; ``angles`` [rad] start the
    cycle and end with angles[0] + cycle (closing row appended)."""
    reduced = angles[0] + (phi - angles[0]) % cycle
    k = np.searchsorted(angles, reduced, side="right") - 1
    k = min(max(k, 0), angles.size - 2)
    t = (reduced - angles[k]) / (angles[k + 1] - angles[k])
    return table[k] + t * (table[k + 1] - table[k])


def load_table(loads: LoadCycle) -> tuple[np.ndarray, np.ndarray]:
    """Closed (angles [rad], rows W_x, W_y [N], ω_j, ω_b [rad/s]) for :func:`periodic_sample`."""
    angles = np.append(loads.crank_angle, loads.crank_angle[0] + loads.cycle)
    rows = np.column_stack([loads.load_x, loads.load_y, loads.journal_speed, loads.shell_speed])
    return angles, np.vstack([rows, rows[:1]])


def initial_state() -> OrbitState:
    """Concentric start x = y = ẋ = ẏ = 0 (seed 000 eq. 3.5.1)."""
    return OrbitState()
