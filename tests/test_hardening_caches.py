"""Caches on disk that cannot be used never fail a run: an unreadable compiled-kernel
(numba) cache file is discarded and compiled again; an unusable film-table cache folder is
skipped. Each says so in one warning line; the results are those of a good cache."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from hardening_helpers import cheap_table_run, mutated, write_case

SRC = Path(__file__).resolve().parents[1] / "src"


def _run(case: Path, out: Path, **env: str) -> subprocess.CompletedProcess:
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(case), "--out", str(out), "--no-figures"]
    return subprocess.run(command, capture_output=True, text=True, check=False, timeout=300,
                          env={**os.environ, "PYTHONPATH": str(SRC), **env})


def _warnings(stderr: str) -> list[str]:
    return [line for line in stderr.splitlines() if line.startswith("warning:")]


def test_a_truncated_numba_cache_file_is_discarded_and_compiled_again(tmp_path):
    case = write_case(tmp_path, mutated(cheap_table_run(), ("solver", "max_cycles"), 6))
    cache = tmp_path / "numba"
    first = _run(case, tmp_path / "first", NUMBA_CACHE_DIR=str(cache))
    assert first.returncode == 0, first.stderr
    assert _warnings(first.stderr) == []
    data = sorted(cache.rglob("short_bearing.kernel_force-*.nbc"))
    index = sorted(cache.rglob("short_bearing_velocity.short_bearing_cycle-*.nbi"))
    assert len(data) == 1 and len(index) == 1
    data[0].write_bytes(data[0].read_bytes()[:100])  # a data file cut short
    index[0].write_bytes(index[0].read_bytes()[:30])  # an index file cut short

    second = _run(case, tmp_path / "second", NUMBA_CACHE_DIR=str(cache))
    assert second.returncode == 0, second.stderr
    [warning] = _warnings(second.stderr)
    assert "could not be read (pickle data was truncated); discarded, compiling it again" \
        in warning
    assert "Traceback" not in second.stderr
    assert data[0].stat().st_size > 100 and index[0].stat().st_size > 30  # saved anew
    third = _run(case, tmp_path / "third", NUMBA_CACHE_DIR=str(cache))
    assert third.returncode == 0 and _warnings(third.stderr) == []
    for name in ("cycle.csv", "summary.json"):
        assert _strip_time(tmp_path / "first" / name) == _strip_time(tmp_path / "second" / name)
        assert _strip_time(tmp_path / "first" / name) == _strip_time(tmp_path / "third" / name)


def _strip_time(path: Path) -> list[str]:
    return [line for line in path.read_text(encoding="utf-8").splitlines()
            if "wall_time_s" not in line]
