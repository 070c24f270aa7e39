"""Cost of the axial dimension: a tilted journal (prescribed, or two more degrees of freedom)
and a bore profile, against the aligned cylindrical bearing, per orbit cycle.

Run from the repository root:  python benchmarks/axial_benchmarks.py [GRID]
Writes benchmarks/axial_benchmarks.md. Case: examples/kamaz_740_truck_diesel.toml on a rigid
bore with the finite-length Reynolds film (default 72×16), the orbit with mass (``auto``).
Every row times cycles started from the end of a warm-up cycle; the fastest of
:data:`REPEATS` counts (a shared machine), all rows in one run so the ratios compare.
"""

from __future__ import annotations

import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "kamaz_740_truck_diesel.toml"
REPEATS = 3
"""Cycles timed per row after the warm-up cycle [-]."""

PROFILE = {"crush_relief_depth": 12e-6, "crush_relief_extent": 20.0,
           "end_relief_depth": 6e-6, "end_relief_length": 0.004}
"""Crush and end reliefs of the profile row (those of the shipped KamAZ tilt example)."""

ROWS = [
    # label, case changes, target
    ("aligned, cylindrical bore (reference)", {}, "(reference)"),
    ("bore profile (crush + end reliefs)", {"bearing": {"profile": PROFILE}},
     "nothing measurable"),
    ("prescribed tilt 0 (the tilted journal's steps, aligned)",
     {"misalignment": {"tilt_x": 0.0}}, "(driver cost)"),
    ("prescribed tilt (0.2, 0.1) mrad", {"misalignment": {"tilt_x": 2e-4, "tilt_y": 1e-4}},
     "-"),
    ("tilt as 2 DOF: load 2 mm off mid-width, J = 0.02 kg m²",
     {"misalignment": {"mode": "free", "load_axial_offset": 0.002,
                       "moment_of_inertia_x": 0.02, "moment_of_inertia_y": 0.02}},
     "≤ 1.5× reference"),
]


def case_with(changes: dict):
    """The benchmark case with ``changes`` merged section by section."""
    from conrod import Case

    case = Case.from_toml(CASE)
    data = case.model_dump(mode="python", exclude_unset=True)
    for section, values in changes.items():
        data.setdefault(section, {}).update(values)
    data["housing"] = {"model": "rigid"}
    return Case.from_dict(data, base_dir=CASE.parent, path=CASE)


def time_row(changes: dict, grid: tuple[int, int]) -> tuple[float, str]:
    """(fastest seconds per cycle, result) of one configuration."""
    from conrod import Simulation
    from conrod.orbit import initial_state, integrate_cycle

    sim = Simulation(case_with(changes), film="reynolds", integrator="auto",
                     n_theta=grid[0], n_z=grid[1])
    problem = sim.problem()
    cycle = integrate_cycle(problem, initial_state(), sim.solver)
    best = float("inf")
    for _ in range(REPEATS):
        start = time.perf_counter()
        cycle = integrate_cycle(problem, cycle.end_state, sim.solver)
        best = min(best, time.perf_counter() - start)
    tilt = "" if cycle.tilt is None else (
        f", tilt up to {1e3 * float(abs(cycle.tilt[:, :2]).max()):.3g} mrad")
    ratio = float((cycle.x**2 + cycle.y**2).max() ** 0.5) / problem.clearance
    return best, f"e/c up to {ratio:.3f}{tilt}"


def main() -> None:
    grid = tuple(int(n) for n in (sys.argv[1] if len(sys.argv) > 1 else "72x16").split("x"))
    lines = ["# Axial benchmarks: tilt and bore profile", "",
             f"Case `{CASE.relative_to(ROOT)}` on a rigid bore, Reynolds film {grid[0]}×{grid[1]}, "
             f"integrator `auto`; fastest of {REPEATS} cycles after a warm-up cycle; machine: "
             f"{platform.processor() or platform.machine()}, Python {sys.version.split()[0]} "
             "(shared 2-core machine, timings ±30 %).", "",
             "| configuration | time per cycle | ratio to reference | result | target |",
             "| --- | ---: | ---: | --- | --- |"]
    reference = None
    for label, changes, target in ROWS:
        seconds, result = time_row(changes, grid)
        reference = reference or seconds
        lines.append(f"| {label} | {seconds:.2f} s | {seconds / reference:.2f}× | {result} | "
                     f"{target} |")
        print(lines[-1], flush=True)
    (ROOT / "benchmarks" / "axial_benchmarks.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
