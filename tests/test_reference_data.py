"""The copies in tests/data stay identical to the project's reference folder ../shared/data."""

from __future__ import annotations

from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent / "data"
SHARED = Path(__file__).resolve().parents[2] / "shared" / "data"


@pytest.mark.parametrize("name", sorted(p.name for p in HERE.glob("*.csv")))
def test_copy_is_verbatim(name):
    if not (SHARED / name).exists():
        pytest.skip("../shared/data is not beside this checkout")
    assert (HERE / name).read_bytes() == (SHARED / name).read_bytes()


def test_copies_keep_their_provenance_header():
    for path in HERE.glob("*.csv"):
        assert path.read_text().startswith("#"), f"{path.name} lost its provenance header"
