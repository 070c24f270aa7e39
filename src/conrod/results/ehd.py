"""Results of an elastohydrodynamic run: the elastic answer, its rigid companion, the
comparison in the columns of Rodin (2004, Table 2); their tables are registered in
:mod:`conrod.output.ehd_tables`.

``cycle.csv`` and ``summary.json`` hold the elastic answer (the run columns plus the coupling
diagnostics of :mod:`conrod.ehd.cycle`); ``cycle_rigid.csv`` the rigid companion run;
``summary.json["comparison"]`` the cycle extremes and means of both, with the relative
difference (elastic − rigid) / rigid in %.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.results.cycle_results import RunResults

COMPARISON_COLUMNS = (
    ("h_min_um", "smallest h_min over the cycle [µm]", lambda s: 1e6 * s.h_min),
    ("p_max_MPa", "largest p_max over the cycle [MPa]", lambda s: 1e-6 * s.p_max),
    ("friction_power_W", "cycle mean friction power N [W]", lambda s: s.mean_friction_power),
    ("side_flow_cm3_s", "cycle mean side flow Q [cm^3/s]", lambda s: 1e6 * s.mean_side_flow),
    ("mean_h_min_um", "cycle mean of h_min, h* [µm]", lambda s: 1e6 * s.mean_h_min),
    ("mean_p_max_MPa", "cycle mean of p_max, p* [MPa]", lambda s: 1e-6 * s.mean_p_max),
)
"""Columns of Rodin (2004, Table 2): key, meaning with unit, value from a RunSummary."""


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
    def headline_extra(self) -> dict[str, str]:
        """Headline lines: elastic vs rigid h_min and p_max, coupling effort."""
        lines = dict(self.elastic.headline_extra or {})
        if self.rigid is not None:
            e, r = self.elastic.summary, self.rigid.summary
            lines["rigid vs elastic"] = (
                f"h_min {r.h_min * 1e6:.3f} → {e.h_min * 1e6:.3f} µm "
                f"({100.0 * (e.h_min - r.h_min) / r.h_min:+.1f} %), p_max "
                f"{r.p_max / 1e6:.1f} → {e.p_max / 1e6:.1f} MPa "
                f"({100.0 * (e.p_max - r.p_max) / r.p_max:+.1f} %)")
        if self.deformation_field is not None:
            field = self.deformation_field
            lines["bore"] = (f"deforms along the width: u(θ, z) at {field[0].size} film nodes, "
                             f"{field.min() * 1e6:.1f} … {field.max() * 1e6:.1f} µm")
        iterations = self.columns.get("coupling_iterations")
        if iterations is not None and len(iterations):
            updates = self.columns.get("newton_updates")
            newton = ("" if updates is None else
                      f", {float(np.mean(updates)):.1f} Newton updates")
            lines["coupling"] = (f"{float(np.mean(iterations)):.1f} film solves{newton} per "
                                 "step (mean, all force balances of the step)")
        return lines


def comparison(elastic: RunResults, rigid: RunResults) -> dict:
    """Rigid and elastic values of :data:`COMPARISON_COLUMNS` and (elastic − rigid)/rigid
    [%]."""
    table: dict[str, dict] = {"rigid": {}, "elastic": {}, "difference_percent": {},
                              "units": {}}
    for key, meaning, value in COMPARISON_COLUMNS:
        r, e = float(value(rigid.summary)), float(value(elastic.summary))
        table["rigid"][key], table["elastic"][key] = r, e
        table["difference_percent"][key] = 100.0 * (e - r) / r if r != 0.0 else None
        table["units"][key] = meaning
    return table
