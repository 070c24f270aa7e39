"""Same input, same output, bit for bit: every shipped example run twice, figures without
timestamps, and cold vs warm numba and film-table caches."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

import conrod.output  # noqa: F401  (registers the tables and figures)
from conrod import Case, Simulation
from conrod.io.atomic import write_csv, write_json, write_text
from conrod.loads.engine_loads import compute_engine_loads
from conrod.mechanism.setup import mechanism_case
from conrod.mechanism.simulation import simulate
from conrod.output.registry import write_results
from conrod.output.tables import (
    cycle_table,
    impacts_text,
    loads_table,
    mechanism_table,
    summary_items,
)
from hardening_helpers import EXAMPLES, cheap_table_run, example_dict, mutated, write_case

RUN_EXAMPLES = ["flores2006_table_load", "passenger_car_diesel_2000rpm",
                "passenger_car_diesel_1000rpm", "ruston_hornsby_6vebx_mk3",
                "kamaz_740_truck_diesel"]
ENGINE_EXAMPLES = ["passenger_car_diesel_2000rpm", "passenger_car_diesel_1000rpm",
                   "kamaz_740_truck_diesel", "kulayev_worn_rod_bearings"]
TIMING_KEYS = (b'"wall_time_s"',)
"""summary.json lines that hold a measured duration (the only non-reproducible field)."""


def _contents(folder: Path) -> dict[str, bytes]:
    """File name → bytes, timing lines removed from JSON files (and the checksum of the
    file holding them from the manifest)."""
    files = {}
    for path in sorted(folder.iterdir()):
        data = path.read_bytes()
        if path.name == "manifest.json":
            manifest = json.loads(data)
            manifest["files"].pop("summary.json", None)
            data = json.dumps(manifest).encode()
        elif path.suffix == ".json":
            data = b"\n".join(line for line in data.splitlines()
                              if not line.strip().startswith(TIMING_KEYS))
        files[path.name] = data
    return files


def _write_tables(case: Case, out: Path) -> None:
    """cycle.csv and summary.json of one run (contact columns and items included)."""
    results = Simulation(case).run()
    write_csv(out / "cycle.csv", cycle_table(results))
    write_json(out / "summary.json", summary_items(results))


@pytest.mark.parametrize("name", RUN_EXAMPLES)
def test_run_examples_are_byte_identical(tmp_path, name):
    case = Case.from_toml(EXAMPLES / f"{name}.toml")
    for attempt in ("first", "second"):
        _write_tables(case, tmp_path / attempt)
    assert _contents(tmp_path / "first") == _contents(tmp_path / "second")


def test_whole_result_folder_with_figures_is_byte_identical(tmp_path):
    case = Case.from_toml(EXAMPLES / "flores2006_table_load.toml")
    for attempt in ("first", "second"):
        write_results(Simulation(case).run(), tmp_path / attempt, figures=True)
    first = _contents(tmp_path / "first")
    assert {"cycle.csv", "summary.json", "orbit.png", "case.toml"} <= set(first)
    assert first == _contents(tmp_path / "second")


@pytest.mark.parametrize("name", ENGINE_EXAMPLES)
def test_loads_are_byte_identical(tmp_path, name):
    case = Case.from_toml(EXAMPLES / f"{name}.toml")
    for attempt in ("first", "second"):
        loads = compute_engine_loads(case)
        write_csv(tmp_path / attempt / "loads.csv", loads_table(loads))
        write_json(tmp_path / attempt / "loads_summary.json", loads.summary())
    assert _contents(tmp_path / "first") == _contents(tmp_path / "second")


def test_mechanism_example_is_byte_identical(tmp_path):
    base = mechanism_case(Case.from_toml(EXAMPLES / "kulayev_worn_rod_bearings.toml"))
    for attempt in ("first", "second"):
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
        write_csv(tmp_path / attempt / "mechanism.csv", mechanism_table(results))
        write_text(tmp_path / attempt / "impacts.csv", impacts_text(results))
        write_json(tmp_path / attempt / "summary.json", results.summary())
    assert _contents(tmp_path / "first") == _contents(tmp_path / "second")


def test_cold_and_warm_film_table_cache_give_identical_results(tmp_path, monkeypatch):
    monkeypatch.setattr("conrod.film.table.film.DEFAULT_CACHE_DIR", tmp_path / "tables")
    case = Case.from_dict(mutated(cheap_table_run(), ("solver", "film"), "table"),
                          base_dir=EXAMPLES)
    assert not Simulation(case).film_model().loaded_from_cache  # builds and stores the table
    _write_tables(case, tmp_path / "cold")
    for stored in (tmp_path / "tables").glob("*.npz"):
        stored.unlink()  # cold again: rebuilt inside the run
    _write_tables(case, tmp_path / "rebuilt")
    assert Simulation(case).film_model().loaded_from_cache
    _write_tables(case, tmp_path / "warm")
    assert _contents(tmp_path / "rebuilt") == _contents(tmp_path / "warm")
    assert _contents(tmp_path / "cold") == _contents(tmp_path / "warm")


def test_cold_numba_cache_gives_the_same_bytes_as_a_warm_one(tmp_path):
    """A fresh process compiling every kernel (empty NUMBA_CACHE_DIR) writes the same
    cycle.csv as this warm process."""
    case = example_dict("flores2006_table_load")
    case["load"]["table"] = str(EXAMPLES / "data" / "flores2006_load.csv")
    path = write_case(tmp_path, case)
    environment = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "numba"),
                   "PYTHONPATH": str(Path(__file__).resolve().parents[1] / "src")}
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(path), "--out", str(tmp_path / "cold"), "--no-figures"]
    subprocess.run(command, env=environment, check=True, capture_output=True, timeout=600)
    _write_tables(Case.from_toml(path), tmp_path / "warm")
    cold, warm = _contents(tmp_path / "cold"), _contents(tmp_path / "warm")
    for name in ("cycle.csv", "summary.json"):
        assert cold[name] == warm[name]
