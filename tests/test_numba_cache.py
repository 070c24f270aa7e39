"""The compiled implicit free flight is loaded from numba's disk cache by a second process,
and the second process writes the same results bit for bit."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"

RUN_AND_COUNT = """
import sys
from conrod.cli.app import main
from conrod.film.short_bearing import kernel_force
from conrod.orbit.compiled_flight import flight_segment

try:
    main()
except SystemExit as stop:
    code = stop.code
stats = flight_segment(kernel_force).stats
print("CACHE", sum(stats.cache_hits.values()), sum(stats.cache_misses.values()))
sys.exit(code)
"""


def _run(out: Path, cache: Path) -> tuple[int, int]:
    """(cache hits, cache misses) of the short film's compiled segment in a new process."""
    command = [sys.executable, "-c", RUN_AND_COUNT, "run", str(CASE), "--film", "short",
               "--integrator", "implicit", "--no-figures", "--out", str(out)]
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "NUMBA_CACHE_DIR": str(cache)}
    done = subprocess.run(command, capture_output=True, text=True, env=env, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    line = next(x for x in done.stdout.splitlines() if x.startswith("CACHE"))
    hits, misses = (int(v) for v in line.split()[1:])
    return hits, misses


def _summary(out: Path) -> dict:
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    summary.pop("wall_time_s")
    return summary


def test_a_second_process_loads_the_compiled_flight_and_writes_the_same_results(tmp_path):
    cache = tmp_path / "numba"
    first = _run(tmp_path / "first", cache)
    second = _run(tmp_path / "second", cache)
    assert first == (0, 1)  # compiled and saved
    assert second == (1, 0)  # loaded, nothing compiled
    for name in ("cycle.csv", "wear_journal.csv", "wear_shell.csv"):
        assert (tmp_path / "first" / name).read_bytes() == \
            (tmp_path / "second" / name).read_bytes()
    assert _summary(tmp_path / "first") == _summary(tmp_path / "second")
