"""Engine loads on the big-end bearing over one 720° cycle  — the orchestrator.

.. code-block:: python

    from conrod import Case
    from conrod.loads.engine_loads import compute_engine_loads

    loads = compute_engine_loads(Case.from_toml("examples/passenger_car_diesel_2000rpm.toml"))
    loads.summary()["peak_load_N"]
    cycle = loads.to_load_cycle()        # rod (bearing-fixed) frame, for the orbit solver

Frames and signs are those of :mod:`conrod.loads.forces` and ``docs/conventions.md``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.cases.case import Case
from conrod.cases.engine import EngineSection
from conrod.cases.solver import LONGEST_CYCLE_DEG, MAX_OUTPUT_POINTS
from conrod.errors import CaseError
from conrod.loads import forces, kinematics
from conrod.loads.cycle import LoadCycle
from conrod.loads.diagrams import least_worn_angle, wear_diagram
from conrod.loads.pressure import CYCLE, build_pressure
from conrod.units import rpm_to_rad_s


@dataclass(frozen=True)
class EngineLoads:
    """Loads over one cycle on a uniform crank-angle grid 0 ≤ φ < 4π (end excluded).

    crank_angle : ndarray  φ from firing TDC [rad].
    crank_speed : float  ω [rad/s].
    cylinder_pressure : ndarray  Absolute cylinder pressure [Pa].
    gas_force : ndarray  P_g, towards the crank positive [N].
    reciprocating_inertia_force : ndarray  P_j of piston + rod small-end share [N].
    rotating_inertia_force : float  P_r = −m_rk r ω² (outward, included in R) [N].
    axial_force : ndarray  P_Σ = P_g + P_j along the cylinder axis [N].
    rod_force : ndarray  S, compression positive [N].
    radial_force, tangential_force : ndarray  R (towards the crank axis +), T (rotation +) [N].
    rod_angle : ndarray  β with sin β = λ sin φ [rad].
    rod_angular_velocity : ndarray  Ω_rod = −dβ/dt, engine frame, CCW + [rad/s].
    load_engine_x, load_engine_y : ndarray  Load W on the journal, engine frame [N].
    load_crank_x, load_crank_y : ndarray  W in the crank frame (x outward, y rotation) [N].
    load_rod_x, load_rod_y : ndarray  W in the rod frame (x towards the small end) [N].
    load_magnitude : ndarray  |W| [N].
    journal_speed, shell_speed : ndarray  ω − Ω_rod and 0, rod frame [rad/s].
    rod_model : str  "two_mass" or "three_mass".
    bearing_diameter, bearing_width : float | None  d and l' for specific loads [m].
    """

    crank_angle: np.ndarray
    crank_speed: float
    cylinder_pressure: np.ndarray
    gas_force: np.ndarray
    reciprocating_inertia_force: np.ndarray
    rotating_inertia_force: float
    axial_force: np.ndarray
    rod_force: np.ndarray
    radial_force: np.ndarray
    tangential_force: np.ndarray
    rod_angle: np.ndarray
    rod_angular_velocity: np.ndarray
    load_engine_x: np.ndarray
    load_engine_y: np.ndarray
    load_crank_x: np.ndarray
    load_crank_y: np.ndarray
    load_rod_x: np.ndarray
    load_rod_y: np.ndarray
    load_magnitude: np.ndarray
    journal_speed: np.ndarray
    shell_speed: np.ndarray
    rod_model: str
    bearing_diameter: float | None = None
    bearing_width: float | None = None

    @property
    def crank_angle_deg(self) -> np.ndarray:
        """Crank angle [deg]."""
        return np.degrees(self.crank_angle)

    def journal_load_angle(self) -> np.ndarray:
        """Direction of W on the journal, crank frame, from the outward crank radius [rad]."""
        return np.arctan2(self.load_crank_y, self.load_crank_x)

    def wear(self, bins: int = 360) -> tuple[np.ndarray, np.ndarray]:
        """Journal wear diagram ([D1]): (journal angle [rad], summed strips [N])."""
        return wear_diagram(self.journal_load_angle(), self.load_magnitude, bins=bins)

    def oil_hole_angle(self) -> float:
        """Least-worn journal angle [rad] (crank frame, from the outward crank radius)."""
        return least_worn_angle(*self.wear())

    def summary(self) -> dict[str, Any]:
        """Cycle figures written to ``loads_summary.json`` (SI units in the key names)."""
        peak = int(np.argmax(self.load_magnitude))
        mean = float(np.mean(self.load_magnitude))
        area = (
            self.bearing_diameter * self.bearing_width
            if self.bearing_diameter and self.bearing_width
            else None
)
        return {
            "peak_load_N": float(self.load_magnitude[peak]),
            "peak_load_crank_angle_deg": float(self.crank_angle_deg[peak]),
            "mean_load_N": mean,
            "min_load_N": float(self.load_magnitude.min()),
            "mean_specific_load_Pa": mean / area if area else None,
            "peak_specific_load_Pa": float(self.load_magnitude[peak]) / area if area else None,
            "oil_hole_angle_deg": math.degrees(self.oil_hole_angle()),
            "oil_hole_angle_reference": "journal (crankpin), from the outward crank radius "
            "towards the direction of rotation",
            "peak_cylinder_pressure_Pa": float(self.cylinder_pressure.max()),
            "peak_gas_force_N": float(self.gas_force.max()),
            "rotating_inertia_force_N": float(self.rotating_inertia_force),
            "crank_speed_rad_s": float(self.crank_speed),
            "rod_model": self.rod_model,
        }

    def to_load_cycle(self) -> LoadCycle:
        """Hand-over to the orbit solver: rod (bearing-fixed) frame, shell speed 0."""
        return LoadCycle(
            crank_angle=self.crank_angle,
            load_x=self.load_rod_x,
            load_y=self.load_rod_y,
            journal_speed=self.journal_speed,
            shell_speed=self.shell_speed,
            crank_speed=self.crank_speed,
            cycle=CYCLE,
)


SMALLEST_STEP_DEG = LONGEST_CYCLE_DEG / MAX_OUTPUT_POINTS
"""Finest crank-angle step of the loads: the row budget of a case file's output step [deg]."""
LARGEST_STEP_DEG = 10.0
"""Coarsest crank-angle step of the loads [deg]."""


def check_step(step_deg: Any, name: str = "step_deg") -> float:
    """``step_deg`` [deg] if it is a number within the row budget dividing 720 (``name``
    is the option or argument named in the :class:`CaseError` otherwise)."""
    allowed = (f"allowed: >= {SMALLEST_STEP_DEG:g} (budget {MAX_OUTPUT_POINTS} rows per "
               f"cycle) and <= {LARGEST_STEP_DEG:g} deg, dividing 720")
    if isinstance(step_deg, bool) or not isinstance(step_deg, int | float):
        raise CaseError(f"{name} = {step_deg!r}: a number is required ({allowed})")
    if not (math.isfinite(step_deg) and SMALLEST_STEP_DEG <= step_deg <= LARGEST_STEP_DEG):
        raise CaseError(f"{name} = {step_deg!r}: out of range ({allowed})")
    count = LONGEST_CYCLE_DEG / step_deg
    if abs(count - round(count)) > 1e-9 * count:
        raise CaseError(f"{name} = {step_deg!r}: must divide 720 deg exactly (e.g. 0.5, 1, 2, 5)")
    return float(step_deg)


def crank_angle_grid(step_deg: float, name: str = "step_deg") -> np.ndarray:
    """Uniform grid 0 ≤ φ < 720° with ``step_deg`` dividing 720 [rad]; CaseError otherwise
    (:func:`check_step`)."""
    step = check_step(step_deg, name)
    return np.radians(np.arange(round(LONGEST_CYCLE_DEG / step)) * step)


def _piston_acceleration(engine: EngineSection, phi: np.ndarray, omega: float) -> np.ndarray:
    series = engine.kinematics == "series" and engine.rod_inertia is None
    accel = kinematics.piston_acceleration_series if series else kinematics.piston_acceleration
    return accel(phi, engine.crank_radius, engine.rod_length, omega)


def _pin_force(
    engine: EngineSection, phi: np.ndarray, omega: float, gas: np.ndarray, accel: np.ndarray
) -> tuple[np.ndarray, np.ndarray, forces.RodMasses]:
    """Force of the rod on the crankpin (engine frame) and the rod mass split used."""
    r, length, l1 = engine.crank_radius, engine.rod_length, engine.rod_cg_from_big_end
    beta = kinematics.rod_angle(phi, r / length)
    if engine.rod_inertia is None:
        masses = forces.two_mass_split(engine.rod_mass, length, l1)
        axial = gas + forces.reciprocating_inertia_force(
            engine.piston_mass + masses.small_end, accel
)
        radial, tangential = forces.crank_forces(
            forces.rod_force(axial, beta), phi, beta, -masses.big_end * r * omega**2
)
        return (*forces.crank_to_engine(radial, tangential, phi), masses)
    masses = forces.three_mass_split(engine.rod_mass, length, l1, engine.rod_inertia)
    fx, fy = forces.rigid_rod_pin_force(
        phi,
        gas + forces.reciprocating_inertia_force(engine.piston_mass, accel),
        kinematics.rod_centre_of_mass_acceleration(phi, r, length, l1, omega),
        kinematics.rod_angular_acceleration(phi, r / length, omega),
        crank_to_rod=r / length,
        rod_mass=engine.rod_mass,
        rod_length=length,
        cg_from_big_end=l1,
        rod_inertia=engine.rod_inertia,
)
    return fx, fy, masses


def compute_engine_loads(case: Case, step_deg: float = 1.0) -> EngineLoads:
    """Loads on the big-end bearing of ``case`` over 0..720° (end excluded) every ``step_deg``
    [deg]; bad arguments raise :class:`CaseError` naming them."""
    if not isinstance(case, Case):
        raise CaseError(f"case = {case!r}: a conrod.Case is required (e.g. "
                        "Case.from_toml('case.toml'))")
    case.require("loads", "engine")
    engine = case.engine
    assert engine is not None
    phi = crank_angle_grid(step_deg)
    omega = rpm_to_rad_s(engine.speed)
    r, lam = engine.crank_radius, engine.crank_radius / engine.rod_length
    pressure = build_pressure(case)
    gas = forces.gas_force(pressure.gauge(phi), engine.bore)
    accel = _piston_acceleration(engine, phi, omega)
    pin_x, pin_y, masses = _pin_force(engine, phi, omega, gas, accel)
    beta = kinematics.rod_angle(phi, lam)
    pin_r, pin_t = forces.engine_to_crank(pin_x, pin_y, phi)
    rotating = -masses.big_end * r * omega**2
    reciprocating = forces.reciprocating_inertia_force(engine.piston_mass + masses.small_end, accel)
    rod_x, rod_y = forces.engine_to_rod(-pin_x, -pin_y, beta)
    crank_x, crank_y = forces.engine_to_crank(-pin_x, -pin_y, phi)
    rod_rate = kinematics.rod_angular_velocity(phi, lam, omega)
    bearing = case.bearing
    return EngineLoads(
        crank_angle=phi,
        crank_speed=omega,
        cylinder_pressure=pressure.absolute(phi),
        gas_force=gas,
        reciprocating_inertia_force=reciprocating,
        rotating_inertia_force=rotating,
        axial_force=gas + reciprocating,
        rod_force=rod_x + masses.big_end * r * omega**2 * np.cos(phi + beta),
        radial_force=-pin_r,
        tangential_force=pin_t,
        rod_angle=beta,
        rod_angular_velocity=rod_rate,
        load_engine_x=-pin_x,
        load_engine_y=-pin_y,
        load_crank_x=crank_x,
        load_crank_y=crank_y,
        load_rod_x=rod_x,
        load_rod_y=rod_y,
        load_magnitude=np.hypot(pin_x, pin_y),
        journal_speed=omega - rod_rate,
        shell_speed=np.zeros_like(phi),
        rod_model="two_mass" if engine.rod_inertia is None else "three_mass",
        bearing_diameter=bearing.diameter if bearing else None,
        bearing_width=bearing.width if bearing else None,
)
