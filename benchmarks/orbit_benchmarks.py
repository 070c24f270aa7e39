"""Time per periodic orbit cycle for each film model and integrator.

Run from the repository root:  python benchmarks/orbit_benchmarks.py [fed]
(``fed``: re-measure only the rows of the fed comparison of the mass-conserving film with
the Reynolds film and replace them in the existing table.)
Writes benchmarks/orbit_benchmarks.md. Case: examples/passenger_car_diesel_2000rpm.toml
(engine loads, rod frame). Each row times the second cycle, started from the end of a
warm-up cycle (numba compilation and film tables excluded; build time reported separately).
Targets in the last column.
"""

from __future__ import annotations

import platform
import signal
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"
TIME_LIMIT_S = 90
"""A configuration still running after this is reported as '> limit' [s]."""

ROWS = [
    # film, integrator, overrides, target
    ("short", "quasi_static", {}, "≤ 5 ms"),
    ("short", "implicit", {}, "≤ 20 ms (with mass)"),
    ("short", "adaptive", {}, "(SciPy Radau, for comparison)"),
    ("short", "rk2", {}, "(fidelity to [D0]; automatic stable step)"),
    ("mobility", "quasi_static", {}, "≤ 5 ms"),
    ("table", "quasi_static", {}, "≤ 10 ms"),
    ("table", "implicit", {}, "≤ 50 ms (with mass)"),
    ("table", "adaptive", {}, "(SciPy Radau, for comparison)"),
    ("reynolds", "quasi_static", {"n_theta": 72, "n_z": 16}, "≤ 1 s"),
    ("reynolds", "implicit", {"n_theta": 72, "n_z": 16}, "≤ 1 s (with mass)"),
    ("reynolds", "adaptive", {"n_theta": 72, "n_z": 16}, "(SciPy Radau, for comparison)"),
    ("reynolds", "quasi_static", {"n_theta": 144, "n_z": 32}, "≤ 3 s"),
    ("reynolds", "implicit", {"n_theta": 144, "n_z": 32}, "≤ 3 s (with mass)"),
]

FED = {"supply_pressure": 3.0e5, "groove_width": 0.002}
"""Oil feed of the mass-conserving comparison: a central circumferential groove [m] fed at
the supply pressure [Pa] (the mass-conserving film needs a feed to refill)."""
FED_REPEATS = 3
"""Cycles timed per fed row after the warm-up; the fastest counts (a shared machine) [-]."""
FED_ROWS = [
    # film, integrator, target; each timed against the fed Reynolds film of the same
    # integrator in the same run
    ("reynolds", "quasi_static", "(reference of the next row)"),
    ("mass_conserving", "quasi_static", "≤ 2× Reynolds"),
    ("reynolds", "implicit", "(reference of the next row)"),
    ("mass_conserving", "implicit", "≤ 2× Reynolds (with mass)"),
]

CONSTANT_LOAD_CASE = """title = "constant load, L/D = 1, 3000 rpm"
[bearing]
diameter = 0.05
width = 0.05
radial_clearance = 25e-6
[lubricant]
viscosity = 0.01
supply_temperature = 80.0
[load]
table = "load.csv"
speed = 3000
cycle_deg = 360
[solver]
film = "reynolds"
"""
"""A [load]-table case with nothing else set: defaults must finish it (≤ 10 s)."""


def time_constant_load() -> str:
    """Markdown row: total time of ``Simulation(case).run()`` for
    :data:`CONSTANT_LOAD_CASE` (default integrator, periodic loop included)."""
    import tempfile

    from conrod import Case, Simulation

    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder)
        rows = "\n".join(f"{a},5000,0" for a in range(0, 360, 30))
        (path / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + rows + "\n")
        (path / "case.toml").write_text(CONSTANT_LOAD_CASE)
        start = time.perf_counter()
        results = Simulation(Case.from_toml(path / "case.toml")).run()
        total = time.perf_counter() - start
    return (f"| reynolds | auto (default) | constant 5 kN, L/D = 1, 3000 rpm, total run | - | "
            f"{total:.2f} s total | {results.summary.cycles} cycles | ≤ 10 s total |")


def fed_case():
    """The benchmark case with the oil feed :data:`FED`."""
    from conrod import Case
    from conrod.cases.bearing import GrooveSection

    case = Case.from_toml(CASE)
    bearing = case.bearing.model_copy(update={
        "supply_pressure": FED["supply_pressure"],
        "grooves": [GrooveSection(width=FED["groove_width"])]})
    return case.model_copy(update={"bearing": bearing})


def fed_rows() -> list[str]:
    """Markdown rows of :data:`FED_ROWS` on the 72×16 grid (fastest of
    :data:`FED_REPEATS` cycles), ratios within this run."""
    rows, reference = [], {}
    detail = (f"n_theta=72, n_z=16, fed: {FED['groove_width'] * 1e3:.0f} mm groove at "
              f"{FED['supply_pressure'] / 1e6:.1f} MPa")
    for film, integrator, target in FED_ROWS:
        build, per_cycle, result, seconds = time_row(
            film, integrator, {"n_theta": 72, "n_z": 16}, fed_case(), FED_REPEATS)
        reference.setdefault(integrator, seconds)
        per_cycle += f", best of {FED_REPEATS}"
        if film != "reynolds":
            per_cycle += f" ({seconds / reference[integrator]:.2f}× Reynolds)"
        rows.append(f"| {film} | {integrator} | {detail} | {build} | {per_cycle} | {result} "
                    f"| {target} |")
        print(rows[-1], flush=True)
    return rows


def time_row(film: str, integrator: str, overrides: dict, case=None,
             repeats: int = 1) -> tuple[str, str, str, float]:
    """(build time, time per cycle, result, seconds per cycle) of one configuration of
    ``case`` (default: the benchmark case); the fastest of ``repeats`` cycles after the
    warm-up cycle."""
    from conrod import Case, Simulation
    from conrod.orbit import initial_state, integrate_cycle

    case = case if case is not None else Case.from_toml(CASE)
    start = time.perf_counter()
    sim = Simulation(case, film=film, integrator=integrator, **overrides)
    problem = sim.problem()
    build = time.perf_counter() - start
    signal.signal(signal.SIGALRM, _timeout)
    signal.alarm(TIME_LIMIT_S)
    try:
        cycle = integrate_cycle(problem, initial_state(), sim.solver)
        per_cycle = float("inf")
        for _ in range(repeats):
            start = time.perf_counter()
            cycle = integrate_cycle(problem, cycle.end_state, sim.solver)
            per_cycle = min(per_cycle, time.perf_counter() - start)
        h_min = min(problem.clearance - (cycle.x**2 + cycle.y**2) ** 0.5)
        label = "2nd cycle" if repeats == 1 else f"cycle {repeats + 1}"
        return (f"{build:.2f} s", _fmt(per_cycle), f"h_min {h_min * 1e6:.2f} µm ({label})",
                per_cycle)
    except TimeoutError:
        return (f"{build:.2f} s", f"> {TIME_LIMIT_S} s for 2 cycles", "not finished",
                float("nan"))
    except Exception as error:  # report, do not hide
        if isinstance(error.__cause__ or error.__context__, TimeoutError):  # inside numba
            return (f"{build:.2f} s", f"> {TIME_LIMIT_S} s for 2 cycles", "not finished",
                    float("nan"))
        return (f"{build:.2f} s", "failed", f"{type(error).__name__}: {str(error)[:60]}",
                float("nan"))
    finally:
        signal.alarm(0)


def _timeout(signum, frame):
    raise TimeoutError


def _fmt(seconds: float) -> str:
    return f"{seconds * 1e3:.1f} ms" if seconds < 1.0 else f"{seconds:.2f} s"


def replace_fed_rows() -> None:
    """Re-measure only the fed rows and put them in place of those of the existing table."""
    path = ROOT / "benchmarks" / "orbit_benchmarks.md"
    kept = [line for line in path.read_text().splitlines() if "fed:" not in line]
    last = max(i for i, line in enumerate(kept) if line.startswith("| "))
    kept[last:last] = fed_rows()
    path.write_text("\n".join(kept) + "\n")


def main() -> None:
    if sys.argv[1:] == ["fed"]:
        replace_fed_rows()
        return
    lines = [
        "# Orbit benchmarks",
        "",
        f"Case `{CASE.relative_to(ROOT)}`, time of the second cycle (after a warm-up cycle); "
        "machine: "
        f"{platform.processor() or platform.machine()}, Python {sys.version.split()[0]} "
        "(shared 2-core machine, timings ±30 %).",
        "",
        "| film | integrator | grid/step | build | time per cycle | result | target |",
        "| --- | --- | --- | --- | --- | --- | --- |",
    ]
    for film, integrator, overrides, target in ROWS:
        build, per_cycle, result, _ = time_row(film, integrator, overrides)
        detail = ", ".join(f"{k}={v}" for k, v in overrides.items()) or "default"
        row = f"| {film} | {integrator} | {detail} | {build} | {per_cycle} | {result} | {target} |"
        print(row, flush=True)
        lines.append(row)
    lines += fed_rows()
    row = time_constant_load()
    print(row, flush=True)
    lines.append(row)
    (ROOT / "benchmarks" / "orbit_benchmarks.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
