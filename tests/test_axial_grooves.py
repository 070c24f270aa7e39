"""Axial oil grooves: case-file mapping, limits and flow balance in the grid films."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.base import validate_section
from conrod.cases.bearing import BearingSection
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.steady import solve_for_load
from conrod.film.supply import supply_mask

D, L, C, MU = 0.06, 0.024, 3.0e-5, 0.01
R = 0.5 * D


def bearing(grooves: list[dict], supply: float = 3.0e5) -> BearingGeometry:
    data = {"diameter": D, "width": L, "radial_clearance": C, "supply_pressure": supply,
            "axial_grooves": grooves}
    return validate_section(BearingSection, data, "bearing").geometry()


def test_axial_groove_maps_onto_a_full_length_groove():
    geometry = bearing([{"angle": 90.0, "width": 0.004}])
    (groove,) = geometry.grooves
    assert groove.extent == pytest.approx(0.004 / R, rel=1e-14)
    assert groove.start_angle + 0.5 * groove.extent == pytest.approx(0.5 * math.pi, rel=1e-14)
    assert groove.width == L and groove.axial_position == 0.0
    film = ReynoldsFilm(geometry, n_theta=144, n_z=16)
    mask = supply_mask(geometry, film.film_grid)
    columns = np.flatnonzero(mask.any(axis=1))
    centre = film.film_grid.theta[columns].mean()
    assert centre == pytest.approx(0.5 * math.pi, abs=0.5 * film.film_grid.d_theta)
    assert mask[columns[0], 1:-1].all() and not mask[:, [0, -1]].any()


def test_axial_groove_input_errors_name_the_field():
    with pytest.raises(CaseError, match=r"bearing.axial_grooves\[0\].length"):
        bearing([{"angle": 0.0, "width": 0.003, "length": 2 * L}])
    with pytest.raises(CaseError, match="width"):
        bearing([{"angle": 0.0, "width": 0.0}])


def test_groove_in_the_ruptured_zone_at_ambient_pressure_changes_nothing():
    """Holding p = 0 where the ungrooved Swift–Stieber film is already at p_cav = 0 leaves
    the discrete solution unchanged (the complementarity problem keeps its solution)."""
    state = FilmState(eccentricity_x=0.7 * C, eccentricity_y=0.0, journal_speed=300.0, viscosity=MU)
    plain = ReynoldsFilm(BearingGeometry(diameter=D, width=L, radial_clearance=C), 72, 16).solve(
        state, with_pressure=True)
    theta_low = 0.5 * math.pi  # after the minimum film at θ = 0 for ω > 0: cavitated
    grooved_geometry = bearing([{"angle": math.degrees(theta_low), "width": 0.002}], supply=0.0)
    grooved = ReynoldsFilm(grooved_geometry, 72, 16).solve(state, with_pressure=True)
    mask = supply_mask(grooved_geometry, ReynoldsFilm(grooved_geometry, 72, 16).film_grid)
    assert np.all(plain.pressure[mask] == 0.0)
    assert grooved.force_x == pytest.approx(plain.force_x, rel=1e-9)
    assert grooved.force_y == pytest.approx(plain.force_y, rel=1e-9)


def test_grooved_film_converges_to_ungrooved_as_groove_shrinks():
    """A pressurised groove in the loaded film: the force change falls monotonically as
    the groove's axial length shrinks (fine grid, groove ≥ 2 axial intervals)."""
    state = FilmState(eccentricity_x=0.6 * C, eccentricity_y=0.0, journal_speed=300.0, viscosity=MU)
    plain = ReynoldsFilm(BearingGeometry(diameter=D, width=L, radial_clearance=C,
                                         supply_pressure=1e6), 144, 64).solve(state)
    changes = []
    for fraction in (1.0, 0.5, 0.25, 0.125, 0.0625):
        geometry = bearing([{"angle": 200.0, "width": 0.002, "length": fraction * L}], 1e6)
        r = ReynoldsFilm(geometry, 144, 64).solve(state)
        changes.append(math.hypot(r.force_x - plain.force_x, r.force_y - plain.force_y))
    assert np.all(np.diff(changes) < 0.0)
    assert changes[-1] < 0.5 * changes[0]
    assert changes[0] > 0.01 * math.hypot(plain.force_x, plain.force_y)


@pytest.mark.parametrize("model", ["reynolds", "mass_conserving"])
def test_supply_through_grooves_balances_side_flow(model):
    """Steady, fed, uncavitated: all oil entering through the two grooves leaves at the
    edges (discrete conservation)."""
    geometry = bearing([{"angle": 90.0, "width": 0.003}, {"angle": 270.0, "width": 0.003}],
                       supply=5.0e5)
    state = FilmState(eccentricity_x=0.1 * C, eccentricity_y=0.0, journal_speed=20.0, viscosity=MU)
    if model == "reynolds":
        result = ReynoldsFilm(geometry, 96, 24).solve(state)
    else:
        result = MassConservingFilm(geometry, 96, 24, tolerance=1e-12).solve(state)
    assert result.cavitated_fraction == 0.0
    assert result.supply_flow > 0.0
    assert result.supply_flow == pytest.approx(result.side_flow, rel=1e-8)


def test_steady_calculator_sees_the_grooves():
    plain = solve_for_load(2000.0, 300.0, MU, BearingGeometry(diameter=D, width=L,
                                                              radial_clearance=C,
                                                              supply_pressure=5e5))
    grooved = solve_for_load(2000.0, 300.0, MU, bearing(
        [{"angle": 90.0, "width": 0.003}, {"angle": 270.0, "width": 0.003}], supply=5.0e5))
    assert grooved.inlet_flow > plain.inlet_flow
    assert grooved.eccentricity != pytest.approx(plain.eccentricity, rel=1e-3)
