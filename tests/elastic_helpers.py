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


def captured_mass_step(film, request, memory):
    """One implicit step of the journal with mass (:func:`conrod.ehd.mass_step.
    mass_step` from ``memory``, BDF2 with ``memory`` as the previous one too) and the
    residual parts its Newton iteration was given: (outcome, captured dict)."""
    import conrod.ehd.mass_step as module

    captured = {}
    original = module.newton_balance

    def capture(evaluate, respond, u0, v0, load, inertia, operator, clearance, v_scale,
                *args, **kwargs):
        captured.update(evaluate=evaluate, respond=respond, load=load, inertia=inertia,
                        operator=operator, clearance=clearance, v_scale=v_scale)
        return original(evaluate, respond, u0, v0, load, inertia, operator, clearance,
                        v_scale, *args, **kwargs)

    module.newton_balance = capture
    try:
        outcome = module.mass_step(film, request, memory, memory)
    finally:
        module.newton_balance = original
    return outcome, captured


def step_jacobian_and_residual(outcome, captured):
    """At the converged step: the exact Jacobian of the scaled residual (G/c, (F + W −
    m a)/|W|) from the film response, the residual function of z = (u/c, v/v_s), z there
    and the film payload: (jacobian, residual, z0, payload)."""
    from conrod.ehd.newton import _inverse

    c, v_scale = captured["clearance"], captured["v_scale"]
    n = len(outcome.memory.deformation)
    w_scale = float(np.hypot(*captured["load"])) + 1.0

    def residual(z):
        u, v = c * z[:n], v_scale * z[n:]
        forces, force, _, _ = captured["evaluate"](u, v)
        g = (u - captured["operator"] @ forces - captured["inertia"]) / c
        return np.concatenate([g, (force + captured["load"]) / w_scale])

    payload = captured["evaluate"](outcome.memory.deformation, outcome.velocity)[3]
    jac = np.linalg.inv(_inverse(captured["respond"](payload), captured["operator"], n, c,
                                 v_scale, w_scale, True))
    z0 = np.concatenate([outcome.memory.deformation / c, outcome.velocity / v_scale])
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
