"""The warm start's secant predictor: exact where it must be, closer where it can be."""

from __future__ import annotations

import numpy as np

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.reynolds.memory import ReynoldsMemory, scaled_state

GEOMETRY = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)


def _state(angle: float) -> FilmState:
    c = GEOMETRY.radial_clearance
    return FilmState(eccentricity_x=0.6 * c * np.cos(angle),
                     eccentricity_y=0.6 * c * np.sin(angle), journal_speed=200.0,
                     viscosity=0.02)


def _chain(film, angles):
    memory = film.initial_memory()
    for angle in angles:
        _, memory = film.solve_with_memory(_state(angle), memory)
    return memory


def test_repeated_state_starts_from_the_last_field():
    """α = 0 at the state of the last solve: the start is that field, bit for bit."""
    film = ReynoldsFilm(GEOMETRY, n_theta=72, n_z=16)
    memory = _chain(film, (0.0, 0.01))
    start = memory.start(scaled_state(_state(0.01), GEOMETRY.radial_clearance))
    assert np.array_equal(start, memory.pressure)


def test_secant_start_is_closer_and_needs_fewer_cycles():
    """Along a creeping journal (uniform steps) the secant start is nearer the converged
    field than the last one (its error is second order in the step, the last field's
    first order), and the solve needs fewer cycles."""
    film = ReynoldsFilm(GEOMETRY, n_theta=144, n_z=32, tolerance=1e-12)
    memory = _chain(film, (0.0, 0.002))
    exact = film.solve(_state(0.004), with_pressure=True).pressure
    q = scaled_state(_state(0.004), GEOMETRY.radial_clearance)
    predicted = np.maximum(memory.start(q), 0.0)
    last_error = np.abs(memory.pressure - exact).max()
    assert np.abs(predicted - exact).max() < 0.5 * last_error
    without = ReynoldsMemory(memory.pressure)
    plain = film.solve_with_memory(_state(0.004), without)[0].extra["sweeps"]
    secant = film.solve_with_memory(_state(0.004), memory)[0].extra["sweeps"]
    assert secant < plain


def test_predictor_step_is_clipped():
    """A state far along the last step extrapolates at most PREDICTOR_RANGE[1] steps."""
    old, new = np.zeros((4, 3)), np.ones((4, 3))
    memory = ReynoldsMemory(new, np.array([1.0, 0, 0, 0]), old, np.zeros(4))
    assert np.array_equal(memory.start(np.array([50.0, 0, 0, 0])), 3.0 * np.ones((4, 3)))
