"""The local worker pool of a sweep: every item once, batches sized from measured times,
exceptions and worker deaths as outcomes, Ctrl-C not seen by the workers, no worker left
behind (also when the sweep's process is killed), the forkserver where threads run, and one
BLAS thread per worker."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import pytest

from blas_helpers import blas_threads, two_blas_threads
from conrod.errors import CaseError
from conrod.sweep.pool import DIED, DONE, ERROR, MAX_DEATHS, BatchSizer, LocalPool

REPO = Path(__file__).resolve().parents[1]


def square_and_pid(value: int) -> tuple[int, int]:
    return value * value, os.getpid()


def fail_on_odd(value: int) -> int:
    if value % 2:
        raise ValueError(f"odd value {value}")
    return value


def die_once(value: int, marker: str) -> int:
    """Kill the worker the first time ``value`` 3 is computed (the marker file remembers)."""
    if value == 3 and not os.path.exists(marker):
        Path(marker).write_text("died", encoding="utf-8")
        os.kill(os.getpid(), signal.SIGKILL)
    return value


def die_always(value: int) -> int:
    if value == 3:
        os.kill(os.getpid(), signal.SIGKILL)
    return value


def sleep_and_pid(seconds: float) -> int:
    time.sleep(seconds)
    return os.getpid()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    with open(f"/proc/{pid}/stat", encoding="utf-8") as stat:
        return stat.read().split(") ")[1][0] != "Z"  # a zombie has ended


def test_every_item_once_from_both_workers():
    with LocalPool(square_and_pid, 2) as pool:
        outcomes = list(pool.imap([(value,) for value in range(50)]))
        pids = set(pool.pids)
    assert sorted(index for index, _, _ in outcomes) == list(range(50))
    assert all(kind == DONE and value[0] == index * index for index, kind, value in outcomes)
    assert {value[1] for _, _, value in outcomes} == pids and len(pids) == 2
    assert os.getpid() not in pids


def test_an_exception_is_an_outcome_not_a_crash():
    with LocalPool(fail_on_odd, 2) as pool:
        outcomes = {index: (kind, value) for index, kind, value in
                    pool.imap([(value,) for value in range(6)])}
    assert [outcomes[i][0] for i in range(6)] == [DONE, ERROR] * 3
    assert isinstance(outcomes[3][1], ValueError) and "odd value 3" in str(outcomes[3][1])


def test_a_dead_worker_is_replaced_and_its_items_computed(tmp_path):
    marker = str(tmp_path / "died")
    with LocalPool(die_once, 2) as pool:
        outcomes = sorted(pool.imap([(value, marker) for value in range(8)]))
    assert Path(marker).is_file()  # a worker did die
    assert outcomes == [(value, DONE, value) for value in range(8)]


def test_an_item_that_kills_every_worker_is_given_up():
    with LocalPool(die_always, 2) as pool:
        outcomes = {index: (kind, value) for index, kind, value in
                    pool.imap([(value,) for value in range(6)])}
    assert outcomes[3][0] == DIED
    assert f"killed by SIGKILL) {MAX_DEATHS} times" in outcomes[3][1]
    assert all(outcomes[i] == (DONE, i) for i in (0, 1, 2, 4, 5))


def test_batches_follow_the_measured_item_time():
    sizer = BatchSizer(workers=2, seconds=0.5, largest=64)
    assert sizer.next_size(1000) == 1  # nothing measured yet
    for _ in range(4):
        sizer.record(0.01)
    assert sizer.next_size(1000) == 50  # 0.5 s of 10 ms items
    assert sizer.next_size(40) == 10  # a fair share of what is left: 40 / (2 workers x 2)
    assert sizer.next_size(3) == 1
    slow = BatchSizer(workers=2)
    slow.record(3.0)
    assert slow.next_size(1000) == 1
    fast = BatchSizer(workers=1, seconds=0.5, largest=64)
    fast.record(1e-6)
    assert fast.next_size(10_000) == 64


def test_workers_ignore_ctrl_c_and_end_with_the_pool():
    pool = LocalPool(sleep_and_pid, 2)
    try:
        outcomes = pool.imap([(0.3,), (0.3,)])
        first = next(outcomes)
        for pid in pool.pids:
            os.kill(pid, signal.SIGINT)  # what a terminal's Ctrl-C sends the process group
        second = next(outcomes)
        pids = pool.pids
        assert {first[1], second[1]} == {DONE} and all(_alive(pid) for pid in pids)
    finally:
        pool.close()
    assert not any(_alive(pid) for pid in pids)


def test_each_worker_runs_blas_on_one_thread():
    """The workers start with the sweep's NumPy loaded; a BLAS pool in each would spin on the
    cores the other workers compute on."""
    with two_blas_threads():
        with LocalPool(blas_threads, 2) as pool:
            counts = [value for _, kind, value in pool.imap([(i,) for i in range(4)])
                      if kind == DONE]
        assert blas_threads() == 2  # the sweep's own process keeps its pool
    assert counts == [1, 1, 1, 1]


def test_workers_are_forked_from_a_forkserver_where_threads_run():
    stop = threading.Event()
    thread = threading.Thread(target=stop.wait, daemon=True)
    thread.start()
    try:
        with LocalPool(square_and_pid, 1) as pool:
            (index, kind, value), = pool.imap([(7,)])
            parent = int(Path(f"/proc/{value[1]}/stat").read_text().split(") ")[1].split()[1])
    finally:
        stop.set()
        thread.join()
    assert (index, kind, value[0]) == (0, DONE, 49)
    assert parent != os.getpid()  # a child of the forkserver, not of this threaded process


def test_workers_end_when_the_sweep_process_is_killed(tmp_path):
    """SIGKILL of the process that owns the pool: its workers, in the middle of an item,
    end too (nothing keeps computing for a sweep that is gone)."""
    script = textwrap.dedent("""
        import sys, time
        from conrod.sweep.pool import LocalPool
        from test_sweep_pool import sleep_and_pid
        pool = LocalPool(sleep_and_pid, 2)
        items = pool.imap([(0.01,), (0.01,), (60.0,), (60.0,)])
        next(items), next(items)
        print(*pool.pids, flush=True)
        time.sleep(60)
    """)
    env = {**os.environ, "PYTHONPATH": os.pathsep.join([str(REPO / "src"), str(REPO / "tests")])}
    with subprocess.Popen([sys.executable, "-c", script], env=env, text=True,
                          stdout=subprocess.PIPE) as process:
        try:
            pids = [int(pid) for pid in process.stdout.readline().split()]
            assert len(pids) == 2 and all(_alive(pid) for pid in pids)
        finally:
            process.kill()
    deadline = time.monotonic() + 5.0
    while any(_alive(pid) for pid in pids) and time.monotonic() < deadline:
        time.sleep(0.02)
    assert not any(_alive(pid) for pid in pids)


@pytest.mark.parametrize("workers", [0, -1, 1.5, True, "2"])
def test_worker_count_is_checked(workers):
    with pytest.raises(CaseError, match=r"workers = .*allowed: an integer >= 1"):
        LocalPool(square_and_pid, workers)
