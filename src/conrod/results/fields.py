"""Fields on the film grid over the last cycle: pressure, film thickness, film fraction,
bore deformation, asperity pressure, temperature, ... (``conrod run --fields``; the per-cell
sign-off indicators of :mod:`conrod.results.indicators` read them).

A field is known by its name; :data:`FIELD_SPECS` gives the unit and long name of the ones
conrod computes. A film declares further fields of its own
(:class:`~conrod.film.capabilities.HasFilmFields`, e.g. a thermal film's ``temperature``)
with their unit and long name, and they travel through the same arrays, file and maps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class FieldSpec:
    """Unit (UDUNITS spelling, as CF wants it) and long name of a field [-]."""

    units: str
    long_name: str


FIELD_SPECS = {
    "pressure": FieldSpec("Pa", "film pressure (gauge)"),
    "film_thickness": FieldSpec("m", "film thickness"),
    "film_fraction": FieldSpec("1", "film fraction (1: full film, mass-conserving film)"),
    "deformation": FieldSpec("m", "bore deformation (outward +)"),
    "asperity_pressure": FieldSpec("Pa", "asperity contact pressure (Greenwood-Tripp)"),
    "temperature": FieldSpec("degC", "film temperature"),
}
"""The fields conrod knows by name → unit and long name; a declared field brings its own."""


@dataclass(frozen=True)
class CycleFields:
    """Fields on the film grid at the output crank angles of the last cycle.

    crank_angle : ndarray  Output crank angles φ_i (n,) [rad].
    theta : ndarray  Shell angles θ_j of the film nodes (n_θ,) [rad], film frame, 2π
        excluded (periodic).
    z : ndarray  Axial positions z_k of the film nodes (n_z,) [m], 0 at mid-width.
    journal_rotation : ndarray  Rotation of the journal relative to the shell since the
        first output angle (n,) [rad]: the journal point at its own angle α lies at the
        shell angle α + rotation.
    values : dict  Field name → (n, n_θ, n_z) array in the unit of ``specs[name]``.
    specs : dict  Field name → :class:`FieldSpec`.
    cycle_length : float  Length of the cycle [rad] (4π for a four-stroke engine).
    crank_speed : float  Crank angular velocity ω [rad/s] (time between rows Δφ/ω).
    cavitation_pressure : float  Gauge cavitation pressure of the film [Pa].
    film_model : str  Name of the film model that computed them [-].
    """

    crank_angle: np.ndarray
    theta: np.ndarray
    z: np.ndarray
    journal_rotation: np.ndarray
    values: dict[str, np.ndarray]
    specs: dict[str, FieldSpec]
    cycle_length: float = 4.0 * math.pi
    crank_speed: float = 1.0
    cavitation_pressure: float = 0.0
    film_model: str = ""
    notes: tuple[str, ...] = field(default=())
    """What the fields leave out or approximate, in words [-]."""
    row_extremes: dict[str, tuple[np.ndarray, np.ndarray]] = field(default_factory=dict)
    """Field name → (the film's own extreme per row, its shell angle θ [rad]) as the film
    reported it with these fields (p_max and h_min of ``cycle.csv``, refined between the
    nodes where the film refines them); the maps' worst values take these (one truth)."""

    def __contains__(self, name: str) -> bool:
        return name in self.values

    def __getitem__(self, name: str) -> np.ndarray:
        return self.values[name]

    @property
    def crank_angle_deg(self) -> np.ndarray:
        """Output crank angles [deg]."""
        return np.degrees(self.crank_angle)

    def every(self, stride_deg: float) -> CycleFields:
        """The rows at the first output angle and every ``stride_deg`` after it (the
        nearest output angle at or after each multiple; every row when the stride is not
        larger than the output step) [deg]."""
        rows = stride_rows(self.crank_angle, math.radians(stride_deg))
        return CycleFields(
            self.crank_angle[rows], self.theta, self.z, self.journal_rotation[rows],
            {name: values[rows] for name, values in self.values.items()}, dict(self.specs),
            self.cycle_length, self.crank_speed, self.cavitation_pressure, self.film_model,
            self.notes, {name: (v[rows], a[rows]) for name, (v, a) in self.row_extremes.items()})


def stride_rows(crank_angle: np.ndarray, stride: float) -> np.ndarray:
    """Indices of the output angles kept at a stride [rad]: the first, then the first at or
    after each multiple of ``stride`` from it (sorted, unique) [-]."""
    phi = np.asarray(crank_angle, dtype=float) - float(crank_angle[0])
    targets = np.arange(0.0, phi[-1] + 1e-12, stride)
    rows = np.searchsorted(phi, targets - 1e-9 * max(stride, 1e-12))
    return np.unique(rows[rows < phi.size])
