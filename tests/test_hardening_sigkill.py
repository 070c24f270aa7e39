"""SIGKILL at random moments: the result folder holds the complete old or the complete new
result set, nothing truncated, no temporary file (seeded moments, reproducible)."""

from __future__ import annotations

import hashlib
import json
import multiprocessing
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from conrod.io.result_folder import STAGE_TAG, staged_result_folder
from hardening_helpers import cheap_table_run, mutated, write_case

SRC = Path(__file__).resolve().parents[1] / "src"
RUN_FILES = {"cycle.csv", "summary.json", "manifest.json", "orbit.png", "hmin_pmax.png",
             "friction_flow.png", "pressure_map.png", "film_thickness_map.png",
             "min_film_envelope.png", "case.toml", "case.load.table.csv"}
"""A run without contact: no wear tables or contact figures; the case as run recorded."""

def _write_new_result(out: Path, pause: float) -> None:
    """Child process: a 12-file result written slowly through the staged folder."""
    with staged_result_folder(out) as stage:
        for k in range(12):
            with open(stage / f"part{k}.txt", "w") as handle:
                for line in range(200):
                    handle.write(f"new {k} {line}\n")
                    handle.flush()
            time.sleep(pause)


def _environment() -> dict:
    return {**os.environ, "PYTHONPATH": str(SRC)}


def complete_set(folder: Path) -> dict[str, str]:
    """The verified manifest of ``folder`` (name → sha256); fails on anything partial."""
    names = {p.name for p in folder.iterdir()}
    assert not [n for n in names if n.startswith(".")], f"temporary files left: {names}"
    listed = json.loads((folder / "manifest.json").read_text())["files"]
    assert names == set(listed) | {"manifest.json"}, "files missing or extra"
    for name, entry in listed.items():
        data = (folder / name).read_bytes()
        assert len(data) == entry["bytes"], f"{name} truncated"
        assert hashlib.sha256(data).hexdigest() == entry["sha256"], f"{name} changed"
    return {name: entry["sha256"] for name, entry in listed.items()}


def _no_stage_next_to(folder: Path) -> None:
    assert not [p for p in folder.parent.iterdir() if STAGE_TAG in p.name]


def _generation(folder: Path) -> set[str]:
    return {line.split()[0] for p in folder.glob("part*.txt") for line in p.read_text()
            .splitlines()}


def test_killed_writer_leaves_old_or_new_set(tmp_path):
    rng = np.random.default_rng(17)
    outcomes = {"old": 0, "new": 0, "absent": 0}
    for trial in range(24):
        out = tmp_path / f"out{trial % 2}"
        if trial % 2 == 0:  # over an empty place
            assert not out.exists()
        else:  # over an older result
            with staged_result_folder(out) as stage:
                for k in range(12):
                    (stage / f"part{k}.txt").write_text("old\n")
        process = multiprocessing.get_context("fork").Process(
            target=_write_new_result, args=(out, 0.01))
        process.start()
        time.sleep(rng.uniform(0.0, 0.3))
        process.kill()  # SIGKILL
        process.join()
        if not out.exists():
            assert trial % 2 == 0
            outcomes["absent"] += 1
            continue
        complete_set(out)
        generation = _generation(out)
        assert len(generation) == 1, f"mixed result set {generation}"
        outcomes[generation.pop()] += 1
        if trial % 2 == 0:
            shutil.rmtree(out)
    assert sum(outcomes.values()) == 24
    print(f"staged writer killed 24 times: {outcomes}")
    # the next write removes stages abandoned by killed processes
    with staged_result_folder(tmp_path / "out1") as stage:
        (stage / "part0.txt").write_text("final\n")
    with staged_result_folder(tmp_path / "out0") as stage:
        (stage / "part0.txt").write_text("final\n")
    _no_stage_next_to(tmp_path / "out0")


def _run(case: Path, out: Path) -> subprocess.Popen:
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(case), "--out", str(out), "--accept-warnings"]  # 2 cycles: not periodic
    return subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                            env=_environment())


def test_killed_conrod_run_leaves_old_or_new_set(tmp_path):
    rng = np.random.default_rng(6)
    old_case = write_case(tmp_path, cheap_table_run(), "old.toml")
    new_case = write_case(tmp_path, mutated(cheap_table_run(), ("load", "speed"), 2100),
                          "new.toml")
    reference = tmp_path / "reference"
    start = time.perf_counter()
    assert _run(old_case, reference).wait() == 0
    duration = time.perf_counter() - start
    old = complete_set(reference)
    assert set(old) | {"manifest.json"} == RUN_FILES
    seen = []
    for trial in range(4):
        out = tmp_path / f"kill{trial}"
        if trial % 2:  # over an older result
            shutil.copytree(reference, out)
        process = _run(new_case, out)
        time.sleep(rng.uniform(0.6, 1.05) * duration)  # most kills land in the writing phase
        process.send_signal(signal.SIGKILL)
        process.wait()
        if not out.exists():
            assert trial % 2 == 0, "an older result disappeared"
            seen.append("absent")
            continue
        files = complete_set(out)
        seen.append("old" if files == old else "new")
        assert set(files) | {"manifest.json"} == RUN_FILES
    print(f"conrod run killed 4 times after {duration:.1f} s runs: {seen}")
