"""Ctrl-C while a command starts (the command line and the numerical modules loading, the case
being read): one line, exit code 130, nothing written, no traceback.

The child process holds an import open (a finder that waits on the module's import) so that
the interrupt lands there for sure, whatever the machine's speed."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from hardening_helpers import cheap_table_run, write_case

SRC = Path(__file__).resolve().parents[1] / "src"

HOLD_IMPORT = """
import sys, time

class Hold:
    def find_spec(self, name, path=None, target=None):
        if name == {module!r}:
            print("holding", flush=True)
            time.sleep(60)
        return None

sys.meta_path.insert(0, Hold())
from conrod.cli.app import main
main()
"""


@pytest.mark.parametrize("module", ["typer", "numpy", "conrod.cases.case"])
def test_ctrl_c_while_starting_exits_130_with_one_line(tmp_path, module):
    case = write_case(tmp_path, cheap_table_run())
    out = tmp_path / "out"
    code = HOLD_IMPORT.format(module=module)
    process = subprocess.Popen(
        [sys.executable, "-c", code, "run", str(case), "--out", str(out)],
        stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        env={**os.environ, "PYTHONPATH": str(SRC)})
    try:
        assert process.stdout.readline() == "holding\n"
        process.send_signal(signal.SIGINT)
        _, err = process.communicate(timeout=60)
    finally:
        process.kill()
        process.wait()
        process.stdout.close()
        process.stderr.close()
    assert process.returncode == 130, err
    assert err.splitlines() == ["interrupted (nothing written)"]
    assert not out.exists()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["case.toml"]
