"""Worker processes load the compiled kernels from numba's disk cache: with the cache there,
no worker of a new sweep compiles anything, each loads what it runs."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[1]
STUDY = REPO / "examples" / "studies" / "passenger_car_3x3.toml"


def _sweep(out: Path) -> tuple[int, int]:
    """(kernels loaded, kernels compiled and saved) by the workers of one ``conrod sweep``."""
    env = {**os.environ, "PYTHONPATH": str(REPO / "src"), "NUMBA_DEBUG_CACHE": "1"}
    done = subprocess.run([sys.executable, "-c", "from conrod.cli.app import main; main()",
                           "sweep", str(STUDY), "--out", str(out), "--workers", "2"],
                          env=env, capture_output=True, text=True, timeout=600, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    log = done.stdout + done.stderr
    return log.count("[cache] data loaded"), log.count("[cache] data saved")


@pytest.mark.slow  # two sweeps in new processes (the first may compile)
def test_new_workers_load_the_kernels_and_compile_nothing(tmp_path):
    _sweep(tmp_path / "first")  # fills the cache if it is empty
    loaded, saved = _sweep(tmp_path / "second")
    assert saved == 0
    assert loaded >= 2  # each worker loads what it runs
