"""The lead-in of the orbit with mass on an elastic bore (``[solver] lead_in``).

Independent answer: the periodic orbit that starts with a whole first cycle from the
concentric start (``lead_in = 0``, the orbit before the lead-in existed). The lead-in runs
only the last share of that cycle from the same start, so that the first whole cycle is
already near the periodic orbit and is accepted by its own closure; the periodic orbits of
both agree within the periodicity tolerance (max |Δe|/c over the cycle, h_min within
tolerance × c, p_max within 1 %) in 1.5 cycles instead of 2. ``lead_in = 0`` is the whole
first cycle bit for bit; a rigid film has no lead-in.
"""

from __future__ import annotations

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.orbit.implicit_step import implicit_step_cycle, implicit_step_deg
from conrod.orbit.integrators import AutomaticIntegrator, ImplicitIntegrator
from conrod.orbit.periodic import integrate_cycle, periodic_orbit
from conrod.orbit.problem import initial_state
from conrod.simulation.simulation import Simulation
from elastic_helpers import kamaz_case
from orbit_helpers import assert_same_periodic_orbit

GRID = {"n_theta": 24, "n_z": 6, "film": "reynolds", "output_step_deg": 4.0,
        "integrator": "implicit"}


def _elastic(**solver) -> Simulation:
    return Simulation(kamaz_case(**{**GRID, **solver}), rigid_companion=False)


@pytest.fixture(scope="module")
def orbits():
    """(problem, settings, whole first cycle, lead-in) periodic orbits of the KamAZ-740 on
    its elastic rod at 24 × 6."""
    whole = _elastic(lead_in=0.0)
    problem = whole.problem()
    first = periodic_orbit(problem, whole.solver, integrator=whole.integrator())
    led = _elastic()
    shortened = periodic_orbit(problem, led.solver, integrator=led.integrator())
    return problem, led.solver, first, shortened


def test_lead_in_orbit_is_the_orbit_of_a_whole_first_cycle(orbits):
    problem, settings, whole, led = orbits
    assert (whole.cycles, whole.lead_in, whole.cycles_run) == (2, 0.0, 2)
    assert (led.cycles, led.lead_in, led.cycles_run) == (1, 0.5, 1.5)
    # both periodic, the first whole cycle after the lead-in closing on itself, the orbits,
    # h_min and p_max alike
    assert_same_periodic_orbit(problem, settings, whole, led)


def test_no_lead_in_is_the_whole_first_cycle_bit_for_bit(orbits):
    """Two cycles from the concentric start on a new problem (its film carries the Newton
    iteration's Jacobian from step to step, so a used one would start elsewhere)."""
    _, _, whole, _ = orbits
    simulation = _elastic(lead_in=0.0)
    problem, settings = simulation.problem(), simulation.solver
    first = integrate_cycle(problem, initial_state(), settings, ImplicitIntegrator())
    second = integrate_cycle(problem, first.end_state, settings, ImplicitIntegrator())
    assert np.array_equal(whole.last.x, second.x) and np.array_equal(whole.last.vy, second.vy)
    assert whole.previous is not None and np.array_equal(whole.previous.y, first.y)


def test_lead_in_is_the_last_share_of_the_cycle_at_the_output_angles(orbits):
    problem, settings, _, led = orbits
    step = implicit_step_deg(settings)
    cycle = implicit_step_cycle(problem, initial_state(), step, settings.output_step_deg,
                                with_mass=True)
    lead = implicit_step_cycle(problem, initial_state(), step, settings.output_step_deg,
                               with_mass=True, lead_in=0.5)
    half = len(cycle.crank_angle) // 2
    assert np.array_equal(lead.crank_angle, cycle.crank_angle[half:])
    assert lead.steps == cycle.steps - half * round(settings.output_step_deg / step)
    assert (lead.x[0], lead.y[0], lead.vx[0]) == (0.0, 0.0, 0.0)  # concentric at 360°
    assert led.previous is None  # the lead-in is not a cycle
    tiny = implicit_step_cycle(problem, initial_state(), step, settings.output_step_deg,
                               with_mass=True, lead_in=1e-6)
    assert len(tiny.crank_angle) == 1  # at least one output interval


def test_a_rigid_film_has_no_lead_in():
    simulation = Simulation(kamaz_case(**GRID), housing="rigid")
    problem = simulation.problem()
    for integrator in (ImplicitIntegrator(), AutomaticIntegrator()):
        assert integrator.lead_in(problem, initial_state(), simulation.solver) is None
    elastic = _elastic().problem()
    assert ImplicitIntegrator().lead_in(elastic, initial_state(),
                                        _elastic(lead_in=0.0).solver) is None


def test_the_run_counts_and_says_the_lead_in():
    results = _elastic().run()
    summary = results.summary
    assert summary.cycles == 1.5 and summary.periodic
    assert summary.as_json_items()["cycles"] == 1.5
    from conrod.results.summary import headline

    line = headline(results)["orbit"]
    assert line.startswith("periodic after 1.5 cycles (the first 0.5 of a cycle a lead-in")


@pytest.mark.parametrize("value", [-0.1, 1.0])
def test_a_lead_in_outside_its_range_is_refused_in_one_line(value):
    with pytest.raises(CaseError) as caught:
        kamaz_case(**GRID, lead_in=value)
    message = str(caught.value)
    assert "lead_in" in message and "\n" not in message
