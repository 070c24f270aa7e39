"""Start-up time of the command line and of ``import conrod``, before and after.

    python benchmarks/startup_benchmarks.py --base OLD/src [--runs 15]
        # → benchmarks/startup_benchmarks.md

Each command is a fresh Python process, timed from outside (wall clock around
``subprocess.run``, output discarded), with ``PYTHONPATH`` pointing at this checkout's
``src`` (after) or at ``--base`` (before, e.g. the ``src`` of an older checkout). After one
warm-up run each, the two versions run in turn, after-before-after-before..., so that a
machine whose speed drifts moves both alike; the ratio after/before is taken pair by pair
and its median reported. Also listed: which of the heavy packages each command loads
(``sys.modules`` at exit).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CLI = "from conrod.cli.app import main; main()"
COMMANDS = {  # label → (python arguments, target [s])
    "conrod --version": (["-c", CLI, "--version"], 0.3),
    "conrod --help": (["-c", CLI, "--help"], 0.3),
    "conrod run --help": (["-c", CLI, "run", "--help"], 0.5),
    "import conrod": (["-c", "import conrod"], 0.5),
    "from conrod import Case": (["-c", "from conrod import Case"], None),
}
HEAVY = ("numpy", "scipy", "numba", "pandas", "dask", "matplotlib", "pydantic", "rich")

def environment(src: Path) -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(src), "PYTHONDONTWRITEBYTECODE": "0"}


def wall_time(arguments: list[str], src: Path) -> float:
    """Seconds of one fresh process (output discarded)."""
    start = time.perf_counter()
    subprocess.run([sys.executable, *arguments], env=environment(src), check=False,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return time.perf_counter() - start


def heavy_loaded(arguments: list[str], src: Path) -> list[str]:
    """Heavy packages in ``sys.modules`` when the command's process ends."""
    probe = ("import atexit, json, sys\n"
             "atexit.register(lambda: print(json.dumps([m for m in "
             f"{HEAVY!r} if m in sys.modules]), file=sys.stderr))\n" + arguments[1])
    done = subprocess.run([sys.executable, "-c", probe, *arguments[2:]], env=environment(src),
                          check=False, capture_output=True, text=True)
    return json.loads(done.stderr.strip().splitlines()[-1])


def measure(runs: int, base: Path | None) -> list[dict]:
    rows = []
    for label, (arguments, target) in COMMANDS.items():
        after, before, ratios = [], [], []
        wall_time(arguments, REPO / "src")
        if base is not None:
            wall_time(arguments, base)
        for _ in range(runs):
            after.append(wall_time(arguments, REPO / "src"))
            if base is not None:
                before.append(wall_time(arguments, base))
                ratios.append(after[-1] / before[-1])
        rows.append({"label": label, "target": target, "after": after, "before": before,
                     "ratio": statistics.median(ratios) if ratios else None,
                     "heavy_after": heavy_loaded(arguments, REPO / "src"),
                     "heavy_before": heavy_loaded(arguments, base) if base else None})
        print(label, f"{statistics.median(after):.3f} s", file=sys.stderr)
    return rows


def spread(values: list[float]) -> str:
    if not values:
        return "–"
    return f"{min(values):.3f} / {statistics.median(values):.3f} / {max(values):.3f}"


def report(rows: list[dict], runs: int, base: Path | None) -> str:
    lines = ["# Start-up time", "",
             f"`python benchmarks/startup_benchmarks.py --base OLD/src --runs {runs}`: each "
             "command a fresh process, wall seconds min / median / max of "
             f"{runs} runs, the two versions alternating; ratio = median of after/before "
             f"pairs. Python {sys.version.split()[0]}, {os.cpu_count()} cores.", "",
             "| Command | Target | Before [s] | After [s] | After / before | Meets target |",
             "| --- | ---: | --- | --- | ---: | --- |"]
    for row in rows:
        median = statistics.median(row["after"])
        target = f"≤ {row['target']:g} s" if row["target"] else "–"
        meets = ("yes" if median <= row["target"] else "no") if row["target"] else "–"
        ratio = f"{row['ratio']:.3f}" if row["ratio"] is not None else "–"
        lines.append(f"| `{row['label']}` | {target} | {spread(row['before'])} | "
                     f"{spread(row['after'])} | {ratio} | {meets} |")
    lines += ["", "Heavy packages loaded by each command (of "
              f"{', '.join(HEAVY)}):", "",
              "| Command | Before | After |", "| --- | --- | --- |"]
    for row in rows:
        before = ", ".join(row["heavy_before"]) if row["heavy_before"] else (
            "none" if row["heavy_before"] == [] else "–")
        lines.append(f"| `{row['label']}` | {before} | "
                     f"{', '.join(row['heavy_after']) or 'none'} |")
    return "\n".join(lines) + "\n"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--base", type=Path, default=None,
                        help="src folder of the version to compare with (before)")
    parser.add_argument("--runs", type=int, default=15)
    parser.add_argument("--out", type=Path, default=REPO / "benchmarks" / "startup_benchmarks.md")
    options = parser.parse_args()
    rows = measure(options.runs, options.base)
    text = report(rows, options.runs, options.base)
    if options.out.exists():  # keep the hand-written notes below the generated tables
        old = options.out.read_text(encoding="utf-8")
        marker = "\n## Notes"
        text += old[old.index(marker):] if marker in old else ""
    options.out.write_text(text, encoding="utf-8")
    print(text)


if __name__ == "__main__":
    main()
