"""A run with a tilted journal and a bore profile from a case file: inputs, cycle.csv,
summary.json, the headline, and the bearing without either unchanged."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod import Case, Simulation
from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError

CASE = """title = "tilt test"
[bearing]
diameter = 0.05
width = 0.025
radial_clearance = 25e-6
{bearing}
[lubricant]
viscosity = 0.01
[load]
table = "load.csv"
speed = 2000
cycle_deg = 360
[solver]
film = "reynolds"
n_theta = 24
n_z = 8
max_cycles = 2
{extra}
"""


def write_case(folder, bearing: str = "", extra: str = "") -> Case:
    rows = "\n".join(f"{a},{1500 + 800 * math.cos(math.radians(a))},"
                     f"{500 * math.sin(math.radians(a))}" for a in range(0, 360, 15))
    (folder / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + rows + "\n")
    tilt = "\n".join(f"{a},{1e-4 * math.sin(math.radians(a))},{5e-5}" for a in range(0, 360, 30))
    (folder / "tilt.csv").write_text("# crank-pin bending\ncrank_angle_deg,tilt_x_rad,tilt_y_rad\n"
                                     + tilt + "\n")
    path = folder / "case.toml"
    path.write_text(CASE.format(bearing=bearing, extra=extra))
    return Case.from_toml(path)


def test_zero_profile_changes_nothing(tmp_path):
    """A [bearing.profile] of zeros runs the cylindrical bore bit for bit."""
    plain = Simulation(write_case(tmp_path)).run()
    zero = Simulation(write_case(tmp_path, "[bearing.profile]\ncrown = 0.0")).run()
    assert plain.cycle.axial is None and zero.cycle.axial is not None
    for name in ("eccentricity_x", "eccentricity_y", "h_min", "p_max", "friction_power"):
        assert np.array_equal(getattr(plain.cycle, name), getattr(zero.cycle, name))


def test_tilt_table_and_reliefs_in_outputs(tmp_path):
    """Tilt table and crush/end reliefs: cycle.csv has the tilt, moments and where h_min sits,
    summary.json and the headline the edge h_min and the moments."""
    from conrod.output.registry import write_results
    from conrod.results.summary import headline

    reliefs = ("[bearing.profile]\ncrush_relief_depth = 8e-6\ncrush_relief_extent = 20.0\n"
               "end_relief_depth = 3e-6\nend_relief_length = 0.003")
    case = write_case(tmp_path, reliefs, '[misalignment]\ntable = "tilt.csv"')
    results = Simulation(case).run()
    axial = results.cycle.axial
    assert np.abs(axial["tilt_y"] - 5e-5).max() < 1e-12
    assert np.all(axial["edge_h_min"] >= results.cycle.h_min - 1e-15)
    write_results(results, tmp_path / "out", figures=False)
    with open(tmp_path / "out" / "cycle.csv", encoding="utf-8") as handle:
        header = next(csv.reader(handle))
    for column in ("tilt_x_rad", "moment_x_N_m", "moment_y_N_m", "h_min_axial_position_m",
                   "h_min_at_edge", "edge_h_min_m"):
        assert column in header
    summary = json.loads((tmp_path / "out" / "summary.json").read_text(encoding="utf-8"))
    assert summary["edge_h_min_m"] == pytest.approx(float(axial["edge_h_min"].min()))
    lines = headline(results)
    assert "edge h_min" in lines and "moments" in lines and "N m" in lines["moments"]


def test_misalignment_and_profile_inputs_are_checked(tmp_path):
    with pytest.raises(CaseError, match="misalignment.tilt_x"):
        write_case(tmp_path, extra='[misalignment]\nmode = "free"\ntilt_x = 1e-4')
    with pytest.raises(CaseError, match="crush_relief_extent"):
        write_case(tmp_path, "[bearing.profile]\ncrush_relief_depth = 1e-5")
    (tmp_path / "profile.csv").write_text("angle_deg,offset_m\n0,0\n90,0\n")
    with pytest.raises(CaseError, match="axial_position_m"):
        write_case(tmp_path, 'profile_file = "profile.csv"')
    _register_commands()
    result = CliRunner().invoke(app, ["run", str(tmp_path / "case.toml"), "--out",
                                      str(tmp_path / "x"), "--film", "short"])
    assert result.exit_code == 2 and "axial_position_m" in result.output


@pytest.mark.slow
def test_shipped_tilt_example_runs_coarsened(tmp_path):
    """The KamAZ-740-like example with the crank-pin tilt table and the shell reliefs runs on
    its elastic big end (coarsened: 24 x 8, one cycle): tilt from the table, moments, the
    edge h_min in the headline."""
    from pathlib import Path

    from conrod.results.summary import headline

    path = Path(__file__).resolve().parents[1] / "examples" / "kamaz_740_truck_diesel_tilt.toml"
    results = Simulation(Case.from_toml(path), n_theta=24, n_z=8, max_cycles=1,
                         rigid_companion=False).run()
    elastic = getattr(results, "elastic", results)
    axial = elastic.cycle.axial
    assert 1.0e-4 < np.abs(axial["tilt_y"]).max() < 2.0e-4  # the table: 0.15 mrad at firing
    assert np.hypot(axial["moment_x"], axial["moment_y"]).max() > 10.0  # [N m]
    assert "edge h_min" in headline(elastic) and elastic.summary.h_min > 0.0


def test_tilt_tables_and_turning_shells_are_checked(tmp_path):
    """A tilt table out of order names its file; a profile on a shell that turns in the
    film frame is refused (the profile is fixed in that frame)."""
    case = write_case(tmp_path, extra='[misalignment]\ntable = "tilt.csv"')
    (tmp_path / "tilt.csv").write_text("crank_angle_deg,tilt_x_rad,tilt_y_rad\n0,0,0\n90,0,0\n"
                                       "60,0,0\n120,0,0\n")
    with pytest.raises(CaseError, match="tilt.csv.*strictly increasing"):
        Simulation(case).run()
    (tmp_path / "tilt.csv").write_text("crank_angle_deg,tilt_x_rad,tilt_y_rad\n0,0.5,0\n90,0,0\n"
                                       "180,0,0\n270,0,0\n")
    with pytest.raises(CaseError, match="0.01 rad"):
        Simulation(case).run()
    turning = write_case(tmp_path, "[bearing.profile]\ncrown = 2e-6").with_(
        load__shell_speed=10.0)
    with pytest.raises(CaseError, match="shell speed"):
        Simulation(turning).run()
