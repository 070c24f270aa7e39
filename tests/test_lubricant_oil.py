"""Oil from its data sheet: Walther law, density table, SAE J300 grade file, [lubricant]."""

from __future__ import annotations

import math

import pytest

from conrod.cases.base import validate_section
from conrod.cases.lubricant import LubricantSection
from conrod.errors import CaseError
from conrod.oil import LUBE_OIL_K1, WaltherLaw, density_at, oil_grades


def lubricant(**fields) -> LubricantSection:
    return validate_section(LubricantSection, fields, "lubricant")


@pytest.mark.parametrize("nu40, nu100", [(64.0, 10.9), (32.0, 5.4), (220.0, 19.0)])
def test_walther_reproduces_both_data_sheet_points(nu40, nu100):
    law = WaltherLaw(nu40, nu100)
    assert law.kinematic_viscosity(40.0) == pytest.approx(nu40, rel=1e-12)
    assert law.kinematic_viscosity(100.0) == pytest.approx(nu100, rel=1e-12)


def test_walther_is_a_straight_line_on_the_astm_d341_chart():
    """log log(ν + 0.7) is linear in log T [K] (ASTM D341's defining property): the chart
    coordinates of 20, 60, 150 °C lie on the line through 40 and 100 °C."""
    law = WaltherLaw(64.0, 10.9)
    points = [(math.log10(t + 273.15), math.log10(math.log10(law.kinematic_viscosity(t) + 0.7)))
              for t in (20.0, 40.0, 60.0, 100.0, 150.0)]
    (x0, y0), (x1, y1) = points[1], points[3]
    for x, y in points:
        assert y == pytest.approx(y0 + (y1 - y0) * (x - x0) / (x1 - x0), abs=1e-12)


def test_density_table_value_and_expansion_coefficient():
    """ρ(15 °C) = ρ₁₅ and −dρ/dT/ρ at 15 °C = K₁/ρ₁₅ (lubricating-oil table)."""
    assert density_at(860.0, 15.0) == 860.0
    slope = (density_at(860.0, 15.5) - density_at(860.0, 14.5)) / 1.0
    assert -slope / 860.0 == pytest.approx(LUBE_OIL_K1 / 860.0, rel=1e-6)
    assert 780.0 < density_at(850.0, 120.0) < 800.0  # engine oils lose ~7 % by 120 °C


@pytest.mark.parametrize("grade", sorted(oil_grades()))
def test_grade_file_is_consistent_with_sae_j300(grade):
    """Typical values inside the J300 kinematic band; the Walther low-shear viscosity at
    150 °C is at least the J300 high-shear minimum (shear thinning only lowers it)."""
    row = oil_grades()[grade]
    assert row.kv100_min <= row.viscosity_100 < row.kv100_max
    assert row.viscosity_40 > row.viscosity_100
    mu_150 = WaltherLaw(row.viscosity_40, row.viscosity_100).kinematic_viscosity(150.0) * (
        density_at(row.density_15, 150.0) * 1e-3)
    assert mu_150 >= row.hths_min
    assert row.source and row.basis.startswith("assumed typical")


def test_lubricant_from_grade_and_from_data_sheet():
    by_grade = lubricant(grade="5w-30")
    row = oil_grades()["5W-30"]
    sheet = lubricant(kinematic_viscosity_40C=row.viscosity_40,
                      kinematic_viscosity_100C=row.viscosity_100, density_15C=row.density_15)
    for temperature in (40.0, 100.0, 120.0):
        assert by_grade.viscosity_at(temperature) == sheet.viscosity_at(temperature)
    expected = row.viscosity_100 * 1e-6 * density_at(row.density_15, 100.0)
    assert sheet.viscosity_at(100.0) == pytest.approx(expected, rel=1e-12)
    assert sheet.temperature_dependent and sheet.density_at(15.0) == row.density_15


@pytest.mark.parametrize("fields, match", [
    ({"grade": "7W-33"}, "lubricant.grade"),
    ({"kinematic_viscosity_40C": 64.0, "kinematic_viscosity_100C": 10.9}, "density_15C"),
    ({"kinematic_viscosity_40C": 9.0, "kinematic_viscosity_100C": 10.9, "density_15C": 850.0},
     "kinematic_viscosity_100C"),
    ({"viscosity": 0.01, "grade": "5W-30"}, "exactly one"),
    ({"viscosity": 0.01, "pressure_viscosity": "barus"}, "pressure_viscosity_coefficient"),
    ({"viscosity": 0.01, "pressure_viscosity": "roelands"}, "roelands_index"),
    ({"viscosity": 0.01, "pressure_viscosity_coefficient": 2e-8}, "only used"),
])
def test_bad_lubricant_input_is_one_line_case_error(fields, match):
    with pytest.raises(CaseError, match=match) as error:
        lubricant(**fields)
    assert "\n" not in str(error.value)


def test_pressure_viscosity_law_from_the_section():
    assert lubricant(viscosity=0.01).pressure_viscosity_law() is None
    law = lubricant(viscosity=0.01, pressure_viscosity="barus",
                    pressure_viscosity_coefficient=1.6e-8).pressure_viscosity_law()
    assert law.law == "barus" and law.coefficient == 1.6e-8 and law.limit_pressure == 1e9


def test_heat_balance_iterates_with_the_walther_law(repo):
    """A grade oil makes the viscosity temperature-dependent: the heat-balance loop runs,
    ends at μ(T) of the data-sheet law and satisfies N̄ = ρ(T_s) c_p Q̄ (T_eff − T_s)."""
    import tomllib

    from conrod.cases.case import Case
    from conrod.simulation.simulation import Simulation

    path = repo / "examples" / "passenger_car_diesel_2000rpm.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["lubricant"] = {"grade": "5W-30", "supply_temperature": 100.0}
    case = Case.from_dict(data, base_dir=path.parent, path=path)
    summary = Simulation(case).run().summary
    oil = case.lubricant
    assert summary.thermal_iterations >= 1
    t_eff = summary.effective_temperature
    slope = abs(oil.viscosity_at(t_eff + 0.5) - oil.viscosity_at(t_eff - 0.5))
    assert abs(summary.viscosity - oil.viscosity_at(t_eff)) <= (
        slope * case.solver.thermal_tolerance * 4.0)
    heat = oil.density_at(100.0) * oil.specific_heat * summary.mean_side_flow
    assert summary.mean_friction_power == pytest.approx(heat * (t_eff - 100.0), rel=1e-9)
