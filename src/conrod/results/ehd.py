"""Results of an elastohydrodynamic run: the elastic answer, its rigid companion, the
comparison in the columns of Rodin (2004, Table 2); their tables are registered in
:mod:`conrod.output.ehd_tables`.

``cycle.csv`` and ``summary.json`` hold the elastic answer (the run columns plus the coupling
diagnostics of :mod:`conrod.ehd.cycle`); ``cycle_rigid.csv`` the rigid companion run;
``summary.json["comparison"]`` the cycle extremes and means of both, with the relative
difference (elastic − rigid) / rigid in %, the same extremes over the firing stroke
(±90° around firing TDC) and, at the elastic h_min, the bore displacement split into its
film-pressure and inertia parts.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.results.cycle_results import CycleResults, RunResults


def _film_h_min(s) -> float:
    return s.h_min if s.film_h_min is None else s.film_h_min


COMPARISON_COLUMNS = (
    ("h_min_um", "smallest film h_min over the cycle [µm]", lambda s: 1e6 * _film_h_min(s)),
    ("p_max_MPa", "largest p_max over the cycle [MPa]", lambda s: 1e-6 * s.p_max),
    ("friction_power_W", "cycle mean film friction power N [W]",
     lambda s: s.mean_friction_power),
    ("side_flow_l_min", "cycle mean side flow Q [l/min]", lambda s: 6e4 * s.mean_side_flow),
    ("mean_h_min_um", "cycle mean of h_min, h* [µm]", lambda s: 1e6 * s.mean_h_min),
    ("mean_p_max_MPa", "cycle mean of p_max, p* [MPa]", lambda s: 1e-6 * s.mean_p_max),
)
"""Columns of Rodin (2004, Table 2): key, meaning with unit, value from a RunSummary."""

FIRING_HALF_WIDTH_DEG = 90.0
"""The firing stroke: crank angles within this of firing TDC (φ = 0) [deg]."""


def firing_stroke(crank_angle: np.ndarray, cycle: float = 4.0 * np.pi) -> np.ndarray:
    """True at the crank angles [rad] within :data:`FIRING_HALF_WIDTH_DEG` of firing TDC,
    φ = 0 of a cycle of length ``cycle`` [rad] (expansion after it, compression before) [-]."""
    offset = (np.asarray(crank_angle) + 0.5 * cycle) % cycle - 0.5 * cycle
    return np.abs(np.degrees(offset)) <= FIRING_HALF_WIDTH_DEG + 1e-9


def extremes(cycle: CycleResults, where: np.ndarray | None = None) -> dict[str, float | None]:
    """The smallest film h_min (angles outside hard contact) and the largest p_max over the
    output angles ``where`` (all: None), with their crank angles [µm, MPa, deg]."""
    rows = np.ones(len(cycle), dtype=bool) if where is None else np.asarray(where, bool)
    film = rows & ~np.asarray(cycle.in_contact, dtype=bool)
    out: dict[str, float | None] = {"h_min_um": None, "h_min_crank_angle_deg": None}
    if np.any(film):
        i = int(np.flatnonzero(film)[np.argmin(cycle.h_min[film])])
        out = {"h_min_um": 1e6 * float(cycle.h_min[i]),
               "h_min_crank_angle_deg": float(cycle.crank_angle_deg[i])}
    j = int(np.flatnonzero(rows)[np.argmax(cycle.p_max[rows])])
    out.update(p_max_MPa=1e-6 * float(cycle.p_max[j]),
               p_max_crank_angle_deg=float(cycle.crank_angle_deg[j]))
    return out


def _cycle_length(cycle: CycleResults) -> float:
    phi = np.asarray(cycle.crank_angle)
    return float(phi[-1] - phi[0] + np.median(np.diff(phi)))


def _percent(elastic: float | None, rigid: float | None) -> float | None:
    if elastic is None or rigid is None or rigid == 0.0:
        return None
    return 100.0 * (elastic - rigid) / rigid


@dataclass(frozen=True)
class ElasticRunResults:
    """An elastohydrodynamic run.

    elastic : RunResults  The answer on the deforming bore.
    columns : dict  Coupling diagnostics per output crank angle (names with units).
    deformation : ndarray  Corrected bore displacement (n_out, n_θ) [m], outward +; for a
        housing that deforms along the width, its mean over the width.
    bore_angles : ndarray  Bore-node angles θ [rad].
    housing : object  The :class:`conrod.housing.housing.Housing` used.
    rigid : RunResults or None  The rigid companion run (None when skipped).
    info : dict  Coupling settings and totals for summary.json.
    peak_load_index : int  Output row of the largest load [-].
    peak_load_pressure : ndarray or None  Film pressure p(θ, z) there [Pa].
    deformation_field : ndarray or None  Corrected bore displacement u(θ, z)
        (n_out, n_θ, n_z + 1) [m] of a housing that deforms along the width (a 3-D
        compliance); None for a plane housing, whose deformation is uniform in z.
    pressure_fields : dict  Crank angle [deg] → film pressure p(θ, z) on the film grid
        (``elastic.pressure_grid``) [Pa] at the largest load and the stress angles of
        ``[housing]``: the pressure ``conrod stress`` loads the rod with.
    stresses : dict or None  Rod stresses at the largest load under the elastic film
        pressure and under a cosine load of the same resultant
        (:func:`conrod.housing.stresses.compare_schemes`); None without a finite-element rod.
    bore_displacement : dict or None  At the elastic film h_min: crank and shell angle
        [deg], the bore displacement there and its inertia and film-pressure parts [m]
        (:func:`conrod.ehd.cycle.displacement_split`).
    """

    elastic: RunResults
    columns: dict[str, np.ndarray]
    deformation: np.ndarray
    bore_angles: np.ndarray
    housing: Any
    rigid: RunResults | None = None
    info: dict | None = None
    peak_load_index: int = 0
    peak_load_pressure: np.ndarray | None = None
    deformation_field: np.ndarray | None = None
    pressure_fields: dict[float, np.ndarray] | None = None
    stresses: dict | None = None
    bore_displacement: dict[str, float] | None = None

    @property
    def axial_positions(self) -> np.ndarray | None:
        """z_k of ``deformation_field`` [m] from the bearing mid-plane; None when plane."""
        return None if self.deformation_field is None else self.housing.axial

    def gap_field(self, index: int) -> np.ndarray:
        """Film thickness on the deformed bore h(θ, z) = c − e_x cos θ − e_y sin θ + u(θ, z)
        (n_θ, n_z + 1) [m] at output row ``index`` (needs ``deformation_field``)."""
        assert self.deformation_field is not None, "a plane housing has no u(θ, z)"
        return self._rigid_gap(index)[:, None] + self.deformation_field[index]

    def mean_gap(self, index: int) -> np.ndarray:
        """Film thickness per row on the bore deformed by ``deformation`` (the width-mean of
        a 3-D bore), c − e_x cos θ − e_y sin θ + ū(θ) (n_θ,) [m] at output row ``index``."""
        return self._rigid_gap(index) + self.deformation[index]

    def _rigid_gap(self, index: int) -> np.ndarray:
        cycle, theta = self.cycle, self.bore_angles
        return (self.clearance - cycle.eccentricity_x[index] * np.cos(theta)
                - cycle.eccentricity_y[index] * np.sin(theta))

    @property
    def cycle(self):
        """Characteristics of the elastic answer per crank angle."""
        return self.elastic.cycle

    @property
    def summary(self):
        """Summary of the elastic answer."""
        return self.elastic.summary

    @property
    def clearance(self) -> float:
        """Radial clearance c [m]."""
        return self.elastic.clearance

    @property
    def signoff(self):
        """Per-cell indicators and margins of the elastic answer
        (:class:`conrod.results.margins.SignOff`)."""
        return self.elastic.signoff

    @property
    def contact(self):
        """Contact post-processing of the elastic answer."""
        return self.elastic.contact

    @property
    def model(self) -> dict[str, str] | None:
        """What was computed, in words (the elastic answer's description)."""
        return self.elastic.model

    @property
    def case_hash(self) -> str | None:
        """SHA-256 of the resolved case [-]."""
        return self.elastic.case_hash

    @property
    def settings(self) -> dict | None:
        """Resolved ``[solver]`` settings."""
        return self.elastic.settings

    @property
    def pressure_at_p_max(self):
        """Pressure field at the largest p_max of the elastic answer [Pa]."""
        return self.elastic.pressure_at_p_max

    @property
    def pressure_grid(self):
        """(θ [rad], z [m]) nodes of ``pressure_at_p_max``."""
        return self.elastic.pressure_grid

    @property
    def film_thickness(self) -> np.ndarray | None:
        """Film thickness on the deformed bore h(φ, θ) (n_out, n_θ + 1) [m]."""
        return self.elastic.film_thickness

    @property
    def film_angles(self) -> np.ndarray | None:
        """Shell angles θ of ``film_thickness`` [rad]."""
        return self.elastic.film_angles

    @property
    def contact_radius(self) -> float | None:
        """The orbit's contact circle on the deforming bore, 2c − h_c [m]."""
        return self.elastic.contact_radius

    @property
    def case_record(self) -> Any:
        """The case as run (:class:`conrod.results.case_record.CaseRecord`)."""
        return self.elastic.case_record

    @property
    def thermal_film(self) -> Any:
        """The elastic answer's film temperature field (``[solver] thermal = "film"``), or
        None (:class:`conrod.results.thermal.ThermalFilmResults`)."""
        return self.elastic.thermal_film

    @property
    def thermal_maps(self) -> Any:
        """The elastic answer's temperature maps at chosen crank angles, or None
        (:class:`conrod.results.thermal_maps.ThermalMapsResults`)."""
        return self.elastic.thermal_maps

    def firing_comparison(self) -> dict[str, Any]:
        """h_min and p_max, rigid and elastic, over the firing stroke (±90° around firing
        TDC) [µm, MPa, deg], with the relative difference [%]."""
        elastic = self.elastic.cycle
        window = firing_stroke(elastic.crank_angle, _cycle_length(elastic))
        table: dict[str, Any] = {"window_deg": [-FIRING_HALF_WIDTH_DEG, FIRING_HALF_WIDTH_DEG],
                                 "elastic": extremes(elastic, window)}
        if self.rigid is not None:
            rigid = self.rigid.cycle
            table["rigid"] = extremes(rigid, firing_stroke(rigid.crank_angle,
                                                           _cycle_length(rigid)))
            table["difference_percent"] = {
                key: _percent(table["elastic"][key], table["rigid"][key])
                for key in ("h_min_um", "p_max_MPa")}
        return table

    @property
    def headline_extra(self) -> dict[str, str]:
        """Headline lines: elastic vs rigid h_min and p_max over the cycle and over the
        firing stroke, the bore displacement at the elastic h_min, coupling effort."""
        lines = dict(self.elastic.headline_extra or {})
        if self.rigid is not None:
            e, r = self.elastic.summary, self.rigid.summary
            h_min = _text_change(1e6 * _film_h_min(r), 1e6 * _film_h_min(e), "µm", 3)
            lines["rigid vs elastic"] = (
                f"whole cycle: film h_min {h_min}, p_max "
                f"{_text_change(r.p_max / 1e6, e.p_max / 1e6, 'MPa', 1)}")
            firing = self.firing_comparison()
            fr, fe = firing["rigid"], firing["elastic"]
            lines["firing stroke"] = (
                f"±{FIRING_HALF_WIDTH_DEG:.0f}° around firing TDC: film h_min "
                f"{_text_change(fr['h_min_um'], fe['h_min_um'], 'µm', 3)} (at "
                f"{_angle(fr['h_min_crank_angle_deg'])} → {_angle(fe['h_min_crank_angle_deg'])}), "
                f"p_max {_text_change(fr['p_max_MPa'], fe['p_max_MPa'], 'MPa', 1)} (at "
                f"{_angle(fr['p_max_crank_angle_deg'])} → {_angle(fe['p_max_crank_angle_deg'])})")
        if self.deformation_field is not None:
            field = self.deformation_field
            lines["bore"] = (f"deforms along the width: u(θ, z) at {field[0].size} film nodes, "
                             f"{field.min() * 1e6:.1f} … {field.max() * 1e6:.1f} µm")
        split = self.bore_displacement
        if split is not None:
            lines["bore at elastic h_min"] = (
                f"u = {split['total_m'] * 1e6:+.2f} µm at θ = {split['shell_angle_deg']:.0f}°, "
                f"φ = {split['crank_angle_deg']:.0f}° (outward +): film pressure "
                f"{split['pressure_m'] * 1e6:+.2f} µm, rod inertia "
                f"{split['inertia_m'] * 1e6:+.2f} µm")
        iterations = self.columns.get("coupling_iterations")
        if iterations is not None and len(iterations):
            updates = self.columns.get("newton_updates")
            newton = ("" if updates is None else
                      f", {float(np.mean(updates)):.1f} Newton updates")
            lines["coupling"] = (f"{float(np.mean(iterations)):.1f} film solves{newton} per "
                                 "step (mean, all force balances of the step)")
        return lines


def _angle(value: float | None) -> str:
    return "–" if value is None else f"{value:.0f}°"


def _text_change(rigid: float | None, elastic: float | None, unit: str, digits: int) -> str:
    """'1.689 → 2.682 µm (+58.8 %)', rigid → elastic."""
    if rigid is None or elastic is None:
        return "– (the journal touches the shell)"
    change = _percent(elastic, rigid)
    shown = "" if change is None else f" ({change:+.1f} %)"
    return f"{rigid:.{digits}f} → {elastic:.{digits}f} {unit}{shown}"


def comparison(elastic: RunResults, rigid: RunResults) -> dict:
    """Rigid and elastic values of :data:`COMPARISON_COLUMNS` and (elastic − rigid)/rigid
    [%] (the firing stroke and the bore displacement are added by
    :func:`conrod.output.ehd_tables.elastic_summary_items`)."""
    table: dict[str, dict] = {"rigid": {}, "elastic": {}, "difference_percent": {},
                              "units": {}}
    for key, meaning, value in COMPARISON_COLUMNS:
        r, e = float(value(rigid.summary)), float(value(elastic.summary))
        table["rigid"][key], table["elastic"][key] = r, e
        table["difference_percent"][key] = 100.0 * (e - r) / r if r != 0.0 else None
        table["units"][key] = meaning
    return table
