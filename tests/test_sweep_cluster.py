"""``conrod sweep --scheduler tcp://HOST:PORT`` on a Dask cluster started the way
docs/sweep.md tells: ``dask scheduler`` and two ``dask worker`` processes. The table equals
the one of the local workers, value for value."""

from __future__ import annotations

import json
import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pandas as pd
import pytest

from conrod.sweep import Study, Sweep

REPO = Path(__file__).resolve().parents[1]
BASE = REPO / "examples" / "passenger_car_diesel_2000rpm.toml"
STUDY = {"base": str(BASE), "override": {"solver": {"integrator": "quasi_static"}},
         "axis": [{"key": "bearing.radial_clearance", "values": [20e-6, 30e-6]},
                  {"key": "engine.speed", "values": [1000.0, 2000.0, 3000.0]}]}
pytestmark = pytest.mark.slow  # a scheduler, two workers and a sweep: 10-20 s


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """``dask scheduler`` and two single-threaded ``dask worker`` processes; the address."""
    dask = shutil.which("dask", path=str(Path(sys.executable).parent)) or shutil.which("dask")
    assert dask, "the dask command of the distributed package"
    folder = tmp_path_factory.mktemp("cluster")
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    file = folder / "scheduler.json"
    started = [subprocess.Popen([dask, "scheduler", "--host", "127.0.0.1", "--port", "0",
                                 "--no-dashboard", "--scheduler-file", str(file)], env=env,
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                start_new_session=True)]
    try:
        started += [subprocess.Popen([dask, "worker", "--scheduler-file", str(file),
                                      "--nthreads", "1", "--no-dashboard"], env=env,
                                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                                     start_new_session=True) for _ in range(2)]
        yield _address(file, workers=2)
    finally:
        for process in reversed(started):
            os.killpg(process.pid, signal.SIGTERM)
        for process in started:
            try:
                process.wait(timeout=10)
            except subprocess.TimeoutExpired:
                os.killpg(process.pid, signal.SIGKILL)
                process.wait()


def _address(file: Path, workers: int) -> str:
    """The scheduler's address once ``workers`` workers have joined (asked from another
    process: a Dask client would leave its event-loop thread in this one)."""
    deadline = time.monotonic() + 60
    while not file.is_file():
        assert time.monotonic() < deadline, "the scheduler did not start"
        time.sleep(0.1)
    address = json.loads(file.read_text(encoding="utf-8"))["address"]
    wait = (f"from distributed import Client\nwith Client({address!r}, timeout='30s') as c:\n"
            f"    c.wait_for_workers({workers}, timeout=60)")
    subprocess.run([sys.executable, "-c", wait], check=True, timeout=120)
    return address


def test_the_cli_on_a_cluster_gives_the_table_of_the_local_workers(cluster, tmp_path):
    study = tmp_path / "study.toml"
    lines = [f'base = "{BASE.as_posix()}"', "[override.solver]", 'integrator = "quasi_static"']
    for axis in STUDY["axis"]:
        lines += ["[[axis]]", f'key = "{axis["key"]}"', f"values = {axis['values']}"]
    study.write_text("\n".join(lines) + "\n", encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    done = subprocess.run([sys.executable, "-c", "from conrod.cli.app import main; main()",
                           "sweep", str(study), "--out", str(tmp_path / "on_cluster"),
                           "--scheduler", cluster], env=env, capture_output=True, text=True,
                          timeout=300, check=False)
    assert done.returncode == 0, done.stderr
    assert "Traceback" not in done.stderr
    remote = pd.read_parquet(tmp_path / "on_cluster" / "sweep.parquet")
    local = Sweep(Study.from_dict(STUDY), tmp_path / "local", workers=2).run()
    assert list(remote["hash"]) == list(local["hash"])
    varying = ["wall_time_s", "compute_time_s"]
    pd.testing.assert_frame_equal(remote.drop(columns=varying), local.drop(columns=varying))
    for key in remote["hash"]:  # the variant folders hold the same tables, byte for byte
        there = tmp_path / "on_cluster" / "variants" / key
        here = tmp_path / "local" / "variants" / key
        tables = sorted(path.name for path in there.glob("*.csv"))
        assert "cycle.csv" in tables
        assert tables == sorted(path.name for path in here.glob("*.csv"))
        for name in tables:
            assert (there / name).read_bytes() == (here / name).read_bytes()


def test_a_scheduler_that_is_not_there_is_a_clear_error(tmp_path, monkeypatch):
    from conrod.errors import CaseError
    from conrod.sweep import cluster as cluster_module

    monkeypatch.setattr(cluster_module, "CONNECT_SECONDS", 1.0)
    with pytest.raises(CaseError, match=r"--scheduler 'tcp://127.0.0.1:9': cannot connect"):
        Sweep(Study.from_dict(STUDY), tmp_path, scheduler="tcp://127.0.0.1:9").run()


def test_ctrl_c_while_connecting_exits_130_at_once(tmp_path):
    """A scheduler address that accepts the connection but never answers: Ctrl-C while the
    sweep waits for it ends the command within seconds (exit 130), not after the timeout."""
    import socket

    silent = socket.socket()
    silent.bind(("127.0.0.1", 0))
    silent.listen()
    study = tmp_path / "study.toml"
    study.write_text(f'base = "{BASE.as_posix()}"\n[[axis]]\nkey = "engine.speed"\n'
                     "values = [2000.0]\n", encoding="utf-8")
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "sweep",
               str(study), "--out", str(tmp_path / "out"), "--scheduler",
               f"tcp://127.0.0.1:{silent.getsockname()[1]}"]
    try:
        with subprocess.Popen(command, env=env, stderr=subprocess.PIPE, text=True,
                              start_new_session=True) as process:
            for line in process.stderr:
                if "variants validated" in line:
                    break
            time.sleep(0.5)  # connecting
            sent = time.monotonic()
            os.killpg(process.pid, signal.SIGINT)
            stderr = process.stderr.read()
            process.wait(timeout=30)
    finally:
        silent.close()
    assert process.returncode == 130, stderr
    assert time.monotonic() - sent < 5.0
    assert "Traceback" not in stderr
