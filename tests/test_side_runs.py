"""The rigid companion and the coarser grid-error orbits computed by a forked process while
the run's own orbit runs (elastic or rigid): jobs in order, silent, failed or unsendable
jobs left to the run's own process, off where it cannot pay, and the same answer bit for
bit."""

from __future__ import annotations

import multiprocessing
import sys
import threading
import time

import pytest
from typer.testing import CliRunner

from blas_helpers import blas_threads, two_blas_threads
from conrod.cli.app import _register_commands, app
from conrod.io import cores
from conrod.simulation import side_runs

_register_commands()


@pytest.fixture
def fresh(monkeypatch):
    """An idle 2-core machine."""
    monkeypatch.delenv(side_runs.SWITCH, raising=False)
    monkeypatch.setattr(side_runs.os, "sched_getaffinity", lambda pid: {0, 1}, raising=False)
    monkeypatch.setattr(side_runs, "_load", lambda: 0.2)


def _loud(value):
    print("to stdout")  # must go nowhere
    print("to stderr", file=sys.stderr)
    return value


def _fails():
    raise RuntimeError("a solver failed")


def _does_not_converge():
    from conrod.errors import ConvergenceError

    raise ConvergenceError("orbit did not converge", where="crank angle 20.0 deg")


def test_jobs_run_in_order_silently_and_their_results_are_handed_over(fresh, capfd):
    side = side_runs.start([("a", lambda: _loud({"x": 1.5})), ("b", _fails),
                            ("c", lambda: threading.Lock()), ((72, 8), lambda: [2, 3]),
                            ("e", _does_not_converge)])
    assert side is not None
    while side_runs.OPEN in side.claims[:]:  # all taken by the process
        time.sleep(0.01)
    assert list(side.claims[:]) == [side_runs.THERE] * 5
    assert side.take((72, 8)) == [2, 3]  # waits for the earlier ones on the way
    assert side.take("a") == {"x": 1.5}
    assert side.take("b") is side_runs.MISSING  # failed otherwise: computed again here
    assert side.take("c") is side_runs.MISSING  # a lock cannot be sent
    assert side.take("d") is side_runs.MISSING  # not one of its jobs
    assert side.take("a") is side_runs.MISSING  # taken once
    from conrod.errors import ConvergenceError

    with pytest.raises(ConvergenceError, match="did not converge at crank angle 20.0 deg"):
        side.take("e")  # a solver's own error: raised here as there
    side.stop()
    out, err = capfd.readouterr()
    assert "to stdout" not in out and "to stderr" not in err


def test_the_process_runs_blas_on_one_thread(fresh):
    """Forked with the run's BLAS pool (NumPy loaded before the CLI could set it to one
    thread), the process would spin its threads on the core the run computes on."""
    with two_blas_threads():
        side = side_runs.start([("threads", blas_threads)])
        assert side is not None
        while side_runs.OPEN in side.claims[:]:  # taken by the process
            time.sleep(0.01)
        assert side.take("threads") == 1
        side.stop()
        assert blas_threads() == 2  # the run keeps its own


def test_an_ended_process_leaves_its_jobs_to_the_run(fresh):
    side = side_runs.start([("slow", lambda: time.sleep(60))])
    while side.claims[0] == side_runs.OPEN:  # started there
        time.sleep(0.01)
    side.process.kill()
    started = time.perf_counter()
    assert side.take("slow") is side_runs.MISSING
    assert time.perf_counter() - started < 10 and side.process is None


def test_stop_ends_a_running_process(fresh):
    side = side_runs.start([("slow", lambda: time.sleep(60))])
    process = side.process
    side.stop()
    assert not process.is_alive()


def test_no_process_without_jobs_switched_off_on_one_core_or_busy_machine(fresh, monkeypatch):
    job = [("a", lambda: 1)]
    assert side_runs.start([]) is None
    monkeypatch.setenv(side_runs.SWITCH, "0")
    assert side_runs.start(job) is None
    monkeypatch.delenv(side_runs.SWITCH)
    monkeypatch.setattr(side_runs.os, "sched_getaffinity", lambda pid: {0}, raising=False)
    assert side_runs.start(job) is None
    monkeypatch.setattr(side_runs.os, "sched_getaffinity", lambda pid: {0, 1}, raising=False)
    monkeypatch.setattr(side_runs, "_load", lambda: 1.3)  # the other core is busy
    assert side_runs.start(job) is None


def _in_worker(queue):
    queue.put(side_runs.wanted())


def test_no_process_from_a_worker_process(fresh):
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    worker = context.Process(target=_in_worker, args=(queue,))
    worker.start()
    assert queue.get(timeout=60) is False
    worker.join()


def test_elastic_run_with_side_runs_writes_the_same_files_as_without(
        fresh, tmp_path, monkeypatch):
    """`conrod run` on an elastic bore with the rigid companion and the grid-error orbits
    computed beside it, and its figures drawn by a third process meanwhile: the same cycle
    tables, grid error and figures, bit for bit."""
    import json

    from test_ehd_cli import _case_file

    case = _case_file(tmp_path, 1e4)
    handed = []
    take = side_runs.SideRuns.take

    def spied(self, key):
        value = take(self, key)
        handed.append((key, value is not side_runs.MISSING))
        return value

    monkeypatch.setattr(side_runs.SideRuns, "take", spied)
    outs = {}
    for mode in ("beside", "alone"):
        if mode == "alone":
            monkeypatch.setenv(side_runs.SWITCH, "0")
        outs[mode] = tmp_path / mode
        result = CliRunner().invoke(app, ["run", case, "--out", str(outs[mode])])
        assert result.exit_code in (0, 4), result.output
    # each once, in the run's order; from the process, or computed here where the process
    # had not started it (work stealing: which one depends on the timing)
    figures = sorted(p.name for p in outs["alone"].glob("*.png"))
    assert [key for key, _ in handed if key not in figures] == ["rigid", (26, 6), (18, 4)]
    assert sorted(key for key, _ in handed if key in figures) == figures and figures
    for name in ("cycle.csv", "cycle_rigid.csv", *figures):
        assert (outs["beside"] / name).read_bytes() == (outs["alone"] / name).read_bytes()
    summaries = [_untimed(json.loads((outs[m] / "summary.json").read_text()))
                 for m in ("beside", "alone")]
    assert summaries[0] == summaries[1]
    assert "grid error +" in json.dumps(summaries[0]) or "grid error -" in json.dumps(
        summaries[0])


def test_rigid_run_with_its_coarse_orbits_beside_writes_the_same_files_as_without(
        fresh, tmp_path, monkeypatch):
    """`conrod run` of a grid film on a rigid bore: a process started on the coarser
    grid-error orbits (no rigid companion to compute), the same files bit for bit."""
    import json

    from hardening_helpers import cheap_table_run, write_case

    case = cheap_table_run()
    case["solver"].update(film="reynolds", n_theta=36, n_z=8)
    path = str(write_case(tmp_path, case))
    started = []
    start = side_runs.start

    def spied(jobs):
        side = start(jobs)
        started.append(([key for key, _ in jobs], side is not None))
        return side

    monkeypatch.setattr(side_runs, "start", spied)
    outs = {}
    for mode in ("beside", "alone"):
        if mode == "alone":
            monkeypatch.setenv(side_runs.SWITCH, "0")
        outs[mode] = tmp_path / mode
        result = CliRunner().invoke(app, ["run", path, "--out", str(outs[mode]),
                                          "--no-figures"])
        assert result.exit_code in (0, 4), result.output
    assert started == [([(26, 6), (18, 4)], True), ([(26, 6), (18, 4)], False)]
    assert (outs["beside"] / "cycle.csv").read_bytes() == (
        outs["alone"] / "cycle.csv").read_bytes()
    summaries = [_untimed(json.loads((outs[m] / "summary.json").read_text()))
                 for m in ("beside", "alone")]
    assert summaries[0] == summaries[1]
    assert "grid error +" in json.dumps(summaries[0]) or "grid error -" in json.dumps(
        summaries[0])


def _untimed(value):
    """A summary without its wall times (keys naming a time, '(12.3 s)' in the text)."""
    import re

    if isinstance(value, dict):
        return {k: _untimed(v) for k, v in value.items() if "time" not in k}
    if isinstance(value, list):
        return [_untimed(v) for v in value]
    if isinstance(value, str):
        return re.sub(r"\(\d+(\.\d+)? s\)", "", value)
    return value


STAT_BEFORE = """cpu  300 0 100 1600 0 0 0 0 0 0
cpu0 200 0 50 750 0 0 0 0 0 0
cpu1 100 0 50 850 0 0 0 0 0 0
intr 12345
"""
STAT_AFTER = """cpu  390 0 110 1700 0 0 0 0 0 0
cpu0 290 0 60 750 0 0 0 0 0 0
cpu1 100 0 50 950 0 0 0 0 0 0
intr 12399
"""


def test_busy_cores_from_the_per_core_counters():
    """Between the readings core 0 was busy all 100 ticks, core 1 idle all 100: one core in
    use, whichever cores are usable."""
    assert cores.busy_cores(STAT_BEFORE, STAT_AFTER, None) == pytest.approx(1.0)
    assert cores.busy_cores(STAT_BEFORE, STAT_AFTER, [1]) == pytest.approx(0.0)
    assert cores.busy_cores(STAT_BEFORE, STAT_AFTER, [0]) == pytest.approx(1.0)
    assert cores.busy_cores(STAT_BEFORE, STAT_AFTER, [2]) is None  # not counted
    assert cores.busy_cores(STAT_BEFORE, STAT_BEFORE, None) is None  # no time passed


def test_load_falls_back_to_the_load_average_without_counters(monkeypatch, tmp_path):
    monkeypatch.setattr(cores, "PROC_STAT", str(tmp_path / "missing"))
    monkeypatch.setattr(cores.os, "getloadavg", lambda: (0.7, 0.5, 0.4))
    assert cores.load() == 0.7


def test_load_of_this_machine_is_a_share_of_its_usable_cores():
    """Read from this machine's counters (or its load average): between 0 and the usable
    cores (the load average may exceed them)."""
    os = cores.os
    load = cores.load()
    usable = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    assert 0.0 <= load <= max(usable, os.getloadavg()[0]) + 1e-9


def test_the_run_computes_the_jobs_the_process_has_not_started(fresh):
    """Work stealing: the process is busy with "slow"; the run needs "late" and computes it
    (MISSING: the caller's own path), and while it waits for "slow" it computes the others
    nobody took, in their order, with a solver's error raised when that job is taken."""
    started = []
    side = side_runs.start([("slow", lambda: time.sleep(1.0) or "slow done"),
                            ("mid", lambda: started.append("mid") or 1),
                            ("last", _does_not_converge), ("late", lambda: 3)])
    while side.claims[0] == side_runs.OPEN:
        time.sleep(0.01)
    assert side.take("late") is side_runs.MISSING
    assert side.take("slow") == "slow done"  # computed "mid", then "last" here meanwhile
    assert started == ["mid"]  # here: this process's list
    assert list(side.claims[:]) == [side_runs.THERE] + [side_runs.HERE] * 3
    assert side.take("mid") == 1
    from conrod.errors import ConvergenceError

    with pytest.raises(ConvergenceError, match="did not converge"):
        side.take("last")
    assert side.take("late") is side_runs.MISSING  # taken once
    side.stop()


def test_a_process_past_its_patience_is_ended_and_what_is_left_computed_here(fresh):
    """``fork`` starts the process without sampling the cores; with a patience the run waits
    that long for its next result, then ends it and computes the jobs left here."""
    side = side_runs.fork([("stuck", lambda: time.sleep(60)), ("next", lambda: 2)],
                          patience=0.3)
    while side.claims[0] == side_runs.OPEN:
        time.sleep(0.01)
    started = time.perf_counter()
    assert side.take("stuck") is side_runs.MISSING  # to compute here
    assert time.perf_counter() - started < 10.0 and side.process is None
    assert list(side.claims[:]) == [side_runs.THERE, side_runs.HERE]
    assert side.take("next") == 2  # computed here while it waited


def test_a_result_already_sent_is_taken_before_a_job_is_computed_here(fresh):
    """The run waiting for a job whose result is in the pipe takes it at once instead of
    computing a job nobody took first (which the process would take next)."""
    side = side_runs.start([("first", lambda: 1), ("long", lambda: time.sleep(1.0) or 2),
                            ("open", lambda: 3)])
    while side.claims[1] == side_runs.OPEN or not side.connection.poll():
        time.sleep(0.01)
    assert side.take("first") == 1
    assert side.claims[2] == side_runs.OPEN  # left to the process
    assert side.take("long") == 2
    side.stop()
