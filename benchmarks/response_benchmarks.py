"""The elastic film's thickness response: all directions of one LU factor in one compiled
sweep (:mod:`conrod.numerics.sparse_lu`) against one SuperLU back-substitution per
direction (the previous solve), on the responses a KamAZ-740 elastic run asks for.

Records the first ``CALLS`` responses of the shipped example's elastic orbit at each grid,
then times both solves on exactly those, alternating, in one process, and compares the
answers. ``python benchmarks/response_benchmarks.py`` → ``benchmarks/response_benchmarks.md``.
"""

from __future__ import annotations

import os
import platform
import time
from pathlib import Path

import numpy as np
from scipy.sparse.linalg import splu

from conrod import Case, Simulation
from conrod.film.reynolds import response

CALLS = 40
GRIDS = ((72, 16), (144, 16), (144, 32))
HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parent / "examples" / "kamaz_740_truck_diesel.toml"


class _EnoughError(Exception):
    pass


def record(grid: tuple[int, int]) -> list[tuple]:
    """The arguments of the first CALLS thickness responses of the elastic orbit."""
    calls, original = [], response.thickness_response

    def spy(*args):
        calls.append(args)
        if len(calls) >= CALLS:
            raise _EnoughError
        return original(*args)

    response.thickness_response = spy
    try:
        Simulation(Case.from_toml(EXAMPLE), film="reynolds", n_theta=grid[0], n_z=grid[1],
                   rigid_companion=False).run()
    except _EnoughError:
        pass
    finally:
        response.thickness_response = original
    return calls


def _loop_solve(matrix, right, many):
    """The previous solve: one SuperLU back-substitution per direction."""
    factor = splu(matrix, permc_spec="MMD_AT_PLUS_A")
    solved = np.empty_like(right)
    for q in range(len(right)):
        solved[q] = factor.solve(np.ascontiguousarray(right[q]))
    return solved


def timed(calls, solve) -> tuple[float, list]:
    """Mean time per response [ms] and the responses."""
    kept, response._solve = response._solve, solve
    try:
        start = time.perf_counter()
        answers = [response.thickness_response(*args) for args in calls]
        return (time.perf_counter() - start) / len(calls) * 1e3, answers
    finally:
        response._solve = kept


def main() -> None:
    rows = []
    for grid in GRIDS:
        calls = record(grid)
        sweep, loop = [], []
        for _ in range(3):  # alternating rounds
            t, fast = timed(calls, response._solve)
            sweep.append(t)
            t, slow = timed(calls, _loop_solve)
            loop.append(t)
        worst = max(float(np.abs(a.nodal_by_bore - b.nodal_by_bore).max()
                          / np.abs(b.nodal_by_bore).max()) for a, b in zip(fast, slow, strict=True))
        rows.append((grid, np.median(sweep), np.median(loop), worst))
    load = os.getloadavg()[0]
    lines = ["# Thickness response of the elastic film: one compiled sweep vs a loop of "
             "back-substitutions", "",
             f"`python benchmarks/response_benchmarks.py` on {platform.machine()}, "
             f"{os.cpu_count()} cores (shared; 1-minute load average {load:.1f} at the end), "
             f"Python {platform.python_version()}; KamAZ-740 shipped elastic rod, the first "
             f"{CALLS} responses of its orbit with mass per grid (bore rows = film rows), "
             "medians of 3 alternating rounds in one process.", "",
             "| grid | compiled sweep [ms/call] | SuperLU loop [ms/call] | ratio | largest "
             "relative difference |", "| --- | ---: | ---: | ---: | ---: |"]
    lines += [f"| {g[0]}×{g[1]} | {s:.2f} | {loop_:.2f} | {loop_ / s:.2f}× | {w:.1e} |"
              for g, s, loop_, w in rows]
    (HERE / "response_benchmarks.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
