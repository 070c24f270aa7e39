"""Atomic writers: a failure leaves neither a partial target nor a temporary file."""

from __future__ import annotations

import json

import numpy as np
import pytest

from conrod.io import atomic_path, write_csv, write_json


def test_csv_round_trip(tmp_path):
    target = tmp_path / "out" / "table.csv"
    write_csv(target, {"a": np.array([1.0, 2.0]), "b": np.array([3, 4])})
    assert target.read_text().splitlines() == ["a,b", "1,3", "2,4"]


def test_csv_text_is_numpy_savetxt_s(tmp_path):
    """The rows are formatted in one go; the text is np.savetxt's, byte for byte (signed
    zeros, subnormals, huge, integral and integer values)."""
    import io

    rng = np.random.default_rng(7)
    columns = {f"c{i}": rng.normal(size=50) * 10.0 ** rng.integers(-14, 12, size=50)
               for i in range(5)}
    columns["c0"][:6] = [0.0, -0.0, 5e-324, 1e300, 720.0, -123456789012.0]
    columns["n"] = np.arange(50)
    target = write_csv(tmp_path / "x.csv", columns)
    expected = io.StringIO()
    np.savetxt(expected, np.column_stack([v.astype(float) for v in columns.values()]),
               delimiter=",", fmt="%.9g")
    assert target.read_text(encoding="utf-8") == ",".join(columns) + "\n" + expected.getvalue()


def test_failure_keeps_previous_file_and_leaves_no_temp(tmp_path):
    target = tmp_path / "summary.json"
    write_json(target, {"h_min_m": 1e-6})
    with pytest.raises(RuntimeError), atomic_path(target) as tmp:
        tmp.write_text("half")
        raise RuntimeError("crash mid-write")
    assert json.loads(target.read_text()) == {"h_min_m": 1e-6}
    assert [p.name for p in tmp_path.iterdir()] == ["summary.json"]


def test_json_refuses_nan(tmp_path):
    with pytest.raises(ValueError):
        write_json(tmp_path / "x.json", {"bad": float("nan")})
    assert not (tmp_path / "x.json").exists()


def test_csv_refuses_ragged_columns(tmp_path):
    with pytest.raises(ValueError, match="equal length"):
        write_csv(tmp_path / "x.csv", {"a": np.zeros(2), "b": np.zeros(3)})


def test_result_files_are_world_readable(tmp_path):
    target = write_json(tmp_path / "s.json", {"a": 1})
    assert target.stat().st_mode & 0o777 == 0o644
