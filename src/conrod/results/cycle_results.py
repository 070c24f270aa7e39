"""Typed results of one orbit run: per-angle :class:`CycleResults`,
cycle :class:`RunSummary` and the bundle :class:`RunResults`.

Every field documents its unit in brackets. No plotting and no I/O here
(tables: :mod:`conrod.output.tables`; figures are registered by the plotting package).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, ClassVar, Protocol, runtime_checkable

import numpy as np


@dataclass(frozen=True)
class CycleResults:
    """Characteristics of the periodic orbit at each output crank angle ([D2] Table 1)."""

    crank_angle: np.ndarray
    """Crank angle φ of each output point, 0 at firing TDC [rad]."""
    eccentricity_x: np.ndarray
    """Journal centre relative to the shell centre, x, film frame [m]."""
    eccentricity_y: np.ndarray
    """Journal centre relative to the shell centre, y, film frame [m]."""
    velocity_x: np.ndarray
    """Rate of ``eccentricity_x`` [m/s]."""
    velocity_y: np.ndarray
    """Rate of ``eccentricity_y`` [m/s]."""
    eccentricity_ratio: np.ndarray
    """ε = |e|/c [-]."""
    attitude_angle: np.ndarray
    """Angle from the load vector to the line of centres, positive with rotation [rad]."""
    h_min: np.ndarray
    """Minimum film thickness [m]."""
    h_min_angle_shell: np.ndarray
    """Shell angle θ of h_min, film frame [rad]."""
    h_min_angle_journal: np.ndarray
    """Angle of h_min on the journal from a journal-fixed mark, θ_shell − rotation [rad]."""
    p_max: np.ndarray
    """Maximum gauge film pressure [Pa]."""
    p_max_angle_shell: np.ndarray
    """Shell angle θ of p_max [rad]."""
    friction_torque: np.ndarray
    """Film shear moment on the journal [N m]."""
    friction_power: np.ndarray
    """Film friction power loss |M_j (ω_j − ω_b)| (or the model's own) [W]."""
    side_flow: np.ndarray
    """Oil leaving through the bearing edges [m^3/s]."""
    supply_flow: np.ndarray
    """Oil entering through grooves and holes [m^3/s]."""
    load_x: np.ndarray
    """Load pressing the journal on the shell, x, film frame [N]."""
    load_y: np.ndarray
    """Load pressing the journal on the shell, y, film frame [N]."""
    journal_speed: np.ndarray
    """Journal angular velocity ω_j in the film frame [rad/s]."""
    shell_speed: np.ndarray
    """Shell angular velocity ω_b in the film frame [rad/s]."""
    contact_force: np.ndarray
    """Hard-contact normal force P_c ≥ 0 ([D4] eq. 4.2.5) [N]."""
    friction_force: np.ndarray
    """Dry-friction force μ_dry P_c ([D4] eq. 4.2.6) [N]."""
    contact_angle: np.ndarray
    """Shell angle θ of the contact point, film frame (NaN-free: ψ of the centre) [rad]."""
    journal_rotation: np.ndarray
    """Rotation of the journal relative to the shell, ∫(ω_j − ω_b) dt from the cycle start [rad]."""
    sliding_speed: np.ndarray
    """Surface sliding speed at the contact point V_k + (ω_j − ω_b) R [m/s]."""
    in_contact: np.ndarray
    """True where the journal touches the shell [-]."""
    axial: dict[str, np.ndarray] | None = None
    """Tilt [rad, rad/s], moments [N m], h_min axial position and edge h_min [m] per angle
    of a tilted journal or a profiled bore (:mod:`conrod.results.axial`); None: aligned."""
    feed: dict[str, np.ndarray] | None = None
    """Flow [m³/s], shell angle [rad] and pressure [Pa] of the crank-pin oil holes, inlet
    film fraction [-] (:mod:`conrod.results.feed`); None: no journal hole."""

    def __len__(self) -> int:
        return int(self.crank_angle.size)

    @property
    def crank_angle_deg(self) -> np.ndarray:
        """Crank angle [deg]."""
        return np.degrees(self.crank_angle)

    def to_dataframe(self) -> Any:
        """The cycle as a pandas DataFrame, one row per output angle, with the columns and
        names of ``cycle.csv`` (:data:`conrod.results.columns.CYCLE_COLUMNS`: the unit in
        each name, ``h_min_m``, ``p_max_Pa``, ``crank_angle_deg``, ...; angles in degrees;
        ``in_contact`` as booleans where ``cycle.csv`` writes 0/1)."""
        import pandas as pd

        from conrod.results.columns import CYCLE_COLUMNS, axial_table, feed_table

        columns = {}
        for column, (name, convert) in CYCLE_COLUMNS.items():
            values = np.asarray(getattr(self, name))
            columns[column] = convert(values) if convert is not None else values
        columns.update(axial_table(self.axial))
        columns.update(feed_table(self.feed))
        return pd.DataFrame(columns)


@dataclass(frozen=True)
class RunSummary:
    """Cycle characteristics ([D2] Table 1 'cycle' columns) and run diagnostics."""

    undrawn: ClassVar[tuple[str, ...]] = ("grid_error", "warnings")
    """Fields no figure draws: the grid-error estimate and the warnings it may add come
    after the figures are drawn (:class:`conrod.output.registry.FigureDraft`) [-]."""

    h_min: float
    """Smallest h_min over the cycle [m]."""
    h_min_crank_angle: float
    """Crank angle of the smallest h_min [rad]."""
    p_max: float
    """Largest p_max over the cycle [Pa]."""
    p_max_crank_angle: float
    """Crank angle of the largest p_max [rad]."""
    mean_h_min: float
    """Cycle mean of h_min [m]."""
    mean_p_max: float
    """Cycle mean of p_max [Pa]."""
    mean_friction_power: float
    """Cycle mean friction power loss of the film (hydrodynamic) [W]."""
    mean_side_flow: float
    """Cycle mean side flow [m^3/s]."""
    mean_supply_flow: float
    """Cycle mean supply flow [m^3/s]."""
    effective_temperature: float | None
    """Effective film temperature from the heat balance [°C] (None if no flow)."""
    viscosity: float
    """Viscosity used for the final orbit [Pa s]."""
    cycles: float
    """Cycles integrated; a lead-in from the concentric start counts by its share of a cycle
    (``[solver] lead_in``: 1.5 = half a cycle of lead-in, then one cycle) [cycles]."""
    periodicity_error: float
    """max |e_k − e_{k−1}|/c between the last two cycles at the same angles [-]."""
    periodic: bool
    """True if ``periodicity_error`` ≤ the tolerance of ``[solver]``."""
    film_model: str
    """Film model name [-]."""
    integrator: str
    """Integrator name [-]."""
    wall_time: float
    """Wall-clock time of the run [s]."""
    thermal_iterations: int = 0
    """Heat-balance iterations performed [-]."""
    max_contact_force: float = 0.0
    """Largest hard-contact force over the cycle [N]."""
    warnings: tuple[str, ...] = ()
    """Human-readable warnings (non-periodic orbit, ...) [-]."""
    mean_contact_friction_power: float = 0.0
    """Cycle mean dry-friction power of hard contact μ_dry P_c |V_slide| [W]."""
    mean_boundary_friction_power: float = 0.0
    """Cycle mean boundary friction power of the asperities (Greenwood–Tripp contact)
    μ_dry F_a |V_slide| [W]."""
    film_h_min: float | None = None
    """Smallest h_min over the angles outside hard contact, the smallest FILM thickness [m]
    (None: the journal touches the shell over the whole cycle). Where the journal touches,
    the gap is the contact threshold h_c, not a film."""
    film_h_min_crank_angle: float | None = None
    """Crank angle of ``film_h_min`` [rad]."""
    roughness: float | None = None
    """Combined roughness σ of journal and shell ``[contact] roughness`` [m]."""
    grid_error: Any = None
    """Grid-error estimate of h_min and p_max (:class:`conrod.results.grid_error.GridError`),
    None for a film without a grid or when not estimated [-]."""

    @property
    def mean_total_friction_power(self) -> float:
        """Film, hard-contact and boundary (asperity) friction power, the heat the oil
        carries away [W]."""
        return (self.mean_friction_power + self.mean_contact_friction_power
                + self.mean_boundary_friction_power)

    @property
    def film_thickness_ratio(self) -> float | None:
        """λ = film h_min / σ, the film thickness over the combined roughness [-] (None
        without a film h_min or a roughness); below 3 the asperities touch (mixed
        lubrication), below 1 they carry much of the load."""
        if self.film_h_min is None or not self.roughness:
            return None
        return self.film_h_min / self.roughness

    @property
    def exit_code(self) -> int:
        """What ``conrod run`` exits with for this result: 3 not periodic, 4 with warnings,
        0 otherwise (``--accept-warnings`` turns a 3 or 4 into 0) [-]."""
        if not self.periodic:
            return 3
        return 4 if self.warnings else 0

    def as_json_items(self) -> dict[str, Any]:
        """The summary.json items (engineering-friendly names with units in the key)."""
        return {
            "h_min_m": self.h_min,
            "h_min_crank_angle_deg": float(np.degrees(self.h_min_crank_angle)),
            "film_h_min_m": self.film_h_min,
            "film_h_min_crank_angle_deg": (None if self.film_h_min_crank_angle is None
                                           else float(np.degrees(self.film_h_min_crank_angle))),
            "film_thickness_ratio": self.film_thickness_ratio,
            "p_max_Pa": self.p_max,
            "p_max_crank_angle_deg": float(np.degrees(self.p_max_crank_angle)),
            "mean_h_min_m": self.mean_h_min,
            "mean_p_max_Pa": self.mean_p_max,
            "mean_friction_power_W": self.mean_friction_power,
            "mean_contact_friction_power_W": self.mean_contact_friction_power,
            "mean_boundary_friction_power_W": self.mean_boundary_friction_power,
            "mean_total_friction_power_W": self.mean_total_friction_power,
            "mean_side_flow_m3_s": self.mean_side_flow,
            "mean_supply_flow_m3_s": self.mean_supply_flow,
            "effective_temperature_C": self.effective_temperature,
            "viscosity_Pa_s": self.viscosity,
            "cycles": self.cycles,
            "periodicity_error": self.periodicity_error,
            "periodic": self.periodic,
            "film_model": self.film_model,
            "integrator": self.integrator,
            "wall_time_s": self.wall_time,
            "thermal_iterations": self.thermal_iterations,
            "max_orbit_contact_force_N": self.max_contact_force,
            "warnings": list(self.warnings),
            "exit_code": self.exit_code,
            **({"grid_error": self.grid_error.as_json_items()}
               if self.grid_error is not None else {}),
        }


@runtime_checkable
class ContactAnalysis(Protocol):
    """What :func:`conrod.contact.analysis.analyse_contact` returns: items merged into
    summary.json and columns refining cycle.csv (its own tables and figures are registered
    in the output registry)."""

    def summary_items(self) -> dict[str, Any]:
        """Items merged into summary.json."""
        ...

    def cycle_columns(self) -> dict[str, np.ndarray]:
        """Per-angle columns added to cycle.csv [units in the names]."""
        ...


@dataclass(frozen=True)
class RunResults:
    """Everything ``Simulation(case).run()`` returns."""

    cycle: CycleResults
    """Per-angle characteristics of the last (periodic) cycle."""
    summary: RunSummary
    """Cycle summary and diagnostics."""
    clearance: float
    """Radial clearance c [m]."""
    pressure_at_p_max: np.ndarray | None = None
    """Pressure field p(θ, z) at the crank angle of the largest p_max [Pa]."""
    pressure_grid: tuple[np.ndarray, np.ndarray] | None = None
    """(θ [rad], z [m]) nodes of ``pressure_at_p_max``."""
    previous_cycle_eccentricity: np.ndarray | None = None
    """(x, y) of the cycle before the last, shape (2, n) [m] (periodicity figure)."""
    contact: ContactAnalysis | None = None
    """Contact post-processing (friction work, wear) when available."""
    model: dict[str, str] | None = None
    """What was computed, for the headline: "film", "integrator", "housing" (rigid or
    elastic), "viscosity" (isoviscous or the pressure-viscosity law) [-]."""
    case_hash: str | None = None
    """SHA-256 (hex) of the validated case with the resolved solver settings [-]."""
    settings: dict[str, Any] | None = None
    """The resolved ``[solver]`` settings used (SI units) [-]."""
    thermal_film: Any = None
    """The film's temperature field and heat flows with ``[solver] thermal = "film"``
    (:class:`conrod.results.thermal.ThermalFilmResults`); None: the global heat balance."""
    thermal_maps: Any = None
    """Quasi-steady film temperature maps at chosen crank angles with the walls at their
    cycle-mean temperatures (:class:`conrod.results.thermal_maps.ThermalMapsResults`); None:
    no thermal film or no angles."""
    headline_extra: dict[str, str] | None = None
    """Further headline lines (label → text) added by other analyses, e.g. an elastic
    comparison; printed after the standard lines [-]."""
    film_thickness: np.ndarray | None = None
    """Film thickness h(φ, θ) at each output angle over the shell angles ``film_angles``
    (n_out, n_θ) [m]: on the rigid bore c − e_x cos θ − e_y sin θ, on a deforming bore
    with the bore displacement added (the gap the film sees)."""
    film_angles: np.ndarray | None = None
    """Shell angles θ of ``film_thickness``, film frame, 0 … 2π with the closing point [rad]."""
    contact_radius: float | None = None
    """Radius of the orbit's contact circle, on which the journal centre is stopped [m]:
    c − h_c on a rigid bore; on a deforming bore widened by one clearance (2c − h_c: the
    bore gives way, the deformed film stops the journal)."""
    case_record: Any = None
    """The case as run (:class:`conrod.results.case_record.CaseRecord`): the case file,
    the tables it reads, the values set on top of it; written into the result folder."""
    signoff: Any = None
    """Per-cell indicators, margins against ``[limits]`` and the fields over the cycle when
    asked for (:class:`conrod.results.margins.SignOff`); None: not computed."""

    def film_envelope(self) -> tuple[np.ndarray, np.ndarray, np.ndarray] | None:
        """(shell angles θ [rad], the smallest film thickness each of them sees over the
        cycle min_φ h(φ, θ) [m], the crank angle where it does [deg]) from
        ``film_thickness``; None without it."""
        if self.film_thickness is None or self.film_angles is None:
            return None
        rows = np.argmin(self.film_thickness, axis=0)
        return (self.film_angles, self.film_thickness.min(axis=0),
                self.cycle.crank_angle_deg[rows])

    @property
    def contact_threshold(self) -> float | None:
        """h_c, the film thickness at which the journal touches the rigid contact circle
        [m] (None when not set); on a deforming bore the journal is stopped by the deformed
        film, the circle is widened (``contact_radius``)."""
        value = (self.settings or {}).get("contact_film_thickness")
        return None if value is None else float(value)

    @property
    def contact_circle_widened(self) -> bool:
        """True when the orbit's contact circle lies beyond the rigid one, c − h_c: the bore
        deforms and the deformed film stops the journal [-]."""
        if self.contact_radius is None:
            return False
        return self.contact_radius > self.clearance - (self.contact_threshold or 0.0) + 1e-15
