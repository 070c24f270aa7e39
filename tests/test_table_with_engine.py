"""A ``[load]`` table beside ``[engine]``: the table is the bearing load, ``[engine]`` the
crank train (the rod's inertia deformation of an elastic big end)."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.housing.build import crank_kinematics
from conrod.simulation.simulation import Simulation
from elastic_helpers import EXAMPLES


def _ruston_hornsby_with_engine(**engine) -> Case:
    """The Ruston & Hornsby example plus the crank train its load table was made from."""
    data = tomllib.loads((EXAMPLES / "ruston_hornsby_6vebx_mk3.toml").read_text())
    train = tomllib.loads((EXAMPLES / "data" / "ruston_hornsby_engine_assumed.toml").read_text())
    data["engine"] = {**train["engine"], **engine}
    return Case.from_dict(data, base_dir=EXAMPLES)


def test_the_table_is_the_load_and_the_engine_the_crank_train():
    case = _ruston_hornsby_with_engine()
    plain = Case.from_dict(tomllib.loads((EXAMPLES / "ruston_hornsby_6vebx_mk3.toml")
                                         .read_text()), base_dir=EXAMPLES)
    with_engine, table_only = Simulation(case).load_cycle(), Simulation(plain).load_cycle()
    np.testing.assert_array_equal(with_engine.load_x, table_only.load_x)
    np.testing.assert_array_equal(with_engine.load_y, table_only.load_y)
    kinematics = crank_kinematics(case)
    assert crank_kinematics(plain) is None
    assert kinematics is not None  # the elastic big end gets its inertia fields
    np.testing.assert_allclose([kinematics.crank_speed, kinematics.crank_radius],
                               [600.0 * np.pi / 30.0, 0.3683 / 2.0], rtol=1e-12)


def test_table_and_engine_at_different_speeds_are_refused():
    with pytest.raises((CaseError, ValueError), match=r"engine\.speed = 650\.0.*load\.speed = 600"):
        _ruston_hornsby_with_engine(speed=650.0)


def test_loads_command_writes_the_table(tmp_path):
    """`conrod loads` on a case with both sections writes the table's load (as `run` uses),
    not the engine loads."""
    import pandas as pd
    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app
    from hardening_helpers import write_case

    data = tomllib.loads((EXAMPLES / "ruston_hornsby_6vebx_mk3.toml").read_text())
    train = tomllib.loads((EXAMPLES / "data" / "ruston_hornsby_engine_assumed.toml").read_text())
    data["engine"] = train["engine"]
    data["load"]["table"] = str(EXAMPLES / data["load"]["table"])
    path = write_case(tmp_path, data, "both.toml")
    _register_commands()
    result = CliRunner().invoke(app, ["loads", str(path), "--out", str(tmp_path / "out")])
    assert result.exit_code == 0, result.output
    written = pd.read_csv(tmp_path / "out" / "loads.csv")
    table = pd.read_csv(EXAMPLES / data["load"]["table"], comment="#")
    peak_written = float(np.max(np.hypot(written.filter(like="load_x").iloc[:, 0],
                                         written.filter(like="load_y").iloc[:, 0])))
    peak_table = float(np.max(np.hypot(table.filter(like="load_x").iloc[:, 0],
                                       table.filter(like="load_y").iloc[:, 0])))
    assert peak_written == pytest.approx(peak_table, rel=1e-9)
