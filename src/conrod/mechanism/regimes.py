"""Operating modes (speed × load) ranked by diagnostic value ([D3]): the statistics of one
mode and the results of a sweep over many (run by :func:`conrod.sweep.mechanism.run_sweep`).

The most informative diagnostic regime is the one where the worn joint knocks hardest
**relative to** the other joint: the ratio

    κ = v_worn,max / max(v_other,max, v_floor),

with v_floor = 1 mm/s so that a silent other joint does not give an infinite ratio.
Runs are independent and deterministic (≈ 0.3–0.6 s each, compiled).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from conrod.mechanism.results import JOINT_NAMES
from conrod.mechanism.setup import MechanismCase
from conrod.mechanism.simulation import simulate

VELOCITY_FLOOR = 1.0e-3
"""Smallest impact velocity counted as audible in the ratio κ [m/s]."""


@dataclass(frozen=True)
class SweepResults:
    """One row per operating mode.

    speed_rpm : ndarray  Crank speed [rpm]; load_scale : ndarray  Gas-force factor [-].
    max_velocity, mean_velocity : ndarray  (2, n) per joint (big, small) [m/s].
    impacts : ndarray  (2, n) impacts per cycle per joint (mean over the settled cycles) [-].
    worn_joint : int  0 big end, 1 small end.
    """

    speed_rpm: np.ndarray
    load_scale: np.ndarray
    max_velocity: np.ndarray
    mean_velocity: np.ndarray
    impacts: np.ndarray
    worn_joint: int

    @property
    def ratio(self) -> np.ndarray:
        """κ = worn-joint max impact velocity over the other's (floored) [-]."""
        other = 1 - self.worn_joint
        return self.max_velocity[self.worn_joint] / np.maximum(
            self.max_velocity[other], VELOCITY_FLOOR)

    def best(self) -> dict:
        """The most informative regime (largest κ; ties → the first in sweep order)."""
        index = int(np.argmax(self.ratio))
        worn, other = JOINT_NAMES[self.worn_joint], JOINT_NAMES[1 - self.worn_joint]
        return {"speed_rpm": float(self.speed_rpm[index]),
                "load_scale": float(self.load_scale[index]),
                "worn_joint": worn,
                f"max_impact_velocity_{worn}_m_s": float(self.max_velocity[self.worn_joint, index]),
                f"max_impact_velocity_{other}_m_s": float(self.max_velocity[1 - self.worn_joint,
                                                                            index]),
                "impact_velocity_ratio": float(self.ratio[index])}

    def columns(self) -> dict:
        """Columns of ``sweep.csv``."""
        out = {"speed_rpm": self.speed_rpm, "load_scale": self.load_scale}
        for index, name in enumerate(JOINT_NAMES):
            out[f"max_impact_velocity_{name}_m_s"] = self.max_velocity[index]
            out[f"mean_impact_velocity_{name}_m_s"] = self.mean_velocity[index]
            out[f"impacts_per_cycle_{name}"] = self.impacts[index]
        out["impact_velocity_ratio"] = self.ratio
        return out


@dataclass(frozen=True)
class SweepRun:
    """A finished sweep and its wall-clock time (what ``conrod mechanism --sweep`` writes).

    sweep : SweepResults  One row per operating mode.
    wall_time : float  Wall-clock time of the sweep [s].
    """

    sweep: SweepResults
    wall_time: float

    def summary(self) -> dict:
        """``sweep.json`` items: the most informative regime, runs, wall time [s]."""
        return {"most_informative_regime": self.sweep.best(),
                "runs": int(self.sweep.ratio.size), "wall_time_s": round(self.wall_time, 2)}


def impact_statistics(base: MechanismCase, speed_rpm: float, load_scale: float) -> np.ndarray:
    """One operating mode: rows (max, mean velocity [m/s], impacts per cycle) × joints."""
    run = base.with_operating_point(speed_rpm, load_scale)
    results = simulate(run.mechanism, run.scaled_gas_table(), run.settings)
    impacts = results.settled_impacts()
    out = np.zeros((3, 2))
    for joint in range(2):
        speeds = impacts.of_joint(joint)
        if speeds.size:
            out[:, joint] = speeds.max(), speeds.mean(), speeds.size / results.statistics_cycles
    return out
