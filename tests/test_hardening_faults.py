"""Faults of the environment and implausible results: one clear line, nothing half-written."""

from __future__ import annotations

import errno
import math
import os
import signal
import subprocess
import sys
import time
import types
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import ConvexHull
from typer.testing import CliRunner

from conrod import Case
from conrod.cli.app import _register_commands, app
from conrod.errors import CacheWarning, ConvergenceError, NonFiniteResultError
from conrod.film.base import BearingGeometry
from conrod.film.short.film import ShortBearingFilm
from conrod.film.table.film import QUANTITIES, TabulatedFilm, tables_checksum
from conrod.io.atomic import write_csv, write_json
from conrod.io.interrupts import deferred_interrupts, raise_if_interrupted
from conrod.mechanism.geometry import seed_free_play_is_convex, shell_semi_axes
from conrod.mechanism.setup import mechanism_case
from conrod.results import plausibility
from hardening_helpers import cheap_mechanism, cheap_table_run, mutated, write_case

_register_commands()
RUNNER = CliRunner()
SRC = Path(__file__).resolve().parents[1] / "src"


def _cli(*args: str):
    return RUNNER.invoke(app, list(args))


# -- output location, checked before any computation -----------------------------------------
@pytest.fixture
def no_computation(monkeypatch):
    """Fail the test if a command starts computing."""
    def forbidden(*args, **kwargs):
        raise AssertionError("computation started before the output check")

    monkeypatch.setattr("conrod.simulation.simulation.Simulation.run", forbidden)
    monkeypatch.setattr("conrod.mechanism.simulation.simulate", forbidden)
    monkeypatch.setattr("conrod.loads.engine_loads.compute_engine_loads", forbidden)


@pytest.mark.parametrize("command", ["run", "loads", "mechanism"])
def test_out_naming_an_existing_file_exits_2_before_computing(tmp_path, command,
                                                              no_computation):
    case = write_case(tmp_path, cheap_table_run())
    target = tmp_path / "taken"
    target.write_text("keep me")
    result = _cli(command, str(case), "--out", str(target))
    assert result.exit_code == 2
    assert result.output.strip() == (f"error: --out {str(target)!r}: is an existing file "
                                     "(allowed: a folder, new or existing)")
    assert target.read_text() == "keep me"


def test_out_below_a_file_and_unwritable_place_exit_2(tmp_path, no_computation):
    case = write_case(tmp_path, cheap_table_run())
    (tmp_path / "file").write_text("x")
    result = _cli("run", str(case), "--out", str(tmp_path / "file" / "sub"))
    assert result.exit_code == 2 and "is a file, not a folder" in result.output
    result = _cli("run", str(case), "--out", "/proc/conrod-results")
    assert result.exit_code == 2 and "cannot write in '/proc'" in result.output
    assert len(result.output.strip().splitlines()) == 1


def test_disk_full_while_writing_keeps_the_old_result(tmp_path, monkeypatch):
    case = write_case(tmp_path, cheap_table_run())
    out = tmp_path / "out"
    # a 2-cycle orbit is not periodic (exit 3): accepted, this test is about the disk
    assert _cli("run", str(case), "--out", str(out), "--no-figures",
                "--accept-warnings").exit_code == 0
    before = {p.name: p.read_bytes() for p in out.iterdir()}
    from conrod.output import registry

    real = registry.write_csv

    def full_disk(*args, **kwargs):  # the table is written, then the disk is full
        real(*args, **kwargs)
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))

    monkeypatch.setattr(registry, "write_csv", full_disk)
    result = _cli("run", str(case), "--out", str(out), "--no-figures", "--accept-warnings")
    assert result.exit_code == 5  # could not write the results
    assert result.output.strip() == ("error: cannot write the results (No space left on "
                                     "device); the output folder is unchanged")
    assert {p.name: p.read_bytes() for p in out.iterdir()} == before
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []


# -- non-finite results ------------------------------------------------------------------------
def test_json_writer_names_the_non_finite_field(tmp_path):
    with pytest.raises(NonFiniteResultError, match=r"non-finite result contact\.peak = inf "
                                                   r"in summary\.json; nothing written"):
        write_json(tmp_path / "summary.json", {"h_min": 1e-6, "contact": {"peak": math.inf}})
    assert list(tmp_path.iterdir()) == []


def test_csv_writer_names_column_and_row(tmp_path):
    with pytest.raises(ConvergenceError, match=r"p_max_Pa = nan in cycle\.csv, row 3"):
        write_csv(tmp_path / "cycle.csv", {"a": np.arange(4.0),
                                          "p_max_Pa": np.array([1.0, 2.0, np.nan, 4.0])})
    assert list(tmp_path.iterdir()) == []


def _fake_run(**overrides):
    n = 8
    angle = np.radians(np.arange(n) * 90.0)
    cycle = types.SimpleNamespace(
        crank_angle=angle, eccentricity_ratio=np.full(n, 0.5), h_min=np.full(n, 10e-6),
        p_max=np.full(n, 1e7), load_x=np.full(n, 1e4), load_y=np.zeros(n),
        contact_force=np.zeros(n), in_contact=np.zeros(n, dtype=bool))
    for name, (index, value) in overrides.items():
        getattr(cycle, name)[index] = value
    summary = types.SimpleNamespace(effective_temperature=95.0)
    return types.SimpleNamespace(cycle=cycle, clearance=20e-6, summary=summary)


def _case(**lubricant):
    contact = types.SimpleNamespace(model="hard", roughness=0.4e-6)
    return types.SimpleNamespace(contact=contact, lubricant=types.SimpleNamespace(
        max_temperature=lubricant.get("max_temperature", 200.0)))


def test_plausible_run_has_no_warning():
    assert plausibility.check_run(_fake_run(), _case()) == []


def test_centre_excursion_is_measured_from_the_orbit_contact_circle():
    """0.66 c beyond the clearance: a warning on a rigid bore (allowed 0.5 c), none on a
    deforming bore whose contact circle is widened by one clearance (allowed 1.5 c)."""
    run = _fake_run(eccentricity_ratio=(5, 1.66))
    rigid = plausibility.check_run(run, _case())
    assert rigid == ["journal centre 0.66 c beyond the clearance circle at crank angle "
                     "450.0 deg (allowed: <= 0.5 c)"]
    assert plausibility.check_run(run, _case(), contact_radius=2.0 * 20e-6) == []
    far = _fake_run(eccentricity_ratio=(5, 2.6))
    assert "allowed: <= 1.5 c" in plausibility.check_run(far, _case(),
                                                          contact_radius=2.0 * 20e-6)[0]


def test_table_film_past_capacity_is_an_error_naming_the_crank_angle():
    # the fuzzed table film returned p_max -5.2e24 Pa and a 66 MN contact force (25 kN load)
    with pytest.raises(ConvergenceError, match=r"p_max = -5.2e\+24 Pa .* at crank angle "
                                               r"270\.0 deg"):
        plausibility.check_run(_fake_run(p_max=(3, -5.2e24)), _case())
    with pytest.raises(ConvergenceError, match=r"contact force 6.6e\+07 N .* 6.6e\+03 x"):
        plausibility.check_run(_fake_run(contact_force=(2, 6.6e7)), _case())


def test_non_finite_result_is_an_error_naming_field_and_angle():
    with pytest.raises(ConvergenceError, match=r"h_min is not finite at crank angle 180\.0"):
        plausibility.check_run(_fake_run(h_min=(2, np.nan)), _case())


def test_doubtful_results_are_warnings():
    warned = plausibility.check_run(_fake_run(h_min=(1, 0.1e-6), contact_force=(4, 4e4)),
                                    _case(max_temperature=90.0))
    assert len(warned) == 3
    assert "4 x the peak load" in warned[0]
    assert "film thickness 0.1 µm at crank angle 90.0 deg is below the combined roughness" in (
        warned[1])
    assert "95.0 °C is above the oil's valid range" in warned[2]


# -- mechanism: default geometry and the seed formula -----------------------------------------
def test_mechanism_defaults_to_exact_contact_geometry():
    assert mechanism_case(Case.from_dict(cheap_mechanism())).mechanism.contact_geometry == (
        "exact")


@pytest.mark.parametrize("ratio", [1.0, 0.9, 0.75, 0.7, 0.6, 0.5, 0.3])
def test_seed_convexity_agrees_with_the_convex_hull(ratio):
    """Independent answer: a region is convex iff every sampled boundary point is a vertex
    of the convex hull of the boundary."""
    diameter, clearance_max = 0.0478, 120e-6
    major, minor, e2 = shell_semi_axes(diameter, clearance_max, ratio * clearance_max)
    angle = np.linspace(0.0, 2.0 * math.pi, 720, endpoint=False)
    radius = minor / np.sqrt(1.0 - e2 * np.cos(angle) ** 2) - 0.5 * diameter
    points = np.column_stack([radius * np.cos(angle), radius * np.sin(angle)])
    hull_convex = len(ConvexHull(points).vertices) == len(points)
    assert seed_free_play_is_convex(diameter, clearance_max, ratio * clearance_max) == (
        hull_convex)


@pytest.mark.parametrize("diameter, clearance_max", [(0.0478, 120e-6), (0.026, 30e-6),
                                                      (0.2, 400e-6)])
def test_seed_region_turns_non_convex_at_two_thirds(diameter, clearance_max):
    """Independent answer: the outline r ≈ Δmax/2 cos²ϕ + Δmin/2 sin²ϕ of a thin
    clearance is convex iff Δmin >= 2/3 Δmax (r² + 2r'² − r r'' at ϕ = π/2)."""
    assert seed_free_play_is_convex(diameter, clearance_max, 0.67 * clearance_max)
    assert not seed_free_play_is_convex(diameter, clearance_max, 0.66 * clearance_max)


def test_seed_geometry_on_a_strongly_worn_shell_warns(tmp_path):
    case = cheap_mechanism()
    case["clearance"]["contact_geometry"] = "seed"
    result = _cli("mechanism", str(write_case(tmp_path, case)), "--out", str(tmp_path / "o"))
    assert result.exit_code == 4, result.output  # finished with warnings
    assert ("warning: big_end: the seed contact geometry makes the free-play region "
            "non-convex") in result.output
    summary = (tmp_path / "o" / "summary.json").read_text()
    assert "non-convex" in summary


def test_mechanism_warns_on_impacts_above_surface_speed():
    joint = types.SimpleNamespace(diameter=0.05, clearance_max=1e-4, clearance_min=1e-4,
                                  radial_clearance_min=5e-5)
    mechanism = types.SimpleNamespace(
        crank=types.SimpleNamespace(crank_speed=100.0), big_end=joint, small_end=joint,
        contact_geometry="exact")
    impacts = types.SimpleNamespace(of_joint=lambda j: np.array([20.0]) if j == 0 else
                                    np.array([0.1]))
    results = types.SimpleNamespace(
        crank_angle=np.zeros(3), contact_force=np.array([[1.2e7, 0, 0], [0, 0, 0.0]]),
        gap=np.zeros((2, 3)), settled_impacts=lambda: impacts)
    warned = plausibility.check_mechanism(results, mechanism)
    assert warned == ["big_end: impact velocity 20 m/s is above the crank-pin surface speed "
                      "2.5 m/s", "big_end: contact force 1.2e+07 N is above 1e+06 N"]


# -- corrupt film-table cache ----------------------------------------------------------------
def _table(cache_dir):
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6)
    return TabulatedFilm(ShortBearingFilm(geometry), n_eps=5, n_direction=8,
                         cache_dir=cache_dir)


def _nan_filled(data: bytes, path: Path) -> None:
    with np.load(path) as stored:
        tables = {q: np.full_like(stored[q], np.nan) for q in QUANTITIES}
    np.savez(path, checksum=np.frombuffer(tables_checksum(tables), np.uint8), **tables)


@pytest.mark.parametrize("corrupt", ["truncated", "garbage", "zero bytes", "nan-filled",
                                     "bit flip"])
def test_corrupt_table_cache_is_detected_and_rebuilt(tmp_path, corrupt):
    fresh = _table(tmp_path)
    path = fresh.cache_path()
    data = path.read_bytes()
    if corrupt == "truncated":
        path.write_bytes(data[: len(data) // 2])
    elif corrupt == "garbage":
        path.write_bytes(os.urandom(len(data)))
    elif corrupt == "zero bytes":
        path.write_bytes(b"")
    elif corrupt == "nan-filled":
        _nan_filled(data, path)
    else:  # flip one byte of the stored table values (uncompressed npz): checksum catches it
        with np.load(path) as stored:
            tables = {q: stored[q].copy() for q in QUANTITIES}
            checksum = stored["checksum"].copy()
        tables["turning"][2, 3] += 1e-9
        np.savez(path, checksum=checksum, **tables)
    with pytest.warns(CacheWarning, match="is corrupt .*; rebuilding it"):
        rebuilt = _table(tmp_path)
    assert not rebuilt.loaded_from_cache
    for name in QUANTITIES:
        np.testing.assert_array_equal(rebuilt.tables[name], fresh.tables[name])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert _table(tmp_path).loaded_from_cache  # the rebuilt file is intact


# -- Ctrl-C and terminal encoding ------------------------------------------------------------
def test_interrupt_is_deferred_to_a_safe_point():
    with pytest.raises(KeyboardInterrupt), deferred_interrupts():
        os.kill(os.getpid(), signal.SIGINT)
        time.sleep(0.05)  # the handler ran; no exception yet
        reached = True
        raise_if_interrupted()
    assert reached


def _conrod(*args: str, **env: str) -> subprocess.Popen:
    environment = {**os.environ, "PYTHONPATH": str(SRC), **env}
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", *args]
    return subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            env=environment)


def test_non_utf8_terminal_does_not_crash(tmp_path):
    case = write_case(tmp_path, cheap_table_run())
    process = _conrod("run", str(case), "--out", str(tmp_path / "o"), "--no-figures",
                      "--accept-warnings", PYTHONIOENCODING="ascii", LC_ALL="C", LANG="C")
    out, err = process.communicate(timeout=120)
    assert process.returncode == 0, err
    assert b"h_min" in out and b"Traceback" not in err


def test_ctrl_c_during_a_reynolds_run_exits_130_and_writes_nothing(tmp_path):
    case = mutated(cheap_table_run(), ("solver",), {"film": "reynolds", "max_cycles": 50,
                                                     "min_cycles": 50,  # never done in 8 s
                                                     "integrator": "adaptive"})
    out = tmp_path / "o"
    process = _conrod("run", str(write_case(tmp_path, case)), "--out", str(out))
    time.sleep(8.0)  # imports, compilation, then well inside the orbit integration
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=120)
    assert process.returncode == 130, err
    assert err.decode().strip().splitlines()[-1] == "interrupted (nothing written)"
    assert b"Traceback" not in err and b"SystemError" not in err
    assert not out.exists()
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []
