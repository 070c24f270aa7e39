"""Ctrl-C during ``conrod sweep``: exit 130 within seconds, no traceback, the finished
variants kept whole, no temporary folder and no worker process left behind.

The command runs in its own process group and the test sends SIGINT to the whole group,
as a terminal's Ctrl-C does, at three moments: while the variants are validated, while the
workers start, and in the middle of the run.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conrod.sweep.store import RECORD

REPO = Path(__file__).resolve().parents[1]
BASE = REPO / "examples" / "passenger_car_diesel_2000rpm.toml"
EXIT_WITHIN_S = 5.0
VARIANTS = 40


def _study(folder: Path) -> Path:
    """A zip study of cheap variants (short-bearing film, massless orbit)."""
    path = folder / "study.toml"
    path.write_text(f"""
base = "{BASE.as_posix()}"
mode = "zip"
[override.solver]
integrator = "quasi_static"
[[axis]]
key = "bearing.radial_clearance"
start = 20e-6
stop = 35e-6
num = {VARIANTS}
[[axis]]
key = "lubricant.viscosity"
start = 0.005
stop = 0.012
num = {VARIANTS}
""", encoding="utf-8")
    return path


def _wait_for_line(stream, words: str) -> None:
    for line in stream:
        if words in line:
            return
    raise AssertionError(f"the command ended before printing {words!r}")


def _wait_for_variants(out: Path, count: int, process: subprocess.Popen) -> None:
    deadline = time.monotonic() + 60
    while len(list(out.glob(f"variants/*/{RECORD}"))) < count:
        assert process.poll() is None and time.monotonic() < deadline
        time.sleep(0.01)


@pytest.mark.slow  # three commands of 3-5 s each
@pytest.mark.parametrize("moment", ["validating", "starting the workers", "mid-run"])
def test_ctrl_c_exits_130_quickly_and_keeps_finished_variants(tmp_path, moment):
    out = tmp_path / "out"
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "sweep",
               str(_study(tmp_path)), "--out", str(out), "--workers", "2"]
    with subprocess.Popen(command, env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                          text=True, start_new_session=True) as process:
        try:
            if moment == "validating":
                _wait_for_line(process.stderr, "validating the variants")
            elif moment == "starting the workers":
                _wait_for_line(process.stderr, "variants validated")
            else:
                _wait_for_variants(out, 3, process)
            sent = time.monotonic()
            os.killpg(process.pid, signal.SIGINT)
            _, stderr = process.communicate(timeout=30)
            seconds = time.monotonic() - sent
        finally:
            if process.poll() is None:
                os.killpg(process.pid, signal.SIGKILL)
    assert process.returncode == 130, stderr
    assert seconds < EXIT_WITHIN_S, seconds
    assert "Traceback" not in stderr and "KeyboardInterrupt" not in stderr, stderr
    assert "interrupted" in stderr
    with pytest.raises(ProcessLookupError):  # no worker left in the command's group
        os.killpg(process.pid, 0)
    entries = list((out / "variants").iterdir()) if (out / "variants").is_dir() else []
    assert not [e for e in entries if e.name.startswith(".")]  # no staging folder left
    for folder in entries:  # every folder left is a whole finished variant
        record = json.loads((folder / RECORD).read_text(encoding="utf-8"))
        assert record["hash"] == folder.name
        listed = json.loads((folder / "manifest.json").read_text(encoding="utf-8"))["files"]
        assert sorted(listed) == sorted(p.name for p in folder.iterdir()
                                        if p.name not in ("manifest.json", RECORD))
    if moment == "mid-run":
        assert 3 <= len(entries) < VARIANTS
        assert f"{len(entries)} of {VARIANTS} variants finished and kept" in stderr
    if moment == "validating":
        assert not entries
