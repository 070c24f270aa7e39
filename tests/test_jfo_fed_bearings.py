"""Property test: on random plausible fed bearings every grid film (Reynolds and
mass-conserving, massless and with mass) reaches a periodic orbit or stops with a message
naming the cause, within a step count tied to the case."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conrod.cases.solver import SolverSection
from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import BearingGeometry, Groove
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.orbit import OrbitProblem
from conrod.orbit.periodic import periodic_orbit
from orbit_helpers import fed_bearing_problem

STEP_DEG = 2.0
"""Quasi-static step and largest step with mass [deg]."""
MAX_CYCLES = 4
"""Cycles per orbit [-]."""

bearings = st.fixed_dictionaries({
    "bore": st.floats(0.06, 0.15),
    "width_ratio": st.floats(0.3, 0.6),
    "rpm": st.floats(600.0, 4000.0),
    "clearance": st.floats(10e-6, 60e-6),
    "supply": st.floats(0.1e6, 0.5e6),
    "unit_load": st.floats(5e6, 40e6),
    "integrator": st.sampled_from(["quasi_static", "auto"]),
})


def _problem(b, film: str) -> OrbitProblem:
    """Four-stroke big-end-like load: firing pulse on a rotating inertia load."""
    return fed_bearing_problem(b, ReynoldsFilm if film == "reynolds" else MassConservingFilm,
                               0.01)


def _orbit(b, film: str):
    """Periodic orbit of the film, or the error that stopped it (its message checked)."""
    problem = _problem(b, film)
    solver = SolverSection(integrator=b["integrator"], quasi_static_step_deg=STEP_DEG,
                           max_step_deg=1.0, output_step_deg=STEP_DEG, max_cycles=MAX_CYCLES,
                           massless_start=False)
    try:
        result = periodic_orbit(problem, solver)
    except (ConvergenceError, CaseError) as error:
        assert "crank angle" in str(error)
        return error
    last = result.last
    assert np.all(np.isfinite(last.x)) and np.all(np.isfinite(last.y))
    assert np.max(np.hypot(last.x, last.y)) <= problem.contact_radius * (1 + 1e-9)
    # bound tied to the case: steps per cycle at most twice the nominal count of the step
    # (halved steps of the film-content orbit, error-controlled steps of TR-BDF2)
    nominal = 720.0 / min(STEP_DEG, solver.max_step_deg)
    assert last.steps <= 2 * 2 * nominal  # 2 per Heun step of the quasi-static loop
    assert result.cycles <= solver.max_cycles
    if not result.periodic:  # still on its way: the error contracts from the first measured
        first = next(error for error in result.history if np.isfinite(error))
        assert result.history[-1] < 0.5 * first
    return result


@pytest.mark.slow
@settings(max_examples=8, deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.too_slow])
@given(bearings)
def test_fed_bearing_orbit_is_periodic_or_names_the_cause(b):
    """Both grid films end periodic (or still contracting) or name the cause, and the
    mass-conserving film finishes wherever the Reynolds film does."""
    reynolds = _orbit(b, "reynolds")
    jfo = _orbit(b, "mass_conserving")
    if not isinstance(reynolds, Exception):
        assert not isinstance(jfo, Exception), str(jfo)


@pytest.mark.parametrize("film", ["mobility", "table"])
def test_tabulated_films_refuse_a_supply_pressure_naming_the_film_asked(film, tmp_path):
    """The maps are computed once and scaled with speed (Booker's reduction); a supply
    pressure adds a part that does not scale, so a fed groove is refused with a message
    naming the film that was asked for and the films that take it."""
    from conrod.film.table.film import TabulatedFilm
    from conrod.film.table.mobility import MobilityFilm

    geometry = BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6,
                               supply_pressure=3e5, grooves=(Groove(width=0.002),))
    with pytest.raises(CaseError) as error:
        if film == "mobility":
            MobilityFilm(geometry, cache_dir=tmp_path)
        else:
            TabulatedFilm(ReynoldsFilm(geometry), cache_dir=tmp_path)
    message = str(error.value)
    assert f"film {film!r}" in message
    assert "supply_pressure = 300000.0 Pa" in message and "scaled with speed" in message
    assert "'reynolds' or 'mass_conserving'" in message
    other = "table" if film == "mobility" else "mobility"
    assert repr(other) not in message
