"""Worker processes on this machine: started once per sweep, fed batches of items.

``LocalPool(function, workers)`` runs ``function(*args)`` for every item in worker
processes and yields each item's outcome as soon as it is known:

* **Started in milliseconds.** The workers are forked from the sweep's own process after it
  has imported what a variant runs and set up numba's compiler
  (:func:`conrod.sweep.worker.preload`): no interpreter start and no imports per worker;
  each worker loads the compiled kernels from numba's disk cache once, on its first item,
  and keeps them for the rest of the sweep. (Where the process already runs other threads,
  a fork could copy a held lock, so the workers are forked from a clean ``forkserver``
  process instead, which imports the same modules once.)
* **One BLAS thread each.** A worker has a core of its own; NumPy's BLAS pool, loaded
  before the fork, is cut to one thread there (:func:`conrod.io.cores.one_blas_thread`).
* **Batches.** Items go out in batches sized to about :data:`BATCH_SECONDS` of work each
  (:class:`BatchSizer`, from the item times measured so far), so that a cheap item costs
  one message, not one round trip; outcomes come back one by one.
* **A worker that dies** (killed, out of memory, a crash in compiled code) is replaced;
  the items of its batch go to the others, and an item that was being computed when a
  worker died :data:`MAX_DEATHS` times is given up (outcome ``DIED``).
* **Ctrl-C** is not seen by the workers (they ignore SIGINT, which a terminal sends to the
  whole process group); the pool checks for it every :data:`POLL_SECONDS` and, on
  ``KeyboardInterrupt`` or any other exit, ends its workers at once (SIGTERM, then
  SIGKILL). A worker also dies with the sweep's process if that is killed (Linux).
"""

from __future__ import annotations

import contextlib
import ctypes
import gc
import multiprocessing
import os
import signal
import sys
import threading
import time
from collections import Counter, deque
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from multiprocessing.connection import Connection, wait
from typing import Any

from conrod.errors import CaseError
from conrod.io.cores import one_blas_thread
from conrod.io.interrupts import raise_if_interrupted

BATCH_SECONDS = 0.5
"""Work per batch the pool aims at [s]."""
LARGEST_BATCH = 64
"""Most items in one batch [-]."""
MAX_DEATHS = 2
"""Worker deaths while computing one item after which the item is given up [-]."""
POLL_SECONDS = 0.1
"""How often the pool looks for Ctrl-C while it waits for outcomes [s]."""
STOP_SECONDS = 1.0
"""How long a worker gets to end after SIGTERM before SIGKILL [s]."""

DONE, ERROR, DIED = "done", "error", "died"
"""Outcome kinds: the function's return value, the exception it raised, or the message that
the item's workers kept dying."""

_PR_SET_PDEATHSIG = 1


class BatchSizer:
    """Batch sizes from the item times measured so far: about ``seconds`` of work per
    batch, one item while nothing is known, and never more than a fair share of what is
    left (the last batches stay short, so that all workers finish together)."""

    def __init__(self, workers: int, seconds: float = BATCH_SECONDS,
                 largest: int = LARGEST_BATCH):
        self.workers, self.seconds, self.largest = workers, seconds, largest
        self.total_time, self.count = 0.0, 0

    def record(self, seconds: float) -> None:
        """One item took ``seconds`` [s] on its worker."""
        self.total_time += max(seconds, 0.0)
        self.count += 1

    def next_size(self, remaining: int) -> int:
        """Items in the next batch when ``remaining`` items wait [-]."""
        if self.count == 0:
            return 1
        mean = self.total_time / self.count
        size = int(self.seconds / mean) if mean > 0.0 else self.largest
        fair = remaining // (2 * self.workers)
        return max(1, min(size, fair, self.largest, remaining))


@dataclass
class _Worker:
    process: Any
    conn: Connection
    batch: deque[int] = field(default_factory=deque)


class LocalPool:
    """``workers`` processes that run ``function`` (a module-level function) on items."""

    def __init__(self, function: Callable[..., Any], workers: int,
                 batch_seconds: float = BATCH_SECONDS):
        if not isinstance(workers, int) or isinstance(workers, bool) or workers < 1:
            raise CaseError(f"workers = {workers!r}: out of range (allowed: an integer >= 1)")
        self.function, self.workers, self.batch_seconds = function, workers, batch_seconds
        self._live: list[_Worker] = []

    def __enter__(self) -> LocalPool:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    @property
    def pids(self) -> list[int]:
        """Process ids of the running workers."""
        return [w.process.pid for w in self._live]

    def imap(self, items: Sequence[tuple[Any, ...]]) -> Iterator[tuple[int, str, Any]]:
        """Run every item; yield ``(index, kind, value)`` as each finishes (any order):
        kind :data:`DONE` with the return value, :data:`ERROR` with the exception, or
        :data:`DIED` with a message."""
        queue, deaths = deque(range(len(items))), Counter()
        sizer = BatchSizer(self.workers, self.batch_seconds)
        while len(self._live) < min(self.workers, len(items)):
            self._live.append(self._start())
        while queue or any(w.batch for w in self._live):
            self._feed(queue, items, sizer)
            busy = {w.conn: w for w in self._live if w.batch}
            ready = wait(list(busy), timeout=POLL_SECONDS)
            raise_if_interrupted()
            for conn in ready:
                worker = busy[conn]
                try:
                    index, kind, value, seconds = conn.recv()
                except (EOFError, OSError):
                    yield from self._bury(worker, queue, deaths)
                    continue
                worker.batch.remove(index)
                sizer.record(seconds)
                yield index, kind, value

    def close(self) -> None:
        """End every worker now (SIGTERM, then SIGKILL after :data:`STOP_SECONDS`)."""
        workers, self._live = self._live, []
        for worker in workers:
            with contextlib.suppress(OSError):
                worker.process.terminate()
        deadline = time.monotonic() + STOP_SECONDS
        for worker in workers:
            worker.process.join(max(0.0, deadline - time.monotonic()))
            if worker.process.exitcode is None:
                worker.process.kill()
                worker.process.join()
            worker.conn.close()

    def _feed(self, queue: deque[int], items: Sequence[tuple[Any, ...]],
              sizer: BatchSizer) -> None:
        for worker in list(self._live):
            if worker.batch or not queue:
                continue
            size = sizer.next_size(len(queue))
            batch = [queue.popleft() for _ in range(min(size, len(queue)))]
            worker.batch.extend(batch)
            try:
                worker.conn.send((self.function, [(index, items[index]) for index in batch]))
            except OSError:  # it died while idle: nothing of this batch was started
                worker.batch.clear()
                queue.extendleft(reversed(batch))
                self._replace(worker)

    def _bury(self, worker: _Worker, queue: deque[int],
              deaths: Counter) -> Iterator[tuple[int, str, Any]]:
        """A worker died: give its unfinished items back (the one it was computing with a
        death counted against it), and start another worker."""
        code = self._replace(worker, start=False)
        unfinished = list(worker.batch)
        current = unfinished[0]
        deaths[current] += 1
        if deaths[current] >= MAX_DEATHS:
            unfinished.pop(0)
            yield current, DIED, (f"its worker process died ({_exit_text(code)}) "
                                  f"{deaths[current]} times while computing it")
        queue.extendleft(reversed(unfinished))
        if queue:
            self._live.append(self._start())

    def _replace(self, worker: _Worker, start: bool = True) -> int | None:
        """Drop a dead worker (and start another); its exit code."""
        worker.process.join(STOP_SECONDS)
        if worker.process.exitcode is None:
            worker.process.kill()
            worker.process.join()
        worker.conn.close()
        self._live.remove(worker)
        if start:
            self._live.append(self._start())
        return worker.process.exitcode

    def _start(self) -> _Worker:
        context = _context()
        parent_end, child_end = context.Pipe()
        parent = os.getpid() if context.get_start_method() == "fork" else None
        process = context.Process(target=serve, args=(child_end, parent), daemon=True,
                                  name="conrod-sweep-worker")
        process.start()
        child_end.close()  # so that the parent sees EOF when the worker dies
        return _Worker(process, parent_end)


def serve(conn: Connection, parent_pid: int | None) -> None:
    """A worker's loop: batches in, one ``(index, kind, value, seconds)`` out per item;
    ends on ``None`` or when the process that started it is gone."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)  # Ctrl-C is the sweep's to handle
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    parent = os.getppid()
    if parent_pid is not None and parent != parent_pid:
        return  # the sweep ended while this worker started
    _die_with_parent()
    one_blas_thread()  # the worker has its core; NumPy is loaded already
    gc.freeze()  # what it was forked with stays to its end: the collector's passes skip it
    while True:
        try:
            while not conn.poll(POLL_SECONDS * 10):
                if os.getppid() != parent:
                    return
            message = conn.recv()
        except (EOFError, OSError):
            return
        if message is None:
            return
        function, batch = message
        for index, args in batch:
            start = time.perf_counter()
            try:
                outcome = (index, DONE, function(*args))
            except Exception as error:
                outcome = (index, ERROR, error)
            _send(conn, outcome + (time.perf_counter() - start,))


def _send(conn: Connection, message: tuple[Any, ...]) -> None:
    try:
        conn.send(message)
    except (BrokenPipeError, EOFError):
        sys.exit(0)  # the sweep is gone
    except Exception as error:  # an outcome that cannot be pickled
        index, _, value, seconds = message
        text = f"{type(value).__name__}: {value}" if message[1] == ERROR else repr(error)
        conn.send((index, ERROR, RuntimeError(text), seconds))


def _die_with_parent() -> None:
    """Ask Linux to kill this worker as soon as the process that started it ends, also in
    the middle of an item (elsewhere the worker ends at its next look at its parent)."""
    with contextlib.suppress(AttributeError, OSError):
        libc = ctypes.CDLL(None, use_errno=True)
        libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)


def _context():
    """``fork`` from a single-threaded process; ``forkserver`` where other threads run;
    ``spawn`` where neither exists (Windows)."""
    methods = multiprocessing.get_all_start_methods()
    if threading.active_count() == 1 and "fork" in methods:
        return multiprocessing.get_context("fork")
    if "forkserver" not in methods:
        return multiprocessing.get_context("spawn")
    context = multiprocessing.get_context("forkserver")
    context.set_forkserver_preload(["conrod.sweep.worker", "conrod.sweep.pool"])
    return context


def _exit_text(code: int | None) -> str:
    if code is not None and code < 0:
        with contextlib.suppress(ValueError):
            return f"killed by {signal.Signals(-code).name}"
    return f"exit code {code}"
