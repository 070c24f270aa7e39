"""Rigid runs of a grid film with the grid-error orbits on the second core, or in turn.

    python benchmarks/side_runs_benchmarks.py [--rounds 3] [--examples a,b]
        # → benchmarks/side_runs_benchmarks.md (a section appended per run)

``conrod run`` of the shipped rigid-bore examples with a film on a grid computes its orbit,
then the same orbit on two coarser grids for the grid error of h_min and p_max
(:mod:`conrod.simulation.grid_error`), then its figures. With a second core idle the
coarser orbits run in a forked process while the run's orbit runs, and the figures are
drawn by another while the run waits for the last coarse orbit
(:mod:`conrod.simulation.side_runs`); ``CONROD_SIDE_RUNS=0`` computes everything in the
run's process, one after the other, as conrod did for rigid runs before. Each round runs
both, alternating which goes first, as fresh processes with numba's cache warm (one
unmeasured run of each first); wall time is the clock around the process, CPU time the
process and its children (``getrusage``). The files of the two are compared: everything
but the wall times in ``summary.json`` (and the manifest's digest of it) must be the same
bytes.
"""

from __future__ import annotations

import argparse
import filecmp
import json
import os
import platform
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from result_digests import scrub_wall_times  # beside this script

REPO = Path(__file__).resolve().parents[1]
OUT = REPO / "benchmarks" / "side_runs_benchmarks.md"
CLI = "from conrod.cli.app import main; main()"
EXAMPLES = ("passenger_car_diesel_2000rpm_reynolds", "passenger_car_diesel_2000rpm_crank_fed",
            "kamaz_740_truck_diesel_thermal")
MODES = {"beside": {}, "in turn": {"CONROD_SIDE_RUNS": "0"}}
TIMED = {"summary.json", "manifest.json"}  # hold the wall times


def one_run(example: str, out: Path, mode: str) -> dict:
    """Wall and CPU seconds and the exit code of one ``conrod run`` process."""
    env = {**os.environ, "PYTHONPATH": str(REPO / "src"), **MODES[mode]}
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", CLI, "run",
                           str(REPO / "examples" / f"{example}.toml"), "--out", str(out)],
                          env=env, capture_output=True, text=True, check=False)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return {"wall": wall, "cpu": cpu, "code": done.returncode}


def same_files(a: Path, b: Path) -> bool:
    """The two result folders hold the same files, byte for byte but for the wall times."""
    names = sorted(p.name for p in a.iterdir())
    if names != sorted(p.name for p in b.iterdir()):
        return False
    for name in names:
        if name in TIMED:
            continue
        if not filecmp.cmp(a / name, b / name, shallow=False):
            return False
    return _summary(a) == _summary(b)


def _summary(folder: Path):
    """``summary.json`` of a result folder without its wall times."""
    return scrub_wall_times(json.loads((folder / "summary.json").read_text(encoding="utf-8")))


def measure(example: str, rounds: int) -> dict:
    with tempfile.TemporaryDirectory() as folder:
        base = Path(folder)
        for mode in MODES:  # warm the cache, unmeasured
            one_run(example, base / f"warm {mode}", mode)
        runs: dict[str, list[dict]] = {mode: [] for mode in MODES}
        for k in range(rounds):
            order = list(MODES) if k % 2 == 0 else list(MODES)[::-1]
            for mode in order:
                runs[mode].append(one_run(example, base / f"{mode} {k}", mode))
                print(example, mode, runs[mode][-1], file=sys.stderr)
        same = all(same_files(base / f"beside {k}", base / f"in turn {k}")
                   for k in range(rounds))
    return {"runs": runs, "same": same}


def machine() -> str:
    return (f"{os.cpu_count()} cores ({platform.machine()}), Python "
            f"{platform.python_version()}; 1-minute load average {os.getloadavg()[0]:.1f} "
            "at the start")


def cell(runs: list[dict], key: str) -> str:
    """Median (min–max) of ``key`` over ``runs``, one decimal."""
    values = [r[key] for r in runs]
    return f"{statistics.median(values):.1f} ({min(values):.1f}–{max(values):.1f})"


def append_section(out: Path, title: str, lines: list[str]) -> None:
    """Print ``lines`` and append them to the record ``out`` (started with ``title`` and the
    name of the script writing it)."""
    text = "\n".join(lines) + "\n"
    print(text)
    script = Path(sys.argv[0]).name
    previous = out.read_text(encoding="utf-8") if out.exists() else (
        f"# {title}\n\nWritten by `python benchmarks/{script}` (its docstring says what is "
        "measured).\n\n")
    out.write_text(previous + text + "\n", encoding="utf-8")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--examples", default=",".join(EXAMPLES))
    args = parser.parse_args()
    header = machine()
    rows = {example: measure(example, args.rounds) for example in args.examples.split(",")}
    lines = [f"## {time.strftime('%Y-%m-%d')}", "",
             f"Machine: {header}. {args.rounds} rounds, medians (min–max).", "",
             "| Example (`conrod run`, as shipped) | In turn: wall [s] | CPU [s] | "
             "Beside: wall [s] | CPU [s] | Wall, beside ÷ in turn | Same files |",
             "| --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    for example, row in rows.items():
        alone, beside = row["runs"]["in turn"], row["runs"]["beside"]

        ratios = [b["wall"] / a["wall"] for a, b in zip(alone, beside, strict=True)]
        lines.append(f"| `{example}` | {cell(alone, 'wall')} | {cell(alone, 'cpu')} | "
                     f"{cell(beside, 'wall')} | {cell(beside, 'cpu')} | "
                     f"{statistics.median(ratios):.2f} | {'yes' if row['same'] else 'NO'} |")
    append_section(OUT, "Rigid grid-film runs: coarse orbits beside the run or in turn", lines)


if __name__ == "__main__":
    main()
