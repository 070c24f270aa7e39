"""Shared test fixtures."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")

REPO = Path(__file__).resolve().parents[1]
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
