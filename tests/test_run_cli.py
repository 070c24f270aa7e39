"""``conrod run`` command-line contract (issue 4)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
CYCLE_COLUMNS = [
    "crank_angle_deg", "eccentricity_ratio_1", "eccentricity_x_m", "eccentricity_y_m", "h_min_m",
    "p_max_Pa", "friction_power_W", "side_flow_m3_s", "load_x_N", "load_y_N",
    "contact_force_N", "friction_force_N",
]
SUMMARY_KEYS = [
    "h_min_m", "h_min_crank_angle_deg", "p_max_Pa", "p_max_crank_angle_deg", "mean_h_min_m",
    "mean_p_max_Pa", "mean_friction_power_W", "mean_side_flow_m3_s", "effective_temperature_C",
    "cycles", "periodicity_error", "film_model", "wall_time_s",
]


@pytest.fixture(scope="module")
def runner():
    _register_commands()
    return CliRunner()


@pytest.fixture(scope="module")
def flores_run(runner, tmp_path_factory):
    out = tmp_path_factory.mktemp("flores")
    result = runner.invoke(app, ["run", str(EXAMPLES / "flores2006_table_load.toml"),
                                 "--out", str(out), "--max-cycles", "3"])
    return result, out


def test_run_writes_cycle_csv_summary_and_figures(flores_run):
    result, out = flores_run
    assert result.exit_code == 0, result.output
    header = (out / "cycle.csv").read_text().splitlines()[0].split(",")
    assert all(column in header for column in CYCLE_COLUMNS)
    summary = json.loads((out / "summary.json").read_text())
    assert all(key in summary for key in SUMMARY_KEYS)
    assert summary["film_model"] == "short" and summary["cycles"] >= 2
    for figure in ("orbit.png", "hmin_pmax.png", "friction_flow.png", "pressure_map.png"):
        assert (out / figure).stat().st_size > 1000
    assert not list(out.glob(".*"))  # no temporary files left behind


def test_summary_agrees_with_cycle_table(flores_run):
    _, out = flores_run
    import numpy as np

    table = np.genfromtxt(out / "cycle.csv", delimiter=",", names=True)
    summary = json.loads((out / "summary.json").read_text())
    assert summary["h_min_m"] == pytest.approx(table["h_min_m"].min(), rel=1e-8)
    assert summary["mean_p_max_Pa"] == pytest.approx(table["p_max_Pa"].mean(), rel=1e-8)


def test_flags_override_the_case(runner, tmp_path):
    result = runner.invoke(app, [
        "run", str(EXAMPLES / "flores2006_table_load.toml"), "--out", str(tmp_path),
        "--integrator", "adaptive", "--max-cycles", "1", "--no-figures",
    ])
    assert result.exit_code == 3, result.output  # 1 cycle: not periodic, written, marked
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["integrator"] == "adaptive" and summary["cycles"] == 1
    assert not (tmp_path / "orbit.png").exists()


@pytest.mark.parametrize("args, message", [
    (["--film", "bogus"], "--film"),
    (["--integrator", "euler"], "--integrator"),
    (["--grid", "72by16"], "--grid"),
])
def test_bad_options_exit_2(runner, tmp_path, args, message):
    result = runner.invoke(app, ["run", str(EXAMPLES / "flores2006_table_load.toml"),
                                 "--out", str(tmp_path), *args])
    assert result.exit_code == 2
    assert message in result.output


def test_bad_case_exits_2_with_one_line(runner, tmp_path):
    case = tmp_path / "case.toml"
    case.write_text('[bearing]\ndiameter = 0.05\nwidth = 0.02\n[lubricant]\nviscosity = 0.01\n'
                    '[load]\ntable = "missing.csv"\nspeed = 3000\n', encoding="utf-8")
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "out")])
    assert result.exit_code == 2
    assert "radial_clearance" in result.output
    assert not (tmp_path / "out").exists()


def test_non_periodic_orbit_is_reported_not_hidden(runner, tmp_path):
    result = runner.invoke(app, ["run", str(EXAMPLES / "flores2006_table_load.toml"),
                                 "--out", str(tmp_path), "--max-cycles", "1", "--no-figures"])
    assert result.exit_code == 3  # not converged, results written for diagnosis
    assert "warning: orbit not periodic after 1 cycles" in result.output
    assert "not converged" in result.output
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert summary["periodic"] is False and summary["warnings"]


def test_registering_the_commands_again_adds_none(runner):
    """A second registration (every test that invokes the app registers first) leaves one
    command per name: typer builds each registered command whenever the app runs."""
    before = len(app.registered_commands)
    _register_commands()
    _register_commands()
    names = [info.name or info.callback.__name__ for info in app.registered_commands]
    assert len(app.registered_commands) == before
    assert len(names) == len(set(names)), sorted(names)
