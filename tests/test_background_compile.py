"""The rigid companion compiled in a forked process while the elastic orbit runs: what the
process runs, that it is silent, waited for, and off where it cannot pay."""

from __future__ import annotations

import json
import multiprocessing
import sys

import pytest

from conrod.simulation import background_compile


class _Solver:
    n_theta, n_z = 144, 16


class _Companion:
    def __init__(self, record, overrides):
        self.record, self.overrides = record, overrides

    def run_orbit(self):
        print("to stdout")  # must go nowhere
        print("to stderr", file=sys.stderr)
        self.record.write_text(json.dumps(self.overrides))


class _Simulation:
    """What :func:`background_compile.start` uses of a Simulation."""

    solver = _Solver()

    def __init__(self, record, companion=True):
        self.record, self.companion = record, companion

    def rigid_companion(self, integrator=None, **overrides):
        return _Companion(self.record, overrides) if self.companion else None


@pytest.fixture
def fresh(monkeypatch):
    monkeypatch.setitem(vars(background_compile)["_state"], "started", False)
    monkeypatch.delenv(background_compile.SWITCH, raising=False)
    monkeypatch.setattr(background_compile.os, "sched_getaffinity", lambda pid: {0, 1},
                        raising=False)
    monkeypatch.setattr(background_compile, "_load", lambda: 0.2)


def test_the_forked_process_runs_one_coarse_cycle_silently_and_is_waited_for(
        tmp_path, fresh, capfd):
    record = tmp_path / "ran.json"
    process = background_compile.start(_Simulation(record))
    assert process is not None
    background_compile.finish(process)
    assert not process.is_alive() and process.exitcode == 0
    assert json.loads(record.read_text()) == {"n_theta": 24, "n_z": 8, "min_cycles": 1,
                                              "max_cycles": 1}
    out, err = capfd.readouterr()
    assert "to stdout" not in out and "to stderr" not in err
    # once per process: the second elastic run finds the kernels compiled
    assert background_compile.start(_Simulation(tmp_path / "again.json")) is None


def test_a_coarse_grid_of_the_user_is_kept(tmp_path, fresh):
    record = tmp_path / "ran.json"
    simulation = _Simulation(record)
    simulation.solver = type("S", (), {"n_theta": 12, "n_z": 4})()
    background_compile.finish(background_compile.start(simulation))
    assert json.loads(record.read_text())["n_theta"] == 12
    assert json.loads(record.read_text())["n_z"] == 4


def test_no_process_without_companion_switched_off_on_one_core_or_busy_machine(
        tmp_path, fresh, monkeypatch):
    assert background_compile.start(_Simulation(tmp_path / "a", companion=False)) is None
    monkeypatch.setenv(background_compile.SWITCH, "0")
    assert background_compile.start(_Simulation(tmp_path / "b")) is None
    monkeypatch.delenv(background_compile.SWITCH)
    monkeypatch.setattr(background_compile.os, "sched_getaffinity", lambda pid: {0},
                        raising=False)
    assert background_compile.start(_Simulation(tmp_path / "c")) is None
    monkeypatch.setattr(background_compile.os, "sched_getaffinity", lambda pid: {0, 1},
                        raising=False)
    monkeypatch.setattr(background_compile, "_load", lambda: 1.3)  # the other core is busy
    assert background_compile.start(_Simulation(tmp_path / "d")) is None
    assert not any(tmp_path.iterdir())


def _in_worker(queue):
    queue.put(background_compile.wanted())


def test_no_process_from_a_worker_process(fresh):
    context = multiprocessing.get_context("fork")
    queue = context.Queue()
    worker = context.Process(target=_in_worker, args=(queue,))
    worker.start()
    assert queue.get(timeout=60) is False
    worker.join()


def test_a_failing_run_ends_the_process(tmp_path, fresh):
    class _Slow(_Companion):
        def run_orbit(self):
            import time

            time.sleep(60)

    simulation = _Simulation(tmp_path / "x")
    simulation.rigid_companion = lambda integrator=None, **o: _Slow(tmp_path / "x", o)
    process = background_compile.start(simulation)
    background_compile.stop(process)
    assert not process.is_alive()
