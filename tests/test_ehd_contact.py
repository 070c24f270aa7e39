"""Mixed lubrication on the deformed bore (Greenwood–Tripp asperity pressure on the elastic
film's deformed film thickness) against independent answers: the rigid-shell asperity force
in the stiff limit, central differences of the coupled step's Jacobian, the static force
balance, and the orbit with mass of a case that reaches mixed lubrication."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from conrod.contact.asperity import asperity_force, asperity_pressure
from conrod.ehd.asperity import f52_slope
from conrod.ehd.film import ElasticFilm
from conrod.film.base import FilmState
from conrod.housing.housing import Housing
from conrod.simulation.simulation import Simulation
from elastic_helpers import (
    assert_jacobian_columns,
    kamaz_case,
    solved_step,
    step_jacobian_and_residual,
    step_request,
    tight_coupling,
)


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
    order in the compliance: × 10 stiffer, 10 × smaller (linear elasticity). With the
    journal turning, the film pressure at these gaps (~GPa) still deforms the × 1e4 rod by
    ~0.1 µm, so the comparison is made where only the asperities load the bore. The
    deformation at × 1e5, 5e-12 m, is the default coupling tolerance (1e-7 c): the
    coupling is run to 1e-9 c here so that the deformation, not the tolerance, is seen."""
    case = tight_coupling(_mixed(kamaz_case(n_theta=144, n_z=4, film="reynolds")))
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
    request = step_request(
        problem, memory, position_reference=0.985 * c * direction,
        velocity_reference=np.zeros(2), tau=2.0 * dt / 3.0, dt=dt, load=-load * direction,
        crank_angle=0.3, speeds=(272.0, 0.0))
    scale = c * problem.crank_speed
    done = solved_step(film, request, np.zeros(2), scale)
    assert done.newton.converged
    jac, residual, z0, payload = step_jacobian_and_residual(film, request, done.newton.own,
                                                            done.velocity, scale)
    assert np.hypot(*payload.contact_force()) >= 1e-3 * load  # contact active
    n = len(memory.deformation)
    contact_node = int(np.argmin(payload.problem.h[:, 0]))
    assert_jacobian_columns(jac, residual, z0, (n, n + 1, contact_node, contact_node + 1, 3))


@pytest.fixture(scope="module")
def slow_case(tmp_path_factory):
    """KamAZ bearing, the built-in rod's compliance imported, mixed lubrication and a
    constant 10 kN [load] table towards θ = 200° at 100 rpm, where the film alone would need
    h_min well below the roughness."""
    import tomllib

    from conrod.cases.case import Case
    from elastic_helpers import EXAMPLES

    folder = tmp_path_factory.mktemp("mixed_static")
    builtin = Housing.from_case(kamaz_case(n_theta=STATIC_GRID[0]))
    np.savez(folder / "c.npz", angle_deg=np.degrees(builtin.angles),
             compliance_m_per_N=builtin.compliance)
    angles = np.arange(0.0, 721.0, 10.0)
    rows = [f"{a},{STATIC_LOAD * np.cos(STATIC_DIRECTION)},"
            f"{STATIC_LOAD * np.sin(STATIC_DIRECTION)}" for a in angles]
    (folder / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + "\n".join(rows))
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data = {key: data[key] for key in ("title", "bearing", "lubricant")}
    data["load"] = {"table": "load.csv", "speed": STATIC_SPEED_RPM, "cycle_deg": 720}
    data["housing"] = {"model": "compliance", "compliance_file": "c.npz"}
    data["solver"] = {"film": "reynolds", "n_theta": STATIC_GRID[0], "n_z": STATIC_GRID[1]}
    data["contact"] = {"model": "greenwood_tripp"}
    return Case.from_dict(data, base_dir=folder)


STATIC_GRID = (36, 8)
STATIC_LOAD = 10e3
"""Constant load [N]."""
STATIC_DIRECTION = np.radians(200.0)
STATIC_SPEED_RPM = 10.0


def _static_equilibrium(film, loads, viscosity: float):
    """Journal at rest: position (x, y) [m] with F + A + W = 0 by Newton's method
    (finite-difference Jacobian, steps halved where the coupling fails), the coupled result
    there and F + A + W [N]. Each solve starts from the deformation of the last accepted
    iterate moved along with the journal, u_j + δe·(cos θ_j, sin θ_j), so that the start
    keeps its film thickness (an unmoved start closes the film on a step of ~h_min)."""
    from conrod.errors import ConvergenceError, FilmThicknessError

    c = film.geometry.radial_clearance
    load = np.array([loads.load_x[0], loads.load_y[0]])
    size = float(np.hypot(*load))
    trig = np.stack([np.cos(film.housing.angles), np.sin(film.housing.angles)])

    def solve(position, memory, origin):
        state = FilmState(eccentricity_x=c * position[0], eccentricity_y=c * position[1],
                          velocity_x=0.0, velocity_y=0.0,
                          journal_speed=float(loads.journal_speed[0]), shell_speed=0.0,
                          viscosity=viscosity)
        moved = dataclasses.replace(
            memory, deformation=memory.deformation + c * (position - origin) @ trig)
        result, after = film.solve_with_memory(state, moved)
        return result, (np.array([result.force_x, result.force_y]) + load) / size, after

    position = 0.9 * load / size
    result, r, memory = solve(position, film._static_memory(), position)
    for _ in range(40):
        if np.hypot(*r) <= 1e-9:
            break
        jac = np.column_stack([(solve(position + d, memory, position)[1] - r) / 1e-7
                               for d in (np.array([1e-7, 0.0]), np.array([0.0, 1e-7]))])
        step, lam = -np.linalg.solve(jac, r), 1.0
        while True:
            try:
                trial = solve(position + lam * step, memory, position)
            except (FilmThicknessError, ConvergenceError):
                lam *= 0.5
                if lam < 1e-3:
                    raise
                continue
            if np.hypot(*trial[1]) < np.hypot(*r) or lam < 1e-3:
                break
            lam *= 0.5
        position = position + lam * step
        result, r, memory = trial
    return c * position, result, r * size, memory.deformation


def test_static_mixed_equilibrium_balances_film_and_asperities_against_the_load(slow_case):
    """A constant load the film cannot carry alone at 100 rpm: the coupled equilibrium on
    the deformed bore has film + asperity force = load to 1e-6 of its size, the asperities
    carry a share of it, h_min on the deformed film stays > 0, and the journal centre lies
    outside the rigid contact circle (the bore has given way)."""
    simulation = Simulation(slow_case)
    problem = simulation.problem()
    assert problem.film.carries_asperity()
    film = ElasticFilm(problem.film.base, problem.film.housing, problem.film.crank_speed,
                       dataclasses.replace(problem.film.settings, max_iterations=400),
                       problem.asperity)  # room for the large moves of a static Newton step
    loads, mu = simulation.load_cycle(), problem.viscosity
    position, result, balance, deformation = _static_equilibrium(film, loads, mu)
    c = film.geometry.radial_clearance
    assert np.hypot(*balance) <= 1e-6 * STATIC_LOAD
    share = result.extra["asperity_force_N"] / STATIC_LOAD
    assert 0.3 < share < 0.8  # measured 0.56: asperities and film share the load
    assert result.min_film_thickness > 0.0
    assert np.hypot(*position) > 1.2 * c  # measured 1.54 c: the bore has given way
    # the asperity force is p_a(h) of the public law on the deformed gap
    # h_j = c − e·(cos θ_j, sin θ_j) + u_j, integrated by R L Σ Δθ (periodic trapezoid)
    radius, width, sigma, scale = problem.asperity
    theta = film.housing.angles
    gap = c - position[0] * np.cos(theta) - position[1] * np.sin(theta) + deformation
    p_a = asperity_pressure(gap, sigma, scale)
    expected = -radius * width * (2 * np.pi / len(theta)) * np.array(
        [np.sum(p_a * np.cos(theta)), np.sum(p_a * np.sin(theta))])
    assert result.extra["asperity_force_N"] == pytest.approx(np.hypot(*expected), rel=1e-9)


MIXED_VISCOSITY_SHARE = 0.1
"""The KamAZ-740 example's oil viscosity × this: a thin oil that takes the orbit with mass
into mixed lubrication (h_min on the deformed film below the roughness σ = 0.4 µm) [-]."""


def _thin_oil_case_file(folder, mixed: bool) -> str:
    """The KamAZ-740 example on the built-in rod of :func:`kamaz_case` with a tenth of its
    viscosity, the orbit with mass at 1° steps on a 36 × 8 film, with or without
    Greenwood–Tripp asperity contact."""
    import tomllib

    from elastic_helpers import EXAMPLES
    from hardening_helpers import write_case

    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data["lubricant"]["viscosity"] *= MIXED_VISCOSITY_SHARE
    data["housing"] = {"model": "builtin"}
    data["solver"] = {"film": "reynolds", "integrator": "implicit", "n_theta": 36, "n_z": 8,
                      "max_step_deg": 1.0, "output_step_deg": 4.0}
    if mixed:
        data["contact"] = {"model": "greenwood_tripp"}
    return str(write_case(folder, data, "mixed.toml" if mixed else "film_only.toml"))


@pytest.mark.slow
def test_orbit_with_mass_runs_into_mixed_lubrication_on_the_deformed_bore(tmp_path):
    """Thin oil on the KamAZ-740 example (compliant built-in rod): with asperity contact
    the orbit with mass on the elastic bore reaches a periodic cycle with the asperities
    carrying load on the deformed film and the centre outside the rigid contact circle
    (no stop there); cycle.csv's
    contact force is the deformed film's asperity force and the step's force balance holds
    it (F + A + W − m a to 1e-6 of the load). Without asperity contact the same orbit stops
    with exit code 3 naming the crank angle, h_min on the deformed film and the fix."""
    import json

    import pandas as pd
    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app

    _register_commands()
    runner = CliRunner()
    out = tmp_path / "mixed"
    result = runner.invoke(app, ["run", _thin_oil_case_file(tmp_path, True), "--out",
                                 str(out), "--no-rigid", "--no-figures", "--accept-warnings",
                                 "--no-grid-error"])
    assert result.exit_code == 0, result.output
    # this rod's cap opens by ~0.65 c at the gas-exchange TDC (inertia): that warning
    # stays, and h/σ < 1 is boundary lubrication resting on the asperity model; the one
    # about asperities touching without a contact model does not
    assert "boundary lubrication" in result.output
    assert "consider [contact] model" not in result.output
    summary = json.loads((out / "summary.json").read_text())
    assert summary["periodic"]
    cycle = pd.read_csv(out / "cycle.csv")
    c = 50e-6
    assert cycle["asperity_force_N"].max() > 500.0  # measured 2.8 kN
    assert cycle["contact_force_N"].max() == 0.0  # the asperities carry it, no hard contact
    load = np.hypot(cycle["load_x_N"], cycle["load_y_N"])
    assert np.all(cycle["force_residual_N"] <= 1e-6 * (load + 1.0))
    e = np.hypot(cycle["eccentricity_x_m"], cycle["eccentricity_y_m"])
    assert e.max() > c  # beyond the rigid contact circle: the bore has given way
    assert cycle["h_min_m"].min() > 0.0

    failed = runner.invoke(app, ["run", _thin_oil_case_file(tmp_path, False), "--out",
                                 str(tmp_path / "film_only"), "--no-rigid", "--no-figures"])
    assert failed.exit_code == 3, failed.output
    message = " ".join(failed.output.split())
    assert "crank angle" in message and "on the deformed film" in message
    assert "greenwood_tripp" in message and "quasi_static" in message


@pytest.mark.slow
def test_massless_orbit_runs_into_mixed_lubrication_on_the_deformed_bore():
    """The massless orbit (quasi_static) on the same rod with a quarter of the example's
    viscosity: periodic, the asperities carry load on the deformed film (measured up to
    2.9 kN), the film + asperity force balances the load at every output angle, and the
    journal centre goes beyond the rigid contact circle where the bore gives way; its
    contact circle is where the deformed film closes."""
    case = _mixed(kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="quasi_static",
                             quasi_static_step_deg=1.0, output_step_deg=4.0))
    case = case.model_copy(update={"lubricant": case.lubricant.model_copy(
        update={"viscosity": 0.25 * case.lubricant.viscosity})})
    run = Simulation(case, rigid_companion=False).run()
    assert run.elastic.summary.periodic
    asperity = run.columns["asperity_force_N"]
    assert asperity.max() > 500.0
    np.testing.assert_allclose(run.elastic.contact.contact_force, asperity)
    cycle = run.elastic.cycle
    load = np.hypot(cycle.load_x, cycle.load_y)
    assert np.all(run.columns["force_residual_N"] <= 1e-6 * (load + 1.0))
    c = run.elastic.clearance
    assert np.hypot(cycle.eccentricity_x, cycle.eccentricity_y).max() > c
    assert cycle.h_min.min() > 0.0


def test_massless_orbit_without_asperity_contact_names_the_closing_film_and_the_fix():
    """A tenth of the example's viscosity and no asperity model: the massless force balance
    cannot carry the firing load once the deformed film closes; the error names h_min on
    the deformed film and mixed lubrication as the fix (measured: stops at φ = 31°)."""
    from conrod.errors import ConvergenceError

    case = kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="quasi_static",
                      quasi_static_step_deg=1.0, output_step_deg=4.0)
    case = case.model_copy(update={"lubricant": case.lubricant.model_copy(
        update={"viscosity": MIXED_VISCOSITY_SHARE * case.lubricant.viscosity})})
    with pytest.raises(ConvergenceError, match=r"h_min \S+ m on the deformed film; if the "
                       r"film closes, enable mixed lubrication \(\[contact\] model = "
                       r"'greenwood_tripp'\).* at crank angle"):
        Simulation(case, rigid_companion=False).run()


def test_failure_advice_follows_the_deformed_film():
    """A step of the orbit with mass that fails on an open film (the KamAZ-740 rod at
    0.125° steps stalls with h_min 5 µm, 0.1 c) is told to change the step, not to add
    asperity contact; a closing film without an asperity model is told to add it."""
    import types

    from conrod.orbit.system_steps import failure_advice as _advice

    c = 50e-6
    film_only = types.SimpleNamespace(asperity=None, clearance=c)
    assert _advice(film_only, 5e-6).startswith("change solver.max_step_deg")
    assert _advice(film_only, 3.2e-9).startswith("enable mixed lubrication")
    assert _advice(film_only, float("nan")).startswith("enable mixed lubrication")
    mixed = types.SimpleNamespace(asperity=(0.04, 0.03, 0.4e-6, 1e5), clearance=c)
    assert _advice(mixed, 3.2e-9).startswith("change solver.max_step_deg")
