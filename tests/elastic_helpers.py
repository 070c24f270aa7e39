"""Meshes and cases shared by the elastic-housing tests."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.housing.mesh_io import write_housing_mesh
from conrod.housing.mesher import annulus_mesh

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def ring_lines(n_theta: int, ring: int) -> np.ndarray:
    """Line cells (n_theta, 2) around ring ``ring`` of :func:`annulus_mesh` numbering."""
    first = ring * n_theta + np.arange(n_theta)
    return np.column_stack([first, ring * n_theta + (np.arange(n_theta) + 1) % n_theta])


def write_ring_msh(path: Path, inner: float, outer: float, n_theta: int, n_radial: int) -> Path:
    """A thick ring as gmsh 2.2 with big_end_bore (inner) and clamp (outer) groups."""
    points, triangles = annulus_mesh(inner, outer, n_theta, n_radial)
    write_housing_mesh(path, points, triangles, {
        "big_end_bore": ring_lines(n_theta, 0), "clamp": ring_lines(n_theta, n_radial)})
    return path


def kamaz_case(housing: dict | None = None, n_theta: int = 72, **solver) -> Case:
    """The KamAZ-740 example with a built-in housing and the given film grid."""
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data["housing"] = {"model": "builtin", **(housing or {})}
    data["solver"] = {**data.get("solver", {}), "n_theta": n_theta, **solver}
    return Case.from_dict(data, base_dir=EXAMPLES)


def tight_coupling(case: Case, tolerance: float = 1e-9) -> Case:
    """``case`` with ``[housing] coupling_tolerance`` = ``tolerance`` [-, of c]: for a test
    that probes a limit below the default tolerance (1e-7 c)."""
    return case.model_copy(update={"housing": case.housing.model_copy(
        update={"coupling_tolerance": tolerance})})


def lame_bore_displacement(inner: float, outer: float, pressure: float, youngs: float,
                           poisson: float) -> float:
    """Plane-stress Lamé ring, outer radius held, inner pressure: u_r(inner) [m].

    u = A r + B / r with u(outer) = 0 and σ_r(inner) = −p (Timoshenko & Goodier §28).
    """
    a_coefficient = -pressure * (1.0 - poisson**2) / (
        youngs * ((1.0 + poisson) + (1.0 - poisson) * outer**2 / inner**2))
    return a_coefficient * (inner - outer**2 / inner)


WINKLER_SETTINGS = {"rigid_start": 0.0, "ramp": np.radians(90.0)}
"""Elastic coupling settings of the Winkler-bore tests: no rigid start, 90° ramp [rad]."""


def winkler_housing(geometry, n_theta: int, bedding: float):
    """A Winkler bore of ``n_theta`` nodes: node j moves out by ``bedding`` [m/N] × its
    nodal force, no inertia field, no rigid-body correction."""
    from conrod.housing.housing import Housing

    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    return Housing(theta, geometry.radius, bedding * np.eye(n_theta), np.zeros((n_theta, 4)),
                   correction="none")


def step_request(problem, memory, *, position_reference, velocity_reference, tau: float,
                 dt: float, load, crank_angle: float, speeds, bdf2: bool = True):
    """A :class:`~conrod.film.step_system.StepRequest` of ``problem`` from ``memory`` (BDF2
    with ``memory`` as the previous one too)."""
    from conrod.film.step_system import StepRequest

    return StepRequest(np.asarray(position_reference, dtype=float),
                       np.asarray(velocity_reference, dtype=float), tau, dt,
                       np.array([problem.mass_x, problem.mass_y]),
                       np.asarray(load, dtype=float), float(speeds[0]), float(speeds[1]),
                       problem.viscosity, crank_angle, bdf2,
                       (memory, memory) if bdf2 else (memory,))


def solved_step(film, request, guess, velocity_scale: float):
    """One implicit step of the journal with ``film``'s own unknowns
    (:func:`conrod.orbit.journal_step.solve_journal_step`)."""
    from conrod.orbit.journal_step import solve_journal_step

    return solve_journal_step(film, request, np.asarray(guess, dtype=float), velocity_scale)


def step_jacobian_and_residual(film, request, own, velocity, velocity_scale: float):
    """At (y, v) = (``own``, ``velocity``) of the step ``request``: the Jacobian of the
    scaled residual (G/s_y, (F + W − m a)/(|W| + 1 N)) that the Newton iteration inverts
    (from the step system's exact blocks), the residual function of z = (y/s_y, v/s_v)
    (each evaluation by a fresh step system, so that every film solve starts from the
    request's memory), z there and the payload: (jacobian, residual, z0, payload)."""
    from conrod.numerics.newton import length, scaled_jacobian
    from conrod.orbit.journal_step import JournalStep

    load = np.asarray(request.load, dtype=float)
    w_scale = length(load) + 1.0
    scale, n, k = film.step_system(request).scale, len(own), len(velocity)

    def residual(z):
        system = JournalStep(film.step_system(request), request)
        g, force, _, _ = system.evaluate(scale * z[:n], velocity_scale * z[n:])
        return np.concatenate([g / scale, (force + load) / w_scale])

    system = JournalStep(film.step_system(request), request)
    payload = system.evaluate(np.asarray(own, dtype=float),
                              np.asarray(velocity, dtype=float))[3]
    jac = scaled_jacobian(system.respond(payload), scale, velocity_scale, w_scale, k)
    z0 = np.concatenate([np.asarray(own) / scale, np.asarray(velocity) / velocity_scale])
    return jac, residual, z0, payload


def assert_jacobian_columns(jac, residual, z0, columns, step: float = 1e-6,
                            tolerance: float = 1e-5) -> None:
    """Central differences of ``residual`` at ``z0`` equal the ``columns`` of ``jac``
    within ``tolerance`` of each column's largest entry."""
    for column in columns:
        delta = np.zeros(len(z0))
        delta[column] = step
        numeric = (residual(z0 + delta) - residual(z0 - delta)) / (2.0 * step)
        scale = np.max(np.abs(jac[:, column]))
        assert np.max(np.abs(numeric - jac[:, column])) <= tolerance * scale
