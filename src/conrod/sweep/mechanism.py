"""The mechanism's sweep of operating modes (speed × load, [D3]): every mode of
:func:`conrod.mechanism.regimes.impact_statistics`, one after the other or, with ``jobs`` > 1,
on a local Dask cluster with the same result. A study file with ``command = "mechanism"``
runs the same kind of sweep through ``conrod sweep`` (any case keys as axes, cached variant
folders, ``sweep.parquet``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterable

import numpy as np

from conrod.mechanism.regimes import SweepResults, impact_statistics
from conrod.mechanism.setup import MechanismCase


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
