"""The rigid companion and the coarser orbits of the grid-error estimate, computed on a
second core while the run's own orbit runs.

An elastic run (``conrod run`` on an elastic ``[housing]``) computes, besides its own
orbit, the same bearing on a rigid bore and, for the grid error, its orbit on two coarser
grids; a rigid run of a grid film computes the two coarser orbits. None of them needs the
run's own answer. Where a second core is idle, a forked process computes them one after the
other while the run's orbit runs, and hands each result over the moment the run needs it;
a job it has not started when the run needs it, or while the run waits for another, the run
computes itself (work stealing). numba's
kernels it compiles on the way stay in the disk cache. The process runs the same code on
the same input, so the answer is the same bit for bit; a solver's error there is raised in
the run as it would have been, and a job it could not finish otherwise (a result that
cannot be sent, the process ended) is computed again in the run's own process. The forked
process writes nothing (its output goes to the null device), runs BLAS on one thread (a pool
forked from a program that loaded NumPy first took the run's core: README job 21.1 → 14.7 s)
and ends with the run.

Not in a worker process (a sweep's workers have their cores), not where ``fork`` is
missing or only one core is usable, and only while a core is idle now (sampled over 0.1 s
from the per-core counters; on a busy machine the second process would only take the CPU
time it saves); ``CONROD_SIDE_RUNS=0`` turns it off.

:func:`fork` starts such a process on other jobs without asking whether a core is idle:
``conrod run`` draws its figures so while the coarser orbits run
(:class:`conrod.output.registry.FigureDraft`).

.. code-block:: python

    with beside(simulation, coarse_jobs(simulation)):   # starts the process (or nothing)
        results = simulation.run(progress)     # takes the rigid companion from it
        results = with_grid_error(results, simulation, progress)   # and the coarse orbits
"""

from __future__ import annotations

import contextlib
import contextvars
import ctypes
import multiprocessing
import os
import pickle
import queue
import signal
import sys
import threading
import warnings
from collections.abc import Callable, Iterator
from typing import Any

from conrod.errors import ConrodError
from conrod.io.cores import load as _load
from conrod.io.cores import one_blas_thread, spare_core

SWITCH = "CONROD_SIDE_RUNS"
"""Environment variable: ``0`` turns the second process off."""
MISSING = object()
"""What :meth:`SideRuns.take` returns for a job the process did not deliver."""
DONE, RAISED, LOST = "done", "raised", "lost"
"""How a job ended in the process: its result, its error, or nothing to send [-]."""
RIGID = "rigid"
"""Job key of the rigid companion; a coarse grid's key is its (n_θ, n_z)."""
_active: contextvars.ContextVar[SideRuns | None] = contextvars.ContextVar(
    "conrod_side_runs", default=None)


def wanted() -> bool:
    """True when a second process can pay here (see the module docstring)."""
    return os.environ.get(SWITCH, "1") != "0" and spare_core(_load)


OPEN, THERE, HERE = 0, 1, 2
"""Who took a job: nobody yet, the second process, the run's own process [-]."""


class SideRuns:
    """The forked process, the pipe its results come through, and who took each job (a
    shared array: the process takes the next job nobody took, the run a job the process
    has not started)."""

    def __init__(self, process: Any, connection: Any, jobs: list[tuple[Any, Any]],
                 claims: Any, patience: float | None = None):
        self.process, self.connection, self.claims = process, connection, claims
        self.patience = patience
        self.jobs = dict(jobs)
        self.keys = [key for key, _ in jobs]
        self.received: dict[Any, Any] = {}
        self.taken: set[Any] = set()

    def take(self, key: Any) -> Any:
        """The job's result, waiting for it; the :class:`~conrod.errors.ConrodError` it
        raised, raised here; :data:`MISSING` when the process does not have it (not one of
        its jobs, not started there yet, failed otherwise, the process ended or silent past
        its patience): the run computes it. While the job runs there, the run takes the
        results already sent (the job may be among them), then computes the jobs nobody
        took yet itself, in their order, the largest first as the process takes them (work
        stealing: on a cold numba cache the process compiles the rigid companion's kernels
        while the run does the coarse orbits, the finer first, so that the process, once
        free, takes the smaller one instead of waiting)."""
        if key not in self.keys or key in self.taken:
            return MISSING
        self.taken.add(key)
        while key not in self.received and self.process is not None:
            if _claim(self.claims, self.keys.index(key), HERE):
                return MISSING
            if self._receive(0.0) or self._compute_one_here(key):
                continue
            if not self._receive(self.patience):  # silent that long: what is left is
                self.stop()                        # computed here
        outcome, value = self.received.pop(key, (LOST, MISSING))
        if outcome == RAISED:
            raise value
        return value

    def _receive(self, wait: float | None) -> bool:
        """Read the next result the process sent, waiting at most ``wait`` [s] for it (0:
        only one already in the pipe; None: as long as it takes); True if one was read. The
        process ended: it is stopped (what it has not delivered is computed here)."""
        try:
            if wait is not None and not self.connection.poll(wait):
                return False
            got, outcome, value = self.connection.recv()
        except (EOFError, OSError):
            self.stop()
            return False
        if outcome != LOST:
            self.received[got] = (outcome, value)
        return True

    def _compute_one_here(self, waiting_for: Any) -> bool:
        """Compute the first job nobody took (not ``waiting_for``) here; True if one ran."""
        for index in range(len(self.keys)):
            other = self.keys[index]
            if other != waiting_for and _claim(self.claims, index, HERE):
                try:
                    self.received[other] = (DONE, self.jobs[other]())
                except ConrodError as error:  # raised when that job is taken, as there
                    self.received[other] = (RAISED, error)
                return True
        return False

    def stop(self) -> None:
        """End the process now (its jobs are taken, or the run failed)."""
        process, self.process = self.process, None
        if process is not None:
            if process.is_alive():
                process.kill()
            process.join()
            self.connection.close()


def _claim(claims: Any, index: int, who: int) -> bool:
    """Take job ``index`` for ``who`` if nobody took it; True if taken now."""
    with claims.get_lock():
        if claims[index] != OPEN:
            return False
        claims[index] = who
        return True


def start(jobs: list[tuple[Any, Callable[[], Any]]]) -> SideRuns | None:
    """A forked process running ``jobs`` ((key, function) in order; None when it cannot
    pay or there is nothing to run)."""
    if not jobs or not wanted():
        return None
    return fork(jobs)


def fork(jobs: list[tuple[Any, Callable[[], Any]]],
         patience: float | None = None) -> SideRuns | None:
    """A forked process running ``jobs`` as :func:`start` does, without asking whether it
    pays (None only without ``fork`` or jobs); ``patience`` [s]: the longest the run waits
    for the process's next result before it ends the process and computes what is left
    (None: as long as a job takes)."""
    if not jobs or "fork" not in multiprocessing.get_all_start_methods():
        return None
    context = multiprocessing.get_context("fork")
    receiving, sending = context.Pipe(duplex=False)
    claims = context.Array("b", len(jobs))
    process = context.Process(target=_serve, args=(jobs, sending, claims), daemon=True)
    process.start()
    sending.close()
    return SideRuns(process, receiving, jobs, claims, patience)


@contextlib.contextmanager
def beside(simulation: Any, more: tuple[tuple[Any, Callable[[], Any]], ...] = ()
           ) -> Iterator[Any]:
    """Within the block, :func:`take` finds the rigid companion of an elastic
    ``simulation`` and the results of the ``more`` jobs ((key, function), e.g. the coarser
    orbits of :func:`conrod.simulation.grid_error.coarse_jobs`) computed by a second process
    (started here unless one already runs for the block around this one); the block is
    given the :class:`SideRuns` (None: no process)."""
    if _active.get() is not None:
        yield _active.get()
        return
    side = start(_jobs(simulation, more))
    token = _active.set(side)
    try:
        yield side
    finally:
        _active.reset(token)
        if side is not None:
            side.stop()


def take(key: Any) -> Any:
    """The result of job ``key`` from the process of the enclosing :func:`beside` block, or
    :data:`MISSING`."""
    side = _active.get()
    return MISSING if side is None else side.take(key)


def _jobs(simulation: Any, more: tuple[tuple[Any, Any], ...]) -> list[tuple[Any, Any]]:
    """The rigid companion of an elastic orbit (when asked for), then the ``more`` jobs: a
    rigid orbit's coarser grid-error orbits cost about as much CPU as the orbit itself
    (module docstring)."""
    jobs: list[tuple[Any, Any]] = []
    if simulation.elastic() and simulation.rigid_companion() is not None:
        jobs.append((RIGID, lambda: _rigid_companion(simulation)))
    return jobs + list(more)


def _rigid_companion(simulation: Any) -> Any:
    """The rigid companion's results, with the integrator the elastic run resolves to (an
    automatic one chooses by the film, as there)."""
    from conrod import registry
    from conrod.orbit.integrators import resolved

    integrator = simulation.integrator()
    if isinstance(integrator, str):
        integrator = registry.integrator(integrator)
    name = resolved(integrator, simulation.problem()).name
    return simulation.rigid_companion(integrator=name).run_orbit()[0]


def _serve(jobs: list[tuple[Any, Callable[[], Any]]], connection: Any, claims: Any) -> None:
    """The forked process: each job nobody took in turn, its result sent (or MISSING),
    silent."""
    _die_with_parent()
    one_blas_thread()  # forked with the run's BLAS pool, whose threads would take its core
    null = os.open(os.devnull, os.O_WRONLY)
    for descriptor in (1, 2):  # the streams below Python's (which may be replaced)
        os.dup2(null, descriptor)
    sys.stdout = sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - for the process's life
    warnings.simplefilter("ignore")
    # a result is larger than the pipe holds, and the run reads it only when it needs it:
    # a thread sends while the next job computes (sending from here would stall the jobs)
    outbox: queue.Queue = queue.Queue()
    sender = threading.Thread(target=_send_all, args=(outbox, connection), daemon=True)
    sender.start()
    for index, (key, job) in enumerate(jobs):
        if not _claim(claims, index, THERE):  # the run computes it
            continue
        try:
            outcome = (key, DONE, job())
        except ConrodError as error:  # raised there as here, where it survives the pipe
            outcome = (key, RAISED, error) if _sendable(error) else (key, LOST, None)
        except BaseException:  # anything else is computed again there
            outcome = (key, LOST, None)
        outbox.put(outcome)
    outbox.put(None)
    sender.join()


def _send_all(outbox: queue.Queue, connection: Any) -> None:
    """Send the outcomes put in ``outbox`` in order until None (the sending thread)."""
    while (outcome := outbox.get()) is not None:
        try:
            connection.send(outcome)
        except Exception:  # not picklable: computed again there
            connection.send((outcome[0], LOST, None))


def _sendable(error: BaseException) -> bool:
    """True when ``error`` comes out of the pipe as the same type with the same message."""
    try:
        copy = pickle.loads(pickle.dumps(error))
    except Exception:
        return False
    return isinstance(copy, type(error)) and str(copy) == str(error)


def _die_with_parent() -> None:
    """Linux: the process gets SIGKILL when the run's process ends (prctl PDEATHSIG)."""
    with contextlib.suppress(Exception):
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)
