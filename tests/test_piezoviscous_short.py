"""Piezoviscous short-bearing film and its use in cases and orbits."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import integrate

from conrod.cases.base import validate_section
from conrod.cases.solver import SolverSection
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState, Groove
from conrod.film.factory import GroovedShortBearingFilm, build_film_model
from conrod.film.piezoviscosity import PressureViscosity
from conrod.film.short.film import ShortBearingFilm

MU0, D, L, C = 0.0065, 0.05, 0.02, 2.5e-5
R = 0.5 * D
BARUS = PressureViscosity("barus", coefficient=1.5e-8)
STATE = FilmState(eccentricity_x=0.8 * C * math.cos(1.0), eccentricity_y=0.8 * C * math.sin(1.0),
                  velocity_x=0.004,
                  velocity_y=-0.002, journal_speed=210.0, viscosity=MU0)


def quadrature_force(state: FilmState, law: PressureViscosity) -> np.ndarray:
    """F = −∫∫ p(q(θ, z)) (cos θ, sin θ) R dθ dz by adaptive 2-D quadrature of the
    short-bearing reduced pressure (Reynolds equation with ∂/∂θ of the flow dropped)."""
    ex, ey, vx, vy = (state.eccentricity_x, state.eccentricity_y, state.velocity_x,
                      state.velocity_y)

    def pressure(z: float, theta: float) -> float:
        h = C - ex * math.cos(theta) - ey * math.sin(theta)
        dh_dtheta = ex * math.sin(theta) - ey * math.cos(theta)
        dh_dt = -vx * math.cos(theta) - vy * math.sin(theta)
        source = 6.0 * MU0 * (state.journal_speed * dh_dtheta + 2.0 * dh_dt)
        q = max(-source * (0.25 * L * L - z * z) / (2.0 * h**3), 0.0)
        return float(law.from_reduced(q, MU0))

    force = []
    for trig in (math.cos, math.sin):
        value, _ = integrate.dblquad(lambda z, t, f=trig: pressure(z, t) * f(t) * R,
                                     0.0, 2.0 * math.pi, -0.5 * L, 0.5 * L,
                                     epsabs=0.0, epsrel=1e-9)
        force.append(-value)
    return np.array(force)


def test_zero_coefficient_reproduces_closed_form_to_round_off():
    law = PressureViscosity("barus", coefficient=0.0)
    geometry = BearingGeometry(diameter=D, width=L, radial_clearance=C)
    closed = ShortBearingFilm(geometry).solve(STATE)
    mapped = ShortBearingFilm(geometry, pressure_viscosity=law).solve(STATE)
    assert mapped.force_x == pytest.approx(closed.force_x, rel=1e-11)
    assert mapped.force_y == pytest.approx(closed.force_y, rel=1e-11)
    assert mapped.friction_torque_journal == pytest.approx(closed.friction_torque_journal,
                                                           rel=1e-11)


@pytest.mark.parametrize("law", [BARUS, PressureViscosity("roelands", roelands_index=0.6)])
def test_piezoviscous_force_matches_adaptive_quadrature(law):
    film = ShortBearingFilm(BearingGeometry(diameter=D, width=L,
                                            radial_clearance=C), pressure_viscosity=law)
    result = film.solve(STATE)
    reference = quadrature_force(STATE, law)
    iso = ShortBearingFilm(BearingGeometry(diameter=D, width=L, radial_clearance=C)).solve(STATE)
    assert np.hypot(result.force_x - reference[0], result.force_y - reference[1]) <= (
        1e-6 * np.hypot(*reference))
    assert np.hypot(*reference) > 1.2 * math.hypot(iso.force_x, iso.force_y)
    assert result.max_pressure == pytest.approx(
        float(law.from_reduced(iso.max_pressure, MU0)), rel=1e-12)
    assert result.side_flow == iso.side_flow  # the flux depends on q only


def test_factory_passes_law_and_maps_refuse_it():
    solver = validate_section(SolverSection, {"film": "short"}, "solver")
    film = build_film_model(solver, BearingGeometry(diameter=D, width=L,
                                                    radial_clearance=C), pressure_viscosity=BARUS)
    assert film.pressure_viscosity is BARUS
    grooved = BearingGeometry(diameter=D, width=L, radial_clearance=C,
                              grooves=(Groove(width=0.003),))
    two_lands = build_film_model(solver, grooved, pressure_viscosity=BARUS)
    assert isinstance(two_lands, GroovedShortBearingFilm)
    assert two_lands.land.pressure_viscosity is BARUS
    for name in ("table", "mobility"):
        with pytest.raises(CaseError, match="pressure_viscosity"):
            build_film_model(solver, BearingGeometry(diameter=D, width=L,
                                                     radial_clearance=C), name=name,
                             pressure_viscosity=BARUS)


def test_simulation_builds_the_case_law_and_refuses_maps(repo):
    import tomllib

    from conrod.cases.case import Case
    from conrod.simulation.simulation import Simulation

    path = repo / "examples" / "passenger_car_diesel_2000rpm.toml"
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    data["lubricant"].update(pressure_viscosity="barus", pressure_viscosity_coefficient=1.5e-8)
    case = Case.from_dict(data, base_dir=path.parent, path=path)
    film = Simulation(case).film_model()
    assert film.pressure_viscosity == case.lubricant.pressure_viscosity_law()
    data["solver"] = {**data.get("solver", {}), "film": "table"}
    with pytest.raises(CaseError, match="force ∝ μω"):
        Simulation(Case.from_dict(data, base_dir=path.parent, path=path)).film_model()


def test_table_over_a_piezoviscous_base_is_refused():
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.film.table.film import TabulatedFilm

    base = ReynoldsFilm(BearingGeometry(diameter=D, width=L,
                                        radial_clearance=C), 36, 8, pressure_viscosity=BARUS)
    with pytest.raises(CaseError, match="force ∝ μω"):
        TabulatedFilm(base, use_cache=False)
