"""The bearing load over one cycle, as the orbit solver consumes it.

:class:`LoadCycle` is the hand-over between the loads stage (engine loads or a load
table) and the orbit solver. Sign convention (``docs/conventions.md``): ``load_x``,
``load_y`` is the force **pressing the journal against the shell**, in the bearing
(film) frame; the journal centre moves towards it relative to the shell, and the
film force on the journal balances it (F + W = 0 at equilibrium). For a big end in
the rod frame this is minus the force that the rod exerts on the crankpin.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from conrod.errors import CaseError


@dataclass(frozen=True)
class LoadCycle:
    """Periodic load diagram with the surface speeds, sampled on a crank-angle grid.

    crank_angle : ndarray  Sample angles φ, strictly increasing, within one cycle [rad].
    load_x, load_y : ndarray  Load pressing the journal on the shell, film frame [N].
    journal_speed, shell_speed : ndarray  ω_j, ω_b relative to the film frame [rad/s].
    crank_speed : float  Crank angular velocity ω maps angle to time, t = φ/ω [rad/s].
    cycle : float  Period in crank angle: 2π or 4π [rad].
    """

    crank_angle: np.ndarray
    load_x: np.ndarray
    load_y: np.ndarray
    journal_speed: np.ndarray
    shell_speed: np.ndarray
    crank_speed: float
    cycle: float

    def __post_init__(self) -> None:
        angle = np.asarray(self.crank_angle, dtype=float)
        if angle.ndim != 1 or angle.size < 4:
            raise CaseError("load cycle: at least 4 crank angles are needed")
        if not np.all(np.diff(angle) > 0):
            raise CaseError("load cycle: crank angles must be strictly increasing")
        if angle[-1] - angle[0] >= self.cycle + 1e-9:
            raise CaseError(
                f"load cycle: angles span {math.degrees(angle[-1] - angle[0]):.1f} deg, "
                f"more than the cycle of {math.degrees(self.cycle):.0f} deg"
)
        for name in ("load_x", "load_y", "journal_speed", "shell_speed"):
            values = np.asarray(getattr(self, name), dtype=float)
            if values.shape != angle.shape or not np.all(np.isfinite(values)):
                raise CaseError(f"load cycle: {name} must be finite and match crank_angle")

    @functools.cached_property
    def _wrapped(self) -> tuple[np.ndarray, dict[str, np.ndarray]]:
        """(φ, column name → values) of the samples within one period, sorted and extended
        by the last sample before and the first after: what ``np.interp(..., period=)``
        builds on every call (a sort of the whole table), built once."""
        period = abs(self.cycle)
        phi = np.asarray(self.crank_angle, dtype=np.float64) % period
        order = np.argsort(phi)
        phi = phi[order]
        columns = {}
        for name in ("load_x", "load_y", "journal_speed", "shell_speed"):
            values = np.asarray(getattr(self, name), dtype=float)[order]
            columns[name] = np.concatenate((values[-1:], values, values[0:1]))
        return np.concatenate((phi[-1:] - period, phi, phi[0:1] + period)), columns

    def _periodic(self, name: str, crank_angle: np.ndarray | float) -> np.ndarray:
        """Column ``name`` at ``crank_angle`` [rad]: ``np.interp`` with the period, bit for
        bit."""
        phi, columns = self._wrapped
        return np.interp(np.asarray(crank_angle, dtype=np.float64) % abs(self.cycle), phi,
                         columns[name])

    def load(self, crank_angle: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """Load (W_x, W_y) [N] at any crank angle [rad], periodic linear interpolation."""
        return self._periodic("load_x", crank_angle), self._periodic("load_y", crank_angle)

    def speeds(self, crank_angle: np.ndarray | float) -> tuple[np.ndarray, np.ndarray]:
        """Surface speeds (ω_j, ω_b) [rad/s] at any crank angle [rad]."""
        return self._periodic("journal_speed", crank_angle), self._periodic("shell_speed",
                                                                            crank_angle)

    @property
    def period_time(self) -> float:
        """Duration of one cycle [s]."""
        return self.cycle / self.crank_speed
