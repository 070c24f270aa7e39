"""The half-cycle lead-in of the orbit with mass on an elastic bore against a whole first cycle.

Run from the repository root:  python benchmarks/lead_in_benchmarks.py [EXAMPLE_STEM ...]
Writes benchmarks/lead_in_benchmarks.md. For each shipped example on an elastic big end,
``conrod run <example> --film reynolds --no-figures --no-grid-error`` runs twice as a new
process, warm (a first run of each fills numba's cache): as shipped (``[solver] lead_in``
0.5) and with ``lead_in = 0`` (a whole first cycle from the concentric start, the orbit as
before the lead-in; the case copied beside the example with the key added, so that its
relative paths still resolve). Per example: cycles, the periodicity error (closure) of the
accepted cycle, the largest |Δe|/c between the two accepted orbits at equal output angles,
the relative change of h_min and p_max, and the wall time of each run (whole process). The
periodicity tolerance is 1e-3.
"""

from __future__ import annotations

import json
import os
import platform
import re
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "lead_in_benchmarks.md"
EXAMPLES = ("kamaz_740_truck_diesel", "kamaz_740_solid_big_end", "kamaz_740_truck_diesel_tilt",
            "ruston_hornsby_6vebx_mk3", "kamaz_740_truck_diesel_tehd")
"""The shipped examples on an elastic big end (the first is the README's main job)."""


def whole_first_cycle(example: Path) -> Path:
    """A copy of ``example`` beside it with ``[solver] lead_in = 0.0``."""
    text = example.read_text(encoding="utf-8")
    if re.search(r"^\[solver\]\s*$", text, flags=re.M):
        text = re.sub(r"^\[solver\]\s*$", "[solver]\nlead_in = 0.0", text, count=1, flags=re.M)
    else:
        text += "\n[solver]\nlead_in = 0.0\n"
    handle, name = tempfile.mkstemp(prefix=f".{example.stem}_", suffix=".toml",
                                    dir=example.parent)
    with os.fdopen(handle, "w", encoding="utf-8") as stream:
        stream.write(text)
    return Path(name)


def run(case: Path, out: Path) -> tuple[float, dict, np.ndarray]:
    """(wall [s], summary.json, eccentricity (2, n) [m]) of one ``conrod run``."""
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(case), "--film", "reynolds",
               "--no-figures", "--no-grid-error", "--out", str(out)]
    start = time.perf_counter()
    subprocess.run(command, check=True, capture_output=True, cwd=ROOT)
    wall = time.perf_counter() - start
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    table = np.genfromtxt(out / "cycle.csv", delimiter=",", names=True, comments="#")
    return wall, summary, np.vstack([table["eccentricity_x_m"], table["eccentricity_y_m"]])


def measure(stem: str, folder: Path) -> str:
    """One table row: the example as shipped against its whole-first-cycle copy."""
    example = ROOT / "examples" / f"{stem}.toml"
    clearance = tomllib.loads(example.read_text(encoding="utf-8"))["bearing"]["radial_clearance"]
    copy = whole_first_cycle(example)
    try:
        runs = {}
        for name, case in (("lead", example), ("whole", copy)):
            run(case, folder / f"{stem}_{name}_warm")  # fills numba's cache
            runs[name] = run(case, folder / f"{stem}_{name}")
    finally:
        copy.unlink()
    (wall_a, a, e_a), (wall_b, b, e_b) = runs["lead"], runs["whole"]
    gap = float(np.max(np.hypot(*(e_a - e_b)))) / clearance
    h_change = a["h_min_m"] / b["h_min_m"] - 1.0
    p_change = a["p_max_Pa"] / b["p_max_Pa"] - 1.0
    return (f"| `{stem}` | {b['cycles']:g} → {a['cycles']:g} | {b['periodicity_error']:.1e} → "
            f"{a['periodicity_error']:.1e} | {gap:.1e} | {h_change:+.1e}, {p_change:+.1e} | "
            f"{wall_b:.1f} → {wall_a:.1f} |")


def main(stems: list[str]) -> None:
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for stem in stems or EXAMPLES:
            rows.append(measure(stem, Path(folder)))
            print(rows[-1], flush=True)
    lines = [
        "# The half-cycle lead-in against a whole first cycle (elastic bores)",
        "",
        f"Machine: {platform.machine()}, {os.cpu_count()} cores (shared; 1-minute load "
        f"{load:.1f} at the start), Python {platform.python_version()}. "
        "`python benchmarks/lead_in_benchmarks.py`: each shipped elastic example by "
        "`conrod run <example> --film reynolds --no-figures --no-grid-error`, warm, with "
        "`[solver] lead_in = 0` (a whole first cycle) → as shipped (0.5). Closure: the "
        "accepted cycle's periodicity error (tolerance 1e-3). max |Δe|/c: between the two "
        "accepted orbits at equal output angles. Wall: the whole process (the rigid "
        "companion and the figures-free outputs included).",
        "",
        "| Example | Cycles | Closure | max \\|Δe\\|/c | h_min, p_max change (relative) | "
        "Wall [s] |",
        "| --- | --- | --- | ---: | --- | --- |",
        *rows,
    ]
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main(sys.argv[1:])
