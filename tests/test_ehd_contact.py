"""Mixed lubrication on the deformed bore (Greenwood–Tripp asperity pressure on the elastic
film's deformed film thickness) against independent answers: the rigid-shell asperity force
in the stiff limit, central differences of the coupled step's Jacobian, the static force
balance, and the orbit with mass of a case that reaches mixed lubrication."""

from __future__ import annotations

import numpy as np
import pytest

import conrod.elastic.mass_step as mass_step_module
from conrod.contact.asperity import asperity_force
from conrod.elastic.asperity import f52_slope
from conrod.elastic.housing import Housing
from conrod.elastic.mass_step import MassStepRequest, mass_step
from conrod.elastic.newton import _inverse
from conrod.film.base import FilmState
from conrod.simulation import Simulation
from elastic_helpers import kamaz_case


def _mixed(case):
    """The case with Greenwood–Tripp asperity contact (``[contact]`` defaults: σ 0.4 µm)."""
    return case.model_copy(update={"contact": case.contact.model_copy(
        update={"model": "greenwood_tripp"})})


def _stiff(housing: Housing, factor: float) -> Housing:
    """The rod with Young's modulus × ``factor`` and no inertia field (the bore deforms only
    under the pressures it carries)."""
    return Housing(housing.angles, housing.radius, housing.compliance / factor,
                   0.0 * housing.inertia_base, housing.correction, housing.kinematics)


def test_f52_slope_is_the_derivative_of_the_tabulated_f52():
    from conrod.contact.asperity import f52

    for x in (-12.0, -3.2112, 0.5013, 1.8813, 4.0027, 9.0):
        step = 1e-7 if x > -10.0 else 1e-5
        numeric = (f52(x + step) - f52(x - step)) / (2 * step)
        assert f52_slope(x) == pytest.approx(numeric, rel=1e-6)


@pytest.mark.parametrize("eccentricity", [0.985, 0.995])
def test_stiff_limit_gives_the_rigid_shell_asperity_force(eccentricity):
    """Modulus × 1e4 and × 1e5, journal at rest (no hydrodynamic pressure): the asperity
    force on the deformed film against :func:`asperity_force` on the rigid shell (64-point
    Gauss–Legendre over the contact arc). On the undeformed film the 144-node periodic
    trapezoidal rule gives it to < 1e-6; what remains is the bore's deformation under the
    asperity load itself, ≈ 5e-11 m (× 1e4) at h_min = 1.9 σ, which p_a (d ln p_a/dh ≈
    4/σ there) turns into a few 1e-4: hence 1e-3 at e = 0.985 c. Deeper in contact
    (0.995 c, 2 kN) the same deformation argument gives 7e-3, and the deviation is first
    order in the compliance: × 10 stiffer, 10 × smaller (linear elasticity)."""
    case = _mixed(kamaz_case(n_theta=144, n_z=4, film="reynolds"))
    housing = Housing.from_case(case)
    deviations = []
    for factor in (1e4, 1e5):
        simulation = Simulation(case, housing=_stiff(housing, factor), rigid_companion=False)
        film, problem = simulation.film_model(), simulation.problem()
        assert film.carries_asperity() and problem.rigid_asperity is None
        c = problem.clearance
        x, y = eccentricity * c * np.cos(3.5), eccentricity * c * np.sin(3.5)
        state = FilmState(eccentricity_x=x, eccentricity_y=y, velocity_x=0.0,
                          velocity_y=0.0, journal_speed=0.0, shell_speed=0.0,
                          viscosity=problem.viscosity)
        result = film.solve(state)
        rigid = np.array(asperity_force(x, y, c, problem.asperity))
        assert result.extra["asperity_force_N"] > 50.0
        deviations.append(result.extra["asperity_force_N"] / np.hypot(*rigid) - 1.0)
        # the journal force is the asperity force here (no film pressure but the feed's)
        assert np.hypot(result.force_x - rigid[0], result.force_y - rigid[1]) <= (
            0.01 * np.hypot(*rigid))
    if eccentricity < 0.99:
        assert abs(deviations[0]) <= 1e-3
    assert deviations[1] == pytest.approx(0.1 * deviations[0], rel=0.1)


def test_step_jacobian_with_asperity_contact_matches_central_differences():
    """One BDF2 step of the journal with mass on the compliant KamAZ rod, pressed towards
    θ = 200° until the asperities carry ~0.5 % of the load on the deformed film: the exact
    Jacobian (film response plus the asperity's local dp_a/dh terms, velocity columns
    through −τ Σ_j (cos θ_j, sin θ_j) ∂/∂u_j) against central differences of the step's
    residual, within 1e-5 of the largest entry of each column (as without contact)."""
    case = _mixed(kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="implicit"))
    problem = Simulation(case, rigid_companion=False).problem()
    film, c = problem.film, problem.clearance
    memory = film._static_memory()
    dt = np.radians(1.0) / problem.crank_speed
    direction = np.array([np.cos(3.5), np.sin(3.5)])
    load = 20e3
    request = MassStepRequest(
        position_reference=0.985 * c * direction, velocity_reference=np.zeros(2),
        tau=2.0 * dt / 3.0, dt=dt, mass=np.array([problem.mass_x, problem.mass_y]),
        load=-load * direction, journal_speed=272.0, shell_speed=0.0,
        viscosity=problem.viscosity, crank_angle=0.3, guess=np.zeros(2), bdf2=True)
    captured = {}
    original = mass_step_module.newton_balance

    def capture(evaluate, respond, u0, v0, load, inertia, operator, clearance, v_scale,
                *args, **kwargs):
        captured.update(evaluate=evaluate, respond=respond, load=load, inertia=inertia,
                        operator=operator, v_scale=v_scale)
        return original(evaluate, respond, u0, v0, load, inertia, operator, clearance,
                        v_scale, *args, **kwargs)

    mass_step_module.newton_balance = capture
    try:
        outcome = mass_step(film, request, memory, memory)
    finally:
        mass_step_module.newton_balance = original
    assert outcome.converged
    n, w_scale, v_scale = len(memory.deformation), load + 1.0, captured["v_scale"]

    def residual(z):
        u, v = c * z[:n], v_scale * z[n:]
        forces, force, _, _ = captured["evaluate"](u, v)
        g = (u - captured["operator"] @ forces - captured["inertia"]) / c
        return np.concatenate([g, (force + captured["load"]) / w_scale])

    payload = captured["evaluate"](outcome.memory.deformation, outcome.velocity)[3]
    assert np.hypot(*payload.contact_force(film.base)) >= 1e-3 * load  # contact active
    jac = np.linalg.inv(_inverse(captured["respond"](payload), captured["operator"], n, c,
                                 v_scale, w_scale, True))
    z0 = np.concatenate([outcome.memory.deformation / c, outcome.velocity / v_scale])
    contact_node = int(np.argmin(payload.problem.h[:, 0]))
    for column in (n, n + 1, contact_node, contact_node + 1, 3):
        delta = np.zeros(n + 2)
        delta[column] = 1e-6
        numeric = (residual(z0 + delta) - residual(z0 - delta)) / 2e-6
        scale = np.max(np.abs(jac[:, column]))
        assert np.max(np.abs(numeric - jac[:, column])) <= 1e-5 * scale
