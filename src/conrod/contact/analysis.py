"""Contact post-processing of a periodic orbit: contact intervals, Hertz stress, friction
work, wear on journal and shell ([D4] §4.3–4.5).

``Simulation.run()`` calls :func:`analyse_contact` after the orbit (``docs/orbit.md``).
With ``[contact] model = "hard"`` the contact force is the orbit's hard-contact force
P_c ([D4] eq. 4.2.5); with ``"greenwood_tripp"`` the asperity force recomputed from the
orbit (the same compiled kernel the orbit used) is added, with boundary friction μ_dry × that
force (both radial along the line of centres).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.contact.asperity import AsperityParameters, asperity_force_array
from conrod.contact.friction_work import (
    FrictionWork,
    cycle_length,
    element_maximum,
    friction_work_distribution,
)
from conrod.contact.hertz import (
    contact_modulus,
    hertz_half_width,
    hertz_line_contact_pressure,
    nominal_specific_load,
)
from conrod.contact.wear import WearDistribution, wear_distribution
from conrod.errors import CaseError

HERTZ_WIDTH_WARNING = 0.1
"""Hertz half-width, as a share of the journal radius, above which a caveat is issued [-]."""


def contact_runs(crank_angle: np.ndarray, touching: np.ndarray, cycle: float
                 ) -> list[tuple[float, float]]:
    """Crank-angle intervals [rad] of the runs of output angles where ``touching``: from the
    first to the last output angle of each run, so that they are exactly the rows of
    ``cycle.csv`` whose ``in_contact`` is 1. A run over the end of the cycle is joined to
    the one at its start and reported with end > cycle; every angle touching: one interval
    over the whole cycle.

    The one definition of the hard-contact intervals: the headline, ``summary.json``
    (``contact_intervals_deg``) and the figures all take them from here.
    """
    phi = np.asarray(crank_angle, dtype=float)
    flags = np.asarray(touching, dtype=bool)
    if not np.any(flags):
        return []
    if np.all(flags):
        return [(float(phi[0]), float(phi[-1]))]
    edges = np.flatnonzero(np.diff(np.concatenate([[0], flags.astype(int), [0]])))
    runs = [(int(a), int(b) - 1) for a, b in zip(edges[::2], edges[1::2], strict=True)]
    if len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == phi.size - 1:  # over the end
        first, last = runs.pop(0), runs.pop()
        runs.append((last[0], first[1] + phi.size))
    return [(float(phi[a]), float(phi[b] if b < phi.size else phi[b - phi.size] + cycle))
            for a, b in runs]


def contact_intervals(
    crank_angle: np.ndarray, contact_force: np.ndarray, threshold: float, cycle: float
) -> list[tuple[float, float]]:
    """Crank-angle intervals [rad] where ``contact_force`` [N] exceeds ``threshold`` [N].

    Edges are interpolated linearly between output angles; an interval running over the
    end of the cycle is joined to the one at its start and reported with end > cycle.
    """
    phi = np.append(crank_angle, crank_angle[0] + cycle)
    excess = np.append(contact_force, contact_force[0]) - threshold
    above = excess > 0.0
    if not np.any(above):
        return []
    if np.all(above):
        return [(float(phi[0]), float(phi[-1]))]
    edges = []
    for i in np.flatnonzero(above[:-1] != above[1:]):
        fraction = excess[i] / (excess[i] - excess[i + 1])
        edges.append((float(phi[i] + fraction * (phi[i + 1] - phi[i])), bool(above[i + 1])))
    if not edges[0][1]:  # first edge is an exit: the interval started in the previous cycle
        edges.append((edges[0][0] + cycle, False))
        edges = edges[1:]
    return [(edges[k][0], edges[k + 1][0]) for k in range(0, len(edges) - 1, 2)]


@dataclass
class ContactResults:
    """Contact characteristics of one periodic cycle (units in brackets)."""

    crank_angle: np.ndarray
    """Output crank angles φ [rad]."""
    contact_force: np.ndarray
    """Contact force P_c ≥ 0 (hard contact or asperity) [N]."""
    friction_force: np.ndarray
    """Dry / boundary friction force [N]."""
    hertz_stress: np.ndarray
    """Peak Hertz pressure of the line contact at each angle [Pa]."""
    hertz_half_width: np.ndarray
    """Hertz contact half-width at each angle [m]."""
    intervals: list[tuple[float, float]]
    """Hard-contact intervals [rad] (end may exceed the cycle when wrapping): the runs of
    output angles where the journal touches the shell (:func:`contact_runs`)."""
    work: FrictionWork
    """Friction work per step and per element [J]."""
    wear: WearDistribution
    """Friction work and wear per element of journal and shell [J, m]."""
    nominal_specific_load: float
    """Nominal specific load of the bearing at its peak load, W_max/(B·D) [Pa] ([D4]
    eq. 4.4.1 with the peak bearing load)."""
    h_min: np.ndarray
    """Minimum film thickness from the orbit [m]."""
    p_max: np.ndarray
    """Maximum film pressure from the orbit [Pa]."""
    model: str
    """Contact model ('hard' or 'greenwood_tripp') [-]."""
    journal_stress: np.ndarray | None = None
    """Largest Hertz stress each journal element sees over the cycle [Pa] (Fig. 4.4.1)."""
    shell_stress: np.ndarray | None = None
    """Largest Hertz stress each shell element sees over the cycle [Pa] (Fig. 4.4.1)."""
    journal_radius: float = 0.0
    """Journal radius R [m] (validity check of the Hertz half-width)."""
    asperity_intervals: list[tuple[float, float]] | None = None
    """Under Greenwood–Tripp contact: intervals [rad] where the asperity force exceeds
    ``[contact] contact_threshold_ratio`` × the peak load (edges interpolated,
    :func:`contact_intervals`); None under hard contact."""
    width_times_diameter: float = 0.0
    """B·D, the projected bearing area [m²]."""
    asperity_force: np.ndarray | None = None
    """Under Greenwood–Tripp contact: the asperity force F_a at each angle [N] (also in
    ``contact_force``); None under hard contact."""
    boundary_friction_power: np.ndarray | None = None
    """Boundary friction power of the asperities μ_dry F_a |V_slide| at each angle [W]
    (:func:`asperity_friction_power`); None under hard contact."""

    @property
    def has_contact(self) -> bool:
        """True when the journal touches the shell or the asperities carry load somewhere
        in the cycle [-]: only then are the contact and wear tables and figures written."""
        return bool(np.any(self.contact_force > 0.0))

    @property
    def contact_specific_load(self) -> float:
        """P_c,max/(B·D), the largest contact force over the projected area [Pa] (0 without
        contact)."""
        if self.width_times_diameter <= 0.0:
            return 0.0
        return self.max_contact_force / self.width_times_diameter

    @property
    def warnings(self) -> list[str]:
        """Caveats a user should read with the numbers [-]."""
        widest = float(np.max(self.hertz_half_width, initial=0.0))
        if self.journal_radius > 0.0 and widest > HERTZ_WIDTH_WARNING * self.journal_radius:
            return [
                f"Hertz half-width {widest * 1e3:.3g} mm is {widest / self.journal_radius:.2f} "
                "of the journal radius: the contact is conformal and the Hertz stress is an "
                "upper bound (docs/contact.md)"
            ]
        return []

    @property
    def max_contact_force(self) -> float:
        """Largest contact force [N]."""
        return float(np.max(self.contact_force)) if self.contact_force.size else 0.0

    @property
    def max_hertz_stress(self) -> float:
        """Largest Hertz pressure over the cycle [Pa]."""
        return float(np.max(self.hertz_stress)) if self.hertz_stress.size else 0.0

    @property
    def hertz_to_nominal_ratio(self) -> float | None:
        """Hertz stress / P_c,max/(B·D), both at the largest contact force [-] ([D4]: 2.37);
        None without contact."""
        if self.contact_specific_load <= 0.0:
            return None
        return self.max_hertz_stress / self.contact_specific_load

    @property
    def seed_friction_work(self) -> float:
        """[D4] eq. 4.5.1, μ R Σ P_f Δφ with P_f = μ P_c: relative rotation taken equal
        to the crank angle (ignores the rod swing) [J]."""
        step = cycle_length(self.crank_angle) / self.crank_angle.size
        return float(np.sum(self.friction_force) * self.journal_radius * step)

    def summary_items(self) -> dict[str, Any]:
        """Items merged into summary.json."""
        return {
            "contact_model": self.model,
            "contact_intervals_deg": [
                [math.degrees(start), math.degrees(end)] for start, end in self.intervals
            ],
            "max_contact_force_N": self.max_contact_force,
            "max_hertz_stress_Pa": self.max_hertz_stress,
            "max_hertz_half_width_m": float(np.max(self.hertz_half_width, initial=0.0)),
            "nominal_specific_load_Pa": self.nominal_specific_load,
            "contact_specific_load_Pa": self.contact_specific_load,
            "hertz_to_nominal_ratio": self.hertz_to_nominal_ratio,
            "friction_work_J": self.work.total,
            "friction_work_seed_formula_J": self.seed_friction_work,
            "max_wear_journal_m": float(np.max(self.wear.journal_wear)),
            "max_wear_shell_m": float(np.max(self.wear.shell_wear)),
            "contact_warnings": self.warnings,
            **({"asperity_contact_intervals_deg": [
                [math.degrees(start), math.degrees(end)]
                for start, end in self.asperity_intervals]}
               if self.asperity_intervals is not None else {}),
        }

    def cycle_columns(self) -> dict[str, np.ndarray]:
        """Extra per-angle columns for cycle.csv [units in the names]: the Hertz stress and
        the cumulative friction work; under Greenwood–Tripp the asperity force and its
        boundary friction power. (``contact_force_N`` and ``friction_force_N`` of cycle.csv
        stay the orbit's hard contact, as in ``CycleResults.to_dataframe()``.)"""
        columns = {
            "hertz_stress_Pa": self.hertz_stress,
            "friction_work_cumulative_J": self.work.cumulative,
        }
        if self.asperity_force is not None:
            columns["asperity_force_N"] = self.asperity_force
            columns["boundary_friction_power_W"] = self.boundary_friction_power
        return columns


def _contact_from_asperity(case, cycle, asperity_force=None) -> tuple[np.ndarray, np.ndarray]:
    """(asperity force [N], line-of-centres angle [rad]); ``asperity_force`` [N] when the
    film computed it on its own (deformed) film, else on the rigid shell from the orbit."""
    angle = np.arctan2(np.asarray(cycle.eccentricity_y, dtype=float),
                       np.asarray(cycle.eccentricity_x, dtype=float))
    if asperity_force is not None:
        return np.asarray(asperity_force, dtype=float), angle
    bearing = case.bearing
    params = AsperityParameters.from_case(case).kernel_parameters(
        0.5 * bearing.diameter, bearing.width
)
    ex = np.ascontiguousarray(cycle.eccentricity_x, dtype=float)
    ey = np.ascontiguousarray(cycle.eccentricity_y, dtype=float)
    fx, fy = asperity_force_array(ex, ey, float(bearing.radial_clearance), params)
    return np.hypot(fx, fy), np.arctan2(ey, ex)


def asperity_friction_power(case, cycle, asperity_force=None) -> np.ndarray:
    """Boundary friction power of the asperities μ_dry F_a |V_slide| at each output angle
    [W]: zeros under hard contact; under Greenwood–Tripp the asperity force ``asperity_force``
    [N] (as the film computed it on a deformed bore) or, when None, on the rigid shell from
    the orbit. It belongs to the total friction and the heat balance with the film and
    hard-contact friction."""
    if case.contact.model != "greenwood_tripp":
        return np.zeros(np.asarray(cycle.crank_angle).size)
    force = _contact_from_asperity(case, cycle, asperity_force)[0]
    return (case.contact.dry_friction_coefficient * force
            * np.abs(np.asarray(cycle.sliding_speed, dtype=float)))


def _contact_force_and_angle(case, cycle, asperity_force=None
                             ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None]:
    """(P_c [N], friction force [N], contact angle [rad], asperity force [N] or None) per
    output angle: the orbit's hard contact, plus under Greenwood–Tripp the asperity force
    with μ_dry boundary friction."""
    force = np.maximum(np.asarray(cycle.contact_force, dtype=float), 0.0)
    friction = np.abs(np.asarray(cycle.friction_force, dtype=float))  # magnitude, any sign
    if case.contact.model == "greenwood_tripp":
        asperity, angle = _contact_from_asperity(case, cycle, asperity_force)
        mu = case.contact.dry_friction_coefficient
        return force + asperity, friction + mu * asperity, angle, asperity
    return force, friction, np.asarray(cycle.contact_angle, dtype=float), None


def analyse_contact(case, cycle, asperity_force=None) -> ContactResults:
    """Contact, Hertz stress, friction work and wear for the periodic cycle of an orbit.

    case : :class:`conrod.cases.case.Case` with ``[bearing]`` (radial clearance set) and
        ``[contact]``.
    cycle : per-angle results with the fields of :class:`conrod.results.CycleResults`
        (crank_angle, contact_force, friction_force, contact_angle, journal_rotation,
        eccentricity_x/_y, load_x/_y, h_min, p_max).
    asperity_force : ndarray or None  Asperity force per output angle [N] as the film
        computed it (on the deformed bore of an elastic big end); None: on the rigid shell.
    """
    bearing, section = case.bearing, case.contact
    if bearing is None or bearing.radial_clearance is None:
        raise CaseError("contact analysis needs [bearing] with radial_clearance [m]")
    radius, width = 0.5 * bearing.diameter, bearing.width
    crank_angle = np.asarray(cycle.crank_angle, dtype=float)
    if crank_angle.size < 3:
        raise CaseError(f"contact analysis needs at least 3 output angles, got {crank_angle.size}")
    cycle_rad = cycle_length(crank_angle)
    force, friction, angle, asperity = _contact_force_and_angle(case, cycle, asperity_force)
    modulus = contact_modulus(
        section.journal_elastic_modulus, section.journal_poisson_ratio,
        section.shell_elastic_modulus, section.shell_poisson_ratio,
)
    shell_radius = radius + bearing.radial_clearance
    work = friction_work_distribution(
        crank_angle, friction, angle, np.asarray(cycle.journal_rotation, dtype=float),
        radius, section.surface_elements, cycle_rad,
)
    peak_load = float(np.max(np.hypot(cycle.load_x, cycle.load_y)))
    stress = hertz_line_contact_pressure(force, width, radius, shell_radius, modulus)
    asperity_intervals = boundary = None
    if asperity is not None:
        asperity_intervals = contact_intervals(
            crank_angle, asperity, section.contact_threshold_ratio * peak_load, cycle_rad)
        boundary = (section.dry_friction_coefficient * asperity
                    * np.abs(np.asarray(cycle.sliding_speed, dtype=float)))
    journal_stress, shell_stress = element_maximum(
        stress, angle, np.asarray(cycle.journal_rotation, dtype=float), crank_angle,
        section.surface_elements, cycle_rad,
)
    return ContactResults(
        crank_angle=crank_angle,
        contact_force=force,
        friction_force=friction,
        hertz_stress=stress,
        hertz_half_width=hertz_half_width(force, width, radius, shell_radius, modulus),
        intervals=contact_runs(crank_angle, np.asarray(cycle.in_contact, dtype=bool),
                               cycle_rad),
        work=work,
        wear=wear_distribution(
            work, radius, width, section.wear_coefficient_journal, section.wear_coefficient_shell
),
        nominal_specific_load=float(nominal_specific_load(peak_load, width, bearing.diameter)),
        h_min=np.asarray(cycle.h_min, dtype=float),
        p_max=np.asarray(cycle.p_max, dtype=float),
        model=section.model,
        journal_stress=journal_stress,
        shell_stress=shell_stress,
        journal_radius=radius,
        asperity_intervals=asperity_intervals,
        width_times_diameter=width * bearing.diameter,
        asperity_force=asperity,
        boundary_friction_power=boundary,
)
