"""The Python entry points of ``conrod.sweep`` refuse bad arguments with
:class:`conrod.errors.CaseError` naming the argument, the value and what is allowed — before
anything is computed or written."""

from __future__ import annotations

from pathlib import Path

import pytest

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.mechanism.setup import mechanism_case
from conrod.sweep import Study, Sweep, read_table
from conrod.sweep.mechanism import parse_sweep_option, run_sweep

REPO = Path(__file__).resolve().parents[1]
STUDY = REPO / "examples" / "studies" / "passenger_car_3x3.toml"


@pytest.fixture(scope="module")
def mechanism():
    return mechanism_case(Case.from_toml(REPO / "examples" / "kulayev_worn_rod_bearings.toml"))


@pytest.mark.parametrize(("speeds", "loads", "words"), [
    ([0.0], [0.5], "speeds_rpm = 0.0: out of range (allowed: >= 1 and <= 30000 rpm)"),
    ([-1000.0], [0.5], "speeds_rpm = -1000.0: out of range (allowed: >= 1 and <= 30000 rpm)"),
    ([40000.0], [0.5], "speeds_rpm = 40000.0: out of range (allowed: >= 1 and <= 30000 rpm)"),
    ([float("nan")], [0.5], "speeds_rpm = nan: out of range"),
    ([3000.0], [-0.5], "load_scales = -0.5: out of range (allowed: >= 0 and <= 5)"),
    ([3000.0], [float("inf")], "load_scales = inf: out of range"),
    ([], [0.5], "speeds_rpm: empty (allowed: at least one value)"),
    ("3000", [0.5], "speeds_rpm = '3000': not a list of numbers"),
    ([3000.0], [None], "load_scales: None is not a number"),
    ([3000.0], [True], "load_scales: True is not a number"),
])
def test_run_sweep_refuses_bad_operating_points(mechanism, speeds, loads, words):
    with pytest.raises(CaseError) as error:
        run_sweep(mechanism, speeds, loads)
    assert words in str(error.value)


@pytest.mark.parametrize(("options", "words"), [
    ({"jobs": 0}, "jobs = 0: out of range (allowed: an integer >= 1)"),
    ({"jobs": 2.0}, "jobs = 2.0: out of range (allowed: an integer >= 1)"),
    ({"progress": "yes"}, "progress = 'yes': not callable"),
])
def test_run_sweep_refuses_bad_options(mechanism, options, words):
    with pytest.raises(CaseError) as error:
        run_sweep(mechanism, [3000.0], [0.5], **options)
    assert words in str(error.value)


def test_run_sweep_refuses_what_is_not_a_mechanism():
    with pytest.raises(CaseError, match="base = Case: not a mechanism"):
        run_sweep(Case.from_toml(REPO / "examples" / "kulayev_worn_rod_bearings.toml"),
                  [3000.0], [0.5])


@pytest.mark.parametrize(("text", "words"), [
    (12, "--sweep 12: not text"),
    ("speed=1000:3000:inf", "values must be finite numbers"),
    ("speed=1000:3000:nan", "values must be finite numbers"),
    ("speed=1000:3000:2.5", "integer COUNT >= 1"),
    ("rpm=1000", "expected speed=START:STOP:COUNT"),
])
def test_parse_sweep_option_refuses_bad_text(text, words):
    with pytest.raises(CaseError) as error:
        parse_sweep_option(text)
    assert words in str(error.value)


@pytest.mark.parametrize(("arguments", "words"), [
    ({"study": 3}, "study = 3: not a study"),
    ({"out": None}, "out = None: not a folder path"),
    ({"workers": 0}, "--workers = 0: out of range (allowed: an integer >= 1"),
    ({"workers": 1.5}, "--workers = 1.5: out of range"),
    ({"workers": True}, "--workers = True: out of range"),
    ({"scheduler": "localhost"}, "--scheduler 'localhost': not a scheduler address "
                                 "(allowed: PROTOCOL://HOST:PORT"),
    ({"scheduler": "tcp://h:1", "workers": 2}, "--workers applies to the worker processes"),
    ({"figures": "yes"}, "figures = 'yes': not a boolean"),
])
def test_sweep_refuses_bad_arguments_before_anything_is_written(tmp_path, arguments, words):
    given = {"study": STUDY, "out": tmp_path / "out", **arguments}
    with pytest.raises(CaseError) as error:
        Sweep(given.pop("study"), given.pop("out"), **given)
    assert words in str(error.value)
    assert not (tmp_path / "out").exists()


def test_run_refuses_callbacks_that_are_not_callable(tmp_path):
    with pytest.raises(CaseError, match="progress = 5: not callable"):
        Sweep(STUDY, tmp_path / "out").run(progress=5)
    with pytest.raises(CaseError, match="on_record = 'x': not callable"):
        Sweep(STUDY, tmp_path / "out").run(on_record="x")
    assert not (tmp_path / "out").exists()


def test_study_and_table_readers_refuse_what_they_cannot_read(tmp_path):
    with pytest.raises(CaseError, match="study file = None: not a file path"):
        Study.from_toml(None)
    with pytest.raises(CaseError, match="study = list: not a table"):
        Study.from_dict([])
    with pytest.raises(CaseError, match="folder = 5: not a folder path"):
        Study.from_dict({"base": "a.toml", "axis": []}, folder=5)
    with pytest.raises(CaseError, match="out = 7: not a folder path"):
        read_table(7)
    with pytest.raises(CaseError, match="no sweep table here"):
        read_table(tmp_path)
