"""Orchestrator of one clearance-mechanism run: integrate, sample, check energy.

.. code-block:: python

    results = simulate(mechanism, gas_table, RunSettings(cycles=2))
    results.summary()["max_impact_velocity_big_end_m_s"]
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numba import njit

from conrod.cases.mechanism import MAX_OUTPUT_ROWS
from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import check_range
from conrod.loads.kinematics import piston_displacement
from conrod.mechanism import integrator as rk
from conrod.mechanism import kernel as k
from conrod.mechanism.model import Mechanism, seed_initial_state
from conrod.mechanism.results import Impacts, MechanismResults

CYCLE = 4.0 * math.pi
"""Four-stroke cycle [rad]."""
MIN_GAS_POINTS = 1
"""Fewest gas-force values over the cycle that :func:`simulate` interpolates [-]."""


@dataclass(frozen=True)
class RunSettings:
    """Numerics of a run.

    cycles : int  Engine cycles of 4π integrated; results use the last one [-].
    tolerance : float  Local error per step relative to the smallest radial clearance [-].
    output_step : float  Crank-angle spacing of the sampled results [rad].
    max_step : float  Largest integrator step [rad].
    fixed_step : float | None  Run at this fixed step instead of adaptively [rad].
    impact_separation : float  Separation, as a fraction of the joint's smallest radial
        clearance, needed before a new contact entry counts as an impact [-].
    max_steps : int  Step budget; exceeding it raises ConvergenceError [-].
    """

    cycles: int = 2
    tolerance: float = 1.0e-4
    output_step: float = math.radians(0.5)
    max_step: float = math.radians(0.25)
    fixed_step: float | None = None
    impact_separation: float = 0.01
    max_steps: int = 20_000_000

    def __post_init__(self) -> None:
        """Every setting in its range (those of ``[clearance]`` and its budgets)."""
        for name in ("cycles", "max_steps"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int | np.integer):
                raise CaseError(f"RunSettings {name} = {value!r}: a whole number is required")
        check_range("RunSettings", "cycles", self.cycles, 1, 50, "cycles")
        check_range("RunSettings", "max_steps", self.max_steps, 1, 1e9, "steps")
        for name, high, unit in (("tolerance", 0.1, "(of the smallest radial clearance)"),
                                 ("impact_separation", 1.0, "(of the smallest radial clearance)"),
                                 ("output_step", math.radians(10.0), "rad"),
                                 ("max_step", math.radians(5.0), "rad")):
            check_range("RunSettings", name, getattr(self, name), 0.0, high, unit, low_open=True)
        if self.fixed_step is not None:
            check_range("RunSettings", "fixed_step", self.fixed_step, 0.0, math.radians(5.0),
                        "rad", low_open=True)
        rows = self.cycles * CYCLE / self.output_step
        if rows > MAX_OUTPUT_ROWS:
            raise CaseError(f"RunSettings output_step = {self.output_step!r}: out of range "
                            f"(allowed: >= {self.cycles * CYCLE / MAX_OUTPUT_ROWS:.3g} rad "
                            f"with cycles = {self.cycles}, budget {MAX_OUTPUT_ROWS} rows)")


def rigid_piston_position(crank_angle: np.ndarray, crank_radius: float, rod_length: float):
    """Exact slider-crank pin position from the crank centre x = r cos α + √(L² − r² sin² α)
    = r + L − s(α) [m], s the piston displacement of the loads stage
    (:func:`conrod.loads.kinematics.piston_displacement`)."""
    return crank_radius + rod_length - piston_displacement(crank_angle, crank_radius, rod_length)


def error_scale(mechanism: Mechanism, tolerance: float) -> np.ndarray:
    """Absolute error scale of each state component (clearance-sized) [m, m/rad, rad, J]."""
    reference = tolerance * min(mechanism.big_end.radial_clearance_min,
                                mechanism.small_end.radial_clearance_min)
    angle = reference / mechanism.crank.rod_length
    return np.array([reference, reference, reference, reference, angle, angle,
                     reference, reference, 1.0e300])


def simulate(
    mechanism: Mechanism, gas_table: np.ndarray, settings: RunSettings
) -> MechanismResults:
    """Integrate ``settings.cycles`` cycles from the [D3] initial state at firing TDC.

    gas_table : ndarray  Gas force on the piston at equally spaced angles over [0, 4π) [N].
    Raises ConvergenceError when the integrator fails or exceeds its step budget, and
    CaseError naming the argument when one is not what it must be.
    """
    table = checked_arguments(mechanism, gas_table, settings)
    p = mechanism.parameters()
    y0 = seed_initial_state(mechanism, float(table[0]))
    end = settings.cycles * CYCLE
    samples = int(round(end / settings.output_step))
    out_alpha = np.linspace(0.0, end, samples + 1)
    separation = settings.impact_separation * np.array(
        [mechanism.big_end.radial_clearance_min, mechanism.small_end.radial_clearance_min])
    adaptive = settings.fixed_step is None
    step = settings.fixed_step if not adaptive else min(1e-5, settings.max_step)
    max_step = settings.fixed_step if not adaptive else settings.max_step
    out_y, impacts, count, steps, rejected, status, reached = rk.integrate(
        y0, 0.0, end, p, table, error_scale(mechanism, settings.tolerance), step, max_step,
        adaptive, out_alpha, separation, settings.max_steps, 200_000)
    _check_status(status, reached, steps)
    count = min(count, impacts.shape[0])
    found = Impacts(impacts[:count, 0], impacts[:count, 1].astype(int), impacts[:count, 2])
    return _assemble(mechanism, p, table, out_alpha, out_y, found, settings, steps, rejected)


def checked_arguments(mechanism: Any, gas_table: Any, settings: Any) -> np.ndarray:
    """The gas table as a contiguous float array, once the arguments of :func:`simulate`
    are what they must be; otherwise :class:`CaseError` naming the argument."""
    for name, value, kind in (("mechanism", mechanism, Mechanism),
                              ("settings", settings, RunSettings)):
        if not isinstance(value, kind):
            raise CaseError(f"simulate: {name} = {type(value).__name__}: a "
                            f"conrod.mechanism.{kind.__name__} is required")
    try:
        table = np.ascontiguousarray(gas_table, dtype=float)
    except (TypeError, ValueError):
        table = np.zeros(0)
    if table.ndim != 1 or table.size < MIN_GAS_POINTS or not np.all(np.isfinite(table)):
        raise CaseError(f"simulate: gas_table of shape {np.shape(gas_table)}: out of range "
                        f"(allowed: a 1-D array of >= {MIN_GAS_POINTS} finite gas forces "
                        "over 0..4π [N])")
    return table


def _check_status(status: int, reached: float, steps: int) -> None:
    if status == rk.OK:
        return
    reason = {rk.TOO_MANY_STEPS: "step budget exhausted",
              rk.STEP_TOO_SMALL: "step size fell below 1e-14 rad",
              rk.NOT_FINITE: "state became non-finite"}[status]
    raise ConvergenceError(f"clearance mechanism integration failed ({reason}, {steps} steps)",
                           where=f"crank angle {math.degrees(reached):.3f} deg")


def _assemble(mechanism, p, table, alpha, states, impacts, settings, steps, rejected):
    columns = sample_columns(alpha, states, p, table)
    energy = columns[10]
    residual = energy - energy[0] - (states[:, 8] - states[0, 8])
    c = mechanism.crank
    angles = np.linspace(0.0, 2.0 * np.pi, 361)
    outline = {name: (angles, free_play_outline(p, block, angles, joint.clearance_max))
               for name, block, joint in (("big_end", k.BIG_END, mechanism.big_end),
                                          ("small_end", k.SMALL_END, mechanism.small_end))}
    return MechanismResults(
        crank_angle=alpha, piston_position=states[:, 6],
        piston_position_rigid=rigid_piston_position(alpha, c.crank_radius, c.rod_length),
        rod_obliquity=math.pi - states[:, 4], gap=-columns[0:2], journal_offset=np.stack(
            [columns[5:7], columns[7:9]]), contact_force=columns[2:4],
        friction_force=columns[11:13], gas_force=columns[4], energy_residual=residual,
        impacts=impacts, cycles=settings.cycles, steps=steps, rejected_steps=rejected,
        kinetic_energy_scale=float(np.max(columns[9])), clearance_outline=outline)


@njit(cache=True)
def free_play_outline(p, block, angles, clearance_max):
    """Radius [m] of the free-play region of the journal centre at ``angles`` [rad] from
    the rod axis (δ = 0 by bisection; p(ϕ) − D/2 for [D3] geometry)."""
    radii = np.empty(angles.shape[0])
    for i in range(angles.shape[0]):
        c, s = math.cos(angles[i]), math.sin(angles[i])
        low, high = 0.0, clearance_max
        for _ in range(60):
            middle = 0.5 * (low + high)
            if k.joint_depth(middle * c, middle * s, 0.0, p, block) > 0.0:
                high = middle
            else:
                low = middle
        radii[i] = 0.5 * (low + high)
    return radii


@njit(cache=True)
def sample_columns(alpha, states, p, table):
    """Per-sample derived quantities (rows): δ_big, δ_small, R_big, R_small, P_gas,
    journal offset big (along, across), small (along, across), kinetic energy,
    mechanical energy, friction big, friction small."""
    n = alpha.shape[0]
    out = np.zeros((13, n))
    omega = p[k.CRANK_SPEED]
    for i in range(n):
        y = states[i]
        phi = y[4]
        bx, by, bvx, bvy = k.big_end_relative(y, alpha[i], p)
        sx, sy, svx, svy = k.small_end_relative(y, p)
        big = k.joint_loads(bx, by, bvx, bvy, phi, y[5], 1.0, p, k.BIG_END)
        small = k.joint_loads(sx, sy, svx, svy, phi, y[5], 0.0, p, k.SMALL_END)
        depths = k.penetrations(y, alpha[i], p)
        out[0, i], out[1, i] = depths[0], depths[1]
        out[2, i], out[3, i] = big[k.NORMAL], small[k.NORMAL]
        out[4, i] = k.gas_force(alpha[i], table)
        # journal relative to shell, rod frame: e = −(cos φ, sin φ) points to the small end
        c, s = -math.cos(phi), -math.sin(phi)
        out[5, i], out[6, i] = -(bx * c + by * s), -(-bx * s + by * c)
        out[7, i], out[8, i] = -(sx * c + sy * s), -(-sx * s + sy * c)
        out[9, i] = 0.5 * omega * omega * (p[k.ROD_MASS] * (y[1] ** 2 + y[3] ** 2)
                                           + p[k.ROD_INERTIA] * y[5] ** 2
                                           + p[k.PISTON_MASS] * y[7] ** 2)
        out[10, i] = k.mechanical_energy(y, alpha[i], p)
        out[11, i], out[12, i] = big[k.TANGENTIAL], small[k.TANGENTIAL]
    return out
