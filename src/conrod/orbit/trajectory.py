"""Journal-centre samples of one integrated cycle (what every integrator returns)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.orbit.problem import OrbitState


@dataclass
class CycleTrajectory:
    """Samples at the output crank angles of one cycle.

    crank_angle : ndarray  Output angles [rad].
    x, y : ndarray  Journal centre relative to the shell centre [m].
    vx, vy : ndarray  Its velocity [m/s].
    contact_force : ndarray  Hard-contact force P_c [N].
    friction_force : ndarray  Dry friction μ_dry P_c [N].
    in_contact : ndarray  Journal on the contact circle [-].
    end_state : OrbitState  State at the end of the cycle (start of the next).
    steps : int  Integrator steps taken [-].
    film_memory : list or None  Film memory (warm start, mass-conserving film fraction ϑ)
        at each output angle, for films with memory that a Python loop carried.
    tilt : ndarray or None  Journal tilt (γ_x, γ_y [rad], γ̇_x, γ̇_y [rad/s]) at each output
        angle, shape (n, 4), of a tilted run; None: aligned.
    """

    crank_angle: np.ndarray
    x: np.ndarray
    y: np.ndarray
    vx: np.ndarray
    vy: np.ndarray
    contact_force: np.ndarray
    friction_force: np.ndarray
    in_contact: np.ndarray
    end_state: OrbitState
    steps: int = 0
    film_memory: list[Any] | None = None
    tilt: np.ndarray | None = None

    @classmethod
    def from_table(
        cls, crank_angle: np.ndarray, table: np.ndarray, end_state: OrbitState, steps: int
) -> CycleTrajectory:
        """Build from rows (x, y, vx, vy, P_c, P_f, in_contact)."""
        return cls(
            crank_angle=crank_angle, x=table[:, 0].copy(), y=table[:, 1].copy(),
            vx=table[:, 2].copy(), vy=table[:, 3].copy(), contact_force=table[:, 4].copy(),
            friction_force=table[:, 5].copy(), in_contact=table[:, 6] > 0.5,
            end_state=end_state, steps=steps,
)
