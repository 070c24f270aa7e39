"""``conrod mechanism``: the shipped seed-003 example, the sweep and input errors."""

from __future__ import annotations

import csv
import json
import math
import tomllib
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from conrod.cases.case import Case
from conrod.cli import mechanism_command
from conrod.errors import CaseError
from conrod.mechanism.setup import mechanism_case
from conrod.sweep.mechanism import parse_sweep_option, run_sweep

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "kulayev_worn_rod_bearings.toml"
MECHANISM_COLUMNS = {"crank_angle_deg", "piston_position_m", "big_end_gap_m", "small_end_gap_m",
                     "big_end_force_N", "small_end_force_N"}
SUMMARY_KEYS = {"max_impact_velocity_big_end_m_s", "max_impact_velocity_small_end_m_s",
                "impacts_per_cycle", "mean_impact_velocity_big_end_m_s",
                "mean_impact_velocity_small_end_m_s", "energy_residual_relative"}


def mechanism_cli() -> typer.Typer:
    """A typer app with only ``conrod mechanism`` registered."""
    app = typer.Typer()

    @app.callback()
    def _group() -> None:
        """conrod (test instance)."""

    mechanism_command.register(app)
    return app


def write_case(folder: Path, clearance_changes: dict | None = None, **big_end) -> Path:
    """The shipped example with changed [clearance] / [clearance.big_end] keys."""
    data = tomllib.loads(EXAMPLE.read_text(encoding="utf-8"))
    data["clearance"].update(clearance_changes or {})
    data["clearance"]["big_end"].update(big_end)
    lines = []
    _emit(lines, data, "")
    path = folder / "case.toml"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _emit(lines: list[str], table: dict, prefix: str) -> None:
    for key, value in table.items():
        if not isinstance(value, dict):
            lines.append(f"{key} = {json.dumps(value)}")
    for key, value in table.items():
        if isinstance(value, dict):
            name = f"{prefix}.{key}" if prefix else key
            lines.append(f"[{name}]")
            _emit(lines, value, name)


def invoke(*args: str):
    return CliRunner().invoke(mechanism_cli(), ["mechanism", *map(str, args)])


def read_csv(path: Path) -> dict[str, list[str]]:
    with open(path, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return {name: [row[name] for row in rows] for name in rows[0]} if rows else {}


def test_shipped_example_runs_and_writes_the_contract(tmp_path):
    result = invoke(EXAMPLE, "--out", tmp_path)
    assert result.exit_code == 0, result.output
    table = read_csv(tmp_path / "mechanism.csv")
    assert set(table) >= MECHANISM_COLUMNS
    angle = np.array(table["crank_angle_deg"], dtype=float)
    assert angle[0] == 0.0 and angle[-1] == pytest.approx(720.0)
    case = Case.from_toml(EXAMPLE)
    r, length = case.engine.crank_radius, case.engine.rod_length
    piston = np.array(table["piston_position_m"], dtype=float)
    phi = np.radians(angle)
    rigid = r * np.cos(phi) + np.sqrt(length**2 - (r * np.sin(phi)) ** 2)
    free_play = (case.clearance.big_end.clearance_max + case.clearance.small_end.clearance_max) / 2
    assert np.max(np.abs(piston - rigid)) < 1.2 * free_play  # within clearances + deflection
    summary = json.loads((tmp_path / "summary.json").read_text())
    assert set(summary) >= SUMMARY_KEYS
    assert summary["energy_residual_relative"] < 1e-4
    impacts = read_csv(tmp_path / "impacts.csv")
    assert list(impacts)[:3] == ["crank_angle_deg", "joint", "impact_velocity_m_s"]
    cycles = summary["cycles_in_statistics"]
    assert len(impacts["joint"]) == summary["impacts_per_cycle"] * cycles > 0
    assert set(impacts["joint"]) <= {"big_end", "small_end"}
    speeds = np.array(impacts["impact_velocity_m_s"], dtype=float)
    big = speeds[np.array(impacts["joint"]) == "big_end"]
    assert summary["max_impact_velocity_big_end_m_s"] == pytest.approx(big.max(), rel=1e-6)
    for figure in ("gaps_and_forces.png", "journal_orbits.png", "impact_velocities.png"):
        assert (tmp_path / figure).stat().st_size > 10_000


def test_sweep_writes_table_map_and_names_the_regime(tmp_path):
    case = write_case(tmp_path, {"cycles": 1, "tolerance": 1e-3})
    result = invoke(case, "--out", tmp_path / "out", "--sweep", "speed=2000:3000:2",
                    "--sweep", "load=0.5:1.0:2")
    assert result.exit_code == 0, result.output
    table = read_csv(tmp_path / "out" / "sweep.csv")
    assert table["speed_rpm"] == ["2000", "2000", "3000", "3000"]
    assert table["load_scale"] == ["0.5", "1", "0.5", "1"]
    excess = np.array(table["impact_velocity_excess_m_s"], dtype=float)
    assert np.all(np.isfinite(excess))
    big, small = (np.array(table[f"max_impact_velocity_{joint}_m_s"], dtype=float)
                  for joint in ("big_end", "small_end"))
    np.testing.assert_allclose(excess, big - small, rtol=1e-6, atol=1e-12)
    best = json.loads((tmp_path / "out" / "sweep.json").read_text())["most_informative_regime"]
    index = int(np.argmax(excess))
    assert best["speed_rpm"] == float(table["speed_rpm"][index])
    assert best["impact_velocity_excess_m_s"] == pytest.approx(excess.max())
    assert best["driven_by"] in ("big_end", "small_end")
    assert (tmp_path / "out" / "sweep_map.png").stat().st_size > 10_000
    assert "most informative regime" in result.output


@pytest.mark.parametrize("option, words", [
    ("speed=1000-3000", "START:STOP:COUNT"),
    ("rpm=1000:3000:9", "expected speed="),
    ("load=0.5:1.0:2.5", "integer COUNT"),
    ("speed=a:b:3", "must be numbers"),
    ("speed=0:3000:3", "--sweep speed = 0.0"),
])
def test_bad_sweep_option_exits_2_with_a_clear_message(tmp_path, option, words):
    result = invoke(EXAMPLE, "--out", tmp_path, "--sweep", option)
    assert result.exit_code == 2
    assert words in result.output
    assert not (tmp_path / "sweep.csv").exists()


def test_clearance_min_above_max_is_a_case_error(tmp_path):
    case = write_case(tmp_path, clearance_min=200e-6)
    result = invoke(case, "--out", tmp_path / "out")
    assert result.exit_code == 2
    assert "clearance_min" in result.output and "clearance_max" in result.output
    with pytest.raises(CaseError, match="did you mean 'contact_stiffness'"):
        Case.from_toml(write_case(tmp_path, contact_stifness=1e13))


def test_missing_clearance_section_is_named(tmp_path):
    data = EXAMPLE.read_text(encoding="utf-8").split("[clearance]")[0]
    (tmp_path / "case.toml").write_text(data, encoding="utf-8")
    result = invoke(tmp_path / "case.toml", "--out", tmp_path / "out")
    assert result.exit_code == 2
    assert "[clearance]" in result.output


def test_parse_sweep_option_values():
    name, values = parse_sweep_option("speed=1000:3000:9")
    assert name == "speed"
    np.testing.assert_allclose(values, np.linspace(1000, 3000, 9))
    assert parse_sweep_option("load=0.75")[1].tolist() == [0.75]


def test_example_case_maps_seed_symbols_to_si():
    run = mechanism_case(Case.from_toml(EXAMPLE))
    crank = run.mechanism.crank
    assert crank.crank_speed == pytest.approx(3000 * math.pi / 30)
    assert crank.rod_inertia == pytest.approx(0.175 * 0.65 * 0.144**2)  # seed J_c2
    assert run.worn_joint == 0
    area = math.pi * 0.081**2 / 4
    compression_end = 0.10e6 * 16.5**1.36  # seed 003: p_c = p_a ε^n1 at firing TDC
    assert run.gas_table[0] == pytest.approx(area * (compression_end - 0.1e6), rel=1e-9)


@pytest.mark.slow
def test_parallel_sweep_gives_the_same_table():
    base = mechanism_case(Case.from_toml(EXAMPLE))
    base = replace(base, settings=replace(base.settings, cycles=1, tolerance=1e-3))
    serial = run_sweep(base, [2500.0, 3000.0], [0.5])
    parallel = run_sweep(base, [2500.0, 3000.0], [0.5], jobs=2)
    for name, column in serial.columns().items():
        np.testing.assert_array_equal(parallel.columns()[name], column)


def test_python_snippets_of_the_mechanism_docs_run(repo, monkeypatch):
    text = (repo / "docs" / "mechanism.md").read_text(encoding="utf-8")
    snippets = [block.split("```", 1)[0] for block in text.split("```python\n")[1:]]
    assert snippets
    monkeypatch.chdir(repo)
    for snippet in snippets:
        namespace: dict = {}
        exec(compile(snippet, "docs/mechanism.md", "exec"), namespace)
        assert namespace["sweep"].best()["speed_rpm"] in (1000.0, 2000.0, 3000.0)
