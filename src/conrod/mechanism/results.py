"""Results of a clearance-mechanism run (typed, with units; no plotting here)."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

JOINT_NAMES = ("big_end", "small_end")


@dataclass(frozen=True)
class Impacts:
    """Contact entries of one run (one row per impact).

    crank_angle : ndarray  Crank angle of contact entry from firing TDC [rad] (0 … cycles·4π).
    joint : ndarray  0 = big end, 1 = small end [-].
    velocity : ndarray  Normal relative (penetration) velocity at entry [m/s].
    """

    crank_angle: np.ndarray
    joint: np.ndarray
    velocity: np.ndarray

    def of_joint(self, joint: int) -> np.ndarray:
        """Impact velocities [m/s] of one joint (0 big end, 1 small end)."""
        return self.velocity[self.joint == joint]

    def after(self, crank_angle: float) -> Impacts:
        """Impacts at or after ``crank_angle`` [rad]."""
        keep = self.crank_angle >= crank_angle
        return Impacts(self.crank_angle[keep], self.joint[keep], self.velocity[keep])


@dataclass(frozen=True)
class MechanismResults:
    """Time histories (every output angle of the whole run) and impacts.

    crank_angle : ndarray  From firing TDC, continuing over the cycles [rad].
    piston_position : ndarray  Pin centre from the crank centre along the cylinder axis [m].
    piston_position_rigid : ndarray  Same for the rigid slider-crank [m].
    rod_obliquity : ndarray  Rod obliquity β = π − φ₂ (as in ``conrod loads``: the rod
        axis from big end to small end is (cos β, −sin β)) [rad].
    gap : ndarray  (2, n) Minimum gap −δ of big and small end, < 0 in contact [m].
    journal_offset : ndarray  (2, 2, n) Journal centre relative to shell centre in the
        rod frame (along the rod towards the small end, across) [m].
    contact_force : ndarray  (2, n) Normal contact force R [N].
    friction_force : ndarray  (2, n) Friction force F [N].
    gas_force : ndarray  Gas force on the piston, towards the crank [N].
    energy_residual : ndarray  E − E₀ − W, energy balance error [J].
    impacts : Impacts  All contact entries.
    cycle_length : float  4π [rad]; cycles : int  cycles integrated [-].
    steps, rejected_steps : int  Accepted / rejected integrator steps [-].
    kinetic_energy_scale : float  Peak kinetic energy of rod and piston [J].
    clearance_outline : dict  Per joint (angles from the rod axis [rad], free-play radius of
        the journal centre [m]) for plotting.
    """

    crank_angle: np.ndarray
    piston_position: np.ndarray
    piston_position_rigid: np.ndarray
    rod_obliquity: np.ndarray
    gap: np.ndarray
    journal_offset: np.ndarray
    contact_force: np.ndarray
    friction_force: np.ndarray
    gas_force: np.ndarray
    energy_residual: np.ndarray
    impacts: Impacts
    cycles: int
    steps: int
    rejected_steps: int
    kinetic_energy_scale: float
    clearance_outline: dict = field(default_factory=dict)
    cycle_length: float = 4.0 * math.pi

    def last_cycle(self) -> np.ndarray:
        """Boolean mask of the samples of the last cycle."""
        start = (self.cycles - 1) * self.cycle_length
        return self.crank_angle >= start - 1e-12

    def last_cycle_impacts(self) -> Impacts:
        """Impacts of the last cycle."""
        return self.impacts.after((self.cycles - 1) * self.cycle_length)

    @property
    def statistics_cycles(self) -> int:
        """Cycles whose impacts enter the statistics: all but the first (start-up
        transient from the approximate initial state of [D3]) when more than one [-]."""
        return max(self.cycles - 1, 1)

    def settled_impacts(self) -> Impacts:
        """Impacts of the last :attr:`statistics_cycles` cycles."""
        return self.impacts.after((self.cycles - self.statistics_cycles) * self.cycle_length)

    def cycle_to_cycle_change(self) -> float | None:
        """Largest change of either joint's gap between the last two cycles [m] (periodicity
        indicator; None for a single cycle)."""
        if self.cycles < 2:
            return None
        last = self.last_cycle()
        start = (self.cycles - 2) * self.cycle_length
        previous = (self.crank_angle >= start - 1e-12) & (
            self.crank_angle <= start + self.cycle_length + 1e-12)
        if np.count_nonzero(previous) != np.count_nonzero(last):
            return None
        return float(np.max(np.abs(self.gap[:, last] - self.gap[:, previous])))

    def summary(self) -> dict:
        """Per-run numbers for ``summary.json`` (impacts over :attr:`statistics_cycles`,
        forces and piston deviation over the last cycle; SI units in the key names)."""
        impacts = self.settled_impacts()
        cycles = self.statistics_cycles
        out: dict = {"cycles_integrated": self.cycles, "cycles_in_statistics": cycles,
                     "impacts_per_cycle": impacts.velocity.size / cycles}
        for index, name in enumerate(JOINT_NAMES):
            speeds = impacts.of_joint(index)
            out[f"max_impact_velocity_{name}_m_s"] = float(speeds.max()) if speeds.size else 0.0
            out[f"mean_impact_velocity_{name}_m_s"] = float(speeds.mean()) if speeds.size else 0.0
            out[f"impacts_per_cycle_{name}"] = speeds.size / cycles
            out[f"max_contact_force_{name}_N"] = float(self.contact_force[index].max())
        residual = float(np.max(np.abs(self.energy_residual)))
        out["energy_residual_max_J"] = residual
        out["energy_residual_relative"] = residual / max(self.kinetic_energy_scale, 1e-300)
        mask = self.last_cycle()
        deviation = self.piston_position[mask] - self.piston_position_rigid[mask]
        out["piston_deviation_from_rigid_max_m"] = float(np.max(np.abs(deviation)))
        out["cycle_to_cycle_gap_change_m"] = self.cycle_to_cycle_change()
        out["integrator_steps"] = self.steps
        out["integrator_rejected_steps"] = self.rejected_steps
        return out


@dataclass(frozen=True)
class MechanismRun:
    """One mechanism run at its operating point (what ``conrod mechanism`` writes).

    results : MechanismResults  Time histories and impacts.
    speed_rpm : float  Crank speed [rpm].
    load_scale : float  Gas-force factor [-].
    warnings : tuple of str  Plausibility warnings
        (:func:`conrod.results.plausibility.check_mechanism`).
    """

    results: MechanismResults
    speed_rpm: float
    load_scale: float
    warnings: tuple[str, ...] = ()

    def summary(self) -> dict:
        """``summary.json`` items: the operating point, :meth:`MechanismResults.summary` and
        the plausibility warnings."""
        return {"speed_rpm": self.speed_rpm, "load_scale": self.load_scale,
                **self.results.summary(), "warnings": list(self.warnings)}
