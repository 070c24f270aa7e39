"""Time per periodic orbit cycle for each film model and integrator.

Run from the repository root:  python benchmarks/orbit_benchmarks.py
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
TIME_LIMIT_S = 150
"""A configuration still running after this is reported as '> limit' [s]."""

ROWS = [
    # film, integrator, overrides, target
    ("short", "quasi_static", {}, "≤ 5 ms"),
    ("short", "adaptive", {}, "≤ 5 ms"),
    ("short", "rk2", {"step_deg": 0.0002}, "(fidelity to [D0])"),
    ("mobility", "quasi_static", {}, "≤ 5 ms"),
    ("table", "quasi_static", {}, "≤ 10 ms"),
    ("table", "adaptive", {}, "(implicit, for comparison)"),
    ("reynolds", "quasi_static", {"n_theta": 72, "n_z": 16}, "≤ 1 s"),
    ("reynolds", "adaptive", {"n_theta": 72, "n_z": 16}, "≤ 1 s"),
    ("reynolds", "quasi_static", {"n_theta": 144, "n_z": 32}, "≤ 3 s"),
    ("mass_conserving", "quasi_static", {"n_theta": 72, "n_z": 16}, "≤ 2× Reynolds"),
]


def time_row(film: str, integrator: str, overrides: dict) -> tuple[str, str, str]:
    """(build time, time per cycle, result) of one configuration."""
    from conrod import Case, Simulation
    from conrod.orbit import initial_state, integrate_cycle

    case = Case.from_toml(CASE)
    start = time.perf_counter()
    sim = Simulation(case, film=film, integrator=integrator, **overrides)
    problem = sim.problem()
    build = time.perf_counter() - start
    signal.signal(signal.SIGALRM, _timeout)
    signal.alarm(TIME_LIMIT_S)
    try:
        warm = integrate_cycle(problem, initial_state(), sim.solver)
        start = time.perf_counter()
        cycle = integrate_cycle(problem, warm.end_state, sim.solver)
        per_cycle = time.perf_counter() - start
        h_min = min(problem.clearance - (cycle.x**2 + cycle.y**2) ** 0.5)
        return f"{build:.2f} s", _fmt(per_cycle), f"h_min {h_min * 1e6:.2f} µm (2nd cycle)"
    except TimeoutError:
        return f"{build:.2f} s", f"> {TIME_LIMIT_S} s for 2 cycles", "not finished"
    except Exception as error:  # report, do not hide
        return f"{build:.2f} s", "failed", f"{type(error).__name__}: {str(error)[:60]}"
    finally:
        signal.alarm(0)


def _timeout(signum, frame):
    raise TimeoutError


def _fmt(seconds: float) -> str:
    return f"{seconds * 1e3:.1f} ms" if seconds < 1.0 else f"{seconds:.2f} s"


def main() -> None:
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
        build, per_cycle, result = time_row(film, integrator, overrides)
        detail = ", ".join(f"{k}={v}" for k, v in overrides.items()) or "default"
        row = f"| {film} | {integrator} | {detail} | {build} | {per_cycle} | {result} | {target} |"
        print(row, flush=True)
        lines.append(row)
    (ROOT / "benchmarks" / "orbit_benchmarks.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
