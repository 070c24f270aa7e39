"""The rod-stress study (``conrod stress``): the rod under the film pressure of a run and
under the same resultant as a cosine load (:mod:`conrod.housing.stresses` compares the two
load schemes), as :class:`conrod.results.housing.StressResults`.

The film pressure is the one of the run the study is given: the elastic run of the case
(the film on the deforming bore, when the case's film can take the bore deformation), run
here, or the pressure fields an elastic run wrote (``film_pressure.npz``, read by the
command line); where the case's film cannot take the deformation (the short film) the run
is the rigid-bore one, and the study says so in ``pressure_source``.
"""

from __future__ import annotations

import numpy as np

from conrod.results.housing import StressResults
from conrod.simulation.simulation import Simulation


def nearest_angle(available: list[float], angle: float, cycle_deg: float = 720.0) -> float:
    """The angle of ``available`` [deg] nearest to ``angle`` [deg] around the cycle."""
    offsets = [abs((a - angle + 0.5 * cycle_deg) % cycle_deg - 0.5 * cycle_deg)
               for a in available]
    return available[int(np.argmin(offsets))]


def stress_study(case, housing, crank_angles_deg: list[float], film: str | None = None,
                 **overrides) -> StressResults:
    """Both load schemes at every crank angle [deg] under the film pressure of the run of
    ``case`` (``film`` and ``overrides`` as :class:`Simulation` takes them, e.g.
    ``n_theta=36``): the coupled elastic run when its film takes the bore deformation,
    else the rigid-bore run, named in ``pressure_source``."""
    staged = case.with_(housing__stress_angles=[float(a) for a in crank_angles_deg])
    simulation = Simulation(staged, film=film, housing=housing, rigid_companion=False,
                            **overrides)
    results = simulation.run()
    grid = f"{simulation.solver.n_theta}×{simulation.solver.n_z} grid, "
    name = results.summary.film_model
    if getattr(results, "pressure_fields", None):
        theta, z = results.elastic.pressure_grid
        fields = {angle: results.pressure_fields[nearest_angle(sorted(results.pressure_fields),
                                                               angle)]
                  for angle in crank_angles_deg}
        source = (f"film pressure of the coupled elastic run ({name} film, "
                  f"{grid if name != 'short' else ''}deformed bore), run for this study")
    else:
        theta, z, fields = _rigid_pressures(simulation, results, crank_angles_deg)
        source = (f"film pressure of the rigid-bore run ({name} film): this film cannot take "
                  "the bore deformation, so the rod is loaded with the pressure of a rigid "
                  "bore (a film with a grid, --film reynolds, couples it)")
    return stress_study_from_fields(housing, theta, z, fields, source,
                                    _run_items(results, simulation), simulation.case_record())


def stress_study_from_fields(housing, theta: np.ndarray, z: np.ndarray,
                             fields: dict[float, np.ndarray], source: str,
                             run: dict | None = None, record=None) -> StressResults:
    """Both load schemes at the crank angles [deg] of ``fields`` (angle → film pressure
    p(θ, z) [Pa] on the grid θ [rad], z [m]); ``source`` says which run's pressure it is,
    ``record`` the case (:class:`conrod.results.case_record.CaseRecord`)."""
    schemes = {angle: housing.stresses(p, z, np.radians(angle), theta)
               for angle, p in fields.items()}
    return StressResults(housing.structure, schemes, source, run or {}, record)


def _rigid_pressures(simulation: Simulation, results, crank_angles_deg: list[float]):
    """(θ [rad], z [m], angle [deg] → p(θ, z) [Pa]) of the rigid-bore run, the film solved
    again at the output angle nearest to each requested one."""
    cycle = results.cycle
    film = simulation.film_model()
    problem = simulation.problem()  # its row state: tilt and crank-pin holes of the row
    theta, z = film.grid()
    fields = {}
    for angle in crank_angles_deg:
        k = int(np.argmin(np.abs(np.mod(cycle.crank_angle_deg - angle + 360.0, 720.0) - 360.0)))
        state = problem.row_state(cycle, k, viscosity=results.summary.viscosity)
        fields[angle] = film.solve(state, with_pressure=True).pressure
    return np.asarray(theta), np.asarray(z), fields


def _run_items(results, simulation: Simulation) -> dict:
    """What identifies the run whose pressure loads the rod [SI units, deg]."""
    s = results.summary
    return {"film_model": s.film_model, "housing": (results.model or {}).get("housing"),
            "n_theta": simulation.solver.n_theta, "n_z": simulation.solver.n_z,
            "h_min_m": s.film_h_min if s.film_h_min is not None else s.h_min,
            "p_max_Pa": s.p_max, "p_max_crank_angle_deg": float(np.degrees(s.p_max_crank_angle)),
            "warnings": list(s.warnings)}
