r"""Sweep scaling: 1 worker against N workers on cheap (short-bearing) and expensive (EHD)
variants, the per-variant overhead beyond the computation, and a cold ``conrod sweep``.

Run from the repository root (the defaults suit a 2-core machine)::

    python benchmarks/sweep_benchmarks.py
    python benchmarks/sweep_benchmarks.py --workers 1,16 --short 400 --ehd 32 \
        --ehd-one 8 --repeat 1 --cold 0

(the second on a 16-core machine: about 9 minutes, within a 10-minute command).

Writes ``benchmarks/sweep_benchmarks.md`` (``--out`` to choose), a markdown table headed by
the machine's core count and load. Each timed run is a whole ``Sweep(study, out,
workers=N).run()`` in this process: validation, starting the workers (each loads its
compiled kernels from numba's disk cache), computing, writing every variant folder and the
table; each into a new folder with variants of its own (nothing cached). The worker counts
alternate within each repetition (1, N, 1, N, ...) and each speed-up is the ratio of one
such pair, so that a change in the machine's load between repetitions cancels; the table
gives the median. The cold row runs the ``conrod sweep`` command in a new process
(interpreter start and imports included). Timings here are measurements, never test
assertions.
"""

from __future__ import annotations

import argparse
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SHORT_CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"
EHD_CASE = ROOT / "examples" / "kamaz_740_truck_diesel.toml"
SHORT_SOLVER = {"integrator": "quasi_static"}
EHD_SOLVER = {"film": "reynolds", "n_theta": 36, "n_z": 8}
"""The KamAZ big end on its elastic rod with the Reynolds film (36 × 8), as README's first
command runs it, and its rigid companion."""


def short_study(n: int, offset: int):
    """n cheap variants: clearance and viscosity vary together (zip); ``offset`` makes
    every run's variants new."""
    from conrod.sweep import Study

    clearance = np.linspace(20e-6, 35e-6, n) + offset * 1e-10
    viscosity = np.linspace(0.005, 0.012, n)
    return Study.from_dict({"base": str(SHORT_CASE), "mode": "zip",
                            "override": {"solver": SHORT_SOLVER},
                            "axis": [{"key": "bearing.radial_clearance",
                                      "values": [float(v) for v in clearance]},
                                     {"key": "lubricant.viscosity",
                                      "values": [float(v) for v in viscosity]}]})


def ehd_study(n: int, offset: int):
    """n EHD variants: crank speeds around the rated 2600 rpm."""
    from conrod.sweep import Study

    speeds = np.linspace(2200.0, 2800.0, n) + offset * 1e-3
    return Study.from_dict({"base": str(EHD_CASE), "override": {"solver": EHD_SOLVER},
                            "axis": [{"key": "engine.speed",
                                      "values": [float(v) for v in speeds]}]})


def timed_run(study, workers: int) -> dict:
    """One cold-folder sweep: wall time, validation time, summed compute and worker time."""
    from conrod.sweep import Sweep

    with tempfile.TemporaryDirectory(prefix="conrod-sweep-bench-") as folder:
        own, children = _cpu(resource.RUSAGE_SELF), _cpu(resource.RUSAGE_CHILDREN)
        start = time.perf_counter()
        runner = Sweep(study, Path(folder) / "out", workers=workers)
        runner.variants()
        validated = time.perf_counter() - start
        table = runner.run()
        wall = time.perf_counter() - start
        own = _cpu(resource.RUSAGE_SELF) - own
        children = _cpu(resource.RUSAGE_CHILDREN) - children  # the workers, reaped
    return {"wall": wall, "validation": validated, "n": len(table), "own_cpu": own,
            "worker_cpu": children,
            "compute": float(table["compute_time_s"].sum()),
            "worker": float(table["wall_time_s"].sum()),
            "failed": int((table["status"] == "failed").sum())}


def _cpu(who: int) -> float:
    usage = resource.getrusage(who)
    return usage.ru_utime + usage.ru_stime


def spin(loops: int) -> int:
    """Pure-Python work of no I/O: what the machine's cores give in parallel right now."""
    total = 0
    for i in range(loops):
        total += i
    return total


def ceiling_run(n: int, workers: int, loops: int) -> dict:
    """n items of pure-Python work on ``workers`` pool workers: the machine's own limit."""
    from conrod.sweep.pool import LocalPool

    start = time.perf_counter()
    with LocalPool(spin, workers) as pool:
        for _ in pool.imap([(loops,)] * n):
            pass
    return {"wall": time.perf_counter() - start, "n": n, "failed": 0}


def compare(make_study, workers: list[int], n: int, repeat: int, ceiling_loops: int = 0,
            one: int = 0) -> tuple[dict[int, list[dict]], dict[int, list[dict]]]:
    """Every worker count ``repeat`` times, alternating within each repetition; with
    ``ceiling_loops`` each sweep is followed by :func:`ceiling_run` on as many workers; with
    ``one`` the fewest workers run ``one`` variants and their wall time is scaled by n/one
    (a variant costs the same on one worker: ``sweep_benchmarks_16core.md``).
    Returns (sweep runs, ceiling runs) per worker count."""
    runs: dict[int, list[dict]] = {w: [] for w in workers}
    ceiling: dict[int, list[dict]] = {w: [] for w in workers}
    for rep in range(repeat):
        for count in workers:
            size = one if one and count == min(workers) else n
            run = timed_run(make_study(size, offset=1 + rep * len(workers)
                                       + workers.index(count)), count)
            if size != n:
                run = {**run, "wall": run["wall"] * n / size, "n": n}
            runs[count].append(run)
            if ceiling_loops:
                ceiling[count].append(ceiling_run(n, count, ceiling_loops))
            print(f"  {count:>3} workers: {run['wall']:.2f} s (compute {run['compute']:.2f} s"
                  + (f"; ceiling {ceiling[count][-1]['wall']:.2f} s" if ceiling_loops else "")
                  + f"; load {os.getloadavg()[0]:.1f})", flush=True)
    return runs, ceiling


def speedups(runs: dict[int, list[dict]], count: int) -> list[float]:
    """Paired speed-ups of ``count`` workers over the fewest, one per repetition."""
    return [b["wall"] / r["wall"] for b, r in zip(runs[min(runs)], runs[count], strict=True)]


def scaling_rows(label: str, runs: dict[int, list[dict]],
                 ceiling: dict[int, list[dict]] | None = None) -> list[str]:
    """Markdown rows: median wall time per worker count, the paired speed-up and, with the
    ceiling runs, the speed-up as a share of what the machine allowed at that moment."""
    rows = []
    for count, measured in runs.items():
        ratios = speedups(runs, count)
        share = "–"
        if ceiling and ceiling[count]:
            shares = [r / c for r, c in zip(ratios, speedups(ceiling, count), strict=True)]
            share = f"{statistics.median(shares):.0%}"
        rows.append(f"| {label} | {measured[0]['n']} | {count} | "
                    f"{statistics.median(r['wall'] for r in measured):.2f} | "
                    f"{statistics.median(ratios):.2f}× ({min(ratios):.2f}–{max(ratios):.2f}) | "
                    f"{share} | {len(measured)} | {sum(r['failed'] for r in measured)} |")
    return rows


def cpu_rows(runs: dict[int, list[dict]]) -> list[str]:
    """CPU seconds of the workers and of the sweep's own process per worker count: the
    same work split over more processes, or more work?"""
    rows = []
    for count, measured in runs.items():
        workers = statistics.median(r["worker_cpu"] for r in measured)
        own = statistics.median(r["own_cpu"] for r in measured)
        rows.append(f"| {count} | {workers:.2f} | {workers / measured[0]['n'] * 1e3:.1f} | "
                    f"{own:.2f} |")
    return rows


def overhead_rows(runs: list[dict]) -> list[str]:
    """Per-variant overhead of the 1-worker runs beyond the computation [ms]."""
    n = runs[0]["n"]

    def per_variant(key) -> str:
        return f"{statistics.median(key(r) for r in runs) / n * 1e3:.1f}"

    return [f"| all of it: (wall − Σ compute) / n | "
            f"{per_variant(lambda r: r['wall'] - r['compute'])} |",
            f"| validating the variants | {per_variant(lambda r: r['validation'])} |",
            f"| writing each variant folder (Σ (worker time − compute) / n) | "
            f"{per_variant(lambda r: r['worker'] - r['compute'])} |",
            f"| the rest: starting the worker, loading its kernels, dispatch, table | "
            f"{per_variant(lambda r: r['wall'] - r['worker'] - r['validation'])} |"]


def _seconds_per_loop() -> float:
    start = time.perf_counter()
    spin(2_000_000)
    return (time.perf_counter() - start) / 2_000_000


def cold_cli(n: int, workers: int) -> float:
    """Wall time of ``conrod sweep`` in a new process on n cheap variants [s]."""
    with tempfile.TemporaryDirectory(prefix="conrod-sweep-cli-") as folder:
        study = Path(folder) / "study.toml"
        study.write_text(
            f'base = "{SHORT_CASE.as_posix()}"\nmode = "zip"\n[override.solver]\n'
            'integrator = "quasi_static"\n[[axis]]\nkey = "bearing.radial_clearance"\n'
            f"start = 20.01e-6\nstop = 35e-6\nnum = {n}\n[[axis]]\n"
            f'key = "lubricant.viscosity"\nstart = 0.005\nstop = 0.012\nnum = {n}\n',
            encoding="utf-8")
        env = {**os.environ, "PYTHONPATH": str(ROOT / "src")}
        start = time.perf_counter()
        subprocess.run([sys.executable, "-c", "from conrod.cli.app import main; main()",
                        "sweep", str(study), "--out", str(Path(folder) / "out"), "--workers",
                        str(workers)], env=env, check=True, capture_output=True)
        return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--workers", default="1,2", help="worker counts, e.g. 1,16")
    parser.add_argument("--short", type=int, default=60, help="short-bearing variants")
    parser.add_argument("--ehd", type=int, default=4, help="EHD variants (0: none)")
    parser.add_argument("--ehd-one", type=int, default=0, help=(
        "EHD variants of the 1-worker run, its time scaled to --ehd (0: all); on a 16-core "
        "machine 8 keeps the command within 10 minutes"))
    parser.add_argument("--repeat", type=int, default=3, help="repetitions (cheap variants)")
    parser.add_argument("--cold", type=int, default=1000, help="variants of the cold row")
    parser.add_argument("--out", default=str(ROOT / "benchmarks" / "sweep_benchmarks.md"))
    args = parser.parse_args()
    workers = sorted({int(w) for w in args.workers.split(",")})
    load = os.getloadavg()[0]
    from conrod.sweep import Sweep  # noqa: F401  (imports outside the timings)

    timed_run(short_study(4 * max(workers), offset=0), 1)  # kernels on disk
    warm = timed_run(short_study(4 * max(workers), offset=-1), 1)  # the ceiling's item length
    loops = int(warm["compute"] / warm["n"] / _seconds_per_loop())
    print("short-bearing variants, each followed by the machine's ceiling", flush=True)
    short, ceiling = compare(short_study, workers, args.short, args.repeat, loops)
    rows = scaling_rows("short-bearing film, massless orbit", short, ceiling)
    rows += scaling_rows("ceiling: pure-Python items as long, same pool, no I/O", ceiling)
    if args.ehd:
        print("EHD variants", flush=True)
        timed_run(ehd_study(1, offset=0), 1)  # compiles the EHD kernels if needed
        label = "EHD: Reynolds 36×8 on the elastic rod + rigid companion"
        if args.ehd_one:
            label += f" (1 worker: {args.ehd_one} variants, time × {args.ehd}/{args.ehd_one})"
        rows += scaling_rows(label, compare(ehd_study, workers, args.ehd, 1,
                                            one=args.ehd_one)[0])
    cold = cold_cli(args.cold, max(workers)) if args.cold else None
    write_table(args, workers, rows, overhead_rows(short[min(workers)]) + [""] + [
        "CPU time of the short-bearing runs (median): the workers' (all of them) and the sweep "
        "process's own (validation, dispatch, table):", "",
        "| Workers | Workers' CPU [s] | per variant [ms] | Sweep process CPU [s] |",
        "| ---: | ---: | ---: | ---: |", *cpu_rows(short)], cold, load)


def write_table(args, workers: list[int], rows: list[str], overhead: list[str],
                cold: float | None, load: float) -> None:
    lines = [
        "# Sweep benchmarks", "",
        f"Machine: {os.cpu_count()} cores ({platform.machine()}), Python "
        f"{platform.python_version()}; 1-minute load average {load:.1f} at the start, "
        f"{os.getloadavg()[0]:.1f} at the end (above the core count the workers share the "
        "cores with other jobs, which bounds the speed-up). Command: `python "
        f"benchmarks/sweep_benchmarks.py --workers {','.join(map(str, workers))} --short "
        f"{args.short} --ehd {args.ehd} --ehd-one {args.ehd_one} --repeat {args.repeat} "
        f"--cold {args.cold}`.", "",
        "Each run: `Sweep(study, new_folder, workers=N).run()` — validation, worker start "
        "(kernels loaded from numba's disk cache), computing, writing every variant folder "
        "and the table. Speed-up: 1-worker time / N-worker time of the runs made one after "
        "the other (median, range). The ceiling rows run, right after each sweep, items of "
        "pure-Python work as long as a variant's computation on a worker pool of the same "
        "size: the speed-up the machine's cores allowed at that moment.", "",
        "| Variants | Count | Workers | Wall time [s] (median) | Speed-up vs fewest workers "
        "(median, range) | Of the ceiling's speed-up (median) | Runs | Failed |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |", *rows, "",
        "Per-variant overhead beyond the computation (1 worker, short-bearing variants, "
        "median of the runs):", "", "| Part | ms per variant |", "| --- | ---: |", *overhead]
    if cold is not None:
        lines += ["", f"Cold `conrod sweep` (new process: interpreter, imports, validation, "
                  f"{max(workers)} workers, {args.cold} short-bearing variants, table): "
                  f"{cold:.1f} s."]
    lines += ["", "Targets: per-variant overhead beyond the computation ≤ 20 ms; 2 workers ≥ 1.8× "
              "one worker on 60 short-bearing variants; on a 16-core machine 16 workers ≥ 10× "
              "one worker on 400 short-bearing variants and ≥ 14× on 32 EHD variants."]
    if (os.cpu_count() or 1) < 16:
        lines += ["", f"Not measured here: the 16-worker rows (this machine has "
                  f"{os.cpu_count()} cores). On a 16-core machine run `python "
                  "benchmarks/sweep_benchmarks.py --workers 1,16 --short 400 --ehd 32 "
                  "--ehd-one 8 --repeat 1 --cold 0` (about 9 minutes there); one such run "
                  "is in `sweep_benchmarks_16core.md`."]
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
