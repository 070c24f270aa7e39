"""Build a clearance-mechanism run from a case file (``[engine]`` + ``[clearance]``).

Gas force P = π D_p²/4 · (p − p_ambient) from :func:`conrod.loads.pressure.build_pressure`
(trace or [D3] parametric model), scaled by ``load_scale``, tabulated over 4π.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.cases.case import Case
from conrod.cases.mechanism import MAX_STEPS_PER_CYCLE, ClearanceSection, JointClearanceSection
from conrod.errors import CaseError
from conrod.mechanism.model import ROD_INERTIA_FACTOR, ClearanceJoint, CrankTrain, Mechanism
from conrod.mechanism.simulation import CYCLE, RunSettings
from conrod.units import rpm_to_rad_s

GAS_TABLE_POINTS = 2880
"""Samples of the gas-force table over 720° (0.25°) [-]."""


@dataclass(frozen=True)
class MechanismCase:
    """Everything one run needs, in SI.

    mechanism : Mechanism; settings : RunSettings;
    gas_table : ndarray  Gas force at load_scale = 1 over [0, 4π) [N];
    load_scale : float  Gas-force factor [-]; speed_rpm : float  Crank speed [rpm];
    worn_joint : int  0 big end, 1 small end (the joint diagnosed in a sweep) [-].
    """

    mechanism: Mechanism
    settings: RunSettings
    gas_table: np.ndarray
    load_scale: float
    speed_rpm: float
    worn_joint: int

    def with_operating_point(self, speed_rpm: float, load_scale: float) -> MechanismCase:
        """Copy at another crank speed [rpm] and gas-force factor [-]."""
        return MechanismCase(self.mechanism.at_speed(rpm_to_rad_s(speed_rpm)), self.settings,
                             self.gas_table, load_scale, speed_rpm, self.worn_joint)

    def scaled_gas_table(self) -> np.ndarray:
        """Gas-force table times ``load_scale`` [N]."""
        return self.load_scale * self.gas_table


def joint_from_section(section: JointClearanceSection) -> ClearanceJoint:
    """SI joint parameters from a ``[clearance.*]`` section."""
    return ClearanceJoint(
        diameter=section.diameter, clearance_max=section.clearance_max,
        clearance_min=section.clearance_min, ellipse_angle=math.radians(section.ellipse_angle_deg),
        contact_stiffness=section.contact_stiffness, contact_exponent=section.contact_exponent,
        damping_factor=section.damping_factor, friction_coefficient=section.friction_coefficient,
        damping_scale=section.damping_scale)


def settings_from_section(section: ClearanceSection) -> RunSettings:
    """Run numerics from ``[clearance]``."""
    return RunSettings(cycles=section.cycles, tolerance=section.tolerance,
                       output_step=math.radians(section.output_step_deg),
                       max_step=math.radians(section.max_step_deg),
                       impact_separation=section.impact_separation,
                       max_steps=section.cycles * MAX_STEPS_PER_CYCLE)


def gas_force_table(case: Case, points: int = GAS_TABLE_POINTS) -> np.ndarray:
    """Gas force on the piston π D_p²/4 (p − p_ambient) at ``points`` angles over 4π [N]
    (cylinder pressure and gas force of the loads stage)."""
    from conrod.loads.forces import gas_force
    from conrod.loads.pressure import build_pressure

    angles = np.arange(points) * (CYCLE / points)
    case.require("mechanism", "engine")
    assert case.engine is not None
    gauge = np.asarray(build_pressure(case).gauge(angles), dtype=float)
    return np.asarray(gas_force(gauge, case.engine.bore), dtype=float)


def mechanism_case(case: Case) -> MechanismCase:
    """Validate that the case has ``[engine]`` and ``[clearance]`` and build the run."""
    if not isinstance(case, Case):
        raise CaseError(f"mechanism_case: case = {type(case).__name__}: a conrod.Case is "
                        "required (e.g. Case.from_toml('case.toml'))")
    case.require("mechanism", "engine", "clearance")
    engine, clearance = case.engine, case.clearance
    assert engine is not None and clearance is not None  # checked by require()
    inertia = engine.rod_inertia
    if inertia is None:
        inertia = ROD_INERTIA_FACTOR * engine.rod_mass * engine.rod_length**2
    crank = CrankTrain(
        crank_radius=engine.crank_radius, rod_length=engine.rod_length,
        rod_cg_from_big_end=engine.rod_cg_from_big_end, rod_mass=engine.rod_mass,
        rod_inertia=inertia, piston_mass=engine.piston_mass,
        crank_speed=rpm_to_rad_s(engine.speed))
    mechanism = Mechanism(crank, joint_from_section(clearance.big_end),
                          joint_from_section(clearance.small_end),
                          friction_velocity=clearance.friction_velocity,
                          contact_geometry=clearance.contact_geometry)
    worn = clearance.worn_joint
    if worn == "auto":
        small, big = clearance.small_end, clearance.big_end
        relative_small = small.clearance_max / small.diameter
        worn = "small_end" if relative_small > big.clearance_max / big.diameter else "big_end"
    return MechanismCase(mechanism, settings_from_section(clearance), gas_force_table(case),
                         clearance.load_scale, engine.speed, 0 if worn == "big_end" else 1)
