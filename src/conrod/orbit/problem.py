"""The orbit problem: film model, load cycle, masses and contact circle ([D0] §3.1).

Equation of motion of the journal centre relative to the shell in the film frame, with the
crank angle φ as independent variable (dt = dφ/ω, [D0] eqs 3.1.3–3.1.6):

.. math:: \\frac{dx}{dφ} = \\frac{v_x}{ω},\\quad
          \\frac{dv_x}{dφ} = \\frac{W_x(φ) + F_x(x, y, v_x, v_y)}{m_x ω}

(likewise for y), W the load pressing the journal on the shell, F the film force on the
journal (F + W = 0 at equilibrium). [D0] writes the same with the bearing centre relative
to the journal, hence its R − P signs.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numba as nb
import numpy as np

from conrod.errors import CaseError
from conrod.film.base import FilmModel, FilmState
from conrod.film.capabilities import CarriesAsperityContact, CompiledKernel, HasCompiledKernel
from conrod.loads.cycle import LoadCycle
from conrod.loads.tilt import cycle_tilt
from conrod.orbit.memory import FilmSession

ForceFunction = Callable[..., tuple[float, float]]
"""(x, y, v_x, v_y, ω_j, ω_b[, φ]) → film force (F_x, F_y) [N]; the crank angle φ [rad]
places the journal's oil holes (required when the film has some)."""


@dataclass(frozen=True)
class OrbitState:
    """Journal-centre state carried from cycle to cycle.

    x, y : float  Position relative to the shell centre [m].
    vx, vy : float  Velocity [m/s].
    in_contact : bool  Journal on the contact circle [-].
    film_memory : object or None  Memory of a film with
        :class:`~conrod.film.capabilities.HasMemory` (warm start, film content); None: the
        film's initial memory.
    tilt : tuple or None  Journal tilt (γ_x, γ_y [rad], γ̇_x, γ̇_y [rad/s]) of a run whose
        tilt is solved (:class:`~conrod.loads.tilt.JournalTilt`); None: aligned.
    """

    x: float = 0.0
    y: float = 0.0
    vx: float = 0.0
    vy: float = 0.0
    in_contact: bool = False
    film_memory: Any = None
    tilt: tuple[float, float, float, float] | None = None


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
        :func:`conrod.contact.asperity.asperity_force`: mixed lubrication; the rigid asperity
        force is added to the film force unless the film carries it
        (:attr:`rigid_asperity`).
    tilt : JournalTilt or None  The journal's tilt, prescribed or solved as two more degrees
        of freedom (:mod:`conrod.loads.tilt`, :mod:`conrod.orbit.tilt_steps`); None:
        aligned.
    feed : FeedSchedule or None  Position and pressure of the journal's oil holes over the
        cycle (:class:`conrod.loads.oil_feed.FeedSchedule`); None: no journal hole.
    """

    film: FilmModel
    loads: LoadCycle
    viscosity: float
    mass_x: float
    mass_y: float
    dry_friction: float = 0.1
    contact_film_thickness: float = 0.0
    asperity: tuple[float, float, float, float] | None = None
    tilt: Any = None
    feed: Any = None

    def journal_feed(self, crank_angle: float) -> Any:
        """The :class:`~conrod.film.base.JournalFeed` at ``crank_angle`` [rad] (None without
        journal holes)."""
        return None if self.feed is None else self.feed.at(crank_angle)

    def row_state(self, cycle: Any, i: int, viscosity: float | None = None) -> FilmState:
        """The film state of output row ``i`` of ``cycle`` (CycleResults): position,
        velocity, speeds, tilt and the crank-pin holes of that crank angle, the problem's
        viscosity unless ``viscosity`` [Pa s] is given — the one state every output that
        solves the film again at a row uses."""
        return FilmState(
            eccentricity_x=float(cycle.eccentricity_x[i]),
            eccentricity_y=float(cycle.eccentricity_y[i]),
            velocity_x=float(cycle.velocity_x[i]), velocity_y=float(cycle.velocity_y[i]),
            journal_speed=float(cycle.journal_speed[i]),
            shell_speed=float(cycle.shell_speed[i]),
            viscosity=self.viscosity if viscosity is None else viscosity,
            **cycle_tilt(cycle.axial, i),
            journal_feed=self.journal_feed(float(cycle.crank_angle[i])))

    @property
    def clearance(self) -> float:
        """Radial clearance c [m]."""
        return self.film.geometry.radial_clearance

    @property
    def contact_radius(self) -> float:
        """Radius of the contact circle r_c = c − h_c [m]."""
        return self.clearance - self.contact_film_thickness

    @property
    def rigid_asperity(self) -> tuple[float, float, float, float] | None:
        """The asperity parameters when the orbit adds the rigid-shell asperity force to the
        film force; None without mixed lubrication or when the film carries the asperity
        contact on its deformed film (the one place that decides) [-]."""
        film = self.film
        if isinstance(film, CarriesAsperityContact) and film.carries_asperity():
            return None
        return self.asperity

    @property
    def crank_speed(self) -> float:
        """Crank angular velocity ω [rad/s]."""
        return self.loads.crank_speed

    @cached_property
    def kernel(self) -> CompiledKernel | None:
        """The film's compiled kernel when it declares one and no asperity force is added
        (:class:`~conrod.film.capabilities.HasCompiledKernel`); else None."""
        if self.asperity is not None or not isinstance(self.film, HasCompiledKernel):
            return None
        return self.film.compiled_kernel()

    @property
    def compiled_force(self) -> CompiledKernel | None:
        """The kernel when it has a compiled force (the compiled rk2/adaptive paths)."""
        kernel = self.kernel
        return kernel if kernel is not None and kernel.force is not None else None

    def with_viscosity(self, viscosity: float) -> OrbitProblem:
        """Same problem with another viscosity [Pa s]."""
        return OrbitProblem(
            self.film, self.loads, viscosity, self.mass_x, self.mass_y,
            self.dry_friction, self.contact_film_thickness, self.asperity, self.tilt,
            self.feed,
)

    @property
    def has_film_content(self) -> bool:
        """True for films whose memory is a film content that evolves in time
        (mass-conserving): advanced in lock-step with a fixed step."""
        return self.film.initial_history() is not None

    def session(self, memory: Any = None) -> FilmSession:
        """The film with ``memory`` (None: its initial memory), held by an integrator."""
        return FilmSession(self.film, memory)

    def force_function(self, session: FilmSession | None = None) -> ForceFunction:
        """(x, y, vx, vy, ω_j, ω_b) → film force (F_x, F_y) [N] for this film and viscosity;
        a film with memory reads and updates ``session`` (a fresh one when None)."""
        asperity = self.rigid_asperity
        if asperity is not None:
            return _with_asperity(self._film_force(session), self.clearance, asperity)
        return self._film_force(session)

    def _film_force(self, session: FilmSession | None) -> ForceFunction:
        mu, kernel = self.viscosity, self.compiled_force
        if kernel is not None:
            force = bound_force(kernel.force, kernel.params)

            def compiled(x: float, y: float, vx: float, vy: float, wj: float, wb: float,
                         phi: float | None = None):
                return force(x, y, vx, vy, wj + wb, mu)

            return compiled
        held = session if session is not None else self.session()

        def generic(x: float, y: float, vx: float, vy: float, wj: float, wb: float,
                    phi: float | None = None):
            feed = None if phi is None else self.journal_feed(phi)
            fx, fy = held.force(FilmState(eccentricity_x=x, eccentricity_y=y, velocity_x=vx,
                                          velocity_y=vy, journal_speed=wj, shell_speed=wb,
                                          viscosity=mu, journal_feed=feed))
            return float(fx), float(fy)

        return generic

    def output_angles(self, step_deg: float) -> np.ndarray:
        """Output crank angles over one cycle from 0, last point excluded [rad]."""
        count = max(int(round(np.degrees(self.loads.cycle) / step_deg)), 4)
        return np.linspace(0.0, self.loads.cycle, count, endpoint=False)


def bound_force(force, params):
    """``force(x, y, v_x, v_y, ω_j + ω_b, μ)`` [N] of a compiled kernel with its ``params``
    (the kernel itself, disk-cached, called with them: the params frozen into a closure
    compiled in every process, 0.1 s a run, saved 0.4 µs of a tuple's dispatch a call)."""
    return lambda x, y, vx, vy, omega_sum, mu: force(x, y, vx, vy, omega_sum, mu, params)


def _with_asperity(film_force: ForceFunction, clearance: float, params) -> ForceFunction:
    """Film force plus the Greenwood–Tripp asperity force on the rigid shell (compiled
    kernel of :mod:`conrod.contact.asperity`); a film that carries the asperity contact on
    its deformed film does not get it (:attr:`OrbitProblem.rigid_asperity`)."""
    from conrod.contact.asperity import asperity_force

    def total(x: float, y: float, vx: float, vy: float, wj: float, wb: float,
              phi: float | None = None):
        fx, fy = film_force(x, y, vx, vy, wj, wb, phi)
        ax, ay = asperity_force(x, y, clearance, params)
        return fx + ax, fy + ay

    return total


@nb.njit(cache=True)
def periodic_sample(phi: float, angles: np.ndarray, table: np.ndarray, cycle: float) -> np.ndarray:
    """Row of ``table`` linearly interpolated at ``phi`` [rad]; ``angles`` [rad] start the
    cycle and end with angles[0] + cycle (closing row appended)."""
    reduced = angles[0] + (phi - angles[0]) % cycle
    k = np.searchsorted(angles, reduced, side="right") - 1
    k = min(max(k, 0), angles.size - 2)
    t = (reduced - angles[k]) / (angles[k + 1] - angles[k])
    return table[k] + t * (table[k + 1] - table[k])


@nb.njit(cache=True)
def scaled_free_rhs(u: np.ndarray, row: np.ndarray, fx: float, fy: float, c_omega: float,
                    omega: float, mass_x: float, mass_y: float) -> np.ndarray:
    """du/dφ [-] of the free journal on the scaled state u = (x/c, y/c, ẋ/(cω), ẏ/(cω)):
    load row (W_x, W_y, …) [N] plus film force (``fx``, ``fy``) [N] over the masses [kg]."""
    scale = c_omega * omega
    out = np.empty(4)
    out[0], out[1] = u[2], u[3]
    out[2] = (row[0] + fx) / (mass_x * scale)
    out[3] = (row[1] + fy) / (mass_y * scale)
    return out


def load_table(loads: LoadCycle) -> tuple[np.ndarray, np.ndarray]:
    """Closed (angles [rad], rows W_x, W_y [N], ω_j, ω_b [rad/s]) for :func:`periodic_sample`."""
    angles = np.append(loads.crank_angle, loads.crank_angle[0] + loads.cycle)
    rows = np.column_stack([loads.load_x, loads.load_y, loads.journal_speed, loads.shell_speed])
    return angles, np.vstack([rows, rows[:1]])


def initial_state() -> OrbitState:
    """Concentric start x = y = ẋ = ẏ = 0 ([D0] eq. 3.5.1)."""
    return OrbitState()


def step_grid(problem: OrbitProblem, step_deg: float, output_step_deg: float):
    """(step points φ over the cycle [rad], steps per output row, output rows) of a fixed
    step ``step_deg`` [deg] that divides ``output_step_deg`` [deg]; CaseError otherwise."""
    record_every = int(round(output_step_deg / step_deg))
    if record_every < 1 or abs(record_every * step_deg - output_step_deg) > 1e-9 * output_step_deg:
        raise CaseError(
            f"solver.step_deg = {step_deg!r}: must divide solver.output_step_deg = "
            f"{output_step_deg!r} (allowed: output_step_deg / k, k = 1, 2, ...) [deg]"
)
    n_out = len(problem.output_angles(output_step_deg))
    n_steps = n_out * record_every
    phi = np.linspace(0.0, problem.loads.cycle, n_steps + 1)
    return phi, record_every, n_out
