"""Finite-difference Reynolds film with Swift–Stieber cavitation ([D2] ch. 3).

The pressure solves the Reynolds equation of :mod:`conrod.film.base` on a
``n_theta × (n_z + 1)``-node grid (:class:`~conrod.film.characteristics.FilmGrid`) with

* p = 0 (ambient, gauge) on the edges z = ±L/2,
* p = supply pressure on grooves and feed holes, the feed pressure on the journal's oil
  holes where ``FilmState.journal_feed`` puts them (:func:`~conrod.film.supply.instant_supply`),
* optionally p = 0 on an axial inlet line at the largest gap θ = ψ + π (Raimondi &
  Boyd's full-bearing condition, ``ambient_line_at_max_gap=True``),
* cavitation by projection p := max(p, p_cav) inside projected SOR
  (:mod:`conrod.film.reynolds.kernel`).

Speed: a cold solve starts on up to three nested grids (coarse → fine, [D2]);
a solve given a :class:`ReynoldsMemory` starts from its field (warm start), moved along the
secant of the last two solves when the memory holds both, which is what makes a transient
orbit cheap. The memory is explicit: the orbit integrator holds it
(:class:`~conrod.film.capabilities.HasMemory`); ``solve``/``force`` alone are cold.
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace
from typing import Any, Literal

import numpy as np

from conrod.errors import CaseError, FilmThicknessError
from conrod.film import characteristics as chars
from conrod.film.base import BearingGeometry, FilmResult, FilmState
from conrod.film.capabilities import CompiledKernel, QuasiStaticRequest
from conrod.film.characteristics import FilmGrid
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.profile import profile_field
from conrod.film.rated_state import state_rate
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds import multigrid as multigrid
from conrod.film.reynolds import viscosity_field as vf
from conrod.film.reynolds.memory import ReynoldsMemory, scaled_state
from conrod.film.reynolds.problem import DiscreteProblem as _Problem
from conrod.film.reynolds.problem import dirichlet_regions, optimal_relaxation  # noqa: F401 (used by the mass-conserving film)
from conrod.film.reynolds.results import reynolds_characteristics
from conrod.film.reynolds.sweep import sweep
from conrod.film.supply import edge_mask, journal_holes_symmetric, supply_mask
from conrod.film.tilt import axial_gap, moment_weights, tilt_fields

FrictionConvention = Literal["full_film", "film_fraction"]
SolverMethod = Literal["multigrid", "sor"]
NESTED_TOLERANCE = 1.0e-4
"""Tolerance of the coarser grids of a cold start [-]: their answer only seeds the next
grid, whose own discretisation differs by ~1e-3, so converging them further is wasted."""


@dataclass
class ReynoldsFilm:
    """Finite-difference Reynolds film model implementing :class:`FilmModel`.

    geometry : BearingGeometry  Geometry and oil supply.
    n_theta : int  Circumferential intervals (= nodes, periodic) [-].
    n_z : int  Axial intervals; the grid has n_z + 1 axial nodes including the edges [-].
    tolerance : float  Stop when max|Δp| ≤ tolerance·max|p| over one multigrid cycle
        (one sweep for SOR), or when two cycles contracted by ρ < 0.5 and the geometric
        estimate of the remaining error, max|Δp|·ρ/(1 − ρ), is ≤ tolerance·max|p| [-].
        The tight default makes the force a smooth function of the state to ~1e-12,
        which implicit integrators need: Radau's finite-difference Jacobians (Ruston &
        Hornsby: 16 000 calls at 1e-12, > 450 000 at 1e-7) and TR-BDF2's Newton
        iterations with the analytic Jacobian (passenger car, 72×16: 9 400 solves per
        cycle at 1e-12, 17 400 at 1e-10, no convergence at 1e-9).
    max_iterations : int  Cycle (SOR: sweep) limit per grid level; beyond it
        ConvergenceError [-].
    friction : 'full_film' (Raimondi–Boyd 360° Couette) or 'film_fraction'.
    ambient_line_at_max_gap : bool  Hold p = 0 on the axial line at θ = ψ + π.
    method : 'multigrid' (projected multigrid, :mod:`reynolds_multigrid`, default) or
        'sor' (projected SOR, kept for comparison).
    relaxation : float or None  SOR factor ω [-]; None = :func:`optimal_relaxation`.
    warm_start : bool  Start each solve from the memory's field (:class:`ReynoldsMemory`)
        when it holds one; False: every solve is cold.
    use_symmetry : bool  Solve only z ≤ 0 when the problem is symmetric about the
        mid-plane (supply features symmetric, no deformation field; multigrid only).
    pressure_viscosity : PressureViscosity or None  μ(p) law: the solver works on the
        reduced pressure q(p) (:mod:`conrod.film.piezoviscosity`) and maps back; the
        warm-start field is q. None = isoviscous.
    deformation_rate : bool  Add the bore's rate ``RatedFilmState.deformation_rate`` [m/s]
        (:mod:`conrod.film.rated_state`) to the squeeze term (:meth:`with_deformation_rate`).
    viscosity_field : ndarray or None  μ(θ, z) [Pa s] for states without a field of their
        own (:meth:`with_viscosity_field`, :mod:`conrod.film.reynolds.viscosity_field`).
    """

    geometry: BearingGeometry
    n_theta: int = 144
    n_z: int = 32
    tolerance: float = 1.0e-12
    max_iterations: int = 20000
    method: SolverMethod = "multigrid"
    friction: FrictionConvention = "full_film"
    ambient_line_at_max_gap: bool = False
    relaxation: float | None = None
    warm_start: bool = True
    use_symmetry: bool = True
    pressure_viscosity: PressureViscosity | None = None
    name: str = "reynolds"
    deformation_rate: bool = False
    viscosity_field: Any = field(default=None, compare=False, repr=False)

    def __post_init__(self) -> None:
        if self.n_theta < 8 or self.n_theta % 2:
            raise CaseError(f"n_theta = {self.n_theta}: out of range (allowed: even, >= 8)")
        if self.n_z < 2 or self.n_z % 2:
            raise CaseError(f"n_z = {self.n_z}: out of range (allowed: even, >= 2)")
        if self.method not in ("multigrid", "sor"):
            raise CaseError(f"method = {self.method!r}: allowed 'multigrid' or 'sor'")
        if self.friction not in ("full_film", "film_fraction"):
            raise CaseError(
                f"friction = {self.friction!r}: allowed 'full_film' or 'film_fraction'")
        g = self.geometry
        self.film_grid = FilmGrid(g.radius, g.width, self.n_theta, self.n_z)
        self._cos_nodes = np.cos(self.film_grid.theta)
        self._sin_nodes = np.sin(self.film_grid.theta)
        self._cos = self._cos_nodes[:, None]
        self._sin = self._sin_nodes[:, None]
        self._supply = supply_mask(g, self.film_grid)
        self._edges = edge_mask(self.film_grid)
        self._fixed = self._edges | self._supply
        self._moment_weights: tuple[np.ndarray, np.ndarray] | None = None
        self._fixed.setflags(write=False)  # shared by every problem: never modified
        self._supply_values = np.where(self._supply, g.supply_pressure, 0.0)
        self._supply_values.setflags(write=False)
        self._force_weights = chars.force_weights(self.film_grid)
        self._profile = profile_field(g, self.film_grid.theta, self.film_grid.z)
        self.viscosity_field = vf.checked_field(self.viscosity_field, self.deformation_shape())
        self._symmetric = (self.use_symmetry and self.method == "multigrid"
                           and np.array_equal(self._supply, self._supply[:, ::-1])
                           and journal_holes_symmetric(g)
                           and vf.mirror_symmetric(self.viscosity_field)
                           and vf.mirror_symmetric(self._profile))

    @classmethod
    def from_settings(cls, geometry: BearingGeometry, settings: Any) -> ReynoldsFilm:
        """Film on the ``[solver]`` grid ``n_theta`` × ``n_z`` with ``film_tolerance``."""
        return cls(geometry, n_theta=int(settings.n_theta), n_z=int(settings.n_z),
                   tolerance=float(settings.film_tolerance))

    # ----------------------------------------------------------------- interface
    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """θ nodes [rad] (periodic, 2π excluded) and z nodes [m] (edges included)."""
        return self.film_grid.theta, self.film_grid.z

    def initial_history(self) -> None:
        """The Swift–Stieber film has no film-content history."""
        return None

    def deformation_shape(self) -> tuple[int, int]:
        """Shape (n_theta, n_z + 1) of the accepted deformation field δ(θ, z) [m]."""
        return self.n_theta, self.n_z + 1

    def initial_memory(self) -> ReynoldsMemory:
        """No warm-start field: the first solve is cold."""
        return ReynoldsMemory()

    def advance_memory(self, state: FilmState, memory: ReynoldsMemory,
                       dt: float) -> ReynoldsMemory:
        """A warm start does not evolve in time: ``memory`` unchanged."""
        return memory

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N] (cold solve)."""
        fx, fy, _ = self.force_with_memory(state, self.initial_memory())
        return fx, fy

    def force_with_memory(self, state: FilmState,
                          memory: ReynoldsMemory) -> tuple[float, float, ReynoldsMemory]:
        """Film force (F_x, F_y) [N] warm-started from ``memory``, and the new memory."""
        problem = self._problem(state)
        reduced, _ = self.solve_pressure(problem, state, memory)
        pressure = self._physical(reduced, state)
        w_x, w_y = self._force_weights
        sum_x, sum_y, *_ = kernel.force_and_extremes(pressure, w_x, w_y, problem.h)
        return -sum_x, -sum_y, self._memory_after(memory, reduced, state)

    def sensitivities(self, state: FilmState):
        """Force and moments, stiffness K = −∂Q/∂q and damping C = −∂Q/∂q̇ of
        Q = (F_x, F_y, M_x, M_y) by q = (e_x, e_y, γ_x, γ_y) (the 4 × 4 set; its 2 × 2 block
        in ``stiffness``, ``damping`` [N/m, N s/m]) from one solve and four adjoint solves
        on the converged active set (:func:`conrod.film.linearised.linearise_reynolds`);
        central differences when the viscosity depends on pressure (a pressure-dependent
        viscosity maps the solved field nonlinearly to the pressure)."""
        from conrod.film.linearised import linearise_by_differences, linearise_reynolds

        if self.pressure_viscosity is None and self._field(state) is None:
            return linearise_reynolds(self, state, tilt=True)
        return linearise_by_differences(self, state, tilt=True)

    def force_jacobian(self, state: FilmState, memory: ReynoldsMemory):
        """(F [N], ∂F/∂(e, ė) (2 × 4) [N/m, N s/m], memory) from the linearised solve on
        the converged active set, warm-started from ``memory``
        (:class:`~conrod.film.capabilities.HasForceJacobian`)."""
        from conrod.film.linearised import linearise_by_differences, linearise_reynolds

        lin = (linearise_reynolds(self, state, memory=memory) if self._field(state) is None
               else linearise_by_differences(self, state))  # a viscosity field: differences
        return lin.force, np.hstack([-lin.stiffness, -lin.damping]), memory

    def tilt_jacobian(self, state: FilmState, memory: ReynoldsMemory,
                      tolerance: float | None = None, tilt: bool = True):
        """(Q = (F, M) [N, N m], ∂Q/∂(e, γ, ė, γ̇) (4 × 8), memory), adjoints to
        ``tolerance`` (:func:`conrod.film.linearised.tilt_jacobian`, ``tilt`` False: F)."""
        from conrod.film.linearised import tilt_jacobian

        return tilt_jacobian(self, state, memory, tolerance, tilt)

    def flight_kernel(self, memory: ReynoldsMemory | None, newton_tolerance: float):
        """Compiled force and Jacobian warm-started from ``memory`` for the implicit orbit
        with mass (:func:`conrod.film.reynolds.flight.flight_kernel`; None when not exact
        for this configuration)."""
        from conrod.film.reynolds.flight import flight_kernel

        return None if self.geometry.journal_holes else flight_kernel(  # fixed supply mask
            self, memory, newton_tolerance)

    def tilt_flight_kernel(self, memory: Any, newton_tolerance: float, free: bool = True):
        """Compiled forces and moments of a tilted journal (or None, ``tilt_flight``)."""
        from conrod.film.reynolds.tilt_flight import tilt_flight_kernel

        return None if self.geometry.journal_holes or self.viscosity_field is not None else \
            tilt_flight_kernel(  # a fixed mask, no viscosity field
            self, memory, newton_tolerance, free)

    def with_deformation_rate(self) -> ReynoldsFilm:
        """This film with the bore's rate in its squeeze term
        (:class:`~conrod.film.capabilities.SupportsDeformationRate`)."""
        return replace(self, deformation_rate=True)

    def with_viscosity_field(self, viscosity_field: np.ndarray | None) -> ReynoldsFilm:
        """This film carrying μ(θ, z) [Pa s] for the states without a field of their own
        (:class:`~conrod.film.capabilities.HasViscosityField`); None: scalar viscosity."""
        return replace(self, viscosity_field=viscosity_field)

    def film_flows(self, state: FilmState, memory: ReynoldsMemory) -> tuple[Any, ReynoldsMemory]:
        """(Volume fluxes and dissipation of ``state`` on the grid, the memory after the
        solve) (:func:`conrod.film.reynolds.thermal_flows.film_flows`)."""
        from conrod.film.reynolds.thermal_flows import film_flows

        flows, reduced = film_flows(self, state, memory)
        return flows, self._memory_after(memory, reduced, state)

    def _field(self, state: FilmState) -> np.ndarray | None:
        """The viscosity field a solve of ``state`` uses [Pa s] (None: the scalar)."""
        field = vf.state_field(state, self.viscosity_field, self.deformation_shape())
        if field is not None and self.pressure_viscosity is not None:
            raise CaseError("viscosity_field with pressure_viscosity: not combined (allowed: "
                            "a viscosity field or a pressure-viscosity law)")
        return field

    def evaluate_pressure(self, state: FilmState, memory: ReynoldsMemory | None = None,
                          accuracy: float | None = None):
        """The pressure alone (a PressureEvaluation) from ``memory`` to ``accuracy`` [-]."""
        from conrod.film.reynolds.response import evaluate_pressure

        return evaluate_pressure(self, state, memory, accuracy)

    def answered_evaluation(self, state: FilmState, memory: ReynoldsMemory):
        """The evaluation of ``state`` whose converged pressure ``memory`` holds (no solve)."""
        from conrod.film.reynolds.response import answered_evaluation
        return answered_evaluation(self, state, memory)

    def exact_thickness_response(self) -> bool:
        """True when isoviscous (with or without a viscosity field: its conductances are
        those of h_μ, :mod:`conrod.film.reynolds.response`): a pressure-dependent viscosity
        maps the solved field nonlinearly to the pressure [-]."""
        return self.pressure_viscosity is None

    def thickness_response(self, state: FilmState, solved: Any, nodal: np.ndarray,
                           rate_step: float | None, tilt: tuple[float, float] | None = None):
        """Response of the nodal loads and the force (with ``tilt`` = (τ, ℓ) also of the
        moments, and by the edge velocities) to the film thickness at the solve ``solved``
        (:func:`conrod.film.reynolds.response.thickness_response`)."""
        from conrod.film.reynolds.response import thickness_response

        return thickness_response(self, state, solved.pressure, nodal, rate_step, tilt)

    @property
    def force_weights(self) -> tuple[np.ndarray, np.ndarray]:
        """(w_x, w_y) with the film force F = −Σ p (w_x, w_y) [m²]."""
        return self._force_weights

    @property
    def moment_weights(self) -> tuple[np.ndarray, np.ndarray]:
        """(w_Mx, w_My) with the moments M = −Σ p (w_Mx, w_My) [m³]
        (:func:`conrod.film.tilt.moment_weights`)."""
        if self._moment_weights is None:
            self._moment_weights = moment_weights(self._cos_nodes, self._sin_nodes,
                                                  self.film_grid.z, self.film_grid.area_weights)
        return self._moment_weights

    @property
    def profile(self) -> np.ndarray | None:
        """The bore/shell profile h₀ on the grid [m] (None: a cylindrical bore)."""
        return self._profile

    @property
    def node_directions(self) -> tuple[np.ndarray, np.ndarray]:
        """(cos θ, sin θ) of the θ nodes [-]."""
        return self._cos_nodes, self._sin_nodes

    @property
    def symmetric(self) -> bool:
        """True when only z ≤ 0 is solved for an undeformed film (mid-plane symmetry)."""
        return self._symmetric

    def discrete_problem(self, state: FilmState) -> Any:
        """The discrete problem of ``state``: film thickness h and its rate [m, m/s], the
        Dirichlet nodes and values, the cavitation bound."""
        return self._problem(state)

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """All film characteristics for one state (cold solve)."""
        return self.solve_with_memory(state, self.initial_memory(),
                                      with_pressure=with_pressure)[0]

    def solve_with_memory(self, state: FilmState, memory: ReynoldsMemory, *,
                          with_pressure: bool = False) -> tuple[FilmResult, ReynoldsMemory]:
        """All characteristics (friction convention in ``extra``) warm-started from
        ``memory``, and the memory after the solve."""
        problem = self._problem(state)
        reduced, info = self.solve_pressure(problem, state, memory)
        pressure = self._physical(reduced, state)
        result = self.characteristics(problem, reduced, pressure, state, info)
        if with_pressure:
            result.pressure = pressure
        return result, self._memory_after(memory, reduced, state)

    def _memory_after(self, memory: ReynoldsMemory, reduced: np.ndarray,
                      state: FilmState) -> ReynoldsMemory:
        """The warm start after a solve: the solved (reduced) field, its state and the
        memory's field as the predictor's previous one."""
        if not isinstance(memory, ReynoldsMemory):
            return ReynoldsMemory(reduced)
        return memory.after(reduced, scaled_state(state, self.geometry.radial_clearance))

    def compiled_kernel(self) -> CompiledKernel | None:
        """Booker's squeeze-direction loop (:mod:`conrod.film.reynolds.squeeze`), exact for a
        rigid, isoviscous multigrid film with p_supply = p_cav = 0 and no inlet line; else None."""
        g = self.geometry
        exact = (self.method == "multigrid" and not self.ambient_line_at_max_gap
                 and g.supply_pressure == 0.0 and g.cavitation_pressure == 0.0
                 and self.pressure_viscosity is None  # homogeneous in v_s only if isoviscous
                 and self._profile is None and self.viscosity_field is None  # circular bore
                 and not g.journal_holes)  # the supply mask does not move
        return CompiledKernel(None, (), self._squeeze_cycle) if exact else None

    def _squeeze_cycle(self, request: QuasiStaticRequest) -> Any:
        from conrod.film.reynolds.squeeze import squeeze_cycle

        return squeeze_cycle(self, request)

    # ------------------------------------------------- piezoviscous hooks (q ↔ p)
    def _reduced(self, pressure: float, state: FilmState) -> float:
        """Solved variable for a pressure [Pa]: q(p) when piezoviscous, else p."""
        law = self.pressure_viscosity
        return pressure if law is None else float(law.to_reduced(pressure, state.viscosity))

    def _physical(self, reduced: np.ndarray, state: FilmState) -> np.ndarray:
        """Pressure field [Pa] from the solved field (identity when isoviscous)."""
        law = self.pressure_viscosity
        return reduced if law is None else law.from_reduced(reduced, state.viscosity)

    # ----------------------------------------------------------------- internals
    def _problem(self, state: FilmState) -> _Problem:
        """Film thickness, its rate and the Dirichlet regions for ``state``."""
        g = self.geometry
        h, h_rate = kernel.film_gap(g.radial_clearance, state.eccentricity_x,
                                    state.eccentricity_y, state.velocity_x, state.velocity_y,
                                    self._cos_nodes, self._sin_nodes, self.n_z + 1)
        tilt, tilt_rate = tilt_fields(state, self._cos_nodes, self._sin_nodes,
                                      self.film_grid.z) if state.tilted else (None, None)
        axial = axial_gap(self._profile, tilt)
        if axial is not None:  # the profile h₀ and the journal's tilt (conrod.film.tilt)
            h = h + axial
        if tilt_rate is not None:
            h_rate = h_rate + tilt_rate
        rate = state_rate(state) if self.deformation_rate else None
        if rate is not None:  # the bore's own rate in the squeeze term
            h_rate = h_rate + rate
        if state.deformation is not None:
            if np.shape(state.deformation) != h.shape:
                raise CaseError(
                    f"deformation shape = {np.shape(state.deformation)}: "
                    f"out of range (allowed: {h.shape} = (n_theta, n_z + 1))")
            h = h + state.deformation
        smallest = float(h.min())
        if not smallest > 0.0:
            raise FilmThicknessError(
                f"film thickness min = {smallest:.3g} m (must stay > 0 m): the journal "
                "touches the shell; the load is beyond what the film and the contact model "
                "carry at this step (try a contact model, a finer step or a larger clearance)")
        values = (self._supply_values if self.pressure_viscosity is None
                  else np.where(self._supply, self._reduced(g.supply_pressure, state), 0.0))
        fixed, values, fed = dirichlet_regions(
            self.film_grid, state, g, (self._fixed, values),
            lambda p: self._reduced(p, state), self.ambient_line_at_max_gap)
        field = self._field(state)
        conduction = None if field is None else vf.conduction_thickness(h, state.viscosity, field)
        return _Problem(self.film_grid, h, h_rate, fixed, values, self._reduced(
            g.cavitation_pressure, state), journal_holes=fed, conduction=conduction, h_min=smallest)

    def _levels(self, problem: _Problem) -> list[_Problem]:
        """Coarse-to-fine problems: up to three nested grids for a cold start, none
        coarser than 48 θ intervals (below that the extra level costs more than it saves:
        72×16 cold 0.17 → 0.14 ms CPU)."""
        levels = [problem]
        while len(levels) < 3:
            g = levels[-1].grid
            if g.n_theta % 4 or g.n_z % 4 or g.n_theta < 96 or g.n_z < 8:
                break
            levels.append(levels[-1].coarsened())
        return levels[::-1]

    def solve_pressure(self, problem: _Problem, state: FilmState, memory: ReynoldsMemory,
                       accuracy: float | None = None) -> tuple[np.ndarray, dict]:
        """Pressure [Pa] and diagnostics, to ``accuracy`` where looser than the tolerance."""
        tolerance = self.tolerance if accuracy is None else max(self.tolerance, accuracy)
        warm = self.warm_start and memory.pressure is not None
        if warm:
            last, previous, step = memory.pressure, memory.pressure, 0.0
            if isinstance(memory, ReynoldsMemory):
                previous, step = memory.secant(
                    scaled_state(state, self.geometry.radial_clearance))
            pressure = kernel.warm_field(last, previous, step, problem.cavitation,
                                         problem.fixed, problem.fixed_values)
            total, change = sweep(self, problem, pressure, state, tolerance, True)
        else:
            levels = self._levels(problem)
            pressure = np.zeros(levels[0].h.shape)
            total = 0
            for k, level in enumerate(levels):
                if k > 0:
                    pressure = np.maximum(kernel.prolongate(pressure), level.cavitation)
                final = k == len(levels) - 1
                sweeps, change = sweep(self, level, pressure, state, tolerance if final
                                       else max(10.0 * tolerance, NESTED_TOLERANCE))
                total += sweeps
        return pressure, {"sweeps": float(total), "relative_update": change,
                          "warm_start": float(warm), "multigrid": float(self.method == "multigrid")}

    def characteristics(self, problem: _Problem, reduced: np.ndarray, pressure: np.ndarray,
                        state: FilmState, info: dict) -> FilmResult:
        """All characteristics of a solve of ``problem``: flows and cavitation from the
        solved (reduced) field, forces, p_max and shear from the pressure with μ(p)
        (:func:`conrod.film.reynolds.results.reynolds_characteristics`)."""
        return reynolds_characteristics(self, problem, reduced, pressure, state, info)
