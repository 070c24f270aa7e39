"""Steady calculator: default-grid accuracy (Richardson), dimensional mode, CLI."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from conrod.cli import steady_command
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry
from conrod.film.steady import default_grid, raimondi_boyd_point, solve_for_load

CHECKED = ("sommerfeld_number", "friction_variable", "attitude_angle_deg", "flow_variable",
           "side_flow_ratio", "load_to_peak_pressure_ratio")


def richardson(coarse: float, medium: float, fine: float) -> float:
    """Grid-converged value from three grids halving h, with the observed order
    p = log2((coarse − medium)/(medium − fine)) (p = 2 if the differences are tiny)."""
    lower, upper = coarse - medium, medium - fine
    order = 2.0
    if abs(upper) > 1e-12 * abs(fine) and lower / upper > 1.0:
        order = float(np.clip(math.log2(lower / upper), 1.0, 4.0))
    return fine + (fine - medium) / (2.0**order - 1.0)


def assert_default_grid_within_half_percent(ratio: float, eps: float) -> None:
    n_theta, n_z = default_grid(eps)
    points = [raimondi_boyd_point(ratio, eps, grid=(n_theta * k, n_z * k)) for k in (1, 2, 4)]
    for name in CHECKED:
        values = [getattr(point, name) for point in points]
        converged = richardson(*values)
        assert abs(values[0] - converged) <= 0.005 * abs(converged), name


@pytest.mark.parametrize(("ratio", "eps"), [(1.0, 0.8), (0.5, 0.4), (0.25, 0.9)])
def test_default_grid_is_within_half_percent_of_converged(ratio, eps):
    assert_default_grid_within_half_percent(ratio, eps)


@pytest.mark.slow
def test_default_grid_within_half_percent_at_high_eccentricity():
    assert_default_grid_within_half_percent(1.0, 0.95)


def test_dimensional_mode_inverts_the_dimensionless_point():
    """W from S at ε = 0.7 (L/D = 1) must give back ε = 0.7 and the same attitude."""
    point = raimondi_boyd_point(1.0, 0.7)
    geometry = BearingGeometry(diameter=0.05, width=0.05, radial_clearance=4.0e-5)
    radius, clearance = geometry.radius, geometry.radial_clearance
    speed = 2.0 * math.pi * 50.0
    viscosity = 0.015
    load = ((radius / clearance) ** 2 * viscosity * 50.0 / point.sommerfeld_number
            * geometry.diameter * geometry.width)
    answer = solve_for_load(load, speed, viscosity, geometry)
    assert answer.eccentricity == pytest.approx(0.7, abs=1e-6)
    assert answer.attitude_angle_deg == pytest.approx(point.attitude_angle_deg, abs=1e-4)
    assert answer.min_film_thickness == pytest.approx(0.3 * clearance, rel=1e-5)
    friction = point.friction_variable * clearance / radius * load
    assert answer.friction_power == pytest.approx(friction * radius * speed, rel=1e-4)
    assert answer.side_flow == pytest.approx(
        point.side_flow_ratio * answer.inlet_flow, rel=1e-6)


def test_dimensional_mode_rejects_load_beyond_capacity():
    geometry = BearingGeometry(diameter=0.05, width=0.05, radial_clearance=4.0e-5)
    with pytest.raises(CaseError, match="film capacity"):
        solve_for_load(1e12, 300.0, 0.01, geometry)


@pytest.fixture
def cli() -> typer.Typer:
    app = typer.Typer()

    @app.callback()
    def _group() -> None:
        """conrod (test)."""

    steady_command.register(app)
    return app


def test_cli_prints_raimondi_boyd_keys_as_json(cli):
    result = CliRunner().invoke(cli, ["steady", "--length-to-diameter", "1",
                                      "--eccentricity", "0.8", "--grid", "72x16", "--json"])
    assert result.exit_code == 0, result.output
    values = json.loads(result.output)
    for key in ("sommerfeld_number", "attitude_angle_deg", "friction_variable",
                "flow_variable", "side_flow_ratio", "load_to_peak_pressure_ratio",
                "peak_pressure_angle_deg", "film_end_angle_deg"):
        assert math.isfinite(values[key])
    assert values["sommerfeld_number"] == pytest.approx(0.0446, rel=0.02)


def test_cli_short_model_and_dimensional_mode(cli):
    runner = CliRunner()
    short = runner.invoke(cli, ["steady", "--length-to-diameter", "0.25", "--eccentricity",
                                "0.5", "--model", "short", "--json"])
    assert short.exit_code == 0, short.output
    assert json.loads(short.output)["model"] == "short"
    sized = runner.invoke(cli, ["steady", "--load", "5000", "--speed-rpm", "3000",
                                "--viscosity", "0.01", "--diameter", "0.05", "--width",
                                "0.025", "--radial-clearance", "4e-5", "--json"])
    assert sized.exit_code == 0, sized.output
    assert 0.0 < json.loads(sized.output)["eccentricity"] < 1.0


@pytest.mark.parametrize("arguments", [
    ["--length-to-diameter", "1", "--eccentricity", "1.5"],
    ["--length-to-diameter", "1", "--eccentricity", "0.5", "--grid", "7x3"],
    ["--load", "100"],
])
def test_cli_bad_input_exits_with_code_2(cli, arguments):
    result = CliRunner().invoke(cli, ["steady", *arguments])
    assert result.exit_code == 2
    assert "Traceback" not in result.output
    assert "error:" in result.output
