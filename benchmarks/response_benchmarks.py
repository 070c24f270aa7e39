"""The elastic film's thickness response by its three solves of all directions, on the
responses a KamAZ-740 elastic run asks for: the band of the active set's ring of θ rows cut
at a cavitated row (:func:`conrod.numerics.sparse_lu.banded_solve_rows`, the default where
a row is free), one SuperLU factor swept for all directions in one compiled pass
(:class:`conrod.numerics.sparse_lu.ManyRightHandSides`, the solve before it and the
fallback) and one SuperLU back-substitution per direction (the solve before that).

Records the first ``RECORDED`` responses of the shipped example's elastic orbit at each
grid (the concentric start and most of the lead-in), keeps every ``EVERY``-th, then times
the three solves on exactly those, alternating, in one process, and compares the answers.
``python benchmarks/response_benchmarks.py`` → ``benchmarks/response_benchmarks.md``.
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
from conrod.numerics.sparse_lu import ManyRightHandSides

RECORDED, EVERY = 400, 10
GRIDS = ((72, 16), (144, 16), (144, 32))
HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parent / "examples" / "kamaz_740_truck_diesel.toml"


class _EnoughError(Exception):
    pass


def record(grid: tuple[int, int]) -> list[tuple]:
    """The arguments of every EVERY-th of the first RECORDED thickness responses of the
    elastic orbit."""
    calls, original = [], response.thickness_response

    def spy(*args):
        calls.append(args)
        if len(calls) >= RECORDED:
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
    return calls[::EVERY]


class _Loop(ManyRightHandSides):
    """The solve before the sweep: one SuperLU back-substitution per direction."""

    def __init__(self, matrix, permc_spec: str = "COLAMD"):
        self.factor = splu(matrix, permc_spec=permc_spec)

    def solve_rows(self, right):
        return np.array([self.factor.solve(np.ascontiguousarray(row)) for row in right])


SOLVES = {"band": {}, "sweep": {"banded_solve_rows": lambda *args: None},
          "loop": {"banded_solve_rows": lambda *args: None, "ManyRightHandSides": _Loop}}
"""What each solve replaces in :mod:`conrod.film.reynolds.response` (band: nothing)."""


def timed(calls, solve: str) -> tuple[float, list, float]:
    """Mean time per response [ms], the responses, and the share solved on the band."""
    banded, original = [], response.banded_solve_rows

    def spy(*args):
        banded.append(original(*args) is not None)
        return None if not banded[-1] else original(*args)

    kept = {name: getattr(response, name) for name in ("banded_solve_rows",
                                                        "ManyRightHandSides")}
    try:
        for name, value in SOLVES[solve].items():
            setattr(response, name, value)
        start = time.perf_counter()
        answers = [response.thickness_response(*args) for args in calls]
        elapsed = (time.perf_counter() - start) / len(calls) * 1e3
        if solve == "band":  # the share, counted apart from the timing
            response.banded_solve_rows = spy
            for args in calls:
                response.thickness_response(*args)
        return elapsed, answers, (float(np.mean(banded)) if banded else float("nan"))
    finally:
        for name, value in kept.items():
            setattr(response, name, value)


def _difference(a: list, b: list) -> float:
    return max(float(np.abs(x.nodal_by_bore - y.nodal_by_bore).max()
                     / np.abs(y.nodal_by_bore).max()) for x, y in zip(a, b, strict=True))


def main() -> None:
    rows = []
    for grid in GRIDS:
        calls = record(grid)
        times: dict[str, list[float]] = {name: [] for name in SOLVES}
        answers, share = {}, float("nan")
        for _ in range(3):  # alternating rounds
            for name in SOLVES:
                elapsed, answers[name], banded = timed(calls, name)
                times[name].append(elapsed)
                share = banded if name == "band" else share
        rows.append((grid, len(calls), share, *(np.median(times[n]) for n in SOLVES),
                     _difference(answers["band"], answers["sweep"]),
                     _difference(answers["loop"], answers["sweep"])))
    load = os.getloadavg()[0]
    lines = ["# Thickness response of the elastic film: band, SuperLU sweep, SuperLU loop", "",
             f"`python benchmarks/response_benchmarks.py` on {platform.machine()}, "
             f"{os.cpu_count()} cores (shared; 1-minute load average {load:.1f} at the end), "
             f"Python {platform.python_version()}; KamAZ-740 shipped elastic rod, every "
             f"{EVERY}th of the first {RECORDED} responses of its orbit with mass per grid "
             "(the concentric start and the lead-in; bore rows = film rows), the whole "
             "response per call, medians of 3 alternating rounds in one process. Band: the "
             "default (the active set's ring of θ rows cut at a cavitated row, "
             "`banded_solve_rows`; SuperLU's sweep where no row is free, the share on the "
             "band given); sweep: one SuperLU factor, all directions in one compiled pass "
             "(the default before); loop: one SuperLU back-substitution per direction. "
             "Differences: largest |Δ ∂f/∂u| relative to the sweep's largest.", "",
             "| grid | responses | on the band | band [ms/call] | sweep [ms/call] | loop "
             "[ms/call] | sweep / band | band − sweep | loop − sweep |",
             "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |"]
    lines += [f"| {g[0]}×{g[1]} | {n} | {share:.0%} | {band:.2f} | {sweep:.2f} | {loop:.2f} | "
              f"{sweep / band:.2f}× | {d_band:.1e} | {d_loop:.1e} |"
              for g, n, share, band, sweep, loop, d_band, d_loop in rows]
    (HERE / "response_benchmarks.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
