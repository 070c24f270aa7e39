"""How many of this machine's usable cores other processes use now: whether a second
process of conrod's can pay (the rigid companion and coarse orbits beside an elastic orbit,
:mod:`conrod.simulation.side_runs`; the figures of a result set,
:mod:`conrod.output.registry`); and what a computing process asks of its machine: BLAS on
one thread (:func:`one_blas_thread`), a command's long-lived objects left out of the
garbage collector's passes (:func:`long_lived_objects_frozen`)."""

from __future__ import annotations

import contextlib
import gc
import multiprocessing
import os
import time
from collections.abc import Callable, Iterator

LOAD_WINDOW = 0.1
"""How long the usable cores' use is sampled before the process starts [s]."""
PROC_STAT = "/proc/stat"
"""Linux's CPU time counters per core."""


def load() -> float:
    """Cores in use by other processes now [-]: the usable cores' busy share over
    :data:`LOAD_WINDOW`, from Linux's per-core counters, less what this process used
    meanwhile (its main thread sleeps, but a BLAS thread pool may spin on a core for a
    while after its last call: a whole core in a program that imported NumPy before
    conrod set BLAS to one thread);
    the 1-minute load average where there are none, 0 where neither exists. The load
    average lags a minute: right after ``pip install .`` or another run it reads 1 on an
    idle 2-core machine and kept the second process off."""
    try:
        own, started = time.process_time(), time.monotonic()
        with open(PROC_STAT, encoding="ascii") as stat:
            before = stat.read()
        time.sleep(LOAD_WINDOW)
        with open(PROC_STAT, encoding="ascii") as stat:
            after = stat.read()
        own = (time.process_time() - own) / max(time.monotonic() - started, 1e-9)
        busy = busy_cores(before, after, usable_cores())
    except (OSError, ValueError):
        busy = None
    if busy is not None:  # less this process's own threads
        return max(busy - own, 0.0)
    try:
        return os.getloadavg()[0]
    except (AttributeError, OSError):
        return 0.0


def busy_cores(before: str, after: str, cores: list[int] | None) -> float | None:
    """Σ over ``cores`` (None: all) of the busy share of each core between two readings of
    /proc/stat (``cpuN user nice system idle iowait ...`` in clock ticks; idle and iowait
    count as idle) [-]; None where a core is missing or no time passed."""
    def ticks(text: str) -> dict[int, tuple[int, int]]:
        out = {}
        for line in text.splitlines():
            name, *fields = line.split()
            if name.startswith("cpu") and name[3:].isdigit():
                values = [int(v) for v in fields]
                out[int(name[3:])] = (sum(values), values[3] + (values[4] if len(values) > 4
                                                                 else 0))
        return out
    first, second = ticks(before), ticks(after)
    chosen = sorted(first) if cores is None else cores
    busy = 0.0
    for core in chosen:
        if core not in first or core not in second:
            return None
        total = second[core][0] - first[core][0]
        if total <= 0:
            return None
        busy += 1.0 - (second[core][1] - first[core][1]) / total
    return busy


def one_blas_thread():
    """Limit the BLAS libraries this process has loaded (NumPy's and SciPy's OpenBLAS) to one
    thread; the limit holds from now on, or, used as a context manager, until its end.

    An environment variable cannot do it where NumPy is loaded already: a sweep's worker,
    forked from the sweep's process, or a program that imported NumPy before conrod. At
    conrod's sizes (the elastic bore's n_θ × n_θ matrices) a BLAS pool gains nothing, and its
    threads spin after each call on the cores that other work needs: on a busy machine one
    108 × 108 inverse took 170 ms instead of 1 ms, and a worker of a 16-core machine used
    31 % more CPU than its variant."""
    from threadpoolctl import threadpool_limits

    return threadpool_limits(limits=1, user_api="blas")


@contextlib.contextmanager
def long_lived_objects_frozen() -> Iterator[Callable[[], None]]:
    """Within the block the objects alive at its start (the imported modules, their functions
    and classes, numba's types) are left out of the cyclic garbage collector's passes
    (:func:`gc.freeze`); the block is given a function that adds those alive when it is
    called (a run's results, before they are written). When the outermost block ends they
    are collected as before (:func:`gc.unfreeze`), unless some were frozen when it began (by
    the program around it: all stay frozen then). Objects made in the block are collected
    as usual throughout; a process forked in it inherits the setting. A full pass walks
    every object the collector tracks, and a command's objects stay alive to its end: in the
    README's main job the run process's five full passes took 0.45 s of its 6 s
    (benchmarks/compile_benchmarks.md)."""
    frozen_before = gc.get_freeze_count() > 0  # also inside another such block
    gc.freeze()
    try:
        yield gc.freeze
    finally:
        if not frozen_before:
            gc.unfreeze()


def usable_cores() -> list[int]:
    """The cores this process may run on (its affinity; all where that is unknown)."""
    if hasattr(os, "sched_getaffinity"):
        return sorted(os.sched_getaffinity(0))
    return list(range(os.cpu_count() or 1))


def spare_core(busy: Callable[[], float] = load) -> bool:
    """True where a forked second process gets a core of its own now: ``fork`` exists,
    this is not itself a worker process (a sweep's workers have their cores), more than
    one core is usable and fewer than all but one are ``busy`` (:func:`load`)."""
    if multiprocessing.parent_process() is not None:
        return False
    if "fork" not in multiprocessing.get_all_start_methods():
        return False
    usable = usable_cores()
    return len(usable) > 1 and busy() < len(usable) - 1
