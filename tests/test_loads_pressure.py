"""Cylinder pressure: seed-003 parametric model in closed form, trace reading and checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.loads.kinematics import piston_displacement_series
from conrod.loads.pressure import build_pressure, read_pressure_trace
from loads_helpers import BEARING, ENGINE, write_trace

MODEL = {
    "compression_ratio": 17.0,
    "intake_pressure": 0.09e6,
    "max_pressure": 9.0e6,
    "exhaust_pressure": 0.11e6,
    "max_pressure_duration": 15.0,
    "compression_index": 1.35,
    "expansion_index": 1.25,
    "ambient_pressure": 0.1e6,
}


def model_case(**changes) -> Case:
    engine = {**ENGINE, "pressure_model": {**MODEL, **changes}}
    return Case.from_dict({"engine": engine, "bearing": BEARING})


def test_parametric_model_closed_form_values():
    """Values at the phase boundaries of seed 003 (with S_c = S_p/(ε − 1))."""
    pressure = build_pressure(model_case())
    r, length = ENGINE["stroke"] / 2, ENGINE["rod_length"]
    p_c = 0.09e6 * 17.0**1.35
    deg = np.radians
    values = pressure.absolute(deg(np.array([0.0, 15.0, 20.0, 30.0, 200.0, 450.0, 540.0])))
    assert values[0] == pytest.approx(p_c, rel=1e-12)  # end of compression = start of rise
    assert values[1:4] == pytest.approx([9.0e6] * 3, rel=1e-12)  # plateau 15°..30°
    assert values[4:] == pytest.approx([0.11e6, 0.09e6, 0.09e6], rel=1e-12)
    s_c = 2 * r / 16.0
    s = lambda a: piston_displacement_series(deg(a), r, length)  # noqa: E731
    expected_100 = 9.0e6 * ((s_c + s(30.0)) / (s_c + s(100.0))) ** 1.25
    expected_630 = 0.09e6 * ((s_c + 2 * r) / (s_c + s(630.0))) ** 1.35
    assert pressure.absolute(deg(100.0)) == pytest.approx(expected_100, rel=1e-12)
    assert pressure.absolute(deg(630.0)) == pytest.approx(expected_630, rel=1e-12)
    # continuous at the closing of the cycle (compression end = p_c) and periodic over 4π
    assert pressure.absolute(deg(720.0 - 1e-9)) == pytest.approx(p_c, rel=1e-8)
    assert pressure.absolute(deg(-90.0)) == pytest.approx(pressure.absolute(deg(630.0)))
    assert pressure.gauge(deg(450.0)) == pytest.approx(0.09e6 - 0.1e6)


def test_parametric_model_rejects_peak_below_compression_pressure():
    with pytest.raises(CaseError, match=r"max_pressure = 1000000.0.*>= compression-end"):
        build_pressure(model_case(max_pressure=1.0e6))


def trace_engine_case(folder, **engine) -> Case:
    return Case.from_dict(
        {"engine": {**ENGINE, "pressure_trace": "p.csv", **engine}, "bearing": BEARING},
        base_dir=folder,
    )


def test_trace_is_interpolated_periodically_with_ambient(tmp_path):
    angles = np.arange(0.0, 720.0, 5.0)
    write_trace(tmp_path / "p.csv", angles, 2e5 + 1e3 * angles)
    pressure = build_pressure(trace_engine_case(tmp_path, ambient_pressure=0.9e5))
    assert pressure.absolute(math.radians(2.5)) == pytest.approx(2e5 + 2.5e3)
    # between 715° and 720° (= 0°) the interpolation wraps to the first row
    assert pressure.absolute(math.radians(717.5)) == pytest.approx(0.5 * (2e5 + 715e3 + 2e5))
    assert pressure.gauge(math.radians(725.0)) == pytest.approx(2e5 + 5e3 - 0.9e5)
    assert pressure.ambient == 0.9e5


def test_trace_with_duplicate_720_row_is_accepted(tmp_path):
    angles = np.arange(0.0, 721.0, 10.0)
    write_trace(tmp_path / "p.csv", angles, np.full(angles.shape, 3e5))
    read_angles, _ = read_pressure_trace(tmp_path / "p.csv")
    assert read_angles[-1] == 710.0


@pytest.mark.parametrize(
    ("rows", "message"),
    [
        ([(a, 1e5) for a in range(0, 361)], r"covers only 0\.\.360 deg.*missing angles"),
        (
            [(0, 1e5), (1, float("nan"))] + [(a, 1e5) for a in range(2, 720)],
            r"line 4: pressure_Pa = nan",
        ),
        (
            [(a, 1e5) for a in range(0, 300)] + [(a, 1e5) for a in range(340, 720)],
            r"missing angles: gap of 41 deg from 299 to 340",
        ),
        (
            [(0, 1e5), (2, 1e5), (1, 1e5)] + [(a, 1e5) for a in range(3, 720)],
            r"line 5: crank_angle_deg = 1 is not above",
        ),
        ([(0, -5.0)] + [(a, 1e5) for a in range(1, 720)], r"line 3: pressure_Pa = -5 must be > 0"),
    ],
    ids=["half-cycle", "nan", "gap", "not-increasing", "negative"],
)
def test_bad_traces_name_file_row_and_value(tmp_path, rows, message):
    write_trace(tmp_path / "p.csv", [r[0] for r in rows], [r[1] for r in rows])
    with pytest.raises(CaseError, match=message) as error:
        build_pressure(trace_engine_case(tmp_path))
    assert "p.csv" in str(error.value)


def test_trace_missing_column_and_missing_file(tmp_path):
    (tmp_path / "p.csv").write_text("angle,pressure_Pa\n0,1e5\n", encoding="utf-8")
    with pytest.raises(CaseError, match="missing column 'crank_angle_deg'"):
        build_pressure(trace_engine_case(tmp_path))
    (tmp_path / "p.csv").unlink()
    with pytest.raises(CaseError, match="cannot be read"):
        build_pressure(trace_engine_case(tmp_path))
