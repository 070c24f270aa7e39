"""Mass-conserving (JFO) film: Elrod–Adams p–ϑ cavitation with an explicit film history.

Transient use (what the orbit integrator sees)
----------------------------------------------
The film fraction ϑ(θ, z) [-] is the model's *history*: ``initial_history()`` is a full
film (ϑ = 1). The orbit integrator holds ϑ and the warm-start pressure in an explicit
:class:`MassConservingMemory` (:class:`~conrod.film.capabilities.HasMemory`):
``solve_with_memory`` answers an instant, ``advance_memory`` steps ϑ in time.
``solve(state)`` takes ϑ = ``state.history`` (clipped to [0, 1]) as given
and solves, at that instant, the complementarity problem

* full nodes (ϑ = 1): Reynolds with p ≥ p_cav (projected SOR); where p > p_cav, ∂ϑ/∂t = 0;
  where p = p_cav the cell balance gives ∂ϑ/∂t ≤ 0 (the film starts to rupture);
* partial nodes (ϑ < 1): p = p_cav and the cell balance gives ∂ϑ/∂t (transport by the
  mean surface speed, refilling from pressurised neighbours),

and returns ∂ϑ/∂t as ``FilmResult.history_rate`` [1/s]. Any ODE integrator advances ϑ
together with the journal motion; the kernel clips the stepped ϑ back into [0, 1].
Explicit steps must respect the transport limit Δt · |ω_j + ω_b|/2 ≤ Δθ.
With ``history=None`` (or a full film) the answer is the Swift–Stieber (Reynolds) film.

Steady use (``solve_steady``)
-----------------------------
Raimondi & Boyd's full-bearing conditions: a full-film, ambient-pressure inlet line at the
maximum gap θ = ψ + π; the steady JFO problem is solved with the Elrod–Adams/Ausas sweep.

Supply features (grooves, feed holes) are Dirichlet regions at the supply pressure with a
full film; the bearing edges z = ±L/2 are at ambient (gauge 0) pressure.
See :mod:`conrod.film.mass_conserving.kernel` for the discrete equations.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from conrod.errors import CaseError, ConvergenceError, FilmThicknessError
from conrod.film.base import BearingGeometry, FilmResult, FilmState
from conrod.film.characteristics import FilmGrid
from conrod.film.mass_conserving.kernel import (
    assemble,
    cell_balance,
    elrod_adams_steady,
    projected_sor,
)
from conrod.film.mass_conserving.memory import FULL, FilmFields, MassConservingMemory
from conrod.film.mass_conserving.results import convection, film_end_angle
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.profile import profile_field
from conrod.film.rated_state import state_rate
from conrod.film.supply import instant_supply, nearest_theta_index, supply_mask
from conrod.film.tilt import axial_gap, tilt_fields

__all__ = ["FULL", "FilmFields", "MassConservingFilm", "MassConservingMemory"]


@dataclass
class MassConservingFilm:
    """JFO film (Elrod–Adams p–ϑ) on an (n_theta × n_z) finite-volume grid.

    geometry : BearingGeometry  Bearing geometry and supply features.
    n_theta : int  Circumferential intervals = nodes (periodic) [-].
    n_z : int  Axial intervals; n_z + 1 axial nodes including the edges [-]
        (the grid of :class:`~conrod.film.characteristics.FilmGrid`, as ReynoldsFilm).
    tolerance : float  Relative max pressure change per sweep that stops SOR [-].
    max_iterations : int  Sweep limit; exceeding it raises ConvergenceError [-].
    omega : float or None  SOR factor [-]; None = ReynoldsFilm's ``optimal_relaxation``.
    friction : 'film_fraction' | 'full_film'  Couette shear scaled by ϑ (physical JFO)
        or over the full 360° (Raimondi & Boyd's convention).
    method : 'multigrid' | 'sor'  Full-film solver of a transient instant: the projected
        multigrid of :mod:`conrod.film.reynolds.multigrid` (broken-film nodes held at p_cav
        like Dirichlet nodes; only z ≤ 0 is solved when film fraction, sources and supply
        are mirror-symmetric about the mid-plane) or plain projected SOR.
    pressure_viscosity : PressureViscosity or None  μ(p) law: the p–ϑ problem is solved
        for the reduced pressure q(p) (:mod:`conrod.film.piezoviscosity`; the Couette flux
        has no μ, so the Elrod–Adams complementarity maps exactly) and mapped back.
    deformation_rate : bool  Add the bore's rate ``RatedFilmState.deformation_rate`` [m/s]
        to the squeeze term of the instantaneous solve (:meth:`with_deformation_rate`).
    """

    geometry: BearingGeometry
    n_theta: int = 144
    n_z: int = 32
    tolerance: float = 1.0e-7
    max_iterations: int = 20000
    omega: float | None = None
    friction: Literal["film_fraction", "full_film"] = "film_fraction"
    method: Literal["multigrid", "sor"] = "multigrid"
    pressure_viscosity: PressureViscosity | None = None
    name: str = "mass_conserving"
    deformation_rate: bool = False
    last_iterations: int = field(default=0, init=False)

    def __post_init__(self) -> None:
        if self.n_theta < 8 or self.n_z < 2:
            raise CaseError(
                f"grid {self.n_theta}x{self.n_z}: out of range (allowed: n_theta >= 8, n_z >= 2)"
)
        g = self.geometry
        self.film_grid = FilmGrid(g.radius, g.width, self.n_theta, self.n_z)
        theta = self.film_grid.theta
        self._cos_theta, self._sin_theta = np.cos(theta), np.sin(theta)
        self._edge = np.zeros((self.n_theta, self.n_z + 1), dtype=bool)
        self._edge[:, [0, -1]] = True
        self._supply = supply_mask(g, self.film_grid)
        self._profile = profile_field(g, theta, self.film_grid.z)
        self._fixed = np.where(self._supply, g.supply_pressure, 0.0) - g.cavitation_pressure
        if self.method not in ("multigrid", "sor"):
            raise CaseError(f"method = {self.method!r}: allowed 'multigrid' or 'sor'")
        from conrod.film.reynolds.film import optimal_relaxation

        self._omega = self.omega if self.omega is not None else optimal_relaxation(self.film_grid)

    @classmethod
    def from_settings(cls, geometry: BearingGeometry, settings: Any) -> MassConservingFilm:
        """Film on the ``[solver]`` grid ``n_theta`` × ``n_z`` with ``film_tolerance``."""
        return cls(geometry, n_theta=int(settings.n_theta), n_z=int(settings.n_z),
                   tolerance=float(settings.film_tolerance))

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """θ nodes [rad] (periodic, no duplicate of 2π) and z nodes [m] (edges included)."""
        return self.film_grid.theta, self.film_grid.z

    def spacing(self) -> tuple[float, float]:
        """Cell sizes Δx = R Δθ and Δz [m]."""
        return self.geometry.radius * self.film_grid.d_theta, self.film_grid.d_z

    def initial_history(self) -> np.ndarray:
        """Full film: ϑ = 1 on every node, shape (n_theta, n_z + 1) [-]."""
        return np.ones((self.n_theta, self.n_z + 1))

    def deformation_shape(self) -> tuple[int, int]:
        """Shape (n_theta, n_z + 1) of the accepted deformation field δ(θ, z) [m]."""
        return self.n_theta, self.n_z + 1

    def initial_memory(self) -> MassConservingMemory:
        """Full film (ϑ = 1), no warm-start pressure."""
        return MassConservingMemory(self.initial_history())

    def solve_with_memory(
        self, state: FilmState, memory: MassConservingMemory, *, with_pressure: bool = False
) -> tuple[FilmResult, MassConservingMemory]:
        """:meth:`solve` with the film fraction and warm start of ``memory`` (the state's
        ``history`` is not read), and the memory with the new pressure."""
        result, pressure = self._solve_transient(state, memory.fraction, memory.pressure,
                                                 with_pressure)
        return result, replace(memory, pressure=pressure, thickness=None)

    def force_with_memory(self, state: FilmState, memory: MassConservingMemory
) -> tuple[float, float, MassConservingMemory]:
        """Film force (F_x, F_y) [N] with the fraction and warm start of ``memory``."""
        result, memory = self.solve_with_memory(state, memory)
        return result.force_x, result.force_y, memory

    def advance_memory(self, state: FilmState, memory: MassConservingMemory,
                       dt: float) -> MassConservingMemory:
        """One explicit Euler step of the film content over ``dt`` [s] from ``state``:
        ϑ ← clip(ϑ + dt ∂ϑ/∂t, 0, 1), first order in time (transport limit
        dt |ω_j + ω_b|/2 ≤ Δθ)."""
        result, memory = self.solve_with_memory(state, memory)
        rate = result.history_rate if result.history_rate is not None else 0.0
        fraction = np.clip(memory.fraction + dt * rate, 0.0, 1.0)
        return replace(memory, fraction=fraction, thickness=None)

    def content_vector(self, memory: MassConservingMemory) -> np.ndarray:
        """Film fraction ϑ of ``memory`` as a flat vector [-]."""
        return np.asarray(memory.fraction, dtype=float).ravel()

    def with_content(self, memory: MassConservingMemory,
                     vector: np.ndarray) -> MassConservingMemory:
        """``memory`` with the film fraction ``vector`` (clipped to [0, 1]) and no stored
        thickness: the next implicit step takes h^n at its own start position."""
        fraction = np.clip(np.reshape(vector, np.shape(memory.fraction)), 0.0, 1.0)
        return replace(memory, fraction=fraction, thickness=None)

    def content_step(self, state: FilmState, memory: MassConservingMemory, dt: float,
                     warm: MassConservingMemory | None = None,
                     previous: MassConservingMemory | None = None,
) -> tuple[float, float, MassConservingMemory]:
        """Film force (F_x, F_y) [N] at the end of an implicit step ``dt`` [s] from the
        content of ``memory`` (BDF2 with the content of ``previous``, one step earlier;
        else backward Euler), and the memory after it
        (:func:`conrod.film.mass_conserving.step.content_step`)."""
        from conrod.film.mass_conserving.step import content_step

        return content_step(self, state, memory, dt, warm, previous)

    def accepted_result(self, state: FilmState, memory: MassConservingMemory, *,
                        with_pressure: bool = False) -> FilmResult | None:
        """The answer of the content step that ended at ``state`` with ``memory`` (its
        pressure and film fraction), None when ``memory`` is not such an answer
        (:func:`conrod.film.mass_conserving.step.accepted_result`)."""
        from conrod.film.mass_conserving.step import accepted_result

        return accepted_result(self, state, memory, with_pressure)

    def with_deformation_rate(self) -> MassConservingFilm:
        """This film with the bore's rate in the squeeze term of its instantaneous solve
        (:class:`~conrod.film.capabilities.SupportsDeformationRate`)."""
        return replace(self, deformation_rate=True)

    def exact_thickness_response(self) -> bool:
        """True when isoviscous (the content step is then available) [-]."""
        return self.pressure_viscosity is None

    def thickness_response(self, state: FilmState, solved: MassConservingMemory,
                           nodal: np.ndarray, rate_step: float | None):
        """Response of the nodal loads and the force to the film thickness at the content
        step ``solved`` (its memory) whose content capacity is 12μΔxΔz/``rate_step``
        (:func:`conrod.film.mass_conserving.response.content_step_response`)."""
        from conrod.film.mass_conserving.response import content_step_response

        return content_step_response(self, state, solved, nodal, rate_step)

    @property
    def node_directions(self) -> tuple[np.ndarray, np.ndarray]:
        """(cos θ, sin θ) of the θ nodes [-]."""
        return self._cos_theta, self._sin_theta

    @property
    def sor_factor(self) -> float:
        """Relaxation factor of the film's sweeps [-]."""
        return self._omega

    def fields(self, state: FilmState) -> FilmFields:
        """Assemble the cell-balance coefficients for one state."""
        g = self.geometry
        dx, dz = self.spacing()
        mu = state.viscosity
        if not mu > 0.0:
            raise CaseError(f"viscosity = {mu!r} Pa s: out of range (allowed: > 0 Pa s)")
        if state.deformation is not None and np.shape(state.deformation) != self._edge.shape:
            raise CaseError(f"deformation shape = {np.shape(state.deformation)}: allowed "
                            f"{self._edge.shape} = (n_theta, n_z + 1) [m]")
        added = state.deformation
        tilt, tilt_rate = (tilt_fields(state, self._cos_theta, self._sin_theta,
                                       self.film_grid.z) if state.tilted else (None, None))
        axial = axial_gap(self._profile, tilt)  # the profile h₀ and the tilt (conrod.film.tilt)
        if axial is not None:
            added = axial if added is None else added + axial
        deformation = (np.empty((0, 0)) if added is None
                       else np.ascontiguousarray(added, dtype=float))
        h, a_east, a_north, couette, squeeze = assemble(
            self._cos_theta, self._sin_theta, self.n_z + 1, g.radial_clearance,
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            deformation, dx, dz, mu, g.radius * (state.journal_speed + state.shell_speed),
)
        if tilt_rate is not None:  # the tilt rate in the squeeze term 12μΔxΔz ∂h/∂t
            squeeze = squeeze + 12.0 * state.viscosity * dx * dz * tilt_rate
        rate = state_rate(state) if self.deformation_rate else None
        if rate is not None:  # the bore's own rate in the squeeze term 12μΔxΔz ∂h/∂t
            squeeze = squeeze + 12.0 * state.viscosity * dx * dz * rate
        if not float(h.min()) > 0.0:
            raise FilmThicknessError(
                f"film thickness min = {float(h.min()):.3g} m (must stay > 0 m): the journal "
                "touches the shell; the load is beyond what the film and the contact model "
                "carry at this step (try a contact model, a finer step or a larger clearance)")
        law, offset = self.pressure_viscosity, self.reduced_cavitation(state)
        supply, fixed, fed = instant_supply(  # the journal's holes turn: a mask update
            g, self.film_grid, state.journal_feed, self._supply, self._fixed_values(state),
            lambda p: (p if law is None else float(law.to_reduced(p, mu))) - offset)
        return FilmFields(
            h=h, a_east=a_east, a_north=a_north, couette_east=couette, squeeze=squeeze,
            edge=self._edge, supply=supply.copy(), fixed_pressure=fixed,
            has_deformation=added is not None, fed=fed,
)

    # ------------------------------------------------------------------ transient
    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Pressure, forces, flows and ∂ϑ/∂t for the film fraction ``state.history``
        (cold start)."""
        return self._solve_transient(state, state.history, None, with_pressure)[0]

    def _solve_transient(
        self, state: FilmState, history: np.ndarray | None, warm: np.ndarray | None,
        with_pressure: bool,
) -> tuple[FilmResult, np.ndarray]:
        f = self.fields(state)
        fraction = self.fraction_field(history, f)
        pressure = self.start_pressure(f, fraction, warm, state)
        source = convection(f.couette_east, fraction) + f.squeeze * fraction
        active = f.free & (fraction >= FULL)
        sweeps, change = self._solve_full_film(pressure, active, f, source, state)
        self._check(sweeps, change, state)
        imbalance, from_edges, from_supply = cell_balance(
            pressure, fraction, f.free, f.edge, f.a_east, f.a_north, f.couette_east, f.squeeze)
        dx, dz = self.spacing()
        cell_mass = 12.0 * state.viscosity * dx * dz * f.h
        rate = np.where(f.free & (pressure <= 0.0), -imbalance / cell_mass, 0.0)
        rate = np.where(fraction >= FULL, np.minimum(rate, 0.0), rate)
        result = self.characteristics(state, f, pressure, fraction, (from_edges, from_supply))
        result.history_rate = rate
        content_rate = float(np.sum((fraction * f.squeeze / (12.0 * state.viscosity)
                                     + f.h * rate * dx * dz)[f.free]))
        result.extra.update(iterations=float(sweeps), relative_change=change,
                            content_rate_m3_per_s=content_rate)
        if with_pressure:
            result.pressure = self.gauge_pressure(pressure, state)
        return result, pressure.copy()

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]."""
        result = self.solve(state)
        return result.force_x, result.force_y

    def _solve_full_film(
        self, pressure: np.ndarray, active: np.ndarray, f: FilmFields, source: np.ndarray,
        state: FilmState,
    ) -> tuple[int, float]:
        """Pressure on the full-film nodes (in place on p̃); returns (sweeps, change)."""
        p_cav = self.reduced_cavitation(state)
        if self.method == "sor":
            return projected_sor(pressure, active, f.a_east, f.a_north, source, -p_cav,
                                 self._omega, self.tolerance, self.max_iterations)
        from conrod.film.reynolds import multigrid as multigrid

        gauge = pressure + p_cav
        symmetric = (not f.has_deformation and self.n_z % 4 == 0
                     and np.array_equal(active, active[:, ::-1])
                     and np.array_equal(source, source[:, ::-1]))
        cycles, change = multigrid.solve_on_grid(
            gauge, f.h, -source, ~active, self.film_grid, p_cav, self.tolerance,
            self.max_iterations, symmetric,
)
        pressure[:] = np.maximum(gauge - p_cav, 0.0)
        return cycles * (multigrid.PRE_SWEEPS + multigrid.POST_SWEEPS), change

    # ---------------------------------------------------------------------- steady
    def solve_steady(
        self, state: FilmState, *, with_pressure: bool = False, cavitation: str = "jfo",
        inlet_line: bool = True,
) -> FilmResult:
        """Steady film under Raimondi & Boyd's full-bearing conditions.

        A full-film ambient-pressure inlet line sits at the maximum gap θ = ψ + π
        (nearest grid column). ``cavitation='jfo'`` solves the steady Elrod–Adams problem;
        ``'swift_stieber'`` the Reynolds problem with the same inlet (for comparison).
        ``inlet_line=False`` drops the inlet line: oil then enters only through the
        geometry's grooves and feed holes (a fed, possibly starved, bearing).
        ``extra['film_end_angle_rad']`` [rad] is where the film first ruptures downstream of
        the peak pressure, ``extra['inlet_flow_m3_per_s']`` the oil entering through the
        inlet line and supply features (= side flow in a steady JFO film); the film
        fraction is kept in ``self.last_film_fraction``.
        """
        if not (inlet_line or self.geometry.grooves or self.geometry.feed_holes):
            raise CaseError("steady mass-conserving film without inlet line, grooves or feed "
                            "holes: oil only leaves through the edges, so no loaded steady "
                            "state exists (allowed: inlet_line=True or a supply feature)")
        f = self.fields(state)
        theta, _ = self.grid()
        psi = math.atan2(state.eccentricity_y, state.eccentricity_x)
        inlet = nearest_theta_index(psi + math.pi, self.film_grid)
        if inlet_line:
            f.supply[inlet, 1:-1] = True
            f.fixed_pressure[inlet, :] = -self.reduced_cavitation(state)
        fraction = np.ones_like(f.h)
        pressure = self.start_pressure(f, fraction, None, state)
        if cavitation == "jfo":
            sweeps, change = elrod_adams_steady(
                pressure, fraction, f.free, f.a_east, f.a_north, f.couette_east, f.squeeze,
                self._omega, self.tolerance, self.max_iterations,
)
        else:
            source = convection(f.couette_east, fraction) + f.squeeze
            sweeps, change = projected_sor(
                pressure, f.free.copy(), f.a_east, f.a_north, source,
                -self.reduced_cavitation(state), self._omega, self.tolerance,
                self.max_iterations,
)
        self._check(sweeps, change, state)
        self.last_film_fraction = fraction
        result = self.characteristics(state, f, pressure, fraction)
        result.extra.update(iterations=float(sweeps), relative_change=change,
                            film_end_angle_rad=film_end_angle(theta, pressure, inlet),
                            inlet_flow_m3_per_s=result.supply_flow)
        if with_pressure:
            result.pressure = self.gauge_pressure(pressure, state)
        return result

    # ------------------------------------------------------------------- helpers
    def fraction_field(self, history: np.ndarray | None, f: FilmFields) -> np.ndarray:
        """Film fraction ϑ [-] of ``history`` clipped to [0, 1], full on the Dirichlet nodes
        of ``f`` (a full film when None)."""
        if history is None:
            return np.ones_like(f.h)
        fraction = np.clip(np.asarray(history, dtype=float), 0.0, 1.0)
        return np.where(f.free, fraction, 1.0)

    # ------------------------------------------------- piezoviscous hooks (q ↔ p)
    def reduced_cavitation(self, state: FilmState) -> float:
        """Cavitation bound of the solved variable, q(p_cav) or p_cav [Pa]."""
        p_cav = self.geometry.cavitation_pressure
        law = self.pressure_viscosity
        return p_cav if law is None else float(law.to_reduced(p_cav, state.viscosity))

    def _fixed_values(self, state: FilmState) -> np.ndarray:
        """Shifted Dirichlet values q(p) − q(p_cav) (p − p_cav when isoviscous) [Pa]."""
        if self.pressure_viscosity is None:
            return self._fixed.copy()
        supply = float(self.pressure_viscosity.to_reduced(self.geometry.supply_pressure,
                                                          state.viscosity))
        return np.where(self._supply, supply, 0.0) - self.reduced_cavitation(state)

    def gauge_pressure(self, shifted: np.ndarray, state: FilmState) -> np.ndarray:
        """Gauge pressure p [Pa] from the solved, shifted field p̃ (or q̃)."""
        law = self.pressure_viscosity
        if law is None:
            return shifted + self.geometry.cavitation_pressure
        return law.from_reduced(shifted + self.reduced_cavitation(state), state.viscosity)

    def start_pressure(self, f: FilmFields, fraction: np.ndarray,
                       warm: np.ndarray | None, state: FilmState) -> np.ndarray:
        """Start of the shifted pressure p̃ [Pa]: ``warm`` (else −p_cav) on the free nodes,
        the Dirichlet values on the others, 0 where the film is broken."""
        offset = -self.reduced_cavitation(state)
        start = warm if warm is not None else np.full(f.h.shape, offset)
        pressure = np.where(f.free, start, f.fixed_pressure)
        return np.ascontiguousarray(np.where(f.free & (fraction < FULL), 0.0, pressure))

    def _check(self, sweeps: int, change: float, state: FilmState) -> None:
        self.last_iterations = sweeps
        if not change <= self.tolerance:
            raise ConvergenceError(
                f"mass-conserving film did not converge in {sweeps} sweeps",
                where=f"e = ({state.eccentricity_x:.3e}, {state.eccentricity_y:.3e}) m",
                residual=change,
)

    def characteristics(
        self, state: FilmState, f: FilmFields, pressure: np.ndarray, fraction: np.ndarray,
        inflows: tuple[float, float] | None = None,
) -> FilmResult:
        """Forces, torques, flows, extremes from the shifted pressure p̃ and ϑ."""
        from conrod.film.mass_conserving.results import film_characteristics

        if inflows is None:
            _, from_edges, from_supply = cell_balance(pressure, fraction, f.free, f.edge,
                                                      f.a_east, f.a_north, f.couette_east,
                                                      f.squeeze)
            inflows = (from_edges, from_supply)
        return film_characteristics(self, state, f, pressure, fraction, inflows)

