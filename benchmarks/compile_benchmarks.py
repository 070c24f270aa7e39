"""First run and warm run of the README's main job, and where the first run's time goes.

    python benchmarks/compile_benchmarks.py [--variants default,opt2,...] [--grid 36x8]
        # → benchmarks/compile_benchmarks.md (rows appended to the table of this run)
    python benchmarks/compile_benchmarks.py --kernels [--grid 36x8]
        # in-process: numba's compile events of one cold run, per kernel

Each variant runs the README's main job (its first command's case and flags; ``--grid``
replaces the grid) twice as a fresh ``conrod run`` process: cold, with an empty numba cache
(``NUMBA_CACHE_DIR`` a new temporary folder: what the first run after ``pip install .``
meets, numba compiling every kernel), then warm (the same cache folder: every later run).
Wall time (clock around the process) and CPU time (the process and its children, from
``getrusage``) are measured: on the shared 2-core machine other jobs stretch the wall time,
the CPU time much less. Variants differ only in the environment of the run:

* ``before`` — numba's LLVM optimisation level 3 and no background compilation (as
  conrod compiled before);
* ``level 2`` — conrod's default level 2 (:mod:`conrod.io.numba_cache`), no background
  compilation (``CONROD_SIDE_RUNS=0``);
* ``level 2 + background`` — as shipped: level 2, and the rigid companion (and the
  coarser orbits of the grid-error estimate) computed in a forked process while the
  elastic orbit runs, compiling their kernels there (:mod:`conrod.simulation.side_runs`);
* ``level 1 + background`` — ``NUMBA_OPT=1``.

``--kernels`` lists numba's compile events (``numba:compile``) of one cold run in this
process: per kernel the time inclusive of the kernels it compiles first (what the first
call waits) and exclusive of them.
"""

from __future__ import annotations

import argparse
import contextlib
import json
import os
import platform
import re
import resource
import shlex
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "benchmarks" / "compile_benchmarks.md"
CLI = "from conrod.cli.app import main; main()"
VARIANTS = {
    "before": {"NUMBA_OPT": "3", "CONROD_SIDE_RUNS": "0"},
    "level 2": {"CONROD_SIDE_RUNS": "0"},
    "level 2 + background": {},
    "level 1 + background": {"NUMBA_OPT": "1"},
}


def readme_job() -> list[str]:
    """The arguments of the README's first ``conrod run`` (after ``pip install .``)."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    line = next(row for row in text.splitlines() if "conrod run" in row)
    words = shlex.split(line.split("conrod run", 1)[1])
    return words


def with_grid(arguments: list[str], grid: str | None, out: Path) -> list[str]:
    words = list(arguments)
    if grid is not None:
        words[words.index("--grid") + 1] = grid
    words[words.index("--out") + 1] = str(out)
    return words


def one_run(arguments: list[str], env: dict[str, str]) -> dict:
    """Wall and CPU seconds and the exit code of one ``conrod run`` process."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", CLI, "run", *arguments], env=env,
                          capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    h_min = re.search(r"film h_min\s+([0-9.]+ µm)", done.stdout)
    return {"wall": wall, "cpu": cpu, "code": done.returncode,
            "h_min": h_min.group(1) if h_min else "-"}


def measure(variant: str, grid: str | None) -> dict:
    with tempfile.TemporaryDirectory() as folder:
        env = {**os.environ, "PYTHONPATH": str(REPO / "src"),
               "NUMBA_CACHE_DIR": str(Path(folder) / "numba"), **VARIANTS[variant]}
        rows = {}
        for label in ("cold", "warm"):
            arguments = with_grid(readme_job(), grid, Path(folder) / label)
            rows[label] = one_run(arguments, env)
            print(variant, label, rows[label], file=sys.stderr)
    return rows


def kernels(grid: str | None) -> list[tuple[float, float, str]]:
    """(inclusive, exclusive seconds, kernel) of every compile in one cold run here."""
    from numba.core import event

    from conrod.cli.app import main

    listener = event.RecordingListener()
    event.register("numba:compile", listener)
    with tempfile.TemporaryDirectory() as folder:
        sys.argv = ["conrod", "run", *with_grid(readme_job(), grid, Path(folder) / "out")]
        with contextlib.suppress(SystemExit):
            main()
    event.unregister("numba:compile", listener)
    return _intervals(listener.buffer)


def _intervals(buffer) -> list[tuple[float, float, str]]:
    opened, spans = {}, []
    for stamp, record in buffer:
        dispatcher = record.data["dispatcher"]
        key = (id(dispatcher), str(record.data["args"]))
        if record.is_start:
            opened[key] = stamp
        else:
            name = f"{dispatcher.py_func.__module__}.{dispatcher.py_func.__qualname__}"
            spans.append((opened.pop(key), stamp, name))
    spans.sort()
    rows, stack = [], []
    for begin, end, name in spans:
        while stack and stack[-1][1] <= begin:
            stack.pop()
        row = [end - begin, end - begin, name, len(stack)]
        if stack:
            stack[-1][0][1] -= end - begin
        stack.append((row, end))
        rows.append(row)
    return [(row[0], row[1], ("  " * row[3]) + row[2]) for row in rows]


def machine() -> str:
    load = os.getloadavg()[0]
    return (f"{os.cpu_count()} cores ({platform.machine()}), Python "
            f"{platform.python_version()}, numba {_numba_version()}; 1-minute load average "
            f"{load:.1f} at the start")


def _numba_version() -> str:
    import numba

    return numba.__version__


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--grid", default=None)
    parser.add_argument("--kernels", action="store_true")
    parser.add_argument("--json", default=None, help="also write the rows here")
    args = parser.parse_args()
    if args.kernels:
        rows = kernels(args.grid)
        total = sum(row[0] for row in rows if not row[2].startswith(" "))
        print(f"compile total (top-level kernels): {total:.1f} s")
        for inclusive, exclusive, name in rows:
            if inclusive >= 0.3:
                print(f"| {name} | {inclusive:.1f} | {exclusive:.1f} |")
        return
    header = machine()
    rows = {variant: measure(variant, args.grid) for variant in args.variants.split(",")}
    job = " ".join(with_grid(readme_job(), args.grid, Path("OUT")))
    lines = [f"Machine: {header}. Job: `conrod run {job}`.", "",
             "| Variant | Cold wall [s] | Cold CPU [s] | Warm wall [s] | Warm CPU [s] | "
             "Exit | film h_min |", "| --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    for variant, row in rows.items():
        cold, warm = row["cold"], row["warm"]
        lines.append(f"| {variant} | {cold['wall']:.1f} | {cold['cpu']:.1f} | "
                     f"{warm['wall']:.1f} | {warm['cpu']:.1f} | {cold['code']}/{warm['code']}"
                     f" | {cold['h_min']} / {warm['h_min']} |")
    print("\n".join(lines))
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1), encoding="utf-8")


if __name__ == "__main__":
    main()
