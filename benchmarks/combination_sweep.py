"""Every shipped orbit example × every film × every integrator through ``conrod run``, at
coarse settings: does each combination finish, warn, or get refused with a reason — and
never crash with a traceback or hang?

Run:  python benchmarks/combination_sweep.py [--timeout 120] [--grid 24x8] [--max-cycles 4]
      (writes benchmarks/combination_sweep.md, one row per run, rewritten after each run)

Each run is a separate ``conrod run CASE --film F --integrator I --grid G --max-cycles N
--no-figures --no-step-check`` process (figures and the rk2 half-step rerun are left out to
keep the sweep short; they do not change which combinations work). A run still going after
``--timeout`` seconds is stopped and listed as such: on this 2-core machine, shared while
measuring, a slow but working run can reach it too, so a timeout row says "did not finish
in time", not "hangs". Exit codes as in ``conrod --help``: 0 ok, 2 refused before
computing, 3 failed or not periodic, 4 finished with warnings.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUTPUT = Path(__file__).with_suffix(".md")
EXAMPLES = ("passenger_car_diesel_2000rpm", "passenger_car_diesel_1000rpm",
            "passenger_car_diesel_2000rpm_5w30_piezoviscous", "kamaz_740_truck_diesel",
            "ruston_hornsby_6vebx_mk3", "flores2006_table_load",
            "passenger_car_diesel_2000rpm_reynolds")
FILMS = ("short", "reynolds", "mass_conserving", "mobility", "table")
INTEGRATORS = ("auto", "adaptive", "implicit", "rk2", "quasi_static")
EXIT_MEANING = {0: "ok", 2: "refused", 3: "failed / not periodic", 4: "warnings",
                5: "cannot write"}


def run_one(example: str, film: str, integrator: str, args: argparse.Namespace,
            scratch: Path) -> dict:
    """One ``conrod run`` in its own process: exit code, wall time, first message."""
    out = scratch / f"{example}-{film}-{integrator}"
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(ROOT / "examples" / f"{example}.toml"),
               "--film", film, "--integrator", integrator, "--grid", args.grid,
               "--max-cycles", str(args.max_cycles), "--no-figures", "--no-step-check",
               "--out", str(out)]
    started = time.perf_counter()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=args.timeout,
                              env=os.environ | {"COLUMNS": "200"})
    except subprocess.TimeoutExpired:
        return {"code": "timeout", "seconds": time.perf_counter() - started,
                "message": f"stopped after {args.timeout:g} s"}
    seconds = time.perf_counter() - started
    return {"code": done.returncode, "seconds": seconds, "message": first_message(done)}


def first_message(done: subprocess.CompletedProcess) -> str:
    """The first error or warning line (a traceback is named as such)."""
    if "Traceback (most recent call last)" in done.stderr:
        return "TRACEBACK: " + done.stderr.strip().splitlines()[-1]
    for line in (done.stderr + done.stdout).splitlines():
        if line.startswith(("error:", "warning:", "internal error:")) or "not converged" in line:
            return line.strip()
    return ""


def markdown(rows: list[dict], args: argparse.Namespace, total: int) -> str:
    lines = [
        "# Every example × film × integrator (`conrod run`, coarse settings)", "",
        f"`python benchmarks/combination_sweep.py --timeout {args.timeout:g} --grid "
        f"{args.grid} --max-cycles {args.max_cycles}`: {len(rows)} of {total} runs; each "
        "run with `--no-figures --no-step-check`, wall time of the whole process (Python "
        "start, numba compilation from its cache, computation) on a shared 2-core machine.",
        "", "| example | film | integrator | exit | wall time [s] | first warning / error |",
        "| --- | --- | --- | --- | --- | --- |"]
    for row in rows:
        code = row["code"]
        shown = f"{code} ({EXIT_MEANING.get(code, '?')})" if isinstance(code, int) else code
        message = row["message"].replace("|", "\\|")
        lines.append(f"| {row['example']} | {row['film']} | {row['integrator']} | {shown} | "
                     f"{row['seconds']:.1f} | {message} |")
    tracebacks = sum("TRACEBACK" in row["message"] for row in rows)
    timeouts = sum(row["code"] == "timeout" for row in rows)
    lines += ["", f"Tracebacks: {tracebacks}. Stopped at the time limit: {timeouts}.", ""]
    return "\n".join(lines)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--timeout", type=float, default=120.0, help="per run [s]")
    parser.add_argument("--grid", default="24x8", help="film grid NTHETAxNZ")
    parser.add_argument("--max-cycles", type=int, default=4)
    parser.add_argument("--examples", default=",".join(EXAMPLES))
    parser.add_argument("--output", type=Path, default=OUTPUT, help="markdown table to write")
    args = parser.parse_args()
    examples = args.examples.split(",")
    total = len(examples) * len(FILMS) * len(INTEGRATORS)
    rows: list[dict] = []
    with tempfile.TemporaryDirectory(prefix="conrod-combinations-") as scratch:
        for example in examples:
            for film in FILMS:
                for integrator in INTEGRATORS:
                    row = run_one(example, film, integrator, args, Path(scratch))
                    rows.append({"example": example, "film": film, "integrator": integrator,
                                 **row})
                    print(f"{example} {film} {integrator}: {row['code']} "
                          f"{row['seconds']:.1f} s {row['message'][:120]}", flush=True)
                    args.output.write_text(markdown(rows, args, total), encoding="utf-8")


if __name__ == "__main__":
    main()
