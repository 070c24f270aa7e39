"""Ctrl-C without half-written results or crashes inside compiled loops.

A ``KeyboardInterrupt`` raised at an arbitrary moment can land inside a callback that
compiled (numba) or C code called, where it turns into a ``SystemError`` or worse. Under
:func:`deferred_interrupts` the first Ctrl-C only records the request; the run stops with
``KeyboardInterrupt`` at the next safe point (:func:`raise_if_interrupted`: between
integration steps or cycles, and before a result folder is swapped in). A second Ctrl-C
ends the process at once with exit code 130; result folders are then still either the old
or the new result (:mod:`conrod.io.result_folder`).

While a command starts (:func:`interrupts_stop_at_once`: loading the command line and the
numerical modules, reading and checking the input) nothing is computed or written yet, and a
module being imported can turn a ``KeyboardInterrupt`` into an ``ImportError``; there Ctrl-C
ends the process at once, with one line and exit code 130.
"""

from __future__ import annotations

import contextlib
import os
import signal
import sys
import threading
from collections.abc import Iterator
from typing import Any

EXIT_INTERRUPTED = 130
"""Exit code of a process ended by Ctrl-C (128 + SIGINT)."""
INTERRUPTED_MESSAGE = "interrupted (nothing written)"
"""The line a command prints when Ctrl-C stopped it before anything was written."""
_pending = threading.Event()


def raise_if_interrupted() -> None:
    """Raise ``KeyboardInterrupt`` if Ctrl-C was pressed under :func:`deferred_interrupts`."""
    if _pending.is_set():
        _pending.clear()
        raise KeyboardInterrupt


def _on_sigint(signum: int, frame: Any) -> None:
    if _pending.is_set():
        os.write(sys.stderr.fileno(), b"interrupted\n")
        os._exit(EXIT_INTERRUPTED)
    _pending.set()
    os.write(sys.stderr.fileno(),
             b"stopping at the next safe point (Ctrl-C again to stop at once)\n")


def _stop_at_once(signum: int, frame: Any) -> None:
    with contextlib.suppress(OSError):
        os.write(2, f"{INTERRUPTED_MESSAGE}\n".encode())
    os._exit(EXIT_INTERRUPTED)


@contextlib.contextmanager
def interrupts_stop_at_once() -> Iterator[None]:
    """Within the block (a command starting: imports, reading and checking the input;
    nothing written yet), Ctrl-C ends the process at once: one line, exit code 130.
    Main thread only; the previous handler is restored after the block."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    previous = signal.signal(signal.SIGINT, _stop_at_once)
    if _pending.is_set():  # pressed a moment ago, while Ctrl-C was deferred
        _stop_at_once(signal.SIGINT, None)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)


@contextlib.contextmanager
def deferred_interrupts() -> Iterator[None]:
    """Within the block, Ctrl-C stops the work at the next safe point (main thread only)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _pending.clear()
    previous = signal.signal(signal.SIGINT, _on_sigint)
    try:
        yield
        raise_if_interrupted()
    finally:
        signal.signal(signal.SIGINT, previous)
        _pending.clear()
