"""Variants on an existing Dask cluster (``--scheduler tcp://HOST:PORT``).

Start one with the ``dask`` command of the ``distributed`` package, on any machines that
have conrod installed and see the sweep folder and the case files (a shared file system):

.. code-block:: console

    $ dask scheduler --port 8786                      # on one machine
    $ dask worker tcp://HOST:8786 --nthreads 1        # on each machine, once per core
    $ conrod sweep study.toml --out DIR --scheduler tcp://HOST:8786

Variants go to the cluster in batches (:class:`conrod.sweep.pool.BatchSizer`: about half
a second of work per task), two batches per worker in flight; each worker keeps its
imports and its compiled kernels (loaded from numba's disk cache by its first task) for
every later task. A batch whose workers keep dying (Dask retries it elsewhere first) is
split: the variants that finished are read from the store, the others are tried once
more one by one, and a variant whose worker still dies becomes a failed row.
"""

from __future__ import annotations

import contextlib
import itertools
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from conrod.errors import CaseError
from conrod.io.interrupts import raise_if_interrupted
from conrod.sweep.pool import POLL_SECONDS, BatchSizer
from conrod.sweep.status import STATUS_FAILED
from conrod.sweep.store import read_record
from conrod.sweep.worker import RETURNED_ITEMS, run_batch

CONNECT_SECONDS = 20.0
"""How long to wait for the scheduler [s]."""
IN_FLIGHT_PER_WORKER = 2
"""Batches queued per worker, so that none waits for the next [-]."""


@contextlib.contextmanager
def connect(address: str) -> Iterator[Any]:
    """A Dask client of the scheduler at ``address``, closed quickly on exit.

    The client is made in a helper thread while this one looks for Ctrl-C: an address that
    accepts the connection but never answers would otherwise hold the sweep for good.
    """
    client = _client_within(address, CONNECT_SECONDS)
    try:
        yield client
    finally:
        client.close(timeout=2)


def _client_within(address: str, seconds: float) -> Any:
    from distributed import Client

    made: dict[str, Any] = {}

    def attempt() -> None:
        try:
            made["client"] = Client(address, timeout=f"{seconds}s")
        except Exception as error:  # handed to the waiting thread
            made["error"] = error

    helper = threading.Thread(target=attempt, name="conrod-sweep-connect", daemon=True)
    helper.start()
    deadline = time.monotonic() + seconds + 1.0
    while helper.is_alive() and time.monotonic() < deadline:
        helper.join(POLL_SECONDS)
        raise_if_interrupted()
    if "client" in made:
        return made["client"]
    reason = made.get("error") or f"no answer within {seconds:g} s"
    raise CaseError(f"--scheduler {address!r}: cannot connect ({reason}; allowed: the "
                    "address of a running Dask scheduler, e.g. tcp://HOST:8786)")


def run_on_cluster(client: Any, payloads: list[dict[str, Any]]
                   ) -> Iterator[tuple[int, dict[str, Any]]]:
    """Run every payload on the cluster; yield ``(index, record)`` as batches finish."""
    from distributed import wait

    queue = list(range(len(payloads)))[::-1]  # popped from the end: study order
    retry: list[int] = []  # variants of a failed batch, tried once more on their own
    sizer = BatchSizer(max(1, len(client.scheduler_info().get("workers", {}))))
    pending: dict[Any, list[int]] = {}
    tasks = itertools.count(1)
    try:
        while queue or retry or pending:
            while (queue or retry) and len(pending) < IN_FLIGHT_PER_WORKER * sizer.workers:
                size = 1 if retry else sizer.next_size(len(queue))
                batch = [retry.pop()] if retry else [queue.pop() for _ in range(size)]
                future = client.submit(run_batch, [payloads[i] for i in batch], pure=False,
                                       key=f"conrod-variants-{next(tasks)}-"
                                           f"{payloads[batch[0]]['key']}")
                pending[future] = batch
            try:
                done, _ = wait(list(pending), timeout=POLL_SECONDS,
                               return_when="FIRST_COMPLETED")
            except TimeoutError:
                done = set()
            raise_if_interrupted()
            for future in done:
                yield from _collect(future, pending.pop(future), payloads, retry, sizer)
    finally:
        if pending:
            client.cancel(list(pending), force=True)


def _collect(future: Any, batch: list[int], payloads: list[dict[str, Any]],
             retry: list[int], sizer: BatchSizer) -> Iterator[tuple[int, dict[str, Any]]]:
    """The records of a finished batch, or of a batch whose workers died (see the module
    docstring)."""
    try:
        records = future.result()
    except Exception as error:  # e.g. KilledWorker after repeated worker deaths
        yield from _after_failure(error, batch, payloads, retry)
        return
    for index, record in zip(batch, records, strict=True):
        sizer.record(float(record.get("wall_time_s") or 0.0))
        yield index, record


def _after_failure(error: Exception, batch: list[int], payloads: list[dict[str, Any]],
                   retry: list[int]) -> Iterator[tuple[int, dict[str, Any]]]:
    for index in batch:
        payload = payloads[index]
        stored = read_record(Path(payload["out"]), payload["key"])
        if stored is not None:
            yield index, {name: stored[name] for name in RETURNED_ITEMS if name in stored}
        elif len(batch) > 1:
            retry.append(index)
        else:
            yield index, {"hash": payload["key"], "axes": payload["axes"],
                          "status": STATUS_FAILED, "error": f"{type(error).__name__}: {error}",
                          "summary": {}, "wall_time_s": float("nan")}
