"""Tables of the sign-off of a run (:class:`conrod.results.margins.SignOff`): the margins
against ``[limits]`` (``margins.csv``), the per-cell indicator maps (``indicator_maps.csv``)
and, with ``conrod run --fields``, the fields over the cycle (``fields.nc``,
:mod:`conrod.output.fields_file`). The run tables of :mod:`conrod.output.tables` and
:mod:`conrod.output.ehd_tables` add them."""

from __future__ import annotations

import math

import numpy as np

from conrod.output.fields_file import FIELDS_FILE, fields_bytes
from conrod.output.registry import TableSpec

UNIT_SUFFIX = {"Pa": "Pa", "m": "m", "degC": "degC", "Pa/s": "Pa_per_s", "1": "1"}
"""Unit of a map → the suffix of its column name [-]."""


def margins_table(signoff) -> dict[str, np.ndarray]:
    """margins.csv columns: one row per given limit, values in SI units."""
    rows = signoff.margins

    def column(get) -> np.ndarray:  # empty where not known (a table, not a NaN)
        return np.array(["" if get(m) is None else f"{get(m):.9g}" for m in rows])

    return {
        "limit": np.array([m.name for m in rows]),
        "unit": np.array([m.units for m in rows]),
        "value": column(lambda m: m.value), "limit_value": column(lambda m: m.limit),
        "margin": column(lambda m: m.margin),
        "crank_angle_deg": column(lambda m: None if m.crank_angle is None
                                  else math.degrees(m.crank_angle)),
        "theta_deg": column(lambda m: None if m.theta is None
                            else math.degrees(m.theta) % 360.0),
        "z_m": column(lambda m: m.z), "crossed": np.array([str(int(m.crossed)) for m in rows]),
        "source": np.array([m.source.replace(",", ";") for m in rows]),
    }


def maps_table(indicators) -> dict[str, np.ndarray]:
    """indicator_maps.csv: one row per film node (θ, z), each map and the crank angle where
    its cell's value is reached (units in the column names)."""
    theta, z = np.meshgrid(np.degrees(indicators.theta), indicators.z, indexing="ij")
    table = {"theta_deg": theta.ravel(), "z_m": z.ravel()}
    items = (*indicators.maps, *((indicators.erosion,) if indicators.erosion else ()))
    for item in items:
        stem = f"{item.name}_{item.frame}"
        table[f"{stem}_{UNIT_SUFFIX.get(item.units, item.units)}"] = item.values.ravel()
        table[f"{stem}_crank_angle_deg"] = np.degrees(item.crank_angle).ravel()
    return table


def signoff_tables(results) -> tuple[TableSpec, ...]:
    """The sign-off tables of a run (``results``: a RunResults with ``signoff``)."""
    signoff = getattr(results, "signoff", None)
    if signoff is None:
        return ()
    specs = []
    if signoff.margins:
        specs.append(TableSpec(
            "margins.csv", "Margins against the limits",
            "One row per [limits] entry: the run's worst value and the limit in SI units "
            "(unit column), margin (limit - value)/limit (MOFT: (value - limit)/limit; "
            "negative: crossed), crank angle [deg], shell angle [deg], axial position [m].",
            lambda: margins_table(signoff)))
    if signoff.indicators is not None:
        specs.append(TableSpec(
            "indicator_maps.csv", "Per-cell indicators over the cycle",
            "Per film node (shell or journal angle [deg], z [m]): largest pressure, pressure "
            "range max - min, smallest film thickness, largest asperity pressure and "
            "temperature where computed, on the shell and on the journal, the cavitation-"
            "erosion indicator [Pa/s], each with the crank angle where it is reached [deg].",
            lambda: maps_table(signoff.indicators)))
    if signoff.fields is not None:
        specs.append(TableSpec(
            FIELDS_FILE, "Fields over the cycle (netCDF)",
            "Film fields on the film grid at the kept crank angles (dims crank_angle "
            "[degree], theta [degree], z [m]; units and long names as attributes; CF): "
            + ", ".join(signoff.fields.values) + "; conrod.open_fields(folder) reads it.",
            lambda: fields_bytes(signoff.fields)))
    return tuple(specs)
