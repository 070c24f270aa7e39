"""Compiled Reynolds film force and force Jacobian with a warm start, for the orbit with mass.

The implicit orbit integrator (:mod:`conrod.orbit.tr_bdf2`) runs its whole free flight
compiled when the film force is a numba function. For the rigid, isoviscous
:class:`~conrod.film.reynolds.film.ReynoldsFilm` solved by multigrid this module gives it one:
the discrete source of the Reynolds equation is linear in the squeeze velocity of the
mean frame,

.. math:: b = 12μ\\,w_z R Δθ\\,(v_{s,x}\\cos θ + v_{s,y}\\sin θ), \\qquad
          \\mathbf v_s = \\dot{\\mathbf e} − κ\\bar ω(−e_y, e_x),\\; κ = \\sin Δθ/Δθ,

exactly the central-difference wedge plus squeeze term of
:func:`conrod.film.reynolds.kernel.assemble_coefficients` (Booker [1]; a bore profile h₀
adds its film thickness and its own wedge term, −6μ(ω_j + ω_b) R w_z (h₀,i+1 − h₀,i−1)/2,
a source that does not depend on the state;
:mod:`conrod.film.reynolds.squeeze`), so a force evaluation is one call of the compiled
projected multigrid (:func:`conrod.film.reynolds.multigrid.multigrid_solve`) on the same
grid, masks, supply pressure, cavitation pressure and mid-plane symmetry as the film,
warm-started from the last solved field that the kernel carries in its parameters.

Tolerances: the Newton iterations of the integrator solve the film to a relative change of
``newton_tolerance`` (the integrator's state needs ~1e-8, the film's 1e-12 default is
wasted there); the Jacobian ∂F/∂(e, ė) (forward differences from a converged field, one
warm-started solve per state component) uses the same tolerance, at most 1e-7. Each field
difference of the Jacobian is kept as a tangent ∂p/∂q, q = (e, v_s), and every solve
starts from the last field moved along the tangents to its own q (clipped at the
cavitation pressure): a predictor that leaves the multigrid a smaller correction.

[1] J.F. Booker, "Dynamically loaded journal bearings: mobility method of solution",
    J. Basic Eng. 87 (1965) 537–546.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numba as nb
import numpy as np

from conrod.film.reynolds.memory import ReynoldsMemory
from conrod.film.reynolds.multigrid import multigrid_solve
from conrod.film.reynolds.multigrid_operators import copy_into

JACOBIAN_STEP = 1.0e-5
"""Forward-difference step of the Jacobian: position in units of c, velocity in units of
c |ω_j + ω_b| + |v_s| [-]."""
JACOBIAN_TOLERANCE = 1.0e-7
"""Loosest multigrid tolerance of the Jacobian's solves [-]: the force then carries a
relative error ~3e-9 (measured: ~0.03 × the tolerance), 3e-4 of the difference quotient,
ample for a simplified Newton iteration."""

STATS = ("film solves", "multigrid cycles", "failed solves")
"""Counters in ``params[-1]`` [-]."""


@dataclass
class FlightKernel:
    """A compiled film force with its warm start, for the compiled implicit free flight.

    force : numba function ``(x, y, v_x, v_y, ω_j + ω_b, μ, params) -> (F_x, F_y)`` [N]
        (NaN when the solve failed or the journal leaves the clearance).
    jacobian : numba function ``(x, y, v_x, v_y, ω_j + ω_b, μ, params) -> (F (2,), J (2, 4))``
        with J = ∂F/∂(e_x, e_y, ė_x, ė_y) [N, N/m, N s/m].
    params : tuple  Grid arrays, the warm-start field (changed in place by every call),
        the tangents ∂p/∂q of the last Jacobian and the state q of the last solve, the bore
        profile and its wedge source (empty without one), the film's viscosity field μ(θ, z)
        [Pa s] (empty without one; :mod:`conrod.film.reynolds.viscosity_field`, μ the
        reference) and the counters :data:`STATS`.
    """

    force: Any
    jacobian: Any
    params: tuple
    film: Any

    @property
    def stats(self) -> dict[str, float]:
        """Film solves, multigrid cycles and failed solves so far [-]."""
        return dict(zip(STATS, (float(v) for v in self.params[-1]), strict=True))

    def memory(self):
        """The film's memory (:class:`~conrod.film.reynolds.memory.ReynoldsMemory`) holding the
        last solved field on the full grid."""
        field = self.params[0]
        n_z = self.film.n_z
        if field.shape[1] == n_z + 1:
            return ReynoldsMemory(field.copy())
        mid = n_z // 2
        full = np.empty((field.shape[0], n_z + 1))
        full[:, : mid + 1] = field[:, : mid + 1]
        full[:, mid + 1:] = field[:, mid - 1:: -1]
        return ReynoldsMemory(full)


def flight_kernel(film, memory, newton_tolerance: float) -> FlightKernel | None:
    """The compiled force of a :class:`~conrod.film.reynolds.film.ReynoldsFilm` when it is
    exact for this film (rigid, isoviscous, multigrid, no inlet line at the largest gap),
    warm-started from ``memory`` (a ``ReynoldsMemory``); None otherwise.

    newton_tolerance : float  Multigrid tolerance of the force evaluations [-] (never
        below the film's own ``tolerance``, which the Jacobian uses).
    """
    from conrod.film.reynolds.squeeze import SqueezeGrid, half_rows

    if (film.method != "multigrid" or film.ambient_line_at_max_gap
            or film.pressure_viscosity is not None):
        return None
    grid = SqueezeGrid(film, 1.0)  # sources per unit viscosity
    g = film.geometry
    field = np.zeros(grid.fixed.shape)
    supply = _supply_nodes(film, grid)
    if memory is not None and getattr(memory, "pressure", None) is not None:
        field = _fold(np.asarray(memory.pressure, dtype=float), grid.symmetric, film.n_z)
    field[supply] = g.supply_pressure
    radius, d_theta, d_z, clearance = grid.geometry
    tolerances = np.array([max(float(newton_tolerance), film.tolerance),
                           min(JACOBIAN_TOLERANCE, max(float(newton_tolerance),
                                                       film.tolerance))])
    profile, profile_source = profile_arrays(film, grid)
    viscosity_field = (np.zeros((0, 0)) if film.viscosity_field is None else  # μ(θ, z) [Pa s]
                       kernel_array(half_rows(film.viscosity_field, None)
                                    if grid.symmetric else film.viscosity_field))
    params = (np.ascontiguousarray(field), grid.fixed, grid.source_x, grid.source_y,
              grid.weight_x, grid.weight_y, grid.cos_t, grid.sin_t, radius, d_theta, d_z,
              clearance, grid.n_coarse, grid.symmetric, float(g.cavitation_pressure),
              math.sin(d_theta) / d_theta, tolerances, int(film.max_iterations),
              np.zeros((4,) + field.shape), np.zeros(5), profile, profile_source,
              viscosity_field, np.zeros(3))
    return FlightKernel(reynolds_force, reynolds_jacobian, params, film)


def profile_arrays(film, grid) -> tuple[np.ndarray, np.ndarray]:
    """The bore profile h₀ [m] on the kernel's grid and its wedge source per unit μ(ω_j + ω_b)
    [m⁴] (−3 R w_z (h₀,i+1 − h₀,i−1), the profile's part of the source of
    :func:`conrod.film.reynolds.kernel.assemble_coefficients`, 0 on Dirichlet nodes); empty
    (0, 0) arrays without a profile."""
    from conrod.film.reynolds.squeeze import half_rows

    profile = film.profile
    if profile is None:
        return np.zeros((0, 0)), np.zeros((0, 0))
    g = film.film_grid
    width = np.full(g.n_z + 1, g.d_z)
    width[[0, -1]] *= 0.5
    source = -3.0 * g.radius * width[None, :] * (np.roll(profile, -1, axis=0)
                                                 - np.roll(profile, 1, axis=0))
    if grid.symmetric:
        profile, source = half_rows(profile, None), half_rows(source, 0.0)
    return kernel_array(profile), kernel_array(source * ~grid.fixed)


def kernel_array(values: np.ndarray) -> np.ndarray:
    """A writable C-contiguous float copy of ``values`` for a flight kernel's params. The
    film keeps its fields read-only, and numba types a read-only array apart from a writable
    one: a film's own field passed as it is gave the compiled orbit a second signature,
    compiled again whole (40–100 s of numba for the Reynolds flight, twice that tilted)."""
    return np.array(values, dtype=float, order="C")


def _supply_nodes(film, grid) -> np.ndarray:
    """Supply (groove, hole) nodes on the kernel's grid (half grid when symmetric)."""
    from conrod.film.supply import supply_mask

    mask = supply_mask(film.geometry, film.film_grid)
    return _fold(mask, grid.symmetric, film.n_z, padding=False)


def _fold(field: np.ndarray, symmetric: bool, n_z: int, padding=0.0) -> np.ndarray:
    """Full-grid field → the kernel's grid (z ≤ 0 plus a padding row when symmetric)."""
    if not symmetric:
        return field.copy()
    mid = n_z // 2
    half = np.empty((field.shape[0], mid + 2), dtype=field.dtype)
    half[:, : mid + 1] = field[:, : mid + 1]
    half[:, -1] = padding
    return half


@nb.njit(cache=True, inline="always")
def _squeeze_state(x, y, vx, vy, omega_sum, params):
    """q = (e_x, e_y, v_s,x, v_s,y) [m, m/s]: the pressure depends on the state only
    through q (module docstring)."""
    mean = 0.5 * params[15] * omega_sum
    return np.array([x, y, vx + mean * y, vy - mean * x])


@nb.njit(cache=True, inline="always")
def _predict(q, params):
    """Move the warm-start field along the tangents ∂p/∂q of the last Jacobian from the
    state of the last solve to ``q`` (clipped at the cavitation pressure)."""
    pressure, fixed, cavitation, tangents, anchor = (params[0], params[1], params[14],
                                                     params[18], params[19])
    if anchor[4] == 0.0:
        return
    n, m = pressure.shape
    for i in range(n):
        for j in range(m):
            if fixed[i, j]:
                continue
            value = pressure[i, j]
            for k in range(4):
                value += tangents[k, i, j] * (q[k] - anchor[k])
            pressure[i, j] = value if value > cavitation else cavitation


@nb.njit(cache=True, inline="always")
def _solve(q, viscosity, params, tolerance, omega_sum):
    """Film force [N] at q = (e, v_s), solved in place on the warm-start field (with the
    bore profile's h₀ and wedge source at ω_j + ω_b = ``omega_sum`` when it has one)."""
    (pressure, fixed, src_x, src_y, w_x, w_y, cos_t, sin_t, radius, d_theta, d_z,
     clearance, n_coarse, symmetric, cavitation, _, _, max_cycles, _, anchor,
     profile, profile_source, viscosity_field, stats) = params
    h = clearance - q[0] * cos_t - q[1] * sin_t
    source = viscosity * (q[2] * src_x + q[3] * src_y)
    if profile.shape[0] > 0:
        h = h + profile
        source = source + (viscosity * omega_sum) * profile_source
    if not np.min(h) > 0.0:
        return np.nan, np.nan
    if viscosity_field.shape[0] > 0:  # the conductance thickness h (μ_r/μ)^(1/3)
        h = h * np.cbrt(viscosity / viscosity_field)
    cycles, change = multigrid_solve(pressure, h, source, fixed, radius, d_theta, d_z,
                                     cavitation, tolerance, max_cycles, n_coarse, symmetric)
    stats[0] += 1.0
    stats[1] += cycles
    if not change <= tolerance:
        stats[2] += 1.0
        return np.nan, np.nan
    for k in range(4):
        anchor[k] = q[k]
    return -np.sum(pressure * w_x), -np.sum(pressure * w_y)


@nb.njit(cache=True, inline="always")
def reynolds_force(x, y, vx, vy, omega_sum, viscosity, params):
    """Film force (F_x, F_y) [N] at the Newton tolerance, warm-started from the last field
    moved along the last Jacobian's tangents (module docstring)."""
    q = _squeeze_state(x, y, vx, vy, omega_sum, params)
    _predict(q, params)
    return _solve(q, viscosity, params, params[16][0], omega_sum)


@nb.njit(cache=True, inline="always")
def reynolds_jacobian(x, y, vx, vy, omega_sum, viscosity, params):
    """(F (2,) [N], ∂F/∂(e_x, e_y, ė_x, ė_y) (2, 4) [N/m, N s/m]) by forward differences
    in q = (e, v_s) from the converged field at the state (each solve at the Jacobian
    tolerance); the differences of the fields are kept as the tangents ∂p/∂q."""
    pressure, clearance, tolerance = params[0], params[11], params[16][1]
    tangents, anchor = params[18], params[19]
    q = _squeeze_state(x, y, vx, vy, omega_sum, params)
    _predict(q, params)
    force = np.empty(2)
    by_q = np.full((2, 4), np.nan)
    force[0], force[1] = _solve(q, viscosity, params, tolerance, omega_sum)
    if np.isnan(force[0]):
        return force, by_q
    base = pressure.copy()
    speed = clearance * abs(omega_sum) + math.hypot(q[2], q[3])
    for k in range(4):
        step = JACOBIAN_STEP * (clearance if k < 2 else max(speed, 1e-9 * clearance))
        if k < 2 and q[k] > 0.0:  # towards the centre: a journal closer to the shell than
            step = -step          # the step stays inside it (the film opens, never closes)
        shifted = q.copy()
        shifted[k] += step
        fx, fy = _solve(shifted, viscosity, params, tolerance, omega_sum)
        by_q[0, k] = (fx - force[0]) / step
        by_q[1, k] = (fy - force[1]) / step
        tangent = tangents[k]
        for i in range(pressure.shape[0]):
            for j in range(pressure.shape[1]):
                tangent[i, j] = (pressure[i, j] - base[i, j]) / step
        copy_into(pressure, base)
    for k in range(4):
        anchor[k] = q[k]
    anchor[4] = 1.0
    return force, _in_velocity(by_q, 0.5 * params[15] * omega_sum)


@nb.njit(cache=True, inline="always")
def _in_velocity(by_q, mean):
    """∂F/∂(e, ė) from ∂F/∂(e, v_s), v_s = ė − κω̄(−e_y, e_x) with ``mean`` = κω̄."""
    out = by_q.copy()
    for row in range(2):
        out[row, 0] = by_q[row, 0] - mean * by_q[row, 3]
        out[row, 1] = by_q[row, 1] + mean * by_q[row, 2]
    return out
