"""``conrod housing`` and ``conrod stress`` command-line contracts."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.housing.compliance_io import read_compliance

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
KAMAZ = EXAMPLES / "kamaz_740_truck_diesel.toml"


@pytest.fixture(scope="module")
def runner():
    _register_commands()
    return CliRunner()


def test_housing_writes_reimportable_compliance_summary_and_figures(runner, tmp_path):
    result = runner.invoke(app, ["housing", str(KAMAZ), "--out", str(tmp_path), "--no-cache"])
    assert result.exit_code == 0, result.output
    names = {p.name for p in tmp_path.iterdir()}
    assert {"compliance.npz", "inertia.npz", "housing_summary.json", "housing_mesh.png",
            "bore_deformation.png", "inertia_deformation.png"} <= names
    angles, compliance = read_compliance(tmp_path / "compliance.npz")   # valid import format
    assert len(angles) == compliance.shape[0] == 72
    summary = json.loads((tmp_path / "housing_summary.json").read_text())
    assert summary["build"]["bore_nodes"] == 72
    assert summary["compliance_diagonal_um_per_kN"]["raw_max"] > 0
    assert 0.0 <= summary["bearing_load_distributed_vs_two_mass"]["max_relative_difference"] < 1


def test_housing_of_a_rigid_case_is_bad_input_and_writes_nothing(runner, tmp_path):
    case = tmp_path / "rigid.toml"
    case.write_text(KAMAZ.read_text().split("[housing]")[0])
    out = tmp_path / "out"
    result = runner.invoke(app, ["housing", str(case), "--out", str(out)])
    assert result.exit_code == 2
    assert "housing.model = 'rigid'" in result.output
    assert not out.exists()


def test_stress_rejects_bad_angles(runner, tmp_path):
    result = runner.invoke(app, ["stress", str(KAMAZ), "--out", str(tmp_path / "o"),
                                 "--angles", "25,900"])
    assert result.exit_code == 2
    assert "allowed: >= 0 and <= 720 deg" in result.output
    assert not (tmp_path / "o").exists()


def test_stress_writes_maxima_for_both_schemes(runner, tmp_path):
    result = runner.invoke(app, ["stress", str(KAMAZ), "--out", str(tmp_path), "--angles",
                                 "360"])
    assert result.exit_code == 0, result.output
    table = np.genfromtxt(tmp_path / "stress_maxima.csv", delimiter=",", names=True,
                          dtype=None, encoding="utf-8")
    assert list(table["scheme"]) == ["pressure", "cosine"]
    assert np.all(table["max_von_mises_Pa"] > 1e6)
    summary = json.loads((tmp_path / "stress_summary.json").read_text())
    assert set(summary["360"]["zones"]["pressure"]) == {"cap", "head", "shank", "small_end"}
    assert (tmp_path / "von_mises_pressure_360deg.png").exists()


def test_default_stress_angles_are_the_peak_load_and_360():
    from conrod.cases.case import Case
    from conrod.cli.stress_command import parse_angles
    from conrod.loads.engine_loads import compute_engine_loads

    case = Case.from_toml(KAMAZ)
    assert parse_angles(None, case) == [25.0, 360.0]          # [housing] stress_angles
    plain = case.model_copy(update={"housing": case.housing.model_copy(
        update={"stress_angles": []})})
    loads = compute_engine_loads(plain)
    peak = float(loads.crank_angle_deg[np.argmax(loads.load_magnitude)])
    assert parse_angles(None, plain) == [peak, 360.0]
    assert parse_angles("10, 370", plain) == [10.0, 370.0]
