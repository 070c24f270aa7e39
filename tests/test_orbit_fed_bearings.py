"""Property test: random plausible fed bearings on the Reynolds film, with mass
(implicit) and massless (quasi_static), finish or stop with a message naming the cause."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import BearingGeometry, Groove
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.loads.cycle import LoadCycle
from conrod.orbit import OrbitProblem, OrbitState, integrate_cycle
from orbit_helpers import solver

bearings = st.fixed_dictionaries({
    "bore": st.floats(0.06, 0.15),
    "rpm": st.floats(600.0, 4000.0),
    "clearance": st.floats(10e-6, 60e-6),
    "supply": st.floats(0.1e6, 0.5e6),
    "unit_load": st.floats(2e6, 20e6),
    "integrator": st.sampled_from(["implicit", "quasi_static"]),
})


def _problem(b) -> OrbitProblem:
    width = 0.4 * b["bore"]
    geometry = BearingGeometry(diameter=b["bore"], width=width, radial_clearance=b["clearance"],
                               grooves=(Groove(width=0.1 * width),),
                               supply_pressure=b["supply"])
    film = ReynoldsFilm(geometry, n_theta=24, n_z=8)
    omega = b["rpm"] * math.pi / 30.0
    phi = np.linspace(0.0, 4 * math.pi, 72, endpoint=False)
    peak = b["unit_load"] * b["bore"] * width
    pulse = np.exp(-(((phi + math.pi) % (4 * math.pi) - math.pi) / 0.4) ** 2)
    loads = LoadCycle(phi, peak * (0.2 + 0.8 * pulse) * np.cos(0.5 * phi),
                      peak * 0.2 * np.sin(phi), np.full(72, omega), np.zeros(72), omega,
                      4 * math.pi)
    return OrbitProblem(film, loads, 0.01, 1.0, 1.0, 0.1, 0.1 * b["clearance"])


@settings(max_examples=4, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(bearings)
def test_fed_bearing_cycle_finishes_or_names_the_cause(b):
    problem = _problem(b)
    try:
        traj = integrate_cycle(problem, OrbitState(), solver(output_step_deg=2.0),
                               b["integrator"])
    except (ConvergenceError, CaseError) as error:
        assert "crank angle" in str(error) or "solver." in str(error)
        return
    assert np.all(np.isfinite(traj.x)) and np.all(np.isfinite(traj.y))
    assert np.max(np.hypot(traj.x, traj.y)) <= problem.contact_radius * (1 + 1e-9)
    # bounded work: a few dozen steps per degree at most (the integrators' own caps are
    # far higher), so a grinding integration would fail here instead of running on
    assert traj.steps <= 50 * 720
