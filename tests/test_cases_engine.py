"""Bad input to ``conrod loads``: one clear message, exit code 2, nothing written."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from loads_helpers import case_text, loads_cli, write_trace

GOOD = (
    "bore = 0.1\nstroke = 0.1\nrod_length = 0.18\nspeed = 3000\npiston_mass = 1.2\n"
    "rod_mass = 1.5\nrod_cg_from_big_end = 0.05\n"
)


def run_loads(tmp_path, text: str, *extra: str):
    case = tmp_path / "case.toml"
    case.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    result = CliRunner().invoke(loads_cli(), ["loads", str(case), "--out", str(out), *extra])
    return result, out


def assert_refused(result, out, *fragments: str) -> None:
    assert result.exit_code == 2, result.output
    message = result.stderr.strip()
    assert message.startswith("error: "), result.stderr  # one message (one line per problem)
    for fragment in fragments:
        assert fragment in message
    assert not out.exists() or not any(out.iterdir())
    assert "Traceback" not in result.output


def test_good_case_writes_all_outputs(tmp_path):
    result, out = run_loads(tmp_path, case_text(GOOD), "--step", "2")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in out.iterdir()) == [
        "load_vs_crank_angle.png",
        "loads.csv",
        "loads_summary.json",
        "manifest.json",
        "polar_load_diagram.png",
        "wear_diagram.png",
    ]
    table = np.genfromtxt(out / "loads.csv", delimiter=",", names=True)
    assert table.size == 360 and table["crank_angle_deg"][1] == 2.0


def test_negative_bore(tmp_path):
    result, out = run_loads(tmp_path, case_text(GOOD.replace("bore = 0.1", "bore = -0.1")))
    assert_refused(result, out, "engine.bore = -0.1", "allowed: > 0 and <= 2 m")


def test_rod_shorter_than_crank_radius(tmp_path):
    result, out = run_loads(
        tmp_path, case_text(GOOD.replace("rod_length = 0.18", "rod_length = 0.04"))
    )
    assert_refused(result, out, "rod_length = 0.04", "crank radius", "allowed: rod_length > 0.05 m")


def test_unknown_key_suggests_the_right_one(tmp_path):
    result, out = run_loads(tmp_path, case_text(GOOD.replace("stroke", "strok")))
    assert_refused(result, out, "unknown key 'strok'", "did you mean 'stroke'?")


def test_missing_bearing_section(tmp_path):
    result, out = run_loads(tmp_path, case_text(GOOD, bearing=False))
    assert_refused(result, out, "[bearing]", "'loads'")


@pytest.mark.parametrize(
    ("angles", "pressures", "fragments"),
    [
        (np.arange(0.0, 361.0), np.full(361, 1e5), ("trace.csv", "covers only 0..360 deg")),
        (
            np.arange(0.0, 720.0),
            np.where(np.arange(720) == 100, np.nan, 1e5),
            ("trace.csv", "line 103", "pressure_Pa = nan is not finite"),
        ),
    ],
    ids=["missing-angles", "nan"],
)
def test_bad_trace(tmp_path, angles, pressures, fragments):
    write_trace(tmp_path / "trace.csv", angles, pressures)
    text = (
        "[engine]\n"
        + GOOD
        + 'pressure_trace = "trace.csv"\n[bearing]\ndiameter = 0.06\nwidth = 0.025\n'
    )
    result, out = run_loads(tmp_path, text)
    assert_refused(result, out, *fragments)


def test_bad_step(tmp_path):
    result, out = run_loads(tmp_path, case_text(GOOD), "--step", "0.7")
    assert_refused(result, out, "--step = 0.7", "divide 720")
