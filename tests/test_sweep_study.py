"""Study files: axes, modes, validation of every variant before running, variant hashes."""

from __future__ import annotations

import os
import textwrap
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError
from conrod.sweep import Study
from conrod.sweep import variant as variant_module

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
BASE = EXAMPLES / "passenger_car_diesel_2000rpm.toml"


def study_file(folder: Path, body: str, base: Path = BASE) -> Path:
    path = folder / "study.toml"
    path.write_text(f'base = "{base.as_posix()}"\n' + textwrap.dedent(body), encoding="utf-8")
    return path


def test_product_and_linspace_give_every_combination(tmp_path):
    path = study_file(tmp_path, """
        [[axis]]
        key = "bearing.radial_clearance"
        values = [20e-6, 30e-6]
        [[axis]]
        key = "engine.speed"
        start = 1000
        stop = 3000
        num = 3
    """)
    variants = Study.from_toml(path).variants()
    assert len(variants) == 6
    speeds = [v.axes["engine.speed"] for v in variants]
    assert speeds == [1000.0, 2000.0, 3000.0] * 2  # last axis fastest, np.linspace values
    case = variants[4].case()
    assert case.bearing.radial_clearance == 30e-6 and case.engine.speed == 2000.0
    assert len({v.key for v in variants}) == 6


def test_zip_pairs_the_axes_and_needs_equal_lengths(tmp_path):
    body = """
        mode = "zip"
        [[axis]]
        key = "bearing.radial_clearance"
        values = [20e-6, 30e-6]
        [[axis]]
        key = "solver.n_theta"
        values = [36, 72]
    """
    variants = Study.from_toml(study_file(tmp_path, body)).variants()
    assert [(v.axes["bearing.radial_clearance"], v.axes["solver.n_theta"])
            for v in variants] == [(20e-6, 36), (30e-6, 72)]
    assert variants[1].case().solver.n_theta == 72
    with pytest.raises(CaseError, match="equal length"):
        Study.from_toml(study_file(tmp_path, body.replace("[36, 72]", "[36, 72, 144]")))


def test_case_files_as_an_axis(tmp_path):
    path = tmp_path / "study.toml"
    slow = (EXAMPLES / "passenger_car_diesel_1000rpm.toml").as_posix()
    path.write_text(textwrap.dedent(f"""
        [[axis]]
        key = "case"
        files = ["{BASE.as_posix()}", "{slow}"]
        [[axis]]
        key = "lubricant.viscosity"
        values = [0.005, 0.01]
    """), encoding="utf-8")
    variants = Study.from_toml(path).variants()
    speeds = sorted({v.case().engine.speed for v in variants})
    assert speeds == [1000.0, 2000.0]
    assert variants[3].case().lubricant.viscosity == 0.01


@pytest.mark.parametrize(("key", "value", "words"), [
    ("bearing.radial_clerance", "25e-6", ["radial_clerance", "did you mean 'radial_clearance'"]),
    ("bearing.radial_clearance", "-1e-6", ["bearing.radial_clearance", "-1e-06"]),
    ("solver.film", '"shorter"', ["solver.film", "shorter"]),
    ("engine.speed.value", "1", ["engine.speed", "not a table"]),
])
def test_bad_axis_names_axis_key_and_value(tmp_path, key, value, words):
    path = study_file(tmp_path, f"""
        [[axis]]
        key = "{key}"
        values = [{value}]
    """)
    with pytest.raises(CaseError) as error:
        Study.from_toml(path).variants()
    message = str(error.value)
    assert message.startswith(f"axis {key!r}")
    for word in words:
        assert word in message


def test_a_bad_late_value_stops_before_anything_runs(tmp_path):
    """The CLI validates all variants first: exit 2, one line, nothing written."""
    path = study_file(tmp_path, """
        [[axis]]
        key = "bearing.radial_clearance"
        values = [20e-6, 25e-6, 0.0]
    """)
    out = tmp_path / "out"
    _register_commands()
    result = CliRunner().invoke(app, ["sweep", str(path), "--out", str(out)])
    assert result.exit_code == 2
    assert "axis 'bearing.radial_clearance' = 0.0 (variant 3)" in result.output
    assert "Traceback" not in result.output
    assert not out.exists()


def test_study_schema_errors(tmp_path):
    with pytest.raises(CaseError, match="exactly one of"):
        Study.from_dict({"base": str(BASE), "axis": [{"key": "engine.speed", "values": [1],
                                                      "start": 1, "stop": 2, "num": 2}]})
    with pytest.raises(CaseError, match="more than once"):
        Study.from_dict({"base": str(BASE), "axis": [{"key": "engine.speed", "values": [1]}] * 2})
    with pytest.raises(CaseError, match="unknown key 'axes'"):
        Study.from_dict({"base": str(BASE), "axes": []})
    with pytest.raises(CaseError, match="cannot be read"):
        Study.from_dict({"base": "missing.toml", "axis": [{"key": "engine.speed",
                                                            "values": [1000]}]}).variants()


def test_hash_follows_content_and_version_not_formatting(tmp_path, monkeypatch):
    copy = tmp_path / "copy.toml"
    text = BASE.read_text(encoding="utf-8")
    copy.write_text("# a comment more\n" + text.replace("speed = 2000", "speed = 2000.0"),
                    encoding="utf-8")
    axis = '[[axis]]\nkey = "lubricant.viscosity"\nvalues = [0.0065, 0.007]\n'
    original = Study.from_toml(study_file(tmp_path, axis)).variants()
    reformatted = Study.from_toml(study_file(tmp_path, axis, base=copy)).variants()
    assert [v.key for v in original] == [v.key for v in reformatted]
    assert original[0].key != original[1].key
    case = original[0].case()
    assert variant_module.variant_hash(case, "mechanism") != variant_module.variant_hash(case)
    monkeypatch.setattr(variant_module, "__version__", "99.0")
    assert Study.from_toml(study_file(tmp_path, axis)).variants()[0].key != original[0].key


def test_shipped_study_is_valid():
    variants = Study.from_toml(EXAMPLES / "studies" / "passenger_car_3x3.toml").variants()
    assert len(variants) == 9
    clearances = sorted({v.axes["bearing.radial_clearance"] for v in variants})
    assert np.allclose(clearances, [20e-6, 25e-6, 30e-6])
    assert all(v.case().solver.integrator == "quasi_static" for v in variants)


def test_editing_the_case_file_changes_the_hash_in_the_same_session(tmp_path):
    case = tmp_path / "case.toml"
    text = BASE.read_text(encoding="utf-8")
    case.write_text(text, encoding="utf-8")
    axis = '[[axis]]\nkey = "lubricant.viscosity"\nvalues = [0.0065]\n'
    before = Study.from_toml(study_file(tmp_path, axis, base=case)).variants()[0].key
    case.write_text(text.replace("rod_mass = 0.65", "rod_mass = 0.70"), encoding="utf-8")
    os.utime(case, ns=(0, 10**18))  # a new modification time even on coarse clocks
    after = Study.from_toml(study_file(tmp_path, axis, base=case)).variants()[0].key
    assert before != after
