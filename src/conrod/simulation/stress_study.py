"""The rod-stress study (``conrod stress``): the rod under the film pressure of a run and
under the same resultant as a cosine load (:mod:`conrod.housing.stresses` compares the two
load schemes), as :class:`conrod.results.housing.StressResults`."""

from __future__ import annotations

import numpy as np

from conrod.film.base import FilmState
from conrod.loads.tilt import cycle_tilt
from conrod.results.housing import StressResults
from conrod.simulation.simulation import Simulation


def rigid_run_pressures(case, crank_angles_deg: list[float]):
    """Film pressure fields of the rigid-housing run at the given crank angles.

    Returns (θ [rad], z [m], [p (n_θ, n_z + 1) [Pa] per angle]). The only place that
    reaches into the orbit solution, so it can follow the coupled elastic run later.
    """
    simulation = Simulation(case, housing="rigid")
    results = simulation.run()
    cycle = results.cycle
    film = simulation.film_model()
    viscosity = results.summary.viscosity
    theta, z = film.grid()
    fields = []
    for angle in crank_angles_deg:
        k = int(np.argmin(np.abs(np.mod(cycle.crank_angle_deg - angle + 360.0, 720.0) - 360.0)))
        state = FilmState(eccentricity_x=float(cycle.eccentricity_x[k]),
                          eccentricity_y=float(cycle.eccentricity_y[k]),
                          velocity_x=float(cycle.velocity_x[k]),
                          velocity_y=float(cycle.velocity_y[k]),
                          journal_speed=float(cycle.journal_speed[k]),
                          shell_speed=float(cycle.shell_speed[k]), viscosity=viscosity,
                          **cycle_tilt(cycle.axial, k))
        fields.append(film.solve(state, with_pressure=True).pressure)
    return np.asarray(theta), np.asarray(z), fields


def stress_study(case, housing, crank_angles_deg: list[float]) -> StressResults:
    """Both load schemes at every crank angle [deg], the film pressure from the run on the
    rigid bore (:func:`rigid_run_pressures`)."""
    theta, z, pressures = rigid_run_pressures(case, crank_angles_deg)
    schemes = {angle: housing.stresses(p, z, np.radians(angle), theta)
               for angle, p in zip(crank_angles_deg, pressures, strict=True)}
    source = f"film pressure of the {case.solver.film} film on the rigid bore"
    return StressResults(housing.structure, schemes, source)
