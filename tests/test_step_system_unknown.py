"""A film unknown that plugs into the journal's implicit step by declaring itself.

A test-only film (:class:`ThermalShortFilm`) adds one unknown of its own to the
closed-form short bearing: a film temperature rise T [K] that lowers the viscosity,
F = (1 − γT) F_0(e, v), and that the loaded film heats, G = T − κ‖F_0‖ = 0
(‖F‖ = √(|F|² + 1 N²), smooth at the concentric start). It declares
:class:`~conrod.film.capabilities.HasStepSystem` and nothing else of the elastic films: the
orbit's one step driver and Newton iteration (:mod:`conrod.orbit.implicit_step`,
:mod:`conrod.numerics.newton`) solve T with the journal unchanged. Independent answers:
the balance G = 0 at every output angle, the uncoupled limit (γ = κ = 0) against the
error-controlled orbit of the short bearing itself, and central differences of the step
system's Jacobian blocks."""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np
import pytest

from conrod.cases.solver import SolverSection
from conrod.film.base import FilmState
from conrod.film.capabilities import HasContentStep, HasStepSystem
from conrod.film.linearised import linearise
from conrod.film.short.film import ShortBearingFilm
from conrod.film.step_system import StepRequest
from conrod.numerics.newton import ChordJacobian, StepBlocks, UpdateLimits
from conrod.orbit.characteristics import cycle_characteristics
from conrod.orbit.implicit_step import needs_journal_step
from conrod.orbit.periodic import periodic_orbit
from conrod.orbit.problem import OrbitProblem
from elastic_helpers import assert_jacobian_columns, step_jacobian_and_residual
from test_orbit_jfo import OMEGA, fed_bearing, rotating_load

HEATING = 4e-3
"""κ: temperature rise per newton of film force [K/N]."""
SMOOTHING = 1.0
"""Force added in quadrature to |F_0| so that the heating is smooth at F_0 = 0 [N]."""
THINNING = 0.02
"""γ: relative loss of film force per kelvin [1/K]."""


@dataclass(frozen=True)
class Temperature:
    """The thermal film's memory: the film temperature rise T [K]."""

    value: float = 0.0


class ThermalShortFilm:
    """Short-bearing film with a film temperature rise T as an unknown of its own."""

    name = "short"

    def __init__(self, heating: float = HEATING, thinning: float = THINNING):
        self.base = ShortBearingFilm(fed_bearing())
        self.geometry = self.base.geometry
        self.heating, self.thinning = heating, thinning
        self.chord = ChordJacobian()

    def grid(self):
        return self.base.grid()

    def initial_history(self):
        return None

    def initial_memory(self) -> Temperature:
        return Temperature()

    def force(self, state: FilmState):
        return self.base.force(state)

    def solve(self, state: FilmState, *, with_pressure: bool = False):
        return self.base.solve(state, with_pressure=with_pressure)

    def solve_with_memory(self, state, memory: Temperature, *, with_pressure=False):
        result = self.base.solve(state, with_pressure=with_pressure)
        factor = 1.0 - self.thinning * memory.value
        return dataclasses.replace(result, force_x=factor * result.force_x,
                                   force_y=factor * result.force_y), memory

    def force_with_memory(self, state, memory: Temperature):
        result, memory = self.solve_with_memory(state, memory)
        return result.force_x, result.force_y, memory

    def advance_memory(self, state, memory: Temperature, dt: float) -> Temperature:
        return memory

    def supports_step_system(self) -> bool:
        return True

    def step_system(self, request: StepRequest) -> ThermalStep:
        return ThermalStep(self, request)


class ThermalStep:
    """G = T − κ‖F_0‖, F = (1 − γT) F_0 at the end of the step (module docstring)."""

    def __init__(self, film: ThermalShortFilm, request: StepRequest):
        self.film, self.request = film, request
        self.start = np.array([request.memory.value])
        self.limits = UpdateLimits(0.5, None, gap=slice(0, 0))  # no film-thickness unknown
        self.scale, self.tolerance, self.max_solves = 1.0, 1e-9, 40
        self.chord = film.chord

    def state(self, velocity: np.ndarray) -> FilmState:
        x, y = self.request.position(velocity)
        return FilmState(eccentricity_x=float(x), eccentricity_y=float(y),
                         velocity_x=float(velocity[0]), velocity_y=float(velocity[1]),
                         journal_speed=self.request.journal_speed,
                         shell_speed=self.request.shell_speed,
                         viscosity=self.request.viscosity)

    def evaluate(self, own: np.ndarray, velocity: np.ndarray):
        state = self.state(velocity)
        base = np.array(self.film.base.force(state))
        g = np.array([own[0] - self.film.heating * _loading(base)])
        c = self.film.geometry.radial_clearance
        h_min = c - float(np.hypot(state.eccentricity_x, state.eccentricity_y))
        return g, (1.0 - self.film.thinning * own[0]) * base, h_min, (state, own[0], base)

    def respond(self, payload) -> StepBlocks:
        state, temperature, base = payload
        lin = linearise(self.film.base, state)
        by_velocity = -self.request.tau * lin.stiffness - lin.damping  # τ ∂/∂e + ∂/∂v
        direction = base / _loading(base)
        return StepBlocks(np.eye(1), -self.film.heating * (direction @ by_velocity)[None, :],
                          -self.film.thinning * base[:, None],
                          (1.0 - self.film.thinning * temperature) * by_velocity)

    def finish(self, outcome) -> Temperature:
        return Temperature(float(outcome.own[0]))


def _loading(force: np.ndarray) -> float:
    """‖F‖ = √(|F|² + :data:`SMOOTHING`²) [N]."""
    return float(np.hypot(np.hypot(*force), SMOOTHING))


def _orbit(film):
    problem = OrbitProblem(film, rotating_load(), 0.02, 1.0, 1.0)
    settings = SolverSection(integrator="implicit", max_step_deg=1.0, output_step_deg=10.0,
                             max_cycles=6, min_cycles=2, periodicity_tolerance=1e-4)
    result = periodic_orbit(problem, settings)
    return problem, result, cycle_characteristics(problem, result.last)


def test_the_film_declares_only_the_step_system():
    film = ThermalShortFilm()
    assert isinstance(film, HasStepSystem) and not isinstance(film, HasContentStep)
    assert needs_journal_step(film)


@pytest.fixture(scope="module")
def heated():
    return _orbit(ThermalShortFilm())


def test_the_temperature_balances_the_heating_at_every_output_angle(heated):
    """G = T − κ‖F_0‖ = 0 at the end of every step (Newton to 1e-9 K); the temperature
    follows the load (measured 3.2–11.8 K) and the thinner film runs the journal closer
    (measured min h_min 0.92 of the uncoupled film's)."""
    problem, result, cycle = heated
    assert result.periodic
    temperatures = np.array([memory.value for memory in result.last.film_memory])
    film = problem.film
    for i, memory in enumerate(result.last.film_memory):
        state = FilmState(eccentricity_x=float(result.last.x[i]),
                          eccentricity_y=float(result.last.y[i]),
                          velocity_x=float(result.last.vx[i]),
                          velocity_y=float(result.last.vy[i]), journal_speed=OMEGA,
                          viscosity=problem.viscosity)
        heating = film.heating * _loading(np.array(film.base.force(state)))
        assert memory.value == pytest.approx(heating, rel=1e-6)
    assert temperatures.min() > 1.0 and temperatures.max() > 3.0 * temperatures.min()
    _, _, cold = _orbit(ThermalShortFilm(heating=0.0, thinning=0.0))
    assert cycle.h_min.min() < 0.99 * cold.h_min.min()


def test_an_uncoupled_unknown_leaves_the_orbit_of_the_film():
    """κ = γ = 0: T stays 0 and the BDF2 steps of 1° give the error-controlled TR-BDF2
    orbit of the short bearing itself: h_min and p_max within 0.2 % (measured +6e-5,
    +6e-4)."""
    _, result, cycle = _orbit(ThermalShortFilm(heating=0.0, thinning=0.0))
    assert all(memory.value == 0.0 for memory in result.last.film_memory)
    problem = OrbitProblem(ShortBearingFilm(fed_bearing()), rotating_load(), 0.02, 1.0, 1.0)
    settings = SolverSection(integrator="implicit", output_step_deg=10.0, max_cycles=6,
                             min_cycles=2, periodicity_tolerance=1e-4)
    reference = cycle_characteristics(problem, periodic_orbit(problem, settings).last)
    assert cycle.h_min.min() == pytest.approx(reference.h_min.min(), rel=2e-3)
    assert cycle.p_max.max() == pytest.approx(reference.p_max.max(), rel=2e-3)


def test_the_step_system_blocks_match_central_differences():
    """∂(G, F − m a)/∂(T, v) of one BDF2 step against central differences of the step's
    residual, within 1e-5 of each column's largest entry."""
    film = ThermalShortFilm()
    c = film.geometry.radial_clearance
    dt = np.radians(1.0) / OMEGA
    request = StepRequest(np.array([0.5 * c, -0.3 * c]), np.array([0.01, 0.004]),
                          2.0 * dt / 3.0, dt, np.array([1.0, 1.0]), np.array([-900.0, 500.0]),
                          OMEGA, 0.0, 0.02, 0.3, True, (Temperature(2.0), Temperature(1.9)))
    velocity = np.array([0.2 * c * OMEGA, -0.1 * c * OMEGA])
    jac, residual, z0, _ = step_jacobian_and_residual(film, request, np.array([3.0]),
                                                      velocity, c * OMEGA)
    assert_jacobian_columns(jac, residual, z0, (0, 1, 2), tolerance=1e-5)
