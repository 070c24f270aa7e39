"""Per-cell sign-off indicators over the cycle: what each point of the lining and of the
journal sees.

From the fields on the film grid at the output crank angles (:class:`CycleFields`), per
film cell (θ_j, z_k):

* ``max_pressure`` — the largest film pressure max_φ p (POFP map) [Pa];
* ``pressure_range`` — the pressure range Δp = max_φ p − min_φ p: hydrodynamic fatigue of
  the lining is driven by the pressure each element sees vary over the cycle, not by the
  peak specific load ("Hydrodynamic aspects of fatigue in plain journal bearings",
  J. Lubr. Technol. 103 (1981) 150; docs/references.md) [Pa];
* ``min_film_thickness`` — the smallest film thickness min_φ h (MOFT map) [m];
* ``max_asperity_pressure`` — the largest Greenwood–Tripp asperity pressure [Pa];
* ``max_temperature`` — the largest film temperature, when a film declares one [°C];

on the unrolled shell (θ, z) and on the journal in its own frame (the journal turns: its
point at its own angle α lies at the shell angle α + ψ(φ), ψ the journal rotation of
``cycle.csv``; each row is turned by the nearest whole number of cells, so the journal map
holds exactly the shell's values and its positions are within half a cell, Δθ/2). Each map
has its worst value, where (θ, z) and when (crank angle). The worst film pressure and film
thickness are the film's own p_max and h_min of the output rows (``cycle.csv``, from the
same solve as the fields; between the nodes where the film refines them), so the maps and
the headline give one number; without them (fields from elsewhere) each row's extreme node
is refined in θ by the film's parabola (:func:`conrod.film.characteristics.peak_pressure_at`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import SimpleNamespace
from typing import Any

import numpy as np

from conrod.film.characteristics import minimum_film_at, peak_pressure_at
from conrod.results.fields import CycleFields

TWO_PI = 2.0 * math.pi

INDICATORS = (
    ("max_pressure", "pressure", "max", "largest film pressure (POFP)"),
    ("pressure_range", "pressure", "range", "pressure range max - min (lining fatigue)"),
    ("min_film_thickness", "film_thickness", "min", "smallest film thickness (MOFT)"),
    ("max_asperity_pressure", "asperity_pressure", "max", "largest asperity pressure"),
    ("max_temperature", "temperature", "max", "largest film temperature"),
)
"""Indicator name, the field it reads, how over the cycle, what it is in words [-]."""


@dataclass(frozen=True)
class CellMap:
    """One indicator per film cell over the cycle.

    name : str  Indicator name (:data:`INDICATORS`, or ``erosion``) [-].
    long_name : str  What it is, in words [-].
    units : str  Unit of ``values`` ('Pa', 'm', 'degC', 'Pa/s') [-].
    frame : str  'shell' (θ on the shell) or 'journal' (its own angle α on the journal) [-].
    values : ndarray  The indicator per cell (n_θ, n_z), in ``units``.
    crank_angle : ndarray  Crank angle where each cell's value is reached (the maximum of a
        range) (n_θ, n_z) [rad].
    worst : str  'max' or 'min': which end is the bad one [-].
    worst_value : float  The worst value (film pressure and thickness refined in θ between
        the nodes as the film refines its own p_max and h_min), in ``units``.
    worst_theta : float  Its angle on the shell or the journal [rad].
    worst_z : float  Its axial position [m].
    worst_crank_angle : float  Its crank angle [rad].
    """

    name: str
    long_name: str
    units: str
    frame: str
    values: np.ndarray
    crank_angle: np.ndarray
    worst: str
    worst_value: float
    worst_theta: float
    worst_z: float
    worst_crank_angle: float

    def summary_items(self) -> dict[str, float | str]:
        """The worst value and where, with units in the keys (angles in degrees)."""
        return {"value": self.worst_value, "units": self.units,
                "theta_deg": math.degrees(self.worst_theta), "z_m": self.worst_z,
                "crank_angle_deg": math.degrees(self.worst_crank_angle)}


@dataclass(frozen=True)
class Indicators:
    """The per-cell indicators of a run.

    theta : ndarray  Node angles (n_θ,) [rad] (shell θ, journal α alike).
    z : ndarray  Axial nodes (n_z,) [m].
    maps : tuple  :class:`CellMap` of each indicator whose field the run has, shell and
        journal frame.
    erosion : CellMap or None  The cavitation-erosion indicator on the shell
        (:mod:`conrod.results.erosion`); None when the film gives none.
    erosion_note : str  What ``erosion`` is (indicator or labelled proxy) or why there is
        none [-].
    """

    theta: np.ndarray
    z: np.ndarray
    maps: tuple[CellMap, ...]
    erosion: CellMap | None = None
    erosion_note: str = ""

    def get(self, name: str, frame: str = "shell") -> CellMap | None:
        """The map ``name`` in ``frame`` ('shell', 'journal'); None when not computed."""
        for item in (*self.maps, *((self.erosion,) if self.erosion else ())):
            if item.name == name and item.frame == frame:
                return item
        return None

    def summary_items(self) -> dict:
        """summary.json items: each map's worst value and where, the erosion note."""
        items: dict = {f"{m.name}_{m.frame}": m.summary_items() for m in self.maps}
        if self.erosion is not None:
            items[f"erosion_{self.erosion.frame}"] = {
                **self.erosion.summary_items(), "long_name": self.erosion.long_name}
        items["erosion_note"] = self.erosion_note
        return items


def cell_indicators(fields: CycleFields, erosion: CellMap | None = None,
                    erosion_note: str = "") -> Indicators:
    """The maps of every indicator whose field ``fields`` holds, on the shell and on the
    journal (module docstring)."""
    maps = []
    for name, source, how, words in INDICATORS:
        if source not in fields:
            continue
        history = fields[source]
        units = fields.specs[source].units
        for frame in ("shell", "journal"):
            rows = history if frame == "shell" else journal_frame(history, fields)
            maps.append(_cell_map(name, f"{words}, {frame}", units, frame, rows, how,
                                  fields, history, source))
    return Indicators(fields.theta, fields.z, tuple(maps), erosion, erosion_note)


def journal_shifts(fields: CycleFields) -> np.ndarray:
    """Whole cells s_i = round(ψ_i / Δθ) by which each row is turned into the journal's
    frame (n,) [-]."""
    step = TWO_PI / fields.theta.size
    return np.rint(np.asarray(fields.journal_rotation) / step).astype(int)


def journal_frame(history: np.ndarray, fields: CycleFields) -> np.ndarray:
    """``history`` (n, n_θ, n_z) on the shell as seen on the journal: row i at the journal
    node α_k takes the shell node θ_(k + s_i) (:func:`journal_shifts`)."""
    n_theta = fields.theta.size
    shifts = journal_shifts(fields)
    index = (np.arange(n_theta)[None, :] + shifts[:, None]) % n_theta
    return history[np.arange(history.shape[0])[:, None], index]  # whole axial rows at once


def _cell_map(name, long_name, units, frame, rows, how, fields, shell_rows,
              source) -> CellMap:
    """The indicator of ``rows`` (n, n_θ, n_z) per cell and its worst value."""
    if how == "min":
        (values, when), worst = smallest_over_rows(rows), "min"
    elif how == "max":
        (values, when), worst = largest_over_rows(rows), "max"
    else:
        (high_values, when), worst = largest_over_rows(rows), "max"
        values = high_values - rows.min(axis=0)
    if name in ("max_pressure", "min_film_thickness"):
        value, theta, z, i = _refined(how, shell_rows, fields, source)
        if frame == "journal":
            theta = (theta - float(fields.journal_rotation[i])) % TWO_PI
    else:
        flat = int(values.argmin() if worst == "min" else values.argmax())
        j, node = np.unravel_index(flat, values.shape)
        k = middle_of_ties(values[j], int(node))
        i = int(when[j, k])
        value, theta, z = float(values[j, k]), float(fields.theta[j]), float(fields.z[k])
    return CellMap(name, long_name, units, frame, values, fields.crank_angle[when], worst,
                   value, theta, z, float(fields.crank_angle[i]))


def largest_over_rows(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(max over the rows, the first row reaching it) per cell of ``rows`` (n, ...): what
    ``max(axis=0)`` and ``argmax(axis=0)`` give, the row found on a boolean array (numpy's
    argmax along the first axis of a float array copies it transposed) [-]."""
    values = rows.max(axis=0)
    return values, (rows == values).argmax(axis=0)


def smallest_over_rows(rows: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(min over the rows, the first row reaching it) per cell (:func:`largest_over_rows`)."""
    values = rows.min(axis=0)
    return values, (rows == values).argmax(axis=0)


def middle_of_ties(column: np.ndarray, k: int) -> int:
    """The middle of the axial nodes within round-off of ``column[k]`` (a film uniform
    along the width has its extreme at every z: the film's own h_min position rule) [-]."""
    ties = np.flatnonzero(np.abs(column - column[k]) <= 1e-12 * abs(column[k]))
    return int(ties[len(ties) // 2])


def _refined(how: str, rows: np.ndarray, fields: CycleFields, source: str
             ) -> tuple[float, float, float, int]:
    """(value, shell θ [rad], z [m], output row) of the worst film pressure or thickness:
    the film's own extreme of each row where the fields carry it (the p_max and h_min of
    ``cycle.csv``, from the same solve), else each row's extreme node refined in θ by the
    film's parabola; the worst of the rows (the first on a tie), z of its extreme node."""
    flat = rows.reshape(rows.shape[0], -1)
    nodes = flat.argmax(axis=1) if how == "max" else flat.argmin(axis=1)
    if source in fields.row_extremes:
        values, angles = fields.row_extremes[source]
        i = int(np.argmax(values) if how == "max" else np.argmin(values))
        j, k = divmod(int(nodes[i]), rows.shape[2])
        k = middle_of_ties(rows[i, j], k)
        return float(values[i]), float(angles[i]) % TWO_PI, float(fields.z[k]), i
    n_theta = fields.theta.size
    grid: Any = SimpleNamespace(n_theta=n_theta, theta=fields.theta, d_theta=TWO_PI / n_theta)
    refine = peak_pressure_at if how == "max" else minimum_film_at
    best = None
    for i, node in enumerate(nodes):
        j, k = divmod(int(node), rows.shape[2])
        k = middle_of_ties(rows[i, j], k)
        value, theta = refine(rows[i], grid, j, k)
        if best is None or (value > best[0] if how == "max" else value < best[0]):
            best = (value, theta, float(fields.z[k]), i)
    assert best is not None
    return best
