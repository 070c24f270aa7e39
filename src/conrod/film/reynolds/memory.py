"""Warm start of the Reynolds film (:class:`~conrod.film.reynolds.film.ReynoldsFilm`): the last
solved pressure field and a secant predictor from the one before it."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from conrod.film.base import FilmState

__all__ = ["PREDICTOR_RANGE", "ReynoldsMemory", "scaled_state"]

PREDICTOR_RANGE = (-1.0, 2.0)
"""Range of the secant step α of the warm-start predictor [-] (:class:`ReynoldsMemory`):
beyond it the last two fields say little about the next one."""


@dataclass(frozen=True)
class ReynoldsMemory:
    """Warm start of :class:`ReynoldsFilm`: the last converged pressure field, and the one
    before it for a secant predictor.

    pressure : ndarray or None  p(θ, z) on the fine grid [Pa]; None for a cold start
        (nested coarse-to-fine grids). Never modified in place.
    state : ndarray or None  Scaled state q = (e/c, ė/(c ω̃)) of ``pressure`` [-]
        (ω̃ = max(|ω_j + ω_b|, 1 rad/s)); None: no predictor.
    previous, previous_state : ndarray or None  The field and state solved before [Pa, -].

    A warm solve at state q starts from p + α (p − p_previous), α = (q − q_p)·d/|d|²,
    d = q_p − q_previous, α clipped to ``PREDICTOR_RANGE``: the secant of the last two
    solves along the direction the state moved (creeping journal 144×32 / 288×64 at 1e-12:
    11 → 9 cycles). Repeated calls at one state get α = 0, the last field itself.
    """

    pressure: np.ndarray | None = None
    state: np.ndarray | None = None
    previous: np.ndarray | None = None
    previous_state: np.ndarray | None = None

    def start(self, state: np.ndarray) -> np.ndarray | None:
        """Warm-start field for the scaled ``state`` [Pa] (a new array), None when cold."""
        if self.pressure is None:
            return None
        previous, alpha = self.secant(state)
        if alpha == 0.0:
            return self.pressure.copy()
        return self.pressure + alpha * (self.pressure - previous)

    def secant(self, state: np.ndarray) -> tuple[np.ndarray, float]:
        """(field before the last [Pa], secant step α [-]) of :meth:`start` for the scaled
        ``state``: the start is p + α(p − field); (p, 0.0) when there is no predictor.
        Requires ``pressure``."""
        if self.previous is None or self.state is None or self.previous_state is None:
            return self.pressure, 0.0
        direction = self.state - self.previous_state
        length = float(direction @ direction)
        if not length > 0.0:
            return self.pressure, 0.0
        alpha = float((state - self.state) @ direction) / length
        alpha = min(max(alpha, PREDICTOR_RANGE[0]), PREDICTOR_RANGE[1])
        return self.previous, alpha

    def after(self, pressure: np.ndarray, state: np.ndarray) -> ReynoldsMemory:
        """The memory after a solve of ``pressure`` at the scaled ``state``."""
        return ReynoldsMemory(pressure, state, self.pressure, self.state)


def scaled_state(state: FilmState, clearance: float) -> np.ndarray:
    """q = (e_x/c, e_y/c, v_x/(c ω̃), v_y/(c ω̃)) [-], ω̃ = max(|ω_j + ω_b|, 1 rad/s)."""
    speed = clearance * max(abs(state.journal_speed + state.shell_speed), 1.0)
    return np.array([state.eccentricity_x / clearance, state.eccentricity_y / clearance,
                     state.velocity_x / speed, state.velocity_y / speed])
