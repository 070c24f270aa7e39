"""Plausible big-end bearings for the solver tests (the generator of
``benchmarks/pmax_reference.py`` with the journal diameter drawn too).

The engine, masses and oil feed of ``examples/passenger_car_diesel_2000rpm.toml`` with, per
bearing: journal diameter 40–75 mm, width 0.25–0.5 D, relative clearance c/R 0.5–1.5 ‰,
peak specific load W_max/(L D) 15–70 MPa (the engine's load diagram scaled), viscosity
3–15 mPa s (log-uniform), crank speed 900–4500 rpm; plain, or fed at 0.3 MPa through a full
central circumferential groove of a tenth of the width (two lands). Hard contact only at
the clearance circle (contact_film_thickness = 0).
"""

from __future__ import annotations

import dataclasses
import math
from pathlib import Path

import numpy as np
from hypothesis import strategies as st

from conrod.cases.case import Case
from conrod.errors import CaseError, ConvergenceError
from conrod.loads.engine_loads import compute_engine_loads
from conrod.simulation.simulation import Simulation

TEMPLATE = Path(__file__).resolve().parents[1] / "examples" / "passenger_car_diesel_2000rpm.toml"
CHEAP = {"max_cycles": 1, "min_cycles": 1, "thermal_iterations": 0, "n_theta": 24,
         "n_z": 8, "output_step_deg": 2.0}
"""Settings of a test run: one cycle from the start (what is tested is how a run ends, the
start transient included, not the periodic orbit), isothermal, a coarse grid for the grid
films, rows every 2° [-]."""


@dataclasses.dataclass(frozen=True)
class Bearing:
    """One drawn bearing [SI]."""

    diameter: float
    width_ratio: float
    clearance_ratio: float
    specific_load: float
    viscosity: float
    speed: float
    grooved: bool

    def label(self) -> str:
        return (f"D {self.diameter * 1e3:.0f} mm, L/D {self.width_ratio:.2f}, c/R "
                f"{self.clearance_ratio * 1e3:.2f}‰, {self.specific_load / 1e6:.0f} MPa, "
                f"{self.viscosity * 1e3:.1f} mPa s, {self.speed:.0f} rpm, "
                f"{'grooved' if self.grooved else 'plain'}")


def bearings(grooved=None) -> st.SearchStrategy[Bearing]:
    """Plausible bearings (module docstring); ``grooved`` True/False fixes the feed."""
    return st.builds(
        Bearing, diameter=st.floats(0.040, 0.075), width_ratio=st.floats(0.25, 0.5),
        clearance_ratio=st.floats(0.5e-3, 1.5e-3), specific_load=st.floats(15e6, 70e6),
        viscosity=st.floats(math.log(3e-3), math.log(15e-3)).map(math.exp),
        speed=st.floats(900.0, 4500.0),
        grooved=st.booleans() if grooved is None else st.just(grooved))


def bearing_case(bearing: Bearing):
    """(Case, LoadCycle) of ``bearing``."""
    case = Case.from_toml(TEMPLATE)
    data = case.model_dump(exclude_none=True)
    diameter, width = bearing.diameter, bearing.width_ratio * bearing.diameter
    data["bearing"].update(diameter=diameter, width=width,
                           radial_clearance=bearing.clearance_ratio * diameter / 2)
    if bearing.grooved:
        data["bearing"].update(supply_pressure=0.3e6, grooves=[{"width": 0.1 * width}])
    data["engine"]["speed"] = bearing.speed
    data["lubricant"]["viscosity"] = bearing.viscosity
    data["solver"]["contact_film_thickness"] = 0.0
    case = Case.from_dict(data, base_dir=TEMPLATE.parent)
    loads = compute_engine_loads(case).to_load_cycle()
    scale = bearing.specific_load * width * diameter / float(
        np.max(np.hypot(loads.load_x, loads.load_y)))
    return case, dataclasses.replace(loads, load_x=loads.load_x * scale,
                                     load_y=loads.load_y * scale)


@dataclasses.dataclass(frozen=True)
class Outcome:
    """How a run ended: 'ran' (with its results), 'refused' (CaseError, before the orbit)
    or 'failed' (ConvergenceError); the error message."""

    kind: str
    results: object = None
    message: str = ""


def run(bearing: Bearing, film: str, integrator: str, **settings) -> Outcome:
    """``bearing`` with ``film`` and ``integrator`` at :data:`CHEAP` settings."""
    case, loads = bearing_case(bearing)
    try:
        results = Simulation(case, loads=loads, film=film, integrator=integrator,
                             **{**CHEAP, **settings}).run()
    except CaseError as error:
        return Outcome("refused", message=str(error))
    except ConvergenceError as error:
        return Outcome("failed", message=str(error))
    return Outcome("ran", results)


def assert_plausible(results, bearing: Bearing) -> None:
    """Finite cycle columns; h_min within [0, 2c]; p_max positive and at least the mean
    specific load (the film carries the load)."""
    cycle, summary = results.cycle, results.summary
    for name in ("h_min", "p_max", "eccentricity_x", "eccentricity_y", "friction_power"):
        assert np.all(np.isfinite(getattr(cycle, name))), name
    clearance = bearing.clearance_ratio * bearing.diameter / 2
    assert 0.0 <= summary.h_min <= 2.0 * clearance
    assert summary.p_max > 0.0 and math.isfinite(summary.p_max)
    assert np.all(cycle.p_max >= 0.0)
