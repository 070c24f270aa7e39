"""The BLAS thread pool as the tests see it (threadpoolctl): how many threads it has, and
a pool of two to start from, so that a limit to one thread can be seen."""

from __future__ import annotations

import contextlib
from collections.abc import Iterator

import pytest


def blas_threads(*_: object) -> int:
    """Threads of the BLAS libraries this process has loaded (the largest pool) [-]; any
    arguments are ignored (a worker pool's item)."""
    from threadpoolctl import threadpool_info

    return max(pool["num_threads"] for pool in threadpool_info() if pool["user_api"] == "blas")


@contextlib.contextmanager
def two_blas_threads() -> Iterator[None]:
    """NumPy's BLAS loaded and set to two threads for the block (skips the test where it
    runs on one thread anyway)."""
    import numpy  # noqa: F401  (its BLAS loaded before any fork)
    from threadpoolctl import threadpool_limits

    with threadpool_limits(limits=2, user_api="blas"):
        if blas_threads() != 2:
            pytest.skip("this machine's BLAS runs on one thread anyway")
        yield
