"""Sweep throughput on Dask distributed: variants per minute, speed-up 1 → 2 workers, and a
1,000-variant short-bearing study end to end.

Run from the repository root:  python benchmarks/sweep_benchmarks.py [--quick]
Writes benchmarks/sweep_benchmarks.md. Base case: examples/passenger_car_diesel_2000rpm.toml
with the massless (quasi-static) orbit; variants differ in radial clearance and viscosity.

Throughput rows run on an already started local cluster that has computed a few warm-up
variants (imports and compiled kernels loaded in every worker), and count validation,
computing, writing each variant folder and the table. The 1,000-variant row is a cold
``Sweep(...).run()`` as ``conrod sweep`` does it: cluster start and validation included.
"""

from __future__ import annotations

import os
import platform
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"
FILMS = {
    "short": ({"integrator": "quasi_static"}, 60),
    "reynolds 72×16": ({"integrator": "quasi_static", "film": "reynolds", "n_theta": 72,
                       "n_z": 16}, 8),
}
"""Film → (solver override, variants per throughput run)."""
BIG_STUDY = 1000
TARGET_BIG_S = 300.0


def study(n: int, solver: dict, offset: int = 0):
    """A zip study of n variants (clearance and viscosity vary together)."""
    from conrod.sweep import Study

    clearance = np.linspace(20e-6, 35e-6, n) + offset * 1e-9
    viscosity = np.linspace(0.005, 0.012, n)
    return Study.from_dict({"base": str(CASE), "mode": "zip", "override": {"solver": solver},
                            "axis": [{"key": "bearing.radial_clearance",
                                      "values": [float(v) for v in clearance]},
                                     {"key": "lubricant.viscosity",
                                      "values": [float(v) for v in viscosity]}]})


def throughput(workers: int, solver: dict, n: int) -> tuple[float, int]:
    """(variants per minute on a warm cluster, failed variants)."""
    from distributed import Client, LocalCluster

    from conrod.sweep import Sweep

    with LocalCluster(n_workers=workers, threads_per_worker=1, dashboard_address=":0",
                      silence_logs=50) as cluster, Client(cluster):
        address = cluster.scheduler_address
        with tempfile.TemporaryDirectory() as out:
            Sweep(study(2 * workers, solver, offset=7), out, scheduler=address).run()
        with tempfile.TemporaryDirectory() as out:
            start = time.perf_counter()
            table = Sweep(study(n, solver), out, scheduler=address).run()
            seconds = time.perf_counter() - start
    return n / seconds * 60.0, int((table["status"] != "ok").sum())


def big_study(n: int) -> tuple[float, float, int]:
    """(total wall time [s], of which validation [s], failed) of an n-variant short study."""
    from conrod.sweep import Sweep

    out = Path(tempfile.mkdtemp(prefix="conrod-sweep-bench-"))
    try:
        start = time.perf_counter()
        runner = Sweep(study(n, FILMS["short"][0]), out)
        runner.variants()
        validated = time.perf_counter() - start
        table = runner.run()
        return time.perf_counter() - start, validated, int((table["status"] != "ok").sum())
    finally:
        shutil.rmtree(out, ignore_errors=True)


def main() -> None:
    quick = "--quick" in sys.argv
    load_before = os.getloadavg()[0]
    lines = ["# Sweep benchmarks", "",
             f"{platform.processor() or platform.machine()}, {os.cpu_count()} cores "
             "(shared with other jobs while measured: ±30 %), "
             f"Python {platform.python_version()}. `python benchmarks/sweep_benchmarks.py`.", "",
             "| Film (quasi-static orbit) | Variants | 1 worker [variants/min] | "
             "2 workers [variants/min] | Speed-up | Failed |",
             "| --- | ---: | ---: | ---: | ---: | ---: |"]
    for film, (solver, n) in FILMS.items():
        n = max(n // 4, 4) if quick else n
        one, failed_one = throughput(1, solver, n)
        two, failed_two = throughput(2, solver, n)
        lines.append(f"| {film} | {n} | {one:.0f} | {two:.0f} | {two / one:.2f}× | "
                     f"{failed_one + failed_two} |")
        print(lines[-1], flush=True)
    n = 100 if quick else BIG_STUDY
    total, validated, failed = big_study(n)
    lines += ["", "| Study | Wall time (cold: cluster start, validation, runs, table) | "
              "Of which validation | Failed | Target |", "| --- | ---: | ---: | ---: | --- |",
              f"| {n} short-bearing variants, local cluster on all cores | {total:.0f} s | "
              f"{validated:.0f} s | {failed} | ≤ {TARGET_BIG_S:.0f} s for 1,000 |"]
    print(lines[-1], flush=True)
    lines += ["", f"1-minute load average of the machine: {load_before:.1f} at the start, "
              f"{os.getloadavg()[0]:.1f} at the end (2 cores: above 2 the workers share them "
              "with other jobs, and the speed-up 1 → 2 workers is bounded accordingly)."]
    if not quick:
        (ROOT / "benchmarks" / "sweep_benchmarks.md").write_text("\n".join(lines) + "\n",
                                                                  encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
