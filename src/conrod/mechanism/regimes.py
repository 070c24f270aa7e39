"""Operating modes (speed × load) ranked by diagnostic value ([D3]): the statistics of one
mode and the results of a sweep over many (run by :func:`conrod.sweep.mechanism.run_sweep`).

The most informative diagnostic regime is the one where the worn joint's knock stands out
most above the other joint's: the impact-velocity excess

    Δv = v_worn,max − v_other,max  [m/s],

which stays finite where a joint does not knock (a silent other joint: Δv is the worn
joint's own impact velocity; a silent worn joint: minus the other's), rises with the worn
joint's knock and falls with the other's. (A ratio v_worn/v_other runs to infinity, or to
the size of whatever floor is put under a silent joint.) The regime names the joint that
drives the criterion there: the one knocking harder.
Runs are independent and deterministic (≈ 0.3–0.6 s each, compiled).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from conrod.mechanism.results import JOINT_NAMES
from conrod.mechanism.setup import MechanismCase
from conrod.mechanism.simulation import simulate

SILENT_VELOCITY = 1.0e-3
"""Largest impact velocity of a joint said to be silent (no audible knock) [m/s]."""


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
    def excess(self) -> np.ndarray:
        """Δv = worn joint's max impact velocity minus the other's, per mode [m/s]."""
        return self.max_velocity[self.worn_joint] - self.max_velocity[1 - self.worn_joint]

    def best(self) -> dict:
        """The most informative regime (largest Δv; ties → the first in sweep order), the
        joint that drives it (the one knocking harder there) and whether the other is
        silent."""
        index = int(np.argmax(self.excess))
        worn, other = JOINT_NAMES[self.worn_joint], JOINT_NAMES[1 - self.worn_joint]
        v_worn = float(self.max_velocity[self.worn_joint, index])
        v_other = float(self.max_velocity[1 - self.worn_joint, index])
        driver = worn if v_worn >= v_other else other
        silent = f", {other.replace('_', ' ')} silent" if v_other < SILENT_VELOCITY else ""
        return {"speed_rpm": float(self.speed_rpm[index]),
                "load_scale": float(self.load_scale[index]),
                "worn_joint": worn,
                "criterion": "impact velocity excess of the worn joint, v_worn - v_other "
                             "[m/s]",
                "impact_velocity_excess_m_s": float(self.excess[index]),
                "driven_by": driver,
                "in_words": f"Δv = {float(self.excess[index]):.3g} m/s, driven by the "
                            f"{driver.replace('_', ' ')}{silent}",
                f"{other}_silent": v_other < SILENT_VELOCITY,
                f"max_impact_velocity_{worn}_m_s": v_worn,
                f"max_impact_velocity_{other}_m_s": v_other}

    def columns(self) -> dict:
        """Columns of ``sweep.csv``."""
        out = {"speed_rpm": self.speed_rpm, "load_scale": self.load_scale}
        for index, name in enumerate(JOINT_NAMES):
            out[f"max_impact_velocity_{name}_m_s"] = self.max_velocity[index]
            out[f"mean_impact_velocity_{name}_m_s"] = self.mean_velocity[index]
            out[f"impacts_per_cycle_{name}"] = self.impacts[index]
        out["impact_velocity_excess_m_s"] = self.excess
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
                "runs": int(self.sweep.excess.size), "wall_time_s": round(self.wall_time, 2)}


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
