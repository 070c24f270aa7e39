"""Simulation takes objects (film, loads, integrator), computes each characteristic once and
returns frozen results."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

import conrod.simulation.simulation as simulation_module
from blas_helpers import blas_threads, two_blas_threads
from conrod import Case, Simulation
from conrod.errors import CaseError
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.orbit.integrators import QuasiStaticIntegrator

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
QUICK = {"integrator": "quasi_static", "max_cycles": 3}


@pytest.fixture(scope="module")
def case():
    return Case.from_toml(EXAMPLES / "flores2006_table_load.toml")


@pytest.fixture(scope="module")
def reference(case):
    return Simulation(case, **QUICK).run()


def test_a_film_object_replaces_the_case_film(case, reference):
    film = ShortBearingFilm(case.bearing.geometry())
    given = Simulation(case, film=film, **QUICK).run()
    np.testing.assert_array_equal(given.cycle.h_min, reference.cycle.h_min)
    reynolds = Simulation(case, film=ReynoldsFilm(case.bearing.geometry(), 24, 4),
                          **QUICK).run()
    assert reynolds.summary.film_model == "reynolds"
    assert reynolds.summary.h_min != reference.summary.h_min


def test_a_load_object_replaces_the_case_loads(case, reference):
    loads = Simulation(case).load_cycle()
    same = Simulation(case, loads=loads, **QUICK).run()
    np.testing.assert_array_equal(same.cycle.h_min, reference.cycle.h_min)
    doubled = dataclasses.replace(loads, load_x=2.0 * loads.load_x, load_y=2.0 * loads.load_y)
    heavier = Simulation(case, loads=doubled, **QUICK).run()
    np.testing.assert_allclose(heavier.cycle.load_x, 2.0 * reference.cycle.load_x)
    assert heavier.summary.h_min < reference.summary.h_min  # twice the load, thinner film


@dataclasses.dataclass
class CountingIntegrator:
    """Any object with ``name`` and ``cycle`` integrates the orbit."""

    name: str = "counted_quasi_static"
    calls: int = 0

    def cycle(self, problem, state, settings):
        self.calls += 1
        return QuasiStaticIntegrator().cycle(problem, state, settings)


def test_an_integrator_object_runs_the_orbit(case, reference):
    counted = CountingIntegrator()
    results = Simulation(case, integrator=counted, max_cycles=3).run()
    assert counted.calls == results.summary.cycles
    assert results.summary.integrator == "counted_quasi_static"
    np.testing.assert_array_equal(results.cycle.h_min, reference.cycle.h_min)


def test_results_are_frozen_and_characteristics_solved_once_per_orbit(case, monkeypatch):
    calls = []
    original = simulation_module.cycle_characteristics

    def counted(problem, trajectory, *rows):
        calls.append(problem.viscosity)
        return original(problem, trajectory, *rows)

    monkeypatch.setattr(simulation_module, "cycle_characteristics", counted)
    results = Simulation(case, **QUICK).run()
    assert len(calls) == results.summary.thermal_iterations + 1
    with pytest.raises(dataclasses.FrozenInstanceError):
        results.summary = None  # type: ignore[misc]
    with pytest.raises(dataclasses.FrozenInstanceError):
        results.cycle.h_min = None  # type: ignore[misc]


def test_a_housing_is_refused_until_the_elastic_coupling_exists(case):
    with pytest.raises(CaseError, match="housing"):
        Simulation(case, housing=object())


def _blas_threads_seen(case, monkeypatch, method: str) -> list[int]:
    """The BLAS threads seen while ``Simulation(case).<method>()`` computes the cycle's
    characteristics, started from a pool of two, which must be back afterwards."""
    seen = []
    original = simulation_module.cycle_characteristics

    def watched(problem, trajectory, *rows):
        seen.append(blas_threads())
        return original(problem, trajectory, *rows)

    monkeypatch.setattr(simulation_module, "cycle_characteristics", watched)
    with two_blas_threads():
        getattr(Simulation(case, **QUICK), method)()
        assert blas_threads() == 2
    return seen


def test_a_run_computes_on_one_blas_thread_and_gives_the_pool_back(case, monkeypatch):
    """A program that loaded NumPy first keeps its BLAS pool; the run limits it to one
    thread while it computes (its dense algebra is small) and restores it afterwards."""
    seen = _blas_threads_seen(case, monkeypatch, "run")
    assert seen and set(seen) == {1}


def test_the_orbit_alone_computes_on_one_blas_thread_too(case, monkeypatch):
    """``run_orbit``, which the grid-error estimate calls directly for its coarser orbits
    (in the run's process once the run is done, or in the second process), computes on one
    BLAS thread as ``run`` does: on the threads' pool its spinning threads took the core of
    the process drawing the figures, and the orbit's bits could depend on which process
    computed it."""
    seen = _blas_threads_seen(case, monkeypatch, "run_orbit")
    assert seen and set(seen) == {1}
