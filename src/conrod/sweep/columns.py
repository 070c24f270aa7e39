"""Column names of the sweep table: an axis column carries the unit of its case key.

Every characteristic of ``summary.json`` carries its unit in its name (``h_min_m``,
``viscosity_Pa_s``); an axis column does the same with the unit the case schema gives the
key in brackets: ``engine.speed`` [rpm] → ``engine.speed_rpm``,
``bearing.radial_clearance`` [m] → ``bearing.radial_clearance_m``,
``lubricant.viscosity`` [Pa s] → ``lubricant.viscosity_Pa_s``. Dimensionless keys
(``solver.n_theta``, ``clearance.load_scale``) and the ``case`` axis keep their name.
"""

from __future__ import annotations

import functools
import re
from typing import Any

from pydantic import BaseModel

from conrod.cases.case import Case

_TRAILING_UNIT = re.compile(r"\[([^\[\]]+)\]\s*\.?\s*$")
"""The unit: the bracket that ends a field description (earlier brackets are citations)."""


def key_field(key: str) -> tuple[type[BaseModel], str] | None:
    """(schema section, field name) of a dotted case key, None if the schema has none."""
    model: type[BaseModel] = Case
    parts = key.split(".")
    for part in parts[:-1]:
        info = model.model_fields.get(part)
        nested = model_in(info.annotation) if info is not None else None
        if nested is None:
            return None
        model = nested
    return (model, parts[-1]) if parts[-1] in model.model_fields else None


@functools.lru_cache(maxsize=256)
def key_unit(key: str) -> str:
    """Unit of a dotted case key from the schema's description ('' when dimensionless or
    not a schema field)."""
    found = key_field(key)
    if found is None:
        return ""
    description = found[0].model_fields[found[1]].description or ""
    match = _TRAILING_UNIT.search(description)
    unit = match.group(1).strip() if match else ""
    return "" if unit == "-" else unit


def unit_suffix(unit: str) -> str:
    """A unit written as a column-name suffix, the way ``summary.json`` names are:
    ``Pa s`` → ``Pa_s``, ``m^3/s`` → ``m3_s``, ``°C`` → ``C`` ('' for no unit)."""
    text = unit.replace("°", "").replace("(", "").replace(")", "")
    text = re.sub(r"\^(\d)", r"\1", text)
    return re.sub(r"[\s/*·]+", "_", text).strip("_")


def axis_column(key: str) -> str:
    """Table column of an axis: its dotted key with the key's unit, e.g.
    ``engine.speed_rpm``."""
    suffix = unit_suffix(key_unit(key))
    return f"{key}_{suffix}" if suffix else key


def model_in(annotation: Any) -> type[BaseModel] | None:
    """The pydantic model inside a field annotation (``Model``, ``Model | None``, ...),
    None when there is none."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()) or ():
        found = model_in(arg)
        if found is not None:
            return found
    return None


def axis_label(key: str) -> str:
    """Axis label of a case key on a figure: ``engine.speed [rpm]``."""
    unit = key_unit(key)
    return f"{key} [{unit}]" if unit else key
