"""Every shipped example with [engine] and [bearing] sections runs through ``conrod loads``."""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod.cases.case import Case
from conrod.loads.engine_loads import compute_engine_loads
from loads_helpers import loads_cli

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
ENGINE_EXAMPLES = sorted(
    p
    for p in EXAMPLES.glob("*.toml")
    if {"engine", "bearing"} <= set(tomllib.loads(p.read_text(encoding="utf-8")))
)
REQUIRED_COLUMNS = {
    "crank_angle_deg",
    "gas_force_N",
    "rod_force_N",
    "radial_force_N",
    "tangential_force_N",
    "load_magnitude_N",
    "load_rod_x_N",
    "load_rod_y_N",
    "journal_speed_rad_s",
    "shell_speed_rad_s",
}
REQUIRED_KEYS = {
    "peak_load_N",
    "peak_load_crank_angle_deg",
    "mean_load_N",
    "mean_specific_load_Pa",
    "peak_specific_load_Pa",
    "oil_hole_angle_deg",
}


def test_the_issue_examples_are_shipped():
    names = {p.stem for p in ENGINE_EXAMPLES}
    assert {
        "passenger_car_diesel_2000rpm",
        "passenger_car_diesel_1000rpm",
        "kamaz_740_truck_diesel",
    } <= names


@pytest.mark.parametrize("example", ENGINE_EXAMPLES, ids=lambda p: p.stem)
def test_example_runs_and_writes_the_contract(tmp_path, example):
    out = tmp_path / "out"
    result = CliRunner().invoke(loads_cli(), ["loads", str(example), "--out", str(out)])
    assert result.exit_code == 0, result.output
    header = (out / "loads.csv").read_text(encoding="utf-8").splitlines()[0].split(",")
    assert set(header) >= REQUIRED_COLUMNS
    table = np.genfromtxt(out / "loads.csv", delimiter=",", names=True)
    assert table.size == 720 and np.all(np.isfinite(table.view((float, len(header)))))
    summary = json.loads((out / "loads_summary.json").read_text(encoding="utf-8"))
    assert set(summary) >= REQUIRED_KEYS
    assert summary["peak_load_N"] == pytest.approx(table["load_magnitude_N"].max())
    assert 0.0 <= summary["oil_hole_angle_deg"] < 360.0
    for name in ("polar_load_diagram.png", "load_vs_crank_angle.png", "wear_diagram.png"):
        assert (out / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


@pytest.mark.parametrize("example", ENGINE_EXAMPLES, ids=lambda p: p.stem)
def test_example_loads_are_physically_sensible(example):
    """Peak load near firing TDC; specific load = load / (d l'); journal speed ω(1 ± λ)."""
    case = Case.from_toml(example)
    loads = compute_engine_loads(case)
    summary = loads.summary()
    assert summary["peak_load_crank_angle_deg"] < 40.0 or summary["peak_load_crank_angle_deg"] > 680
    area = case.bearing.diameter * case.bearing.width
    assert summary["mean_specific_load_Pa"] == pytest.approx(summary["mean_load_N"] / area)
    lam = case.engine.crank_radius / case.engine.rod_length
    omega = case.engine.speed * math.pi / 30
    assert loads.journal_speed.max() == pytest.approx(omega * (1 + lam), rel=1e-9)
    assert loads.journal_speed.min() == pytest.approx(omega * (1 - lam), rel=1e-9)


def test_installed_conrod_command_runs_loads(tmp_path):
    """The real console entry point (all commands registered) runs ``conrod loads``."""
    import subprocess
    import sys

    example = EXAMPLES / "passenger_car_diesel_2000rpm.toml"
    command = [
        sys.executable,
        "-c",
        "from conrod.cli.app import main; main()",
        "loads",
        str(example),
        "--out",
        str(tmp_path / "out"),
        "--step",
        "2",
    ]
    completed = subprocess.run(command, capture_output=True, text=True, timeout=300, check=False)
    assert completed.returncode == 0, completed.stderr
    assert "peak load" in completed.stdout
    assert (tmp_path / "out" / "loads_summary.json").exists()
