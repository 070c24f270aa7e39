"""First runs on an empty numba cache with and without the compile lock.

    python benchmarks/compile_lock_benchmarks.py [--rounds 2]
        # → benchmarks/compile_lock_benchmarks.md (a section appended per run)

Two processes that miss the same kernel in one cache folder compiled it both; with the lock
(:mod:`conrod.io.numba_cache`) the first compiles it and the others wait and load it.
Measured, each as a fresh process on a new empty ``NUMBA_CACHE_DIR`` (what a new machine
meets: everything compiled):

* the README's main job (its first command's ``conrod run``): the run's process and the
  second process beside it (rigid companion, grid-error orbits) compile what both use;
* the 3 × 3 study ``examples/studies/passenger_car_3x3.toml`` with ``--workers 2``: each
  worker compiles the film's kernels on its first variant.

Each round runs both modes, alternating which goes first; ``CONROD_COMPILE_LOCK=0`` is
the mode without the lock (as conrod compiled before). Wall time is the clock around the
process, CPU time the process and its children (``getrusage``). The results of the two
are compared: the run's files but the wall times, the sweep's table but its time columns.
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pandas as pd
from compile_benchmarks import readme_job, with_grid  # beside this script
from side_runs_benchmarks import append_section, cell, machine, same_files

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "benchmarks" / "compile_lock_benchmarks.md"
CLI = "from conrod.cli.app import main; main()"
STUDY = REPO / "examples" / "studies" / "passenger_car_3x3.toml"
MODES = {"lock": {}, "no lock": {"CONROD_COMPILE_LOCK": "0"}}
JOBS = ("README job", "3 × 3 sweep, 2 workers")


def command(job: str, out: Path) -> list[str]:
    if job == JOBS[0]:
        return ["run", *with_grid(readme_job(), None, out)]
    return ["sweep", str(STUDY), "--workers", "2", "--out", str(out)]


def one_run(job: str, out: Path, mode: str, cache: Path) -> dict:
    """Wall and CPU seconds and the exit code of one process on the empty ``cache``."""
    env = {**os.environ, "PYTHONPATH": str(REPO / "src"), "NUMBA_CACHE_DIR": str(cache),
           **MODES[mode]}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", CLI, *command(job, out)], env=env, cwd=REPO,
                          capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu, "code": done.returncode}


def same_results(job: str, a: Path, b: Path) -> bool:
    if job == JOBS[0]:
        return same_files(a, b)
    tables = [pd.read_parquet(folder / "sweep.parquet") for folder in (a, b)]
    columns = [name for name in tables[0].columns if not name.endswith("time_s")]
    return tables[0][columns].equals(tables[1][columns])


def measure(job: str, rounds: int) -> dict:
    runs: dict[str, list[dict]] = {mode: [] for mode in MODES}
    same = True
    with tempfile.TemporaryDirectory() as folder:
        base = Path(folder)
        for k in range(rounds):
            order = list(MODES) if k % 2 == 0 else list(MODES)[::-1]
            for mode in order:
                runs[mode].append(one_run(job, base / f"{mode} {k}", mode,
                                          base / f"cache {mode} {k}"))
                print(job, mode, runs[mode][-1], file=sys.stderr)
            same = same and same_results(job, base / f"lock {k}", base / f"no lock {k}")
    return {"runs": runs, "same": same}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=2)
    args = parser.parse_args()
    header = machine()
    rows = {job: measure(job, args.rounds) for job in JOBS}
    lines = [f"## {time.strftime('%Y-%m-%d')}", "",
             f"Machine: {header}. {args.rounds} rounds on empty caches, medians (min–max).",
             "", "| First run | No lock: wall [s] | CPU [s] | Lock: wall [s] | CPU [s] | "
             "CPU, lock ÷ no lock | Exit | Same results |",
             "| --- | ---: | ---: | ---: | ---: | ---: | --- | --- |"]
    for job, row in rows.items():
        plain, locked = row["runs"]["no lock"], row["runs"]["lock"]
        ratios = [b["cpu"] / a["cpu"] for a, b in zip(plain, locked, strict=True)]
        codes = sorted({r["code"] for r in plain + locked})
        lines.append(f"| {job} | {cell(plain, 'wall')} | {cell(plain, 'cpu')} | "
                     f"{cell(locked, 'wall')} | {cell(locked, 'cpu')} | "
                     f"{statistics.median(ratios):.2f} | {'/'.join(map(str, codes))} | "
                     f"{'yes' if row['same'] else 'NO'} |")
    append_section(OUT, "First runs on an empty numba cache: the compile lock", lines)


if __name__ == "__main__":
    main()
