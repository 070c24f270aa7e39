"""Raimondi & Boyd (1958) published S and (R/c)f, 21 rows, within 1.5 %.

The two ε = 0.97 rows at L/D = 0.5 and 0.25 are not reached: the grid-converged FD
answer (576×128) differs from the published numbers by +2.0 % / +1.6 % (L/D = 0.5:
S = 0.006209, (R/c)f = 0.6200) and +3.1 % / +3.0 % (L/D = 0.25: S = 0.01041,
(R/c)f = 0.9497); the data file's own FD cross-check notes the same rows. They are
strict expected failures, not widened tolerances.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import pytest

from conrod.film.steady import raimondi_boyd_point

TABLE = Path(__file__).resolve().parent / "data" / "raimondi_boyd_S_rcf_published.csv"
"""Verbatim copy of ../shared/data/raimondi_boyd_S_rcf_published.csv (provenance inside)."""
TOLERANCE = 0.015
NOT_REACHED = {(0.5, 0.97), (0.25, 0.97)}


def published_rows() -> list:
    """Rows of the published table as pytest params."""
    with TABLE.open() as handle:
        lines = [line for line in handle if not line.startswith("#")]
    params = []
    for row in csv.DictReader(lines):
        ratio, eps = float(row["L_over_D"]), float(row["eps"])
        marks = []
        if (ratio, eps) in NOT_REACHED:
            marks = [pytest.mark.xfail(strict=True, reason="converged FD differs > 1.5 %")]
        params.append(pytest.param(ratio, eps, float(row["S"]), float(row["rc_f"]),
                                   marks=marks, id=f"LD{ratio}-eps{eps}"))
    return params


ROWS = published_rows()


def test_table_has_21_rows():
    assert len(ROWS) == 21


@pytest.mark.parametrize(("ratio", "eps", "sommerfeld", "friction"), ROWS)
def test_sommerfeld_and_friction_variable(ratio, eps, sommerfeld, friction):
    point = raimondi_boyd_point(ratio, eps)
    assert point.sommerfeld_number == pytest.approx(sommerfeld, rel=TOLERANCE)
    assert point.friction_variable == pytest.approx(friction, rel=TOLERANCE)


@pytest.mark.parametrize("ratio", [1.0, 0.5, 0.25])
@pytest.mark.parametrize("eps", [0.2, 0.6, 0.9])
def test_friction_variable_identity(ratio, eps):
    """Torque balance of the rigid bearing: (R/c)f = 2π²S/√(1−ε²) + ε sin φ/2 [Raimondi–Boyd]."""
    point = raimondi_boyd_point(ratio, eps, grid=(72, 16))
    expected = (2 * math.pi**2 * point.sommerfeld_number / math.sqrt(1 - eps**2)
                + 0.5 * eps * math.sin(math.radians(point.attitude_angle_deg)))
    assert point.friction_variable == pytest.approx(expected, rel=1e-3)


def test_concentric_limit_of_flows():
    """ε → 0: Q/(RcNL) → π (Couette flow of the concentric gap), Q_s/Q → 0."""
    point = raimondi_boyd_point(1.0, 0.005)
    assert point.flow_variable == pytest.approx(math.pi, rel=0.01)
    assert point.side_flow_ratio < 0.01
