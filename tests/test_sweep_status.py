"""A variant's status is what ``conrod run`` says about the same case (exit 0 ok, 4 warning,
3 not periodic); an h_min set by hard contact is flagged and never drawn as a film
thickness; the report and the CLI name the variants that are not ok."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.plotting.sweep_plots import sweep_figure
from conrod.sweep import Study, Sweep
from conrod.sweep.status import WARNING_SEPARATOR
from conrod.sweep.store import variants_dir
from conrod.sweep.table import best_and_worst

REPO = Path(__file__).resolve().parents[1]
STUDY = REPO / "examples" / "studies" / "passenger_car_3x3.toml"
BASE = REPO / "examples" / "passenger_car_diesel_2000rpm.toml"
EXIT_STATUS = {0: "ok", 4: "warning", 3: "not_periodic"}
CLEARANCE, SPEED = "bearing.radial_clearance_m", "engine.speed_rpm"


@pytest.fixture(scope="module")
def shipped(tmp_path_factory):
    out = tmp_path_factory.mktemp("shipped")
    return out, Sweep(STUDY, out, workers=2).run()


def _run_by_hand(folder: Path, clearance: float, speed: float, solver: str = ""):
    """``conrod run`` of the base case at one clearance and speed (quasi-static orbit)."""
    text = BASE.read_text(encoding="utf-8")
    text = text.replace("radial_clearance = 0.000025", f"radial_clearance = {clearance!r}")
    text = text.replace("speed = 2000 ", f"speed = {speed!r} ")
    text = text.replace("[solver]\n", f"[solver]\n{solver}")
    case = folder / "case.toml"
    case.write_text(text, encoding="utf-8")
    _register_commands()
    return CliRunner().invoke(app, ["run", str(case), "--out", str(folder / "run"),
                                    "--integrator", "quasi_static", "--no-figures"])


def test_status_is_what_conrod_run_says(shipped, tmp_path):
    out, table = shipped
    for index, row in table.iterrows():
        folder = tmp_path / str(index)
        folder.mkdir()
        result = _run_by_hand(folder, float(row[CLEARANCE]), float(row[SPEED]))
        assert row["status"] == EXIT_STATUS[result.exit_code], result.output
        summary = json.loads((folder / "run" / "summary.json").read_text(encoding="utf-8"))
        expected = WARNING_SEPARATOR.join(summary["warnings"])
        assert row["warnings"] == expected
        for warning in summary["warnings"]:
            assert f"warning: {warning}" in result.output
    assert set(table["status"]) == {"ok", "warning"}  # the contact-dominated ones are flagged


def test_a_non_periodic_orbit_is_its_own_status(tmp_path):
    solver = {"integrator": "quasi_static", "max_cycles": 2, "periodicity_tolerance": 1e-9}
    study = Study.from_dict({"base": str(BASE), "override": {"solver": solver},
                             "axis": [{"key": "engine.speed", "values": [2000.0]}]})
    (row,) = [r for _, r in Sweep(study, tmp_path / "out", workers=1).run().iterrows()]
    by_hand = _run_by_hand(tmp_path, 25e-6, 2000.0,
                           "max_cycles = 2\nperiodicity_tolerance = 1e-9\n")
    assert by_hand.exit_code == 3 and row["status"] == "not_periodic"
    assert "orbit not periodic after 2 cycles" in row["warnings"]


def test_h_min_at_the_contact_threshold_is_flagged_as_contact(shipped):
    out, table = shipped
    for _, row in table.iterrows():
        summary = json.loads((variants_dir(out) / row["hash"] / "summary.json").read_text())
        threshold = summary["solver_settings"]["contact_film_thickness"]
        if row["h_min_set_by"] == "contact":
            assert row["max_orbit_contact_force_N"] > 0.0
            assert row["h_min_m"] == pytest.approx(threshold, rel=1e-9)  # the wall
            assert row["status"] != "ok"
        else:
            assert row["h_min_set_by"] == "film" and row["h_min_m"] > threshold
    assert (table["h_min_set_by"] == "contact").any()


def _artists(figure):
    return [line for line in figure.axes[0].get_lines() if len(line.get_xdata())]


def test_the_h_min_plot_draws_contact_points_apart(shipped):
    _, table = shipped
    figure = sweep_figure(table, CLEARANCE, "h_min_m", SPEED)
    contact = table[table["h_min_set_by"] == "contact"]
    drawn_as_contact = {(x, y) for line in _artists(figure) if line.get_marker() == "v"
                        for x, y in zip(line.get_xdata(), line.get_ydata(), strict=True)}
    assert drawn_as_contact == set(zip(contact[CLEARANCE], contact["h_min_m"], strict=True))
    for line in _artists(figure):  # a line joins only ok film results
        if line.get_linestyle() != "None":
            assert not set(line.get_ydata()) & set(contact["h_min_m"])
    labels = [text.get_text() for text in figure.axes[0].get_legend().get_texts()]
    assert any("hard contact" in label and "not a film thickness" in label
               for label in labels)


def test_other_plots_draw_doubtful_variants_hollow(shipped):
    _, table = shipped
    figure = sweep_figure(table, SPEED, "p_max_Pa", CLEARANCE)
    hollow = {(x, y) for line in _artists(figure) if line.get_markerfacecolor() == "none"
              for x, y in zip(line.get_xdata(), line.get_ydata(), strict=True)}
    doubtful = table[table["status"] != "ok"]
    assert hollow == set(zip(doubtful[SPEED], doubtful["p_max_Pa"], strict=True))


def test_best_and_worst_leave_doubtful_variants_out_and_the_cli_names_them(shipped):
    out, table = shipped
    ok = table[table["status"] == "ok"]
    rows = {r["characteristic"]: r for r in best_and_worst(table)}
    assert rows["h_min_m"]["worst"] == ok["h_min_m"].min()
    assert rows["effective_temperature_C"]["worst"] == ok["effective_temperature_C"].max()
    _register_commands()
    result = CliRunner().invoke(app, ["sweep", str(STUDY), "--out", str(out)])
    assert result.exit_code == 0, result.output
    for _, row in table[table["status"] != "ok"].iterrows():
        assert f"variant {row['variant']} warning: {row['warnings']}" in result.output


def test_the_sweep_report_lists_the_variants_that_are_not_ok(shipped):
    import re

    from conrod.report import build_report

    out, table = shipped
    html = build_report(out)
    section = re.search(r"<h2>Variants that are not ok</h2>.*?<tbody>(.*?)</tbody>", html, re.S)
    assert section.group(1).count("<tr>") == int((table["status"] != "ok").sum())
    assert "hard contact carries up to" in section.group(1)
    assert "Hollow triangles: the journal touches the shell" in html


def test_axis_columns_carry_the_unit_of_their_key(shipped):
    out, table = shipped
    assert list(table.columns[2:4]) == [CLEARANCE, SPEED]
    study = json.loads((out / "study.json").read_text(encoding="utf-8"))
    assert study["axis_columns"] == {"bearing.radial_clearance": CLEARANCE,
                                     "engine.speed": SPEED}
    _register_commands()
    for x in ("engine.speed", SPEED):  # the case key or the column
        result = CliRunner().invoke(app, ["plot-sweep", str(out), "--x", x, "--y", "p_max_Pa",
                                          "--out", str(out / f"{x}.png")])
        assert result.exit_code == 0, result.output
