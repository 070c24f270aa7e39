"""Shared test fixtures."""

from __future__ import annotations

import gc
import os
from pathlib import Path

# Dense linear algebra on one thread, as `conrod run` does, before anything imports NumPy:
# with one test worker per core (pytest-xdist), OpenBLAS' thread pools of the two workers
# spin against each other (an in-process elastic run of the solid KamAZ big end took 723 s
# under -n 2 with them, 46 s in one process).
for _variable in ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_variable, "1")
# No second process beside an elastic run in the suite (conrod.simulation.side_runs): its
# workers already take the cores, and a run's behaviour must not depend on the load average
# (tests/test_side_runs.py turns it on where it tests it).
os.environ.setdefault("CONROD_SIDE_RUNS", "0")
os.environ.setdefault("CONROD_FIGURE_PROCESS", "0")  # nor one drawing figures (its test)

import matplotlib  # noqa: E402
import pytest  # noqa: E402

matplotlib.use("Agg")

REPO = Path(__file__).resolve().parents[1]


def pytest_collection_finish(session: pytest.Session) -> None:
    """The test modules, conrod and its libraries, imported now and alive to the end, are
    left out of the garbage collector's passes (as ``conrod run`` does with its own:
    conrod.io.cores): in a whole suite the two workers' full passes took 19.5 s of CPU."""
    gc.freeze()


SHARED_DATA = REPO / "tests" / "data"
EXAMPLES = REPO / "examples"


@pytest.fixture
def repo() -> Path:
    """Root of the repository."""
    return REPO


@pytest.fixture
def shared_data() -> Path:
    """``tests/data``: verbatim copies of ../shared/data with their provenance headers."""
    return SHARED_DATA
