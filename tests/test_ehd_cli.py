"""`conrod run` with an elastic housing: --no-rigid, the integrators that run it and the
exit code of a failed coupling."""

from __future__ import annotations

import json
import tomllib

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.ehd.bore_system import STEP_FORCE_TOLERANCE
from conrod.housing.housing import Housing
from elastic_helpers import EXAMPLES, kamaz_case

_register_commands()


def _case_file(folder, stiffening: float, **housing) -> str:
    """KamAZ bearing and engine, the built-in rod's compliance / ``stiffening`` imported."""
    built = Housing.from_case(kamaz_case(n_theta=36), use_cache=False)
    np.savez(folder / "c.npz", angle_deg=np.degrees(built.angles),
             compliance_m_per_N=built.compliance / stiffening)
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data["housing"] = {"model": "compliance", "compliance_file": str(folder / "c.npz"),
                       **housing}
    data["solver"] = {"film": "reynolds", "integrator": "quasi_static", "n_theta": 36,
                      "n_z": 8, "quasi_static_step_deg": 2.0, "output_step_deg": 4.0}
    lines = []
    for section, values in data.items():
        if isinstance(values, dict):
            continue
        lines.append(f"{section} = {json.dumps(values)}")
    for section, values in data.items():
        if isinstance(values, dict):
            lines.append(f"[{section}]")
            lines += [f"{k} = {json.dumps(v)}" for k, v in values.items()
                      if not isinstance(v, dict)]
            for sub, inner in values.items():
                if isinstance(inner, dict):
                    lines.append(f"[{section}.{sub}]")
                    lines += [f"{k} = {json.dumps(v)}" for k, v in inner.items()]
    path = folder / "case.toml"
    path.write_text("\n".join(lines) + "\n")
    return str(path)


@pytest.fixture
def runner() -> CliRunner:
    return CliRunner()


def test_no_rigid_skips_the_companion(runner, tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", _case_file(tmp_path, 1e4), "--out", str(out),
                                 "--no-rigid", "--no-figures"])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert "elastic" in summary and "comparison" not in summary
    assert not (out / "cycle_rigid.csv").exists()


def test_a_coupling_that_does_not_converge_exits_3_naming_the_crank_angle(runner, tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", _case_file(tmp_path, 1.0, coupling_iterations=2),
                                 "--out", str(out), "--no-rigid"])
    assert result.exit_code == 3, result.output
    assert "crank angle" in result.output and "did not converge" in result.output
    assert not out.exists() or not any(out.iterdir())


@pytest.mark.parametrize("integrator", ["implicit", "adaptive"])
def test_the_with_mass_integrators_run_the_elastic_bore(runner, tmp_path, integrator):
    """implicit and adaptive run the journal with mass on the elastic bore (fixed BDF2
    steps of the journal and the bore together): periodic, and the step's force balance
    F + W − m a holds at every output angle within its tolerance (each component within
    :data:`~conrod.ehd.bore_system.STEP_FORCE_TOLERANCE` of |W| + 1 N)."""
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", _case_file(tmp_path, 1e4), "--out", str(out),
                                 "--integrator", integrator, "--no-rigid", "--no-figures"])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["integrator"] == integrator and summary["periodic"]
    cycle = pd.read_csv(out / "cycle.csv")
    size = np.hypot(cycle["load_x_N"], cycle["load_y_N"]) + 1.0
    assert np.all(cycle["force_residual_N"] <= np.sqrt(2.0) * STEP_FORCE_TOLERANCE * size)


def test_rk2_is_refused_before_the_run_naming_the_working_integrators(runner, tmp_path):
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", _case_file(tmp_path, 1e4), "--out", str(out),
                                 "--integrator", "rk2"])
    assert result.exit_code == 2, result.output
    assert "solver.integrator = 'rk2'" in result.output
    assert "implicit" in result.output and "quasi_static" in result.output
    assert not out.exists() or not any(out.iterdir())


@pytest.mark.slow
def test_ruston_hornsby_runs_the_elastic_bore_with_its_case_integrator(runner, tmp_path):
    """The shipped Ruston & Hornsby case asks for the adaptive integrator: with the
    Reynolds film it runs the journal with mass on its elastic rod as it stands."""
    out = tmp_path / "out"
    result = runner.invoke(app, ["run", str(EXAMPLES / "ruston_hornsby_6vebx_mk3.toml"),
                                 "--film", "reynolds", "--grid", "36x8", "--out", str(out),
                                 "--no-rigid", "--no-figures"])
    assert result.exit_code == 0, result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["integrator"] == "adaptive" and summary["periodic"]
    assert summary["elastic"]["max_coupling_residual_m"] <= summary["elastic"][
        "coupling_tolerance_m"]
    cycle = pd.read_csv(out / "cycle.csv")
    size = np.hypot(cycle["load_x_N"], cycle["load_y_N"]) + 1.0
    assert np.all(cycle["force_residual_N"] <= np.sqrt(2.0) * STEP_FORCE_TOLERANCE * size)
