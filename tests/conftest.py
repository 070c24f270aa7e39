"""Shared test fixtures."""

from __future__ import annotations

from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")

REPO = Path(__file__).resolve().parents[1]
SHARED_DATA = REPO.parent / "shared" / "data"
EXAMPLES = REPO / "examples"


@pytest.fixture
def repo() -> Path:
    """Root of the repository."""
    return REPO


@pytest.fixture
def shared_data() -> Path:
    """``../shared/data`` with the published reference tables."""
    return SHARED_DATA
