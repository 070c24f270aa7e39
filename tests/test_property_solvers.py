"""Property tests over plausible bearings and worn shells (hypothesis, derandomized): every
film × integrator pair runs with finite, plausible results or is refused before the orbit
with a message naming the field and what to use instead — never a solver failure (exit 3)
on a bearing that another film or integrator runs, never a traceback or a hang; the
clearance mechanism runs every pair of worn shells.

Bearings: :mod:`plausible_bearings` (journal 40–75 mm, L/D 0.25–0.5, c/R 0.5–1.5 ‰,
15–70 MPa, 3–15 mPa s, 900–4500 rpm, plain or fed through a central groove), one cycle at
a 24 × 8 grid (what is tested is the ending, not the periodic orbit).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conrod.cases.case import Case
from conrod.errors import ConvergenceError
from hardening_helpers import EXAMPLES
from plausible_bearings import Bearing, assert_plausible, bearings, run

REFUSAL = re.compile(r"^(solver\.[a-z_]+|supply_pressure|[a-z_]+\.[a-z_]+)( = |: )")
"""A refusal names the field it refuses."""


def _settings(examples: int):
    return settings(max_examples=examples, deadline=None, derandomize=True, database=None,
                    print_blob=True, suppress_health_check=[HealthCheck.too_slow])


def _check(bearing: Bearing, pairs) -> dict:
    """Run ``pairs`` (film, integrator) on ``bearing``; every run plausible, every refusal
    named with its alternative, no failure where another pair ran; returns the outcomes."""
    outcomes = {pair: run(bearing, *pair) for pair in pairs}
    ran = [pair for pair, outcome in outcomes.items() if outcome.kind == "ran"]
    for pair, outcome in outcomes.items():
        if outcome.kind == "ran":
            assert_plausible(outcome.results, bearing)
        elif outcome.kind == "refused":
            assert REFUSAL.match(outcome.message), (pair, outcome.message)
            assert "allowed" in outcome.message or "use " in outcome.message, outcome.message
        else:
            assert "crank angle" in outcome.message, (pair, outcome.message)
            assert not ran, (f"{pair} failed on {bearing.label()} where {ran} ran: "
                             f"{outcome.message}")
    return outcomes


SHORT = [("short", name) for name in ("auto", "implicit", "adaptive", "quasi_static", "rk2")]


@pytest.mark.slow
@_settings(5)
@given(bearings())
def test_short_film_every_integrator_runs_or_is_refused(bearing):
    outcomes = _check(bearing, SHORT)
    assert outcomes["short", "auto"].kind == "ran"  # the default runs every plausible bearing


@pytest.mark.slow
@_settings(2)
@given(bearings(grooved=False))
def test_grid_films_on_plain_bearings(bearing):
    """Reynolds with every integrator; the mass-conserving film is refused without an oil
    feed."""
    pairs = [("reynolds", "auto"), ("reynolds", "quasi_static"), ("reynolds", "adaptive"),
             ("reynolds", "rk2"), ("mass_conserving", "auto")]
    outcomes = _check(bearing, pairs)
    assert outcomes["reynolds", "auto"].kind == "ran"
    assert outcomes["mass_conserving", "auto"].kind == "refused"


@pytest.mark.slow
@_settings(1)
@given(bearings(grooved=False))
def test_tabulated_films_on_plain_bearings(bearing):
    """The table film with mass and the mobility film massless (one map, built once)."""
    outcomes = _check(bearing, [("table", "auto"), ("mobility", "quasi_static"),
                                ("table", "rk2")])
    assert outcomes["table", "auto"].kind == "ran"


@pytest.mark.slow
@_settings(1)
@given(bearings(grooved=True))
def test_grid_films_on_fed_two_land_bearings(bearing):
    """Reynolds and mass-conserving films with mass and massless; rk2 and the adaptive
    integrator of the mass-conserving film are refused before the orbit, or run."""
    pairs = [("reynolds", "auto"), ("reynolds", "quasi_static"), ("reynolds", "rk2"),
             ("mass_conserving", "auto"), ("mass_conserving", "quasi_static"),
             ("mass_conserving", "adaptive")]
    outcomes = _check(bearing, pairs)
    assert outcomes["reynolds", "auto"].kind == "ran"
    assert outcomes["mass_conserving", "auto"].kind == "ran"


# -- worn shells in the clearance mechanism --------------------------------------------------
SHELLS = st.fixed_dictionaries({
    "big": st.tuples(st.floats(60e-6, 300e-6), st.floats(0.3, 1.0), st.floats(-90.0, 90.0)),
    "small": st.tuples(st.floats(15e-6, 60e-6), st.floats(0.3, 1.0), st.floats(-90.0, 90.0)),
    "speed": st.floats(1000.0, 4000.0), "load": st.floats(0.3, 1.0)})
"""Worn shell pairs as in ``benchmarks/worn_shells.py``: Δmax, Δmin/Δmax, major axis [deg]."""


@pytest.mark.slow
@_settings(4)
@given(SHELLS)
def test_worn_shell_pairs_run_with_the_default_contact_geometry(draw):
    from conrod.mechanism.setup import mechanism_case
    from conrod.mechanism.simulation import simulate

    raw = Case.from_toml(EXAMPLES / "kulayev_worn_rod_bearings.toml").model_dump(
        exclude_none=True)
    for joint in ("big", "small"):
        clearance_max, ratio, angle = draw[joint]
        raw["clearance"][f"{joint}_end"].update(
            clearance_max=clearance_max, clearance_min=ratio * clearance_max,
            ellipse_angle_deg=angle)
    raw["clearance"].update(load_scale=draw["load"], cycles=2)
    raw["engine"]["speed"] = draw["speed"]
    base = mechanism_case(Case.from_dict(raw, base_dir=EXAMPLES))
    try:
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
    except ConvergenceError as error:  # the budget or the step size: a defect here
        pytest.fail(f"worn shells {draw}: {error}")
    summary = results.summary()
    assert all(math.isfinite(v) for v in summary.values() if isinstance(v, float))
    surface = base.mechanism.crank.crank_speed * 0.5 * base.mechanism.big_end.diameter
    assert summary["max_impact_velocity_big_end_m_s"] <= surface
    assert np.isfinite(results.contact_force).all()
