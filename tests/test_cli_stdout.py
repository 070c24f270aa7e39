"""A standard output that fails (the reader of a pipe closed it, a full disk) once the
results are written is no failed result: the exit code is that of the results; a closed
pipe is ignored, another failure is one warning line. Where stdout is the result
(``conrod steady``), it is results not written: exit 5."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from hardening_helpers import cheap_table_run, mutated, write_case

SRC = Path(__file__).resolve().parents[1] / "src"


def _conrod(args: list[str], stdout) -> subprocess.CompletedProcess:
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", *args]
    return subprocess.run(command, stdout=stdout, stderr=subprocess.PIPE, text=True,
                          check=False, timeout=300, env={**os.environ, "PYTHONPATH": str(SRC)})


def _closed_pipe() -> int:
    """The write end of a pipe whose reader has gone (every write: EPIPE)."""
    read_end, write_end = os.pipe()
    os.close(read_end)
    return write_end


def _not_progress(stderr: str) -> list[str]:
    """stderr without the orbit's progress log (one line per cycle once a run has taken
    more than a second: a loaded machine prints them)."""
    return [line for line in stderr.splitlines()
            if not re.match(r"^\S.*: cycle \d+ in ", line)]


def _complete(out: Path) -> bool:
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    return all((out / name).stat().st_size == entry["bytes"]
               for name, entry in manifest["files"].items())


@pytest.fixture
def case(tmp_path) -> Path:
    return write_case(tmp_path, mutated(cheap_table_run(), ("solver", "max_cycles"), 6))


@pytest.mark.parametrize("command", ["run", "loads"])
def test_a_closed_pipe_on_stdout_leaves_a_successful_run(tmp_path, case, command):
    stdout = _closed_pipe()
    try:
        done = _conrod([command, str(case), "--out", str(tmp_path / "out")], stdout)
    finally:
        os.close(stdout)
    assert done.returncode == 0, done.stderr
    assert _not_progress(done.stderr) == []
    assert _complete(tmp_path / "out")


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full")
@pytest.mark.parametrize("command", ["run", "loads"])
def test_a_full_stdout_is_one_warning_and_the_results_exit_code(tmp_path, case, command):
    out = tmp_path / "out"
    with open("/dev/full", "w") as full:
        done = _conrod([command, str(case), "--out", str(out)], full)
    assert done.returncode == 0, done.stderr
    assert _not_progress(done.stderr) == [
        "warning: standard output could not be written (No space left on device); the "
        f"results are complete in {out}"]
    assert _complete(out)


def test_steady_whose_result_is_stdout_exits_5_on_a_closed_pipe():
    stdout = _closed_pipe()
    try:
        done = _conrod(["steady", "--length-to-diameter", "1", "--eccentricity", "0.5",
                        "--model", "short"], stdout)
    finally:
        os.close(stdout)
    assert done.returncode == 5
    assert done.stderr.splitlines() == [
        "error: cannot write the results to standard output (Broken pipe)"]
