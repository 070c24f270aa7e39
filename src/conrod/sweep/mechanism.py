"""The mechanism's sweep of operating modes (speed × load, [D3]): every mode of
:func:`conrod.mechanism.regimes.impact_statistics`, one after the other or, with ``jobs`` > 1,
in worker processes on this machine (:class:`conrod.sweep.pool.LocalPool`) with the same
result. A study file with ``command = "mechanism"`` runs the same kind of sweep through
``conrod sweep`` (any case keys as axes, cached variant folders, ``sweep.parquet``).
"""

from __future__ import annotations

import math
import operator
from collections.abc import Callable, Iterable
from typing import Any

import numpy as np

from conrod.cases.base import field_range, range_error
from conrod.errors import CaseError
from conrod.mechanism.regimes import SweepResults, impact_statistics
from conrod.mechanism.setup import MechanismCase
from conrod.sweep.columns import key_field, key_unit

_BOUNDS = (("gt", operator.gt), ("ge", operator.ge), ("lt", operator.lt), ("le", operator.le))


def run_sweep(
    base: MechanismCase, speeds_rpm: Iterable[float], load_scales: Iterable[float],
    progress: Callable[[int, int], None] | None = None, jobs: int = 1,
) -> SweepResults:
    """Run every (speed, load) pair, speed varying slowest; ``progress(done, total)``.

    base : MechanismCase  The mechanism (:func:`conrod.mechanism.setup.mechanism_case`).
    speeds_rpm : numbers  Crank speeds [rpm], each in the range of ``engine.speed``.
    load_scales : numbers  Gas-force factors [-], each in the range of
        ``clearance.load_scale``.
    progress : callable(done, total) or None  Called after every mode.
    jobs : int  Worker processes (1: in this process); the table is the same (each run is
        deterministic and lands in its own row).

    Raises :class:`CaseError` naming the argument, the value and the allowed range.
    """
    speeds = _checked_values("speeds_rpm", speeds_rpm, "engine.speed")
    loads = _checked_values("load_scales", load_scales, "clearance.load_scale")
    _check_options(base, progress, jobs)
    pairs = [(speed, load) for speed in speeds for load in loads]
    rows = np.zeros((len(pairs), 3, 2))
    if jobs > 1:
        _run_in_workers(base, pairs, rows, progress, jobs)
    else:
        for index, pair in enumerate(pairs):
            rows[index] = impact_statistics(base, *pair)
            if progress is not None:
                progress(index + 1, len(pairs))
    max_v, mean_v, counts = rows[:, 0, :].T, rows[:, 1, :].T, rows[:, 2, :].T
    speeds_col = np.array([pair[0] for pair in pairs], dtype=float)
    loads_col = np.array([pair[1] for pair in pairs], dtype=float)
    return SweepResults(speeds_col, loads_col, max_v, mean_v, counts, base.worn_joint)


def _run_in_workers(base: MechanismCase, pairs: list[tuple[float, float]], rows: np.ndarray,
                    progress: Callable[[int, int], None] | None, jobs: int) -> None:
    from conrod.sweep.pool import DONE, LocalPool

    with LocalPool(impact_statistics, jobs) as pool:
        items = [(base, *pair) for pair in pairs]
        for done, (index, kind, value) in enumerate(pool.imap(items), start=1):
            if kind != DONE:
                raise value if isinstance(value, Exception) else RuntimeError(
                    f"mode {pairs[index][0]:g} rpm, load {pairs[index][1]:g}: {value}")
            rows[index] = value
            if progress is not None:
                progress(done, len(pairs))


def _checked_values(name: str, values: Any, key: str) -> list[float]:
    """The values as floats; :class:`CaseError` for a non-number, an empty list or a value
    outside the range of the case key ``key`` (its unit from the schema)."""
    if isinstance(values, str | bytes) or not isinstance(values, Iterable):
        raise CaseError(f"{name} = {values!r}: not a list of numbers")
    numbers = []
    for value in values:
        if isinstance(value, bool) or not isinstance(value, int | float | np.number):
            raise CaseError(f"{name}: {value!r} is not a number")
        numbers.append(float(value))
    if not numbers:
        raise CaseError(f"{name}: empty (allowed: at least one value)")
    section, field = key_field(key) or (None, "")
    metadata = section.model_fields[field].metadata if section is not None else []
    for value in numbers:
        if not math.isfinite(value) or not all(
                check(value, getattr(item, attr)) for item in metadata
                for attr, check in _BOUNDS if getattr(item, attr, None) is not None):
            allowed = field_range(section, field) if section is not None else "finite"
            raise range_error(name, value, allowed, key_unit(key))
    return numbers


def _check_options(base: Any, progress: Any, jobs: Any) -> None:
    if not isinstance(base, MechanismCase):
        raise CaseError(f"base = {type(base).__name__}: not a mechanism (allowed: a "
                        "MechanismCase from conrod.mechanism.setup.mechanism_case)")
    if progress is not None and not callable(progress):
        raise CaseError(f"progress = {progress!r}: not callable (allowed: None or a function)")
    if not isinstance(jobs, int) or isinstance(jobs, bool) or jobs < 1:
        raise CaseError(f"jobs = {jobs!r}: out of range (allowed: an integer >= 1)")


def parse_sweep_option(text: str) -> tuple[str, np.ndarray]:
    """Parse ``name=start:stop:count`` (or ``name=value``) into (name, values).

    Raises :class:`CaseError` (a ``ValueError``) with a readable message on bad syntax.
    """
    if not isinstance(text, str):
        raise CaseError(f"--sweep {text!r}: not text (allowed: speed=START:STOP:COUNT or "
                        "load=START:STOP:COUNT)")
    name, sep, spec = text.partition("=")
    name = name.strip()
    if not sep or name not in ("speed", "load"):
        raise CaseError(f"--sweep {text!r}: expected speed=START:STOP:COUNT or "
                        f"load=START:STOP:COUNT")
    parts = spec.split(":")
    try:
        numbers = [float(part) for part in parts]
    except ValueError:
        raise CaseError(f"--sweep {text!r}: values must be numbers, "
                        f"{name}=START:STOP:COUNT (e.g. {name}=1000:3000:9)") from None
    if not all(math.isfinite(number) for number in numbers):
        raise CaseError(f"--sweep {text!r}: values must be finite numbers")
    if len(numbers) == 1:
        return name, np.array(numbers)
    if len(numbers) != 3 or numbers[2] != int(numbers[2]) or numbers[2] < 1:
        raise CaseError(f"--sweep {text!r}: give START:STOP:COUNT with an integer COUNT >= 1")
    return name, np.linspace(numbers[0], numbers[1], int(numbers[2]))
