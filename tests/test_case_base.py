"""Case-file base: errors name field, value, allowed range and unit; unknown keys suggest."""

from __future__ import annotations

import pytest

from conrod.cases import Case
from conrod.errors import CaseError

ENGINE = {
    "bore": 0.12, "stroke": 0.12, "rod_length": 0.225, "speed": 2000.0, "piston_mass": 2.1,
    "rod_mass": 3.0, "rod_cg_from_big_end": 0.07,
    "pressure_model": {
        "compression_ratio": 17.0, "intake_pressure": 0.09e6, "max_pressure": 9e6,
        "exhaust_pressure": 0.11e6, "max_pressure_duration": 15.0,
        "compression_index": 1.35, "expansion_index": 1.25,
    },
}


def test_out_of_range_names_field_value_range_and_unit():
    with pytest.raises(CaseError) as info:
        Case.from_dict({"engine": {**ENGINE, "bore": -0.12}})
    message = str(info.value)
    assert "engine.bore = -0.12" in message
    assert "> 0" in message and "m)" in message


def test_unknown_key_suggests_the_closest_valid_one():
    with pytest.raises(CaseError) as info:
        Case.from_dict({"bearing": {"diameter": 0.05, "width": 0.02, "radial_clearence": 2e-5}})
    assert "unknown key 'radial_clearence'" in str(info.value)
    assert "did you mean 'radial_clearance'" in str(info.value)


def test_unknown_section_is_an_error():
    with pytest.raises(CaseError, match="unknown key 'bearings'.*did you mean 'bearing'"):
        Case.from_dict({"bearings": {}})


def test_missing_required_field_is_named():
    with pytest.raises(CaseError, match=r"bearing.width: required field is missing \[m\]"):
        Case.from_dict({"bearing": {"diameter": 0.05}})


def test_not_toml_and_missing_file(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("[engine\nbore = 1")
    with pytest.raises(CaseError, match="not valid TOML"):
        Case.from_toml(bad)
    with pytest.raises(CaseError, match="cannot be read"):
        Case.from_toml(tmp_path / "absent.toml")


def test_relative_paths_resolve_against_the_case_folder(tmp_path):
    path = tmp_path / "sub" / "case.toml"
    path.parent.mkdir()
    path.write_text('title = "x"\n')
    case = Case.from_toml(path)
    assert case.resolve("trace.csv") == path.resolve().parent / "trace.csv"


def test_require_reports_the_missing_sections():
    case = Case.from_dict({})
    with pytest.raises(CaseError, match=r"lacks the section\(s\) \[bearing\], \[lubricant\]"):
        case.require("run", "bearing", "lubricant")


def test_cross_field_error_is_one_clean_line():
    with pytest.raises(CaseError) as info:
        Case.from_dict({"engine": {**ENGINE, "rod_length": 0.04}})
    message = str(info.value)
    assert message.startswith("engine.rod_length = 0.04 m must exceed the crank radius")
    assert "Value error" not in message and "{" not in message
