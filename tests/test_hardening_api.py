"""The Python API refuses bad arguments the way the command line does: one CaseError naming
the argument, the value and what is allowed, before anything is computed or written (no
AttributeError, IndexError, TypeError or FileExistsError from inside)."""

from __future__ import annotations

import math

import numpy as np
import pytest

import conrod
from conrod import Case, Simulation
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.short.film import ShortBearingFilm
from conrod.loads.engine_loads import compute_engine_loads
from conrod.mechanism import RunSettings, mechanism_case, simulate
from hardening_helpers import cheap_engine_run, cheap_mechanism, cheap_table_run


def _refused(call, *args, **kwargs) -> str:
    with pytest.raises(CaseError) as caught:
        call(*args, **kwargs)
    [line] = str(caught.value).splitlines()
    return line


@pytest.mark.parametrize("case", [None, {"bearing": {"diameter": 0.05}}, "case.toml"])
def test_simulation_needs_a_case(case):
    assert _refused(Simulation, case).startswith(
        f"Simulation: case = {case!r}: a conrod.Case is required")


@pytest.mark.parametrize(("keyword", "value"), [("film", 3), ("integrator", ["rk2"]),
                                                ("rigid_companion", "no")])
def test_simulation_refuses_arguments_of_the_wrong_kind(keyword, value):
    line = _refused(Simulation, Case.from_dict(cheap_table_run()), **{keyword: value})
    assert line.startswith(f"Simulation: {keyword} = {value!r}: ")


@pytest.mark.parametrize("gas_table", [np.array([]), np.zeros((4, 2)), [math.nan], None])
def test_simulate_refuses_an_empty_or_broken_gas_table(gas_table):
    run = mechanism_case(Case.from_dict(cheap_mechanism()))
    line = _refused(simulate, run.mechanism, gas_table, run.settings)
    assert line.startswith("simulate: gas_table of shape ")
    assert "(allowed: a 1-D array of >= 1 finite gas forces over 0..4π [N])" in line


def test_simulate_and_its_settings_name_what_is_wrong():
    run = mechanism_case(Case.from_dict(cheap_mechanism()))
    assert _refused(simulate, None, np.zeros(8), run.settings) == (
        "simulate: mechanism = NoneType: a conrod.mechanism.Mechanism is required")
    assert _refused(RunSettings, cycles=0) == (
        "RunSettings cycles = 0: out of range (allowed: >= 1 and <= 50 cycles)")
    assert _refused(RunSettings, output_step=1e-9).startswith(
        "RunSettings output_step = 1e-09: out of range (allowed: >= 5.03e-05 rad")


def test_write_results_below_a_file_is_refused_before_writing(tmp_path):
    loads = compute_engine_loads(Case.from_dict(cheap_engine_run()))
    taken = tmp_path / "taken"
    taken.write_text("keep me")
    assert _refused(conrod.write_results, loads, taken / "x") == (
        f"write_results: out_dir {str(taken / 'x')!r}: {str(taken)!r} is a file, not a folder")
    assert _refused(conrod.write_results, object(), tmp_path / "out").startswith(
        "write_results: results = object: no tables registered for object")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["taken"]


@pytest.mark.parametrize(("step", "words"), [
    ("1", "step_deg = '1': a number is required (allowed: >= 0.0072 (budget 100000 rows "
          "per cycle) and <= 10 deg, dividing 720)"),
    (1e-6, "step_deg = 1e-06: out of range (allowed: >= 0.0072 (budget 100000 rows per "
           "cycle) and <= 10 deg, dividing 720)")])
def test_compute_engine_loads_checks_its_step(step, words):
    assert _refused(compute_engine_loads, Case.from_dict(cheap_engine_run()),
                    step_deg=step) == words


@pytest.mark.parametrize(("keyword", "value", "allowed"), [
    ("diameter", -1.0, "(allowed: >= 0.001 and <= 20 m)"),
    ("width", 1e-300, "(allowed: >= 5e-05 and <= 1 m, i.e. 0.001 to 20 x diameter)"),
    ("radial_clearance", 1e-300, "(allowed: >= 2.5e-08 and <= 0.0025 m, i.e. 1e-06 to 0.1 x "
                                 "journal radius)"),
    ("radial_clearance", math.nan, "(allowed: >= 2.5e-08"),
])
def test_bearing_geometry_is_checked(keyword, value, allowed):
    lengths = {"diameter": 0.05, "width": 0.025, "radial_clearance": 25e-6, keyword: value}
    line = _refused(BearingGeometry, **lengths)
    assert line.startswith(f"BearingGeometry {keyword} = {value!r}: out of range {allowed}")


@pytest.mark.parametrize("viscosity", [-0.01, math.inf, 0.0, "0.01"])
def test_a_film_state_needs_a_usable_viscosity(viscosity):
    line = _refused(FilmState, eccentricity_x=10e-6, eccentricity_y=0.0,
                    journal_speed=300.0, viscosity=viscosity)
    assert line.startswith(f"FilmState viscosity = {viscosity!r}: ")
    assert line.endswith("(allowed: > 0 and <= 1e+06 Pa s)")


def test_a_valid_film_state_still_solves():
    film = ShortBearingFilm(BearingGeometry(diameter=0.05, width=0.025,
                                            radial_clearance=25e-6))
    state = FilmState(eccentricity_x=10e-6, eccentricity_y=0.0, journal_speed=300.0,
                      viscosity=np.float64(0.01))
    assert film.solve(state).force_x < 0.0


def test_case_readers_and_builders_name_a_missing_case():
    from conrod.film.table.film import TabulatedFilm
    from conrod.film.table.mobility import MobilityFilm
    from conrod.loads.table_load import load_cycle_from_table

    assert _refused(Case.from_toml, None).startswith(
        "Case.from_toml: path = None: a case-file path is required")
    assert _refused(conrod.run, {"bearing": {}}).startswith(
        "run: case = dict: a conrod.Case or a case-file path is required")
    assert _refused(mechanism_case, None).startswith(
        "mechanism_case: case = NoneType: a conrod.Case is required")
    assert _refused(TabulatedFilm, None).startswith(
        "TabulatedFilm: base = NoneType: a film model is required")
    assert _refused(MobilityFilm, None) == (
        "MobilityFilm: geometry = NoneType: a conrod.BearingGeometry is required")
    assert _refused(load_cycle_from_table, None, None).startswith(
        "load_cycle_from_table: section = NoneType, path = None: ")
