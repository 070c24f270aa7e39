"""Sweeps on a local Dask cluster: the 3×3 shipped study, cache hits, killed workers and
interrupted sweeps, and identity with ``conrod run`` variant by variant."""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.errors import ConvergenceError
from conrod.sweep import Study, Sweep, read_table
from conrod.sweep import worker as worker_module
from conrod.sweep.store import RECORD, variants_dir

REPO = Path(__file__).resolve().parents[1]
STUDY = REPO / "examples" / "studies" / "passenger_car_3x3.toml"
BASE = REPO / "examples" / "passenger_car_diesel_2000rpm.toml"
UNIT_COLUMNS = ["h_min_m", "p_max_Pa", "mean_friction_power_W", "mean_side_flow_m3_s",
                "effective_temperature_C", "max_wear_shell_m"]


@pytest.fixture(scope="module")
def swept(tmp_path_factory):
    out = tmp_path_factory.mktemp("pc_sweep")
    calls = []
    table = Sweep(STUDY, out, workers=2).run(progress=lambda done, total: calls.append(
        (done, total)))
    return out, table, calls


def test_every_variant_finished_with_one_row_each(swept):
    out, table, calls = swept
    assert len(table) == 9 and (table["status"] != "failed").all()
    assert calls[0] == (0, 9) and calls[-1] == (9, 9)
    for column in ["bearing.radial_clearance_m", "engine.speed_rpm", "status", "error",
                   "wall_time_s", "compute_time_s", "h_min_set_by", *UNIT_COLUMNS]:
        assert column in table.columns
    assert np.allclose(table["bearing.radial_clearance_m"],
                       np.repeat([20e-6, 25e-6, 30e-6], 3))
    assert np.allclose(table["engine.speed_rpm"], np.tile([1000.0, 2000.0, 3000.0], 3))
    assert (table["compute_time_s"] <= table["wall_time_s"]).all()
    stored = read_table(out)
    pd.testing.assert_frame_equal(stored, table)
    folders = [p for p in variants_dir(out).iterdir()]
    assert sorted(p.name for p in folders) == sorted(table["hash"])
    for folder in folders:
        record = json.loads((folder / RECORD).read_text())
        assert record["status"] == table.loc[table["hash"] == folder.name, "status"].item()
        assert (folder / "summary.json").is_file() and (folder / "cycle.csv").is_file()
        assert not list(folder.glob("*.png"))  # no figures per variant unless asked


def test_table_values_are_each_variants_summary(swept):
    out, table, _ = swept
    for _, row in table.iterrows():
        summary = json.loads((variants_dir(out) / row["hash"] / "summary.json").read_text())
        assert row["h_min_m"] == summary["h_min_m"]
        assert row["p_max_Pa"] == summary["p_max_Pa"]
        assert row["mean_friction_power_W"] == summary["mean_friction_power_W"]


def test_rerun_is_a_cache_hit_for_all_variants(swept):
    out, table, _ = swept
    stamps = {p.name: (p / RECORD).stat().st_mtime_ns for p in variants_dir(out).iterdir()}
    again = Sweep(STUDY, out).run()
    assert again["cached"].all() and len(again) == 9
    assert {p.name: (p / RECORD).stat().st_mtime_ns
            for p in variants_dir(out).iterdir()} == stamps
    pd.testing.assert_frame_equal(again.drop(columns="cached"), table.drop(columns="cached"))


@pytest.mark.parametrize("index", [0, 7])
def test_sweep_variant_equals_conrod_run(swept, tmp_path, index):
    """The same case written by hand and run with ``conrod run``: identical summary.json."""
    out, table, _ = swept
    row = table.iloc[index]
    text = BASE.read_text(encoding="utf-8")
    text = text.replace("radial_clearance = 0.000025",
                        f"radial_clearance = {float(row['bearing.radial_clearance_m'])!r}")
    text = text.replace("speed = 2000 ", f"speed = {float(row['engine.speed_rpm'])!r} ")
    case = tmp_path / "case.toml"  # the case names no data files
    case.write_text(text, encoding="utf-8")
    _register_commands()
    result = CliRunner().invoke(app, ["run", str(case), "--out", str(tmp_path),
                                      "--integrator", "quasi_static", "--no-figures",
                                      "--accept-warnings"])  # some variants are in contact
    assert result.exit_code == 0, result.output
    by_hand = json.loads((tmp_path / "summary.json").read_text())
    swept_one = json.loads((variants_dir(out) / row["hash"] / "summary.json").read_text())
    by_hand.pop("wall_time_s")
    swept_one.pop("wall_time_s")
    assert by_hand == swept_one


@pytest.fixture(scope="module")
def two_workers():
    """A local cluster of two worker processes and a client on it."""
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, dashboard_address=":0",
                      silence_logs=50) as cluster, Client(cluster) as client:
        yield cluster, client


def test_film_table_cache_is_safe_under_concurrent_workers(two_workers, tmp_path):
    """Workers building the same disk-cached film table at once: every one gets the same
    table, the cache holds one complete file and no temporary file is left."""
    from conrod.film.base import BearingGeometry
    from conrod.film.short.film import ShortBearingFilm
    from conrod.film.table.film import TabulatedFilm

    _, client = two_workers
    base = ShortBearingFilm(BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6))
    futures = [client.submit(TabulatedFilm, base, n_eps=6, n_direction=12,
                             cache_dir=str(tmp_path), pure=False) for _ in range(6)]
    tables = [future.result().tables for future in futures]
    assert [p.suffix for p in tmp_path.iterdir()] == [".npz"]
    reference = TabulatedFilm(base, n_eps=6, n_direction=12, use_cache=False).tables
    for table in tables:
        for name, values in reference.items():
            assert np.array_equal(table[name], values)


def test_killed_worker_loses_no_variant(two_workers, tmp_path):
    """One of two workers is killed (SIGKILL) after the first finished variant; Dask
    reschedules its work and the sweep still ends with 9 finished variants."""
    cluster, client = two_workers
    pids = list(client.run(os.getpid).values())
    killed = []

    def kill_one(record):
        if not killed:
            os.kill(pids[0], signal.SIGKILL)
            killed.append(record["hash"])

    table = Sweep(STUDY, tmp_path, scheduler=cluster.scheduler_address).run(on_record=kill_one)
    assert killed
    assert (table["status"] != "failed").all() and len(table) == 9
    assert _finished(tmp_path) == 9
    assert len(list(variants_dir(tmp_path).iterdir())) == 9  # no temporary folder left


def test_killed_local_worker_loses_no_variant(tmp_path):
    """One of two local worker processes is killed (SIGKILL) after the first finished
    variant; another takes its place and the sweep ends with 9 finished variants."""
    import psutil

    killed = []
    me = psutil.Process()

    def pool_worker(process) -> bool:  # forked from this process, or from its forkserver
        parent = process.parent()
        return process.status() != "zombie" and (
            process.cmdline() == me.cmdline()
            or (parent is not None and "forkserver" in " ".join(parent.cmdline())))

    def kill_one(record):
        if not killed:
            worker = next(p for p in me.children(recursive=True) if pool_worker(p))
            os.kill(worker.pid, signal.SIGKILL)
            killed.append(worker.pid)

    table = Sweep(STUDY, tmp_path, workers=2).run(on_record=kill_one)
    assert killed
    assert (table["status"] != "failed").all() and len(table) == 9
    assert _finished(tmp_path) == 9
    assert len(list(variants_dir(tmp_path).iterdir())) == 9  # no staging folder left


def test_interrupted_sweep_keeps_finished_variants(tmp_path):
    """``conrod sweep`` killed mid-way; the rerun reuses what finished and completes the rest."""
    env = {**os.environ, "PYTHONPATH": str(REPO / "src")}
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "sweep",
               str(STUDY), "--out", str(tmp_path), "--workers", "1"]
    process = subprocess.Popen(command, env=env, stdout=subprocess.DEVNULL,
                               stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        deadline = time.monotonic() + 60
        while time.monotonic() < deadline and _finished(tmp_path) < 2:
            time.sleep(0.02)
    finally:
        os.killpg(process.pid, signal.SIGKILL)
        process.wait()
    before = _finished(tmp_path)
    assert 2 <= before < 9  # killed mid-way
    table = Sweep(STUDY, tmp_path, workers=1).run()
    assert (table["status"] != "failed").all() and len(table) == 9
    assert int(table["cached"].sum()) >= before
    assert not [p for p in variants_dir(tmp_path).iterdir() if p.name.startswith(".")]


def _finished(out: Path) -> int:
    root = variants_dir(out)
    return len(list(root.glob(f"*/{RECORD}"))) if root.is_dir() else 0


def test_a_failing_variant_is_a_row_not_a_crash(tmp_path, monkeypatch):
    """run_variant (what a worker executes) turns a solver failure into a failed record
    and stores nothing, so a rerun tries it again."""
    variant = Study.from_toml(STUDY).variants()[0]

    def fail(self, progress=None):
        raise ConvergenceError("orbit did not converge", where="crank angle 372.0 deg",
                               residual=0.5)

    monkeypatch.setattr("conrod.simulation.simulation.Simulation.run", fail)
    record = worker_module.run_variant(variant.case_data, str(variant.case_file), variant.key,
                                       variant.axes, str(tmp_path))
    assert record["status"] == "failed"
    assert record["error"] == "orbit did not converge at crank angle 372.0 deg (residual 0.5)"
    assert not variants_dir(tmp_path).exists() or not list(variants_dir(tmp_path).iterdir())
    from conrod.sweep.table import record_row, rows_to_frame

    frame = rows_to_frame([record_row(0, variant.axes, record, False)])
    assert frame.loc[0, "status"] == "failed" and "372.0 deg" in frame.loc[0, "error"]


def test_cli_rerun_prints_best_and_worst(swept):
    out, table, _ = swept
    _register_commands()
    result = CliRunner().invoke(app, ["sweep", str(STUDY), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "9 variants: 6 ok, 3 warning, 0 not periodic, 0 failed (9 from earlier runs)" \
        in result.output
    best = table.loc[table["h_min_m"].idxmax()]
    line = next(x for x in result.output.splitlines() if "h_min_m" in x)
    assert f"{best['h_min_m']:.4g}" in line


def test_plot_sweep(swept, tmp_path):
    out, _, _ = swept
    _register_commands()
    target = tmp_path / "h.png"
    result = CliRunner().invoke(app, ["plot-sweep", str(out), "--x", "bearing.radial_clearance",
                                      "--y", "h_min_m", "--hue", "engine.speed_rpm",
                                      "--out", str(target)])
    assert result.exit_code == 0, result.output
    assert target.read_bytes().startswith(b"\x89PNG")
    bad = CliRunner().invoke(app, ["plot-sweep", str(out), "--x", "bearing.radial_clearance",
                                   "--y", "hmin_m"])
    assert bad.exit_code == 2 and "did you mean 'h_min_m'" in bad.output


def test_mechanism_study_equals_the_mechanism_sweep(tmp_path):
    """command = "mechanism": the clearance-joint mechanism runs through the same machinery;
    each row equals impact_statistics of the mechanism sweep at that operating point."""
    from conrod.mechanism.regimes import impact_statistics
    from conrod.mechanism.setup import mechanism_case

    case_file = REPO / "examples" / "kulayev_worn_rod_bearings.toml"
    study = Study.from_dict({"base": str(case_file), "command": "mechanism",
                             "override": {"clearance": {"cycles": 2}},
                             "axis": [{"key": "engine.speed", "values": [3000.0]},
                                      {"key": "clearance.load_scale", "values": [0.5, 1.0]}]})
    table = Sweep(study, tmp_path, workers=1).run()
    assert (table["status"] == "ok").all() and len(table) == 2
    base = mechanism_case(study.variants()[0].case())
    for _, row in table.iterrows():
        stats = impact_statistics(base, row["engine.speed_rpm"], row["clearance.load_scale"])
        assert row["max_impact_velocity_big_end_m_s"] == stats[0, 0]
        assert row["max_impact_velocity_small_end_m_s"] == stats[0, 1]
        assert row["impacts_per_cycle_big_end"] == stats[2, 0]
