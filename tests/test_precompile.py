"""``python -m conrod.simulation.precompile CASE``, what the build backend runs while
``pip install .`` builds the wheel (docs/install.md): the main job's computation, nothing
written. The main job itself compiles for a minute (measured in docs/install.md); here a
short-bearing case runs the same path."""

from __future__ import annotations

from pathlib import Path

import pytest

from conrod.errors import CaseError
from conrod.simulation import precompile

ROOT = Path(__file__).resolve().parents[1]


def test_the_computation_runs_and_writes_nothing(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    seconds = precompile.precompile(ROOT / "examples" / "passenger_car_diesel_2000rpm.toml",
                                    film="short", n_theta=None, n_z=None)
    assert seconds > 0.0
    assert list(tmp_path.iterdir()) == []


def test_the_command_line_wants_one_case_file(capsys):
    assert precompile.main([]) == 2
    assert capsys.readouterr().err.strip() == (
        "usage: python -m conrod.simulation.precompile CASE_FILE")
    with pytest.raises(CaseError):
        precompile.main([str(ROOT / "examples" / "no_such_case.toml")])


def test_the_main_job_is_the_readmes():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    job = precompile.MAIN_JOB
    assert (f"conrod run examples/kamaz_740_truck_diesel.toml --film {job['film']} "
            f"--grid {job['n_theta']}x{job['n_z']}") in readme
