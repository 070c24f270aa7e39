"""analyse_contact on a stand-in cycle: intervals, summary keys, files, Greenwood–Tripp mode."""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.contact.analysis import analyse_contact, contact_intervals
from conrod.contact.asperity import asperity_force, kernel_parameters
from conrod.errors import CaseError
from conrod.io.atomic import write_json

CYCLE = 4.0 * math.pi
PHI = np.arange(720) * CYCLE / 720
CLEARANCE = 30e-6


@dataclass
class StandInCycle:
    """The CycleResults fields analyse_contact reads (docs/orbit.md), SI units."""

    crank_angle: np.ndarray
    contact_force: np.ndarray
    friction_force: np.ndarray
    contact_angle: np.ndarray
    journal_rotation: np.ndarray
    eccentricity_x: np.ndarray
    eccentricity_y: np.ndarray
    load_x: np.ndarray
    load_y: np.ndarray
    h_min: np.ndarray
    p_max: np.ndarray
    in_contact: np.ndarray
    sliding_speed: np.ndarray


def _case(**contact) -> Case:
    return Case.from_dict({
        "bearing": {"diameter": 0.06, "width": 0.025, "radial_clearance": CLEARANCE},
        "contact": contact,
    })


def _combustion_cycle(gap_in_contact: float = 0.0) -> StandInCycle:
    deg = np.degrees(PHI)
    force = np.where((deg > 370) & (deg < 452), 2.0e4 * np.sin(np.pi * (deg - 370) / 82), 0.0)
    angle = np.full(PHI.size, math.pi / 2)
    e = np.where(force > 0, CLEARANCE - gap_in_contact, 0.5 * CLEARANCE)
    return StandInCycle(
        crank_angle=PHI, contact_force=force, friction_force=0.1 * force, contact_angle=angle,
        journal_rotation=PHI - 0.3 * np.sin(PHI), eccentricity_x=e * np.cos(angle),
        eccentricity_y=e * np.sin(angle), load_x=np.zeros(PHI.size), load_y=force + 5.0e3,
        h_min=CLEARANCE - e, p_max=np.full(PHI.size, 5.0e7), in_contact=force > 0.0,
        sliding_speed=np.full(PHI.size, 2.0),
    )


def test_contact_intervals_edges_and_wrap():
    force = np.where(np.degrees(PHI) > 700.5, 1.0, 0.0) + np.where(np.degrees(PHI) < 29.5, 1.0, 0.0)
    (start, end), = contact_intervals(PHI, force, 0.5, CYCLE)
    assert math.degrees(start) == pytest.approx(700.5)
    assert math.degrees(end) == pytest.approx(720.0 + 29.5)
    assert contact_intervals(PHI, np.zeros(PHI.size), 0.0, CYCLE) == []
    ramp = np.interp(np.degrees(PHI), [0, 100, 200, 720], [0, 10, 0, 0])
    (start, end), = contact_intervals(PHI, ramp, 5.0, CYCLE)
    assert (math.degrees(start), math.degrees(end)) == pytest.approx((50.0, 150.0))


def test_hard_contact_summary_matches_seed_definitions(tmp_path):
    case = _case(dry_friction_coefficient=0.1)
    result = analyse_contact(case, _combustion_cycle())
    items = result.summary_items()
    for key in ("contact_intervals_deg", "max_contact_force_N", "max_hertz_stress_Pa",
                "nominal_specific_load_Pa", "hertz_to_nominal_ratio", "friction_work_J",
                "max_wear_journal_m", "max_wear_shell_m"):
        assert key in items
    (start, end), = items["contact_intervals_deg"]
    # the first and the last output angle in contact: the rows of cycle.csv with in_contact
    assert (start, end) == pytest.approx((371.0, 451.0))
    assert items["max_contact_force_N"] == pytest.approx(2.0e4, rel=1e-3)
    # nominal specific load of the bearing at its peak load (2e4 + 5e3 N) over B·D
    assert items["nominal_specific_load_Pa"] == pytest.approx(2.5e4 / (0.06 * 0.025))
    assert items["contact_specific_load_Pa"] == pytest.approx(
        items["max_contact_force_N"] / (0.06 * 0.025))
    assert items["hertz_to_nominal_ratio"] == pytest.approx(
        items["max_hertz_stress_Pa"] / items["contact_specific_load_Pa"])
    assert np.sum(result.wear.journal_work) == pytest.approx(items["friction_work_J"])
    assert np.sum(result.wear.shell_work) == pytest.approx(items["friction_work_J"])
    # seed eq. 4.5.1 on the same cycle: Σ μ P_c R Δφ (rotation = crank angle)
    assert items["friction_work_seed_formula_J"] == pytest.approx(
        0.1 * 0.03 * np.sum(_combustion_cycle().contact_force) * math.radians(1.0))
    write_json(tmp_path / "summary.json", items)  # JSON-clean: no NaN, plain types
    assert json.loads((tmp_path / "summary.json").read_text())["friction_work_J"] > 0.0
    # cycle.csv keeps the orbit's contact_force_N / friction_force_N (as to_dataframe())
    assert set(result.cycle_columns()) == {"hertz_stress_Pa", "friction_work_cumulative_J"}


def test_write_files_tables_and_figures(tmp_path):
    import conrod.output  # noqa: F401  (registers the tables and figures)
    from conrod.output.registry import write_results

    result = analyse_contact(_case(surface_elements=90), _combustion_cycle())
    paths = write_results(result, tmp_path)
    assert {p.name for p in paths} >= {"wear_journal.csv", "wear_shell.csv", "contact_cycle.png"}
    for name in ("wear_journal.csv", "wear_shell.csv"):
        with open(tmp_path / name, encoding="utf-8") as handle:
            rows = list(csv.DictReader(handle))
        assert list(rows[0]) == ["angle_deg", "friction_work_J", "wear_m"]
        assert len(rows) == 90
        total = sum(float(r["friction_work_J"]) for r in rows)
        assert total == pytest.approx(result.work.total, rel=1e-6)
    assert all(p.stat().st_size > 0 for p in paths)


def test_no_contact_gives_zeros_and_null_ratio():
    cycle = _combustion_cycle()
    cycle.contact_force[:] = 0.0
    cycle.friction_force[:] = 0.0
    cycle.in_contact[:] = False
    result = analyse_contact(_case(), cycle)
    items = result.summary_items()
    assert not result.has_contact
    assert items["nominal_specific_load_Pa"] > 0.0  # the bearing's, at its peak load
    assert items["contact_intervals_deg"] == []
    assert items["friction_work_J"] == 0.0 and items["max_wear_shell_m"] == 0.0
    assert items["hertz_to_nominal_ratio"] is None


def test_greenwood_tripp_mode_recomputes_the_asperity_force():
    """Under GT the asperity force comes from the orbit's eccentricity (same kernel as the
    RHS) and adds to any hard-contact force of the orbit."""
    case = _case(model="greenwood_tripp", roughness=0.4e-6)
    cycle = _combustion_cycle(gap_in_contact=0.2e-6)
    hard, hard_friction = cycle.contact_force.copy(), cycle.friction_force.copy()
    cycle.contact_force[:] = 0.0  # a pure mixed-lubrication orbit: no hard contact
    cycle.friction_force[:] = 0.0
    result = analyse_contact(case, cycle)
    index = 400
    expected = math.hypot(*asperity_force(
        cycle.eccentricity_x[index], cycle.eccentricity_y[index], CLEARANCE,
        kernel_parameters(case),
    ))
    assert expected > 0.0
    assert result.contact_force[index] == pytest.approx(expected)
    assert result.friction_force[index] == pytest.approx(0.1 * expected)
    assert result.asperity_force[index] == pytest.approx(expected)
    # boundary friction power μ F_a |V_slide| with the stand-in's 2 m/s sliding speed
    assert result.boundary_friction_power[index] == pytest.approx(0.1 * expected * 2.0)
    assert result.contact_force[0] == 0.0  # ε = 0.5: no asperity contact
    cycle.contact_force[:], cycle.friction_force[:] = hard, hard_friction
    both = analyse_contact(case, cycle)
    assert both.contact_force[index] == pytest.approx(hard[index] + expected)
    assert both.friction_force[index] == pytest.approx(hard_friction[index] + 0.1 * expected)


def test_missing_clearance_is_a_case_error():
    case = Case.from_dict({"bearing": {"diameter": 0.06, "width": 0.025}})
    with pytest.raises(CaseError, match="radial_clearance"):
        analyse_contact(case, _combustion_cycle())


def test_contact_section_errors_name_field_and_unit():
    with pytest.raises(CaseError, match=r"contact.roughness.*m"):
        _case(roughness=-1.0)
    with pytest.raises(CaseError, match="did you mean 'wear_coefficient_shell'"):
        _case(wear_coeficient_shell=1e-16)


def test_running_in_feeds_worn_profile_back_and_accumulates_wear():
    """Stand-in orbit whose contact force falls as the shell wears at the contact point
    (δ at θ = 90° opens the gap): the bookkeeping of the lumped stages must hold."""
    from conrod.simulation.running_in import run_in

    case = _case(surface_elements=72, wear_coefficient_shell=1e-16)
    seen = []

    def simulate(case, profile):
        theta, z = np.linspace(0, 2 * math.pi, 144, endpoint=False), np.zeros(3)
        delta = profile(theta, z)
        assert delta.shape == (144, 3)
        opened = float(delta[36, 1])  # θ = 90°, the contact point of the stand-in
        seen.append(opened)
        cycle = _combustion_cycle()
        scale = max(0.0, 1.0 - opened / 5e-8)
        cycle.contact_force *= scale
        cycle.friction_force *= scale
        return analyse_contact(case, cycle)

    history = run_in(case, cycles=2000, stages=4, simulate=simulate)
    assert history.cycles == [0.0, 500.0, 1000.0, 1500.0]
    assert seen[0] == 0.0 and all(b > a for a, b in zip(seen, seen[1:], strict=False))
    assert all(b < a for a, b in zip(history.friction_work, history.friction_work[1:],
                                     strict=False))
    first_stage = analyse_contact(case, _combustion_cycle()).wear.shell_wear
    assert history.shell_wear.sum() < 2000 * first_stage.sum()  # wear slows as it runs in
    np.testing.assert_allclose(history.shell_wear[:18], 0.0)  # nothing worn 0–90° away


def test_conformal_contact_caveat():
    """The Hertz half-width of a journal in its shell is comparable with R: say so."""
    items = analyse_contact(_case(), _combustion_cycle()).summary_items()
    assert items["max_hertz_half_width_m"] > 0.1 * 0.03
    assert any("conformal" in text for text in items["contact_warnings"])
    quiet = _combustion_cycle()
    quiet.contact_force[:] = 0.0
    assert analyse_contact(_case(), quiet).summary_items()["contact_warnings"] == []
