"""The rigid companion's compiled kernels, compiled on a second core while the elastic
orbit runs.

The first elastic run compiles two sets of numba kernels one after the other: the elastic
film's (the journal and bore step) and, once the elastic orbit is done, the rigid
companion's (the compiled free flight of the rigid film and its massless start), each
kept in numba's disk cache for later runs. Where a second core is usable, a forked process
runs the rigid companion for one cycle on a coarse grid while the elastic orbit runs:
numba compiles per argument type, not per grid size, so the process compiles the
companion's kernels and leaves them in the disk cache, from which the companion loads them
after the elastic orbit. The forked process writes nothing else (its output goes to the
null device), its outcome is ignored, and it ends with the run; the answer is the same
compiled code's, bit for bit.

Once per process (the first elastic run; later ones find the kernels loaded or cached), not
in a worker process (a sweep's workers have their cores), not where ``fork`` is missing or
only one core is usable, and only while the load average leaves a core idle (on a busy
machine the second process would only take the CPU time it saves, and it repeats the
multigrid solver's compilation, which both processes need first);
``CONROD_BACKGROUND_COMPILE=0`` turns it off. The forked process touches nothing of its
parent's but the simulation it was given (its output goes to the null device, it writes no
result folder), so a progress bar's thread in the parent is no hazard; a process that has
not ended after :data:`WAIT_LIMIT` is ended.

.. code-block:: python

    warm = start(simulation)      # before the elastic orbit
    ...
    finish(warm)                  # before the rigid companion runs (waits for it)
"""

from __future__ import annotations

import contextlib
import ctypes
import multiprocessing
import os
import signal
import sys
import warnings
from typing import Any

COARSE_GRID = (24, 8)
"""Largest grid (n_θ, n_z) of the compiling run [-]: the same kernels as any grid."""
WAIT_LIMIT = 300.0
"""Longest wait for the compiling process before the companion runs [s]: past it (a
process stuck or starved) it is ended and the companion compiles what it still lacks."""
SWITCH = "CONROD_BACKGROUND_COMPILE"
"""Environment variable: ``0`` turns background compilation off."""
_state = {"started": False}


def wanted() -> bool:
    """True when a background compilation can pay here (see the module docstring)."""
    if _state["started"] or os.environ.get(SWITCH, "1") == "0":
        return False
    if multiprocessing.parent_process() is not None:  # a worker: its cores are taken
        return False
    if "fork" not in multiprocessing.get_all_start_methods():
        return False
    usable = os.sched_getaffinity(0) if hasattr(os, "sched_getaffinity") else range(
        os.cpu_count() or 1)
    return len(usable) > 1 and _load() < len(usable) - 1  # a core that nothing else uses


def _load() -> float:
    """1-minute load average [-] (0 where the system has none)."""
    try:
        return os.getloadavg()[0]
    except (AttributeError, OSError):
        return 0.0


def start(simulation) -> Any:
    """A forked process compiling the rigid companion of ``simulation`` (None when none
    is asked for or it cannot pay)."""
    if not wanted() or simulation.rigid_companion() is None:
        return None
    _state["started"] = True
    n_theta, n_z = (min(value, limit) for value, limit in zip(
        (simulation.solver.n_theta, simulation.solver.n_z), COARSE_GRID, strict=True))
    process = multiprocessing.get_context("fork").Process(
        target=_compile, args=(simulation, n_theta, n_z), daemon=True)
    process.start()
    return process


def finish(process: Any) -> None:
    """Wait for the compiling process (the kernels it compiles are then on disk)."""
    if process is None:
        return
    try:
        process.join(WAIT_LIMIT)
    finally:
        stop(process)


def stop(process: Any) -> None:
    """End the compiling process now (the run failed or was interrupted)."""
    if process is not None and process.is_alive():
        process.kill()
        process.join()


def _compile(simulation, n_theta: int, n_z: int) -> None:
    """The forked process: one cycle of the rigid companion on the coarse grid, silent."""
    _die_with_parent()
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, sys.stdout.fileno())
    os.dup2(null, sys.stderr.fileno())
    warnings.simplefilter("ignore")
    with contextlib.suppress(BaseException):
        companion = simulation.rigid_companion(n_theta=n_theta, n_z=n_z, min_cycles=1,
                                               max_cycles=1)
        companion.run_orbit()


def _die_with_parent() -> None:
    """Linux: the process gets SIGKILL when the run's process ends (prctl PDEATHSIG)."""
    with contextlib.suppress(Exception):
        ctypes.CDLL(None, use_errno=True).prctl(1, int(signal.SIGKILL), 0, 0, 0)
