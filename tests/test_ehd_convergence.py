"""Grid convergence of the elastohydrodynamic film: the coupled h_min and p_max of the
shipped KamAZ-740 rod at a fixed journal state, refining the film grid and the FE mesh
together (the bore nodes are the film nodes and the elements near the bore shrink with their
spacing); observed order from a log-log fit of the differences to the finest grid."""

from __future__ import annotations

import tomllib

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.ehd.film import ElasticFilm
from conrod.film.base import FilmState
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.housing.housing import Housing
from conrod.units import rpm_to_rad_s
from elastic_helpers import EXAMPLES

GRIDS = ((16, 4), (32, 8), (64, 16), (128, 32))


def _coupled(n_theta: int, n_z: int) -> tuple[float, float, float]:
    """(h_min [m], p_max [Pa], max|u| [m]) of the coupled film at ε = 0.95 towards the cap."""
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data["solver"] = {"film": "reynolds", "n_theta": n_theta, "n_z": n_z}
    case = Case.from_dict(data, base_dir=EXAMPLES)
    housing = Housing.from_case(case, use_cache=False)
    film = ElasticFilm(ReynoldsFilm(case.bearing.geometry(), n_theta=n_theta, n_z=n_z),
                       housing, crank_speed=rpm_to_rad_s(case.engine.speed))
    c = case.bearing.radial_clearance
    angle = np.radians(170.0)  # the cap side, where the rod is most compliant
    state = FilmState(eccentricity_x=0.95 * c * np.cos(angle),
                      eccentricity_y=0.95 * c * np.sin(angle), velocity_x=0.0, velocity_y=0.0,
                      journal_speed=rpm_to_rad_s(case.engine.speed), shell_speed=0.0,
                      viscosity=case.lubricant.viscosity)
    result, memory = film.solve_with_memory(state, film._static_memory())
    assert result.extra["coupling_residual_m"] <= film.coupling.tolerance
    return result.min_film_thickness, result.max_pressure, float(np.max(np.abs(
        memory.deformation)))


@pytest.mark.slow
def test_elastic_hmin_and_pmax_converge_with_the_film_grid_and_the_fe_mesh():
    values = np.array([_coupled(*grid) for grid in GRIDS])
    h_min, p_max, bore = values.T
    # the deformation is not negligible: of the order of the film thickness
    assert bore[-1] > 0.3 * h_min[-1]
    sizes = 1.0 / np.array([grid[0] for grid in GRIDS[:-1]])
    for quantity in (h_min, p_max):
        errors = np.abs(quantity[:-1] - quantity[-1])
        order = np.polyfit(np.log(sizes), np.log(errors), 1)[0]
        # second-order finite differences and quadratic elements: observed order near 2
        assert 1.5 < order < 3.5, (order, quantity)
        assert errors[-1] < 0.05 * abs(quantity[-1])
