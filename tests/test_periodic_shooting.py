"""The quasi-Newton shooting accelerator of the periodic orbit (conrod.orbit.shooting).

Independent answer: the orbit that plainly repeated cycles reach (the fixed point of the
cycle map, found without any extrapolation). On each kind of shipped example — the rigid
journal with mass (short bearing), the massless table-load orbit, the fed Reynolds film,
the film content of the mass-conserving film, the elastic bore (EHD) — the shot orbit
agrees with it within the periodicity tolerance (max |Δe|/c over the cycle, h_min within
tolerance × c, p_max within 1 %) in fewer integrated cycles; with ``accelerate_cycles``
off the loop is the plain repetition bit for bit, and ``periodic_accelerator =
"anderson"`` keeps the measure of the mixing (no error after the first cycle).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.orbit.periodic import integrate_cycle, periodic_orbit
from conrod.orbit.problem import initial_state
from conrod.orbit.shooting import CycleShooting, newton_step
from orbit_helpers import assert_same_periodic_orbit

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
PLAIN = {"accelerate_cycles": False, "massless_start": False}


def test_secant_shooting_lands_on_the_fixed_point_of_a_linear_map():
    """P(x) = A x + b with a slow mode (eigenvalues 0.95, 0.9, −0.5, 0.2): plain repetition
    needs ~300 maps to 1e-8; the secant Newton step is exact on the span of its pairs, so
    the shooting is at the fixed point (I − A)⁻¹ b after n + 2 = 6 maps."""
    rng = np.random.default_rng(3)
    basis = np.linalg.qr(rng.normal(size=(4, 4)))[0] + 0.3 * rng.normal(size=(4, 4))
    a = basis @ np.diag([0.95, 0.9, -0.5, 0.2]) @ np.linalg.inv(basis)
    b = rng.normal(size=4) * 0.05
    fixed = np.linalg.solve(np.eye(4) - a, b)
    shooting, x = CycleShooting(limit=1e9), np.zeros(4)
    for _ in range(6):
        image = a @ x + b
        proposal = shooting.propose(x, image)
        x = image if proposal is None else proposal
    assert np.linalg.norm(x - fixed) < 1e-10 * np.linalg.norm(fixed)
    plain = np.zeros(4)
    for _ in range(6):
        plain = a @ plain + b
    assert np.linalg.norm(plain - fixed) > 0.1 * np.linalg.norm(fixed)


def test_newton_step_is_the_dense_solve_with_the_secant_monodromy():
    """Woodbury's δ equals the dense solve of (I − U Vᵀ) δ = F."""
    rng = np.random.default_rng(7)
    u, vt, residual = rng.normal(size=(9, 3)), 0.1 * rng.normal(size=(3, 9)), rng.normal(size=9)
    dense = np.linalg.solve(np.eye(9) - u @ vt, residual)
    assert np.allclose(newton_step((u, vt), residual), dense, rtol=1e-12, atol=1e-12)


def test_a_rejected_proposal_restarts_the_secant_history():
    """A proposal outside the contact circle is refused: None, history cleared."""
    shooting = CycleShooting(limit=1.0)
    assert shooting.propose(np.array([0.0, 0.0]), np.array([0.5, 0.0])) is None
    assert shooting.propose(np.array([0.5, 0.0]), np.array([0.9, 0.0])) is None  # x* = ∞
    assert shooting.starts == []


def _simulation(stem: str, **overrides) -> Simulation:
    return Simulation(Case.from_toml(EXAMPLES / f"{stem}.toml"), max_cycles=12, **overrides)


def _orbits(stem: str, overrides: dict, accelerated: dict):
    """(problem, settings, plain orbit, accelerated orbit) of an example."""
    plain_sim = _simulation(stem, **overrides, **PLAIN)
    problem = plain_sim.problem()
    plain = periodic_orbit(problem, plain_sim.solver, integrator=plain_sim.integrator())
    sim = _simulation(stem, **overrides, **accelerated)
    shot = periodic_orbit(problem, sim.solver, integrator=sim.integrator())
    return problem, sim.solver, plain, shot


@pytest.mark.parametrize("start", [{"massless_start": False}, {}])
def test_shot_orbit_with_mass_is_the_repeated_orbit_in_two_cycles(start):
    """Passenger car, short bearing with mass, hard contact: plain repetition needs 3
    cycles (the third only shows the second was periodic); shooting accepts the second by
    its closure, from the concentric start and from the massless one."""
    problem, settings, plain, shot = _orbits("passenger_car_diesel_2000rpm", {}, start)
    assert_same_periodic_orbit(problem, settings, plain, shot)
    assert plain.cycles == 3 and shot.cycles == 2


def test_shot_massless_orbit_is_the_repeated_orbit_in_two_cycles():
    """Table load, massless (quasi-static) orbit: 3 → 2 cycles."""
    problem, settings, plain, shot = _orbits("flores2006_table_load", {}, {})
    assert_same_periodic_orbit(problem, settings, plain, shot)
    assert plain.cycles == 3 and shot.cycles == 2


@pytest.mark.slow
def test_shot_orbit_on_the_reynolds_film_is_the_repeated_orbit():
    """KamAZ-740 on a rigid bore, Reynolds film 24 × 8 (the compiled flight of the
    Reynolds film)."""
    problem, settings, plain, shot = _orbits("kamaz_740_truck_diesel",
                                             {"film": "reynolds", "housing": "rigid",
                                              "n_theta": 24, "n_z": 8}, {})
    assert_same_periodic_orbit(problem, settings, plain, shot)
    assert shot.cycles < plain.cycles


@pytest.mark.slow
def test_shot_orbit_on_an_elastic_bore_is_the_repeated_orbit():
    """KamAZ-740 on the built-in elastic rod (EHD), 24 × 6: the bore deformation is solved
    with each step and slaved to the journal state between cycles."""
    problem, settings, plain, shot = _orbits("kamaz_740_truck_diesel",
                                             {"film": "reynolds", "n_theta": 24, "n_z": 6},
                                             {})
    assert_same_periodic_orbit(problem, settings, plain, shot)
    assert shot.cycles < plain.cycles


def test_accelerator_off_is_the_plain_repetition_bit_for_bit():
    """``accelerate_cycles = false``: every cycle starts where the last ended and the
    error is the difference of the last two cycles, as before the accelerator."""
    sim = _simulation("passenger_car_diesel_2000rpm", **PLAIN)
    problem = sim.problem()
    orbit = periodic_orbit(problem, sim.solver, integrator=sim.integrator())
    state, cycles = initial_state(), []
    for _ in range(orbit.cycles):
        cycles.append(integrate_cycle(problem, state, sim.solver, sim.integrator()))
        state = cycles[-1].end_state
    assert np.array_equal(orbit.last.x, cycles[-1].x)
    assert np.array_equal(orbit.last.vy, cycles[-1].vy)
    assert math.isinf(orbit.history[0])
    assert orbit.periodicity_error == float(
        np.max(np.hypot(cycles[-1].x - cycles[-2].x, cycles[-1].y - cycles[-2].y))
        / problem.clearance)


def test_anderson_choice_keeps_the_measure_of_the_mixing():
    """``periodic_accelerator = "anderson"``: no error after the first cycle, the second
    measured against the first (the mixing extrapolates only slow cycles)."""
    sim = _simulation("flores2006_table_load", periodic_accelerator="anderson")
    orbit = periodic_orbit(sim.problem(), sim.solver, integrator=sim.integrator())
    assert math.isinf(orbit.history[0]) and orbit.cycles == 3


def test_a_continued_run_accepts_its_first_cycle_when_it_closes():
    """From the end of a periodic orbit (the heat balance's next iteration at an unchanged
    viscosity) one cycle closes and is accepted; at a viscosity 20 % higher the first cycle
    does not close and the run goes on to the new orbit. The Anderson choice keeps
    ``min_cycles`` (2) for a continued run."""
    sim = _simulation("passenger_car_diesel_2000rpm")
    problem, settings = sim.problem(), sim.solver
    orbit = periodic_orbit(problem, settings, integrator=sim.integrator())
    again = periodic_orbit(problem, settings, integrator=sim.integrator(),
                           start=orbit.last.end_state)
    assert again.periodic and again.cycles == 1
    gap = np.max(np.hypot(again.last.x - orbit.last.x, again.last.y - orbit.last.y))
    assert gap <= settings.periodicity_tolerance * problem.clearance
    thicker = problem.with_viscosity(1.2 * problem.viscosity)
    moved = periodic_orbit(thicker, settings, integrator=sim.integrator(),
                           start=orbit.last.end_state)
    assert moved.periodic and moved.cycles == 2 and moved.history[0] > 1e-3
    mixed = _simulation("passenger_car_diesel_2000rpm", periodic_accelerator="anderson")
    kept = periodic_orbit(problem, mixed.solver, integrator=mixed.integrator(),
                          start=orbit.last.end_state)
    assert kept.cycles == 2
