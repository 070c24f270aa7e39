"""The elastohydrodynamic orbit of the KamAZ-740 example against independent answers."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.housing.housing import Housing
from conrod.output.ehd_tables import elastic_summary_items
from conrod.results.ehd import ElasticRunResults
from conrod.simulation.simulation import Simulation
from elastic_helpers import kamaz_case

GRID = {"n_theta": 36, "n_z": 8, "film": "reynolds", "integrator": "quasi_static",
        "quasi_static_step_deg": 2.0, "output_step_deg": 4.0}


def _scaled(housing: Housing, factor: float) -> Housing:
    """The same rod with Young's modulus × ``factor`` (displacements / factor, linear)."""
    return Housing(housing.angles, housing.radius, housing.compliance / factor,
                   housing.inertia_base / factor, housing.correction, housing.kinematics)


@pytest.fixture(scope="module")
def stiff_run() -> ElasticRunResults:
    case = kamaz_case(**GRID)
    return Simulation(case, housing=_scaled(Housing.from_case(case), 1e4)).run()


def test_stiff_limit_reproduces_the_rigid_orbit(stiff_run):
    """Modulus × 1e4: h_min and p_max of the rigid companion within 0.2 %; the rigid
    companion runs the massless journal the elastic run was asked for (the journal with
    mass: tests/test_ehd_with_mass.py)."""
    assert isinstance(stiff_run, ElasticRunResults) and stiff_run.rigid is not None
    elastic, rigid = stiff_run.elastic.summary, stiff_run.rigid.summary
    assert "quasi_static" in elastic.integrator and "quasi_static" in rigid.integrator
    assert elastic.h_min == pytest.approx(rigid.h_min, rel=2e-3)
    assert elastic.p_max == pytest.approx(rigid.p_max, rel=2e-3)
    assert np.max(np.abs(stiff_run.cycle.h_min - stiff_run.rigid.cycle.h_min)) <= (
        2e-3 * rigid.h_min)


def test_diagnostics_are_reported_per_crank_angle(stiff_run):
    columns = stiff_run.columns
    n = len(stiff_run.cycle.crank_angle)
    for name in ("coupling_iterations", "force_residual_N", "deformation_increment_m",
                 "bore_displacement_min_m", "bore_displacement_max_m"):
        assert columns[name].shape == (n,) and np.all(np.isfinite(columns[name]))
    load = np.hypot(stiff_run.cycle.load_x, stiff_run.cycle.load_y)
    # the massless balance holds at every output angle (orbit tolerance 1e-9 of the load)
    assert np.all(columns["force_residual_N"] <= 1e-6 * (load + 1.0))
    # bore displacement of the stiff rod: 1e-4 of the estimated rod's, i.e. nanometres
    assert np.max(np.abs(stiff_run.deformation)) < 1e-7
    items = elastic_summary_items(stiff_run)
    assert set(items["comparison"]) == {"rigid", "elastic", "difference_percent", "units",
                                        "firing_stroke", "bore_displacement_at_elastic_h_min"}


def test_results_folder_holds_elastic_rigid_and_comparison(stiff_run, tmp_path):
    import json

    import pandas as pd

    import conrod.output  # noqa: F401  (registers the tables and figures)
    from conrod.output.registry import write_results

    write_results(stiff_run, tmp_path)
    cycle = pd.read_csv(tmp_path / "cycle.csv")
    rigid = pd.read_csv(tmp_path / "cycle_rigid.csv")
    assert {"coupling_iterations", "force_residual_N", "deformation_increment_m",
            "bore_displacement_min_m", "bore_displacement_max_m"} <= set(cycle.columns)
    assert len(rigid) == len(cycle)
    summary = json.loads((tmp_path / "summary.json").read_text())
    comparison = summary["comparison"]
    assert comparison["rigid"]["h_min_um"] == pytest.approx(
        stiff_run.rigid.summary.h_min * 1e6)
    assert abs(comparison["difference_percent"]["h_min_um"]) < 0.2
    manifest = json.loads((tmp_path / "manifest.json").read_text())
    files = {entry["file"] for entry in manifest["figures"]}
    assert {"hmin_pmax_rigid_elastic.png", "deformed_bore.png",
            "deformed_film_maps.png"} <= files
    assert all((tmp_path / name).stat().st_size > 0 for name in files)
