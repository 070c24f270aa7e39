"""The grid-error estimate of ``conrod run`` against the three-grid Richardson error of the
run grid (the run grid, 2x and 4x finer), and the grid convergence of the main job's
elastic h_min.

Run:  python benchmarks/grid_error_check.py [--elastic]   → benchmarks/grid_error_check.md

Each case runs in this process, one grid after the other (BLAS on one thread, as
``conrod run`` does); ``--elastic`` adds the KamAZ-740 elastic big end (Reynolds film,
massless-start implicit orbit as ``conrod run --film reynolds``) over the grids of its
convergence study, which takes an hour or more on a 2-core machine.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from conrod import Case, Simulation  # noqa: E402
from conrod.results.grid_error import (  # noqa: E402
    cell_size,
    extrapolated_error,
    observed_order,
)
from conrod.simulation.grid_error import coarser_grids, feature_note  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
RIGID = (("passenger_car_diesel_2000rpm_reynolds", (72, 16)),
         ("kamaz_740_truck_diesel", (72, 16)),
         ("ruston_hornsby_6vebx_mk3", (72, 16)))
"""(example, run grid) run on a rigid bore with the Reynolds film."""
ELASTIC_GRIDS = ((36, 8), (72, 8), (72, 16), (102, 12), (108, 8), (108, 16), (120, 12),
                 (144, 8), (144, 12), (144, 16), (216, 8))
"""Grids of the KamAZ-740 elastic study (n_θ, n_z)."""


def extremes(example: str, grid: tuple[int, int], elastic: bool = False
             ) -> tuple[float, float, float]:
    """(smallest film h_min [m], largest p_max [Pa], wall time [s]) of one run."""
    case = Case.from_toml(ROOT / "examples" / f"{example}.toml")
    options = {} if elastic else {"housing": "rigid"}
    start = time.perf_counter()
    results = Simulation(case, film="reynolds", rigid_companion=False, n_theta=grid[0],
                         n_z=grid[1], **options).run()
    summary = getattr(results, "elastic", results).summary
    return summary.film_h_min, summary.p_max, time.perf_counter() - start


def compare(example: str, grid: tuple[int, int]) -> list[str]:
    """Table rows: estimate (run grid, coarser grids) vs three-grid Richardson reference."""
    coarse = coarser_grids(grid)
    finer = [(2 * grid[0], 2 * grid[1]), (4 * grid[0], 4 * grid[1])]
    runs = {g: extremes(example, g) for g in (grid, *coarse, *finer)}
    note = feature_note(Case.from_toml(ROOT / "examples" / f"{example}.toml").bearing.geometry(),
                        grid[1])
    rows = []
    for index, (name, unit, factor) in enumerate((("h_min", "µm", 1e6), ("p_max", "MPa", 1e-6))):
        ours_grids = (grid, *coarse)
        ours_values = tuple(runs[g][index] for g in ours_grids)
        sizes = tuple(cell_size(g) for g in ours_grids)
        ours = extrapolated_error(ours_values, sizes)
        order = observed_order(ours_values, sizes)
        ref_grids = (finer[1], finer[0], grid)
        ref_values = tuple(runs[g][index] for g in ref_grids)
        ref_sizes = tuple(cell_size(g) for g in ref_grids)
        ref_order = observed_order(ref_values, ref_sizes)
        reference = None if ref_order is None else (
            ref_values[0] + extrapolated_error(ref_values, ref_sizes, ref_order)
            - ours_values[0])
        ratio = "–" if reference in (None, 0.0) else f"{ours / reference:.2f}"
        rows.append(
            f"| {example} {grid[0]}×{grid[1]} | {name} [{unit}] | "
            + " / ".join(f"{runs[g][index] * factor:.4g}" for g in (*ours_grids, *finer))
            + f" | {ours * factor:+.3g} | {'–' if order is None else f'{order:.2f}'} | "
            + ("not monotone" if reference is None else
               f"{reference * factor:+.3g} (order {ref_order:.2f})")
            + f" | {ratio} | {note or '–'} |")
    return rows


def elastic_rows() -> list[str]:
    rows = []
    for grid in ELASTIC_GRIDS:
        h_min, p_max, seconds = extremes("kamaz_740_truck_diesel", grid, elastic=True)
        rows.append(f"| {grid[0]}×{grid[1]} | {h_min * 1e6:.4f} | {p_max / 1e6:.2f} | "
                    f"{seconds:.0f} |")
    return rows


def main() -> None:
    lines = ["# Grid-error estimate against the three-grid Richardson error", "",
             "Grids: run grid / its two coarser grids / 2x / 4x finer; estimate: Richardson "
             "from the run grid and the next coarser one, formal order 2; observed order "
             "over the run grid and its two coarser ones; reference: Richardson error of "
             "the run grid from the run grid, 2x and 4x finer with their observed order.", "",
             "| case | quantity | values | estimate | observed order | reference | "
             "estimate / reference | grid note |", "| --- | --- | --- | --- | --- | --- | --- "
             "| --- |"]
    for example, grid in RIGID:
        lines += compare(example, grid)
    if "--elastic" in sys.argv:
        lines += ["", "KamAZ-740 elastic big end (Reynolds film, implicit orbit):", "",
                  "| grid | film h_min [µm] | p_max [MPa] | wall [s] |",
                  "| --- | --- | --- | --- |"]
        lines += elastic_rows()
    (ROOT / "benchmarks" / "grid_error_check.md").write_text("\n".join(lines) + "\n",
                                                             encoding="utf-8")


if __name__ == "__main__":
    main()
