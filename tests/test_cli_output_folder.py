"""An output folder is new, empty, or conrod's own: a folder holding files of another
origin is refused before computing (exit 2, one line naming the folder, what is in it and
the fix); conrod's own folder is replaced by the new result without stale files."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError
from conrod.io.result_folder import check_output_folder, staged_result_folder
from hardening_helpers import EXAMPLES

CASE = str(EXAMPLES / "flores2006_table_load.toml")
STUDY = str(EXAMPLES / "studies" / "passenger_car_3x3.toml")


@pytest.fixture(scope="module")
def runner():
    _register_commands()
    return CliRunner()


@pytest.fixture
def foreign(tmp_path):
    """A folder holding someone's files (no conrod manifest)."""
    folder = tmp_path / "thesis"
    folder.mkdir()
    (folder / "chapter1.tex").write_text("my work\n", encoding="utf-8")
    (folder / "data.csv").write_text("1,2\n", encoding="utf-8")
    return folder


@pytest.mark.parametrize("command", [
    ["run", CASE], ["loads", CASE], ["mechanism", CASE], ["housing", CASE],
    ["stress", CASE], ["sweep", STUDY]])
def test_every_command_refuses_a_foreign_folder_before_computing(runner, foreign, command):
    result = runner.invoke(app, [*command, "--out", str(foreign)])
    assert result.exit_code == 2, result.output
    lines = result.output.strip().splitlines()
    assert len(lines) == 1, result.output
    assert str(foreign) in lines[0] and "chapter1.tex, data.csv" in lines[0]
    assert "choose another folder or empty this one" in lines[0]
    assert sorted(p.name for p in foreign.iterdir()) == ["chapter1.tex", "data.csv"]
    assert not list(foreign.parent.glob(".*conrod-stage*"))  # nothing computed or staged


def test_refusal_names_the_first_entries_and_their_count(tmp_path):
    for index in range(7):
        (tmp_path / "many" / f"f{index}.txt").parent.mkdir(exist_ok=True)
        (tmp_path / "many" / f"f{index}.txt").write_text("x", encoding="utf-8")
    with pytest.raises(CaseError, match=r"f0.txt, f1.txt, f2.txt, f3.txt, \.\.\. \(7 entries\)"):
        check_output_folder(tmp_path / "many")


def test_new_empty_hidden_only_and_own_folders_are_accepted(tmp_path):
    assert check_output_folder(tmp_path / "new" / "deeper") == tmp_path / "new" / "deeper"
    (tmp_path / "empty").mkdir()
    check_output_folder(tmp_path / "empty")
    (tmp_path / "kept").mkdir()
    (tmp_path / "kept" / ".gitkeep").write_text("", encoding="utf-8")
    check_output_folder(tmp_path / "kept")
    with staged_result_folder(tmp_path / "own") as stage:
        (stage / "cycle.csv").write_text("a\n", encoding="utf-8")
    check_output_folder(tmp_path / "own")


def test_a_sweep_folder_and_a_run_folder_are_not_interchangeable(tmp_path):
    with staged_result_folder(tmp_path / "run") as stage:
        (stage / "cycle.csv").write_text("a\n", encoding="utf-8")
    with pytest.raises(CaseError, match="no study.json"):
        check_output_folder(tmp_path / "run", marker="study.json")
    (tmp_path / "sweep").mkdir()
    (tmp_path / "sweep" / "study.json").write_text("{}", encoding="utf-8")
    (tmp_path / "sweep" / "sweep.parquet").write_bytes(b"")
    check_output_folder(tmp_path / "sweep", marker="study.json")
    with pytest.raises(CaseError, match="no manifest.json"):
        check_output_folder(tmp_path / "sweep")


def test_rerun_drops_the_previous_result_and_its_report_keeps_hand_added_files(tmp_path):
    out = tmp_path / "out"
    with staged_result_folder(out) as stage:
        for name in ("cycle.csv", "orbit.png"):
            (stage / name).write_text("old\n", encoding="utf-8")
    (out / "report.html").write_text("report of the old result\n", encoding="utf-8")
    (out / "notes.txt").write_text("engineer's notes\n", encoding="utf-8")
    with staged_result_folder(out) as stage:
        (stage / "cycle.csv").write_text("new\n", encoding="utf-8")
    assert sorted(p.name for p in out.iterdir()) == ["cycle.csv", "manifest.json", "notes.txt"]
    assert (out / "cycle.csv").read_text(encoding="utf-8") == "new\n"
    listed = json.loads((out / "manifest.json").read_text(encoding="utf-8"))["files"]
    assert sorted(listed) == ["cycle.csv"]  # hand-added files are carried, not listed


def test_python_writers_refuse_a_foreign_folder_too(foreign):
    with pytest.raises(CaseError, match="chapter1.tex"), staged_result_folder(foreign):
        pytest.fail("the block must not run")
    assert sorted(p.name for p in foreign.iterdir()) == ["chapter1.tex", "data.csv"]


def test_the_sweep_python_api_refuses_a_foreign_folder_before_computing(foreign):
    from conrod.sweep import Sweep

    with pytest.raises(CaseError, match=r"out 'thesis'|chapter1.tex"):
        Sweep(STUDY, foreign, workers=1).run()
    assert sorted(p.name for p in foreign.iterdir()) == ["chapter1.tex", "data.csv"]


def test_a_folder_holding_only_the_input_file_is_accepted(tmp_path):
    case = tmp_path / "case.toml"
    case.write_text("title = 'x'\n", encoding="utf-8")
    check_output_folder(tmp_path, inputs=(case,))
    with pytest.raises(CaseError, match=r"\(case.toml\)"):  # without naming it: foreign
        check_output_folder(tmp_path, option="--out")


def test_a_255_byte_folder_name_is_written_and_rewritten(tmp_path):
    """The staging folder beside it has a name that fits too (the long name is cut and
    tagged with its hash)."""
    out = tmp_path / ("r" * 255)
    for _ in range(2):  # new, then the previous result exchanged for the new one
        with staged_result_folder(out) as stage:
            (stage / "cycle.csv").write_text("a\n1\n", encoding="utf-8")
    assert sorted(p.name for p in out.iterdir()) == ["cycle.csv", "manifest.json"]
    assert [p.name for p in tmp_path.iterdir()] == [out.name]


@pytest.mark.parametrize("command", ["run", "loads", "mechanism", "housing", "stress"])
@pytest.mark.parametrize("too_long", ["name", "path"])
def test_over_long_out_names_and_paths_exit_2_before_computing(runner, tmp_path, command,
                                                               too_long):
    if too_long == "name":
        out, expected = tmp_path / ("n" * 256), "a folder name of 256 bytes is too long " \
            "(allowed: <= 255 bytes per name)"
    else:
        out = tmp_path.joinpath(*["p" * 200] * 20)
        expected = f"a path of {len(str(out))} bytes is too long (allowed: <= 3896 bytes"
    result = runner.invoke(app, [command, CASE, "--out", str(out)])
    assert result.exit_code == 2, result.output
    [line] = result.output.strip().splitlines()
    assert line.startswith(f"error: --out {str(out)!r}: {expected}")
    assert list(tmp_path.iterdir()) == []
