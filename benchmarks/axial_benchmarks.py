"""Cost of the axial dimension: a tilted journal (prescribed, or two more degrees of freedom)
and a bore profile, against the aligned cylindrical bearing, per orbit cycle.

Run from the repository root:  python benchmarks/axial_benchmarks.py [GRID] [elastic]
Writes benchmarks/axial_benchmarks.md (``elastic``: benchmarks/axial_benchmarks_elastic.md).
Case: examples/kamaz_740_truck_diesel.toml on a rigid bore (``elastic``: on its elastic big
end) with the finite-length Reynolds film (default 72×16), the orbit with mass (``auto``).
Every row times cycles started from the end of a warm-up cycle, the rows interleaved in
:data:`REPEATS` rounds; the fastest cycle of each row counts (a shared machine).
"""

from __future__ import annotations

import platform
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "kamaz_740_truck_diesel.toml"
REPEATS = 4
"""Cycles timed per row after the warm-up cycle [-]."""

PROFILE = {"crush_relief_depth": 12e-6, "crush_relief_extent": 20.0,
           "end_relief_depth": 6e-6, "end_relief_length": 0.004}
"""Crush and end reliefs of the profile row (those of the shipped KamAZ tilt example)."""

ROWS = [
    # label, case changes, target
    ("aligned, cylindrical bore (reference)", {}, "(reference)"),
    ("uniform 1 nm profile: the profile's code path, the same film",
     {"bearing": {"profile_file": str(ROOT / "benchmarks" / "data" / "uniform_1nm_profile.csv")}},
     "nothing measurable"),
    ("bore profile (crush + end reliefs; a different film)", {"bearing": {"profile": PROFILE}},
     "-"),
    ("aligned, the full grid solved (no mid-plane symmetry, as a tilted film)",
     {"film": {"use_symmetry": False}}, "(reference of the tilt's own cost)"),
    ("prescribed tilt 0 (the tilted journal's path, aligned)",
     {"misalignment": {"tilt_x": 0.0}}, "(cost of the path)"),
    ("prescribed tilt (0.2, 0.1) mrad", {"misalignment": {"tilt_x": 2e-4, "tilt_y": 1e-4}},
     "-"),
    ("tilt as 2 DOF: load 2 mm off mid-width, J = 0.02 kg m²",
     {"misalignment": {"mode": "free", "load_axial_offset": 0.002,
                       "moment_of_inertia_x": 0.02, "moment_of_inertia_y": 0.02}},
     "≤ 1.5× reference"),
]


def case_with(changes: dict, rigid: bool = True):
    """The benchmark case with ``changes`` merged section by section (on a rigid bore, or
    on the example's elastic big end)."""
    from conrod import Case

    case = Case.from_toml(CASE)
    data = case.model_dump(mode="python", exclude_unset=True)
    for section, values in changes.items():
        data.setdefault(section, {}).update(values)
    if rigid:
        data["housing"] = {"model": "rigid"}
    return Case.from_dict(data, base_dir=CASE.parent, path=CASE)


class Row:
    """One configuration: its problem, warmed up by one cycle, and its fastest cycle."""

    def __init__(self, changes: dict, grid: tuple[int, int], rigid: bool = True):
        from conrod import Simulation
        from conrod.film.reynolds.film import ReynoldsFilm
        from conrod.orbit import initial_state, integrate_cycle

        changes = dict(changes)
        options = changes.pop("film", {})
        case = case_with(changes, rigid)
        film = ReynoldsFilm(case.bearing.geometry(), n_theta=grid[0], n_z=grid[1], **options)
        self.sim = Simulation(case, film=film, integrator="auto", n_theta=grid[0],
                              n_z=grid[1])
        self.problem = self.sim.problem()
        self.cycle = integrate_cycle(self.problem, initial_state(), self.sim.solver)
        self.best = float("inf")

    def time_cycle(self) -> None:
        """One more cycle from the last one's end; keep the fastest [s]."""
        from conrod.orbit import integrate_cycle

        start = time.perf_counter()
        self.cycle = integrate_cycle(self.problem, self.cycle.end_state, self.sim.solver)
        self.best = min(self.best, time.perf_counter() - start)

    def result(self) -> str:
        cycle = self.cycle
        ratio = float((cycle.x**2 + cycle.y**2).max() ** 0.5) / self.problem.clearance
        tilt = "" if cycle.tilt is None else (
            f", tilt up to {1e3 * float(abs(cycle.tilt[:, :2]).max()):.3g} mrad")
        return f"e/c up to {ratio:.3f}{tilt}, {cycle.steps} steps"


ELASTIC_ROWS = [ROWS[0], ROWS[-1]]
"""Rows run again on the example's elastic big end (``elastic`` argument)."""


def main() -> None:
    grid = tuple(int(n) for n in (sys.argv[1] if len(sys.argv) > 1 else "72x16").split("x"))
    rigid = "elastic" not in sys.argv[2:]
    rows_asked = ROWS if rigid else ELASTIC_ROWS
    bore = "a rigid bore" if rigid else "its elastic big end"
    lines = ["# Axial benchmarks: tilt and bore profile", "",
             f"Case `{CASE.relative_to(ROOT)}` on {bore}, Reynolds film {grid[0]}×{grid[1]}, "
             f"integrator `auto`; fastest of {REPEATS} interleaved cycles after a warm-up cycle; "
             f"machine: "
             f"{platform.processor() or platform.machine()}, Python {sys.version.split()[0]} "
             "(shared 2-core machine, timings ±30 %).", "",
             "| configuration | time per cycle | ratio to reference | result | target |",
             "| --- | ---: | ---: | --- | --- |"]
    rows = [Row(changes, grid, rigid) for _, changes, _ in rows_asked]
    for _ in range(REPEATS):  # interleaved rounds: the machine's load drifts alike for all
        for row in rows:
            row.time_cycle()
    reference = rows[0].best
    for (label, _, target), row in zip(rows_asked, rows, strict=True):
        lines.append(f"| {label} | {row.best:.2f} s | {row.best / reference:.2f}× | "
                     f"{row.result()} | {target} |")
        print(lines[-1], flush=True)
    name = "axial_benchmarks.md" if rigid else "axial_benchmarks_elastic.md"
    (ROOT / "benchmarks" / name).write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
