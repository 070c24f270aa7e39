"""Sweep of operating modes (speed × load) ranking them by diagnostic value ([D3]).

The most informative diagnostic regime is the one where the worn joint knocks hardest
**relative to** the other joint: the ratio

    κ = v_worn,max / max(v_other,max, v_floor),

with v_floor = 1 mm/s so that a silent other joint does not give an infinite ratio.
Runs are independent and deterministic (≈ 0.3–0.6 s each, compiled); they run one after
the other or, with ``jobs`` > 1, on a local Dask cluster with the same result. A study file
with ``command = "mechanism"`` runs the same kind of sweep through ``conrod sweep`` (any case
keys as axes, cached variant folders, ``sweep.parquet``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
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


def run_sweep(
    base: MechanismCase, speeds_rpm: Iterable[float], load_scales: Iterable[float],
    progress: Callable[[int, int], None] | None = None, jobs: int = 1,
) -> SweepResults:
    """Run every (speed, load) pair, speed varying slowest; ``progress(done, total)``.

    ``jobs`` > 1 runs the modes on a local Dask cluster of that many worker processes (the
    machinery of :mod:`conrod.sweep`); the table is the same (each run is deterministic and
    lands in its own row).
    """
    from distributed import as_completed

    loads = [float(load) for load in load_scales]
    pairs = [(float(speed), load) for speed in speeds_rpm for load in loads]
    rows = np.zeros((len(pairs), 3, 2))
    if jobs > 1:
        from conrod.sweep.runner import local_client

        with local_client(jobs) as client:
            futures = client.map(impact_statistics, [base] * len(pairs),
                                 [pair[0] for pair in pairs], [pair[1] for pair in pairs],
                                 pure=False)
            for done, _ in enumerate(as_completed(futures), start=1):
                if progress is not None:
                    progress(done, len(pairs))
            for index, future in enumerate(futures):
                rows[index] = future.result()
    else:
        for index, pair in enumerate(pairs):
            rows[index] = impact_statistics(base, *pair)
            if progress is not None:
                progress(index + 1, len(pairs))
    max_v, mean_v, counts = rows[:, 0, :].T, rows[:, 1, :].T, rows[:, 2, :].T
    speeds_col = np.array([pair[0] for pair in pairs], dtype=float)
    loads_col = np.array([pair[1] for pair in pairs], dtype=float)
    return SweepResults(speeds_col, loads_col, max_v, mean_v, counts, base.worn_joint)


def parse_sweep_option(text: str) -> tuple[str, np.ndarray]:
    """Parse ``name=start:stop:count`` (or ``name=value``) into (name, values).

    Raises ValueError with a readable message on bad syntax.
    """
    name, sep, spec = text.partition("=")
    name = name.strip()
    if not sep or name not in ("speed", "load"):
        raise ValueError(f"--sweep {text!r}: expected speed=START:STOP:COUNT or "
                         f"load=START:STOP:COUNT")
    parts = spec.split(":")
    try:
        numbers = [float(part) for part in parts]
    except ValueError:
        raise ValueError(f"--sweep {text!r}: values must be numbers, "
                         f"{name}=START:STOP:COUNT (e.g. {name}=1000:3000:9)") from None
    if len(numbers) == 1:
        return name, np.array(numbers)
    if len(numbers) != 3 or numbers[2] != int(numbers[2]) or numbers[2] < 1:
        raise ValueError(f"--sweep {text!r}: give START:STOP:COUNT with an integer COUNT >= 1")
    return name, np.linspace(numbers[0], numbers[1], int(numbers[2]))
