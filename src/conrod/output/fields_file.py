"""The fields over the cycle as one netCDF file (``fields.nc``), and reading it back.

Dimensions ``crank_angle`` [degree] (CF ``axis = "T"``, with the auxiliary coordinate
``time`` [s] from the first kept angle), ``theta`` [degree] (shell angle, film frame,
``axis = "X"``) and ``z`` [m] (axial, 0 at mid-width, ``axis = "Y"``: the unrolled shell);
one variable per field (pressure, film_thickness, film_fraction, deformation,
asperity_pressure, temperature, ... — what the run has) with ``units`` (UDUNITS) and
``long_name`` attributes, ``journal_rotation`` [degree] over ``crank_angle``, global
attributes after the CF conventions (``Conventions = "CF-1.10"``, ``title``, ``source``,
``history``). Written with xarray through h5netcdf: netCDF-4 (HDF5) with zlib compression
level 4 on the fields, float64 as computed — read back, the values are the computed ones
bit for bit (a netCDF-3 file, the one scipy writes, has no compression: the passenger car
at 72 × 16 and 1° takes 21 MB instead of 5.7 MB, benchmarks/signoff_cost.md; ParaView's
NetCDF readers and xarray read netCDF-4 alike).
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.results.fields import CycleFields

FIELDS_FILE = "fields.nc"
"""File name of the fields over the cycle in a run folder [-]."""
ENGINE = "h5netcdf"
"""The netCDF engine xarray writes and reads with (netCDF-4/HDF5, compressed) [-]."""
COMPRESSION = {"zlib": True, "complevel": 4, "shuffle": True}
"""Lossless compression of every field variable [-]."""


def fields_dataset(fields: CycleFields, title: str = "conrod fields over the cycle") -> Any:
    """The :class:`xarray.Dataset` of ``fields`` (module docstring)."""
    import xarray as xr

    from conrod._version import __version__

    elapsed = (fields.crank_angle - fields.crank_angle[0]) / fields.crank_speed
    coords = {
        "crank_angle": ("crank_angle", fields.crank_angle_deg,
                        {"units": "degree", "long_name": "crank angle (0: firing TDC)",
                         "axis": "T"}),
        "theta": ("theta", np.degrees(fields.theta),
                  {"units": "degree", "long_name": "shell angle, film frame", "axis": "X"}),
        "z": ("z", np.asarray(fields.z, dtype=float),
              {"units": "m", "long_name": "axial position, 0 at mid-width", "axis": "Y"}),
        "time": ("crank_angle", elapsed,
                 {"units": "s", "standard_name": "time",
                  "long_name": "time from the first kept crank angle"}),
    }
    data: dict[str, Any] = {name: (("crank_angle", "theta", "z"), np.asarray(values, dtype=float),
                   {"units": fields.specs[name].units, "long_name": fields.specs[name].long_name})
            for name, values in fields.values.items()}
    data["journal_rotation"] = (
        ("crank_angle",), np.degrees(fields.journal_rotation),
        {"units": "degree", "long_name": "journal rotation relative to the shell (the journal "
         "point at its own angle a lies at the shell angle a + journal_rotation)"})
    attrs = {"Conventions": "CF-1.10", "title": title,
             "source": f"conrod {__version__}, film model {fields.film_model}",
             "history": "written by conrod run --fields",
             "cycle_length_deg": float(np.degrees(fields.cycle_length)),
             "crank_speed_rad_per_s": float(fields.crank_speed)}
    return xr.Dataset(data, coords=coords, attrs=attrs)


def fields_bytes(fields: CycleFields) -> bytes:
    """``fields.nc`` as bytes (written by the result folder's atomic writer)."""
    import tempfile

    dataset = fields_dataset(fields)
    encoding = {name: dict(COMPRESSION) for name in fields.values}
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / FIELDS_FILE
        dataset.to_netcdf(path, engine=ENGINE, encoding=encoding)
        return path.read_bytes()


def open_fields(folder: str | os.PathLike[str]) -> Any:
    """The fields over the cycle of a run folder written with ``conrod run --fields``, as an
    :class:`xarray.Dataset` loaded into memory (dims crank_angle [degree], theta [degree],
    z [m]); ``folder`` may also be the ``fields.nc`` file itself."""
    import xarray as xr

    path = Path(folder)
    if path.is_dir():
        path = path / FIELDS_FILE
    if not path.is_file():
        raise CaseError(f"open_fields: {str(path)!r}: no such file (a run folder written with "
                        "'conrod run --fields' holds fields.nc)")
    with xr.open_dataset(path, engine=ENGINE) as dataset:
        return dataset.load()
