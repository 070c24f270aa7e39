"""Small cases and helpers shared by the hardening and property tests (cheap to run)."""

from __future__ import annotations

import copy
import json
import tomllib
from pathlib import Path

import numpy as np

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"

FLORES_TABLE = EXAMPLES / "data" / "flores2006_load.csv"


def example_dict(name: str) -> dict:
    """A shipped example case as a dict (relative files resolved against examples/)."""
    with open(EXAMPLES / f"{name}.toml", "rb") as handle:
        return tomllib.load(handle)


def cheap_table_run() -> dict:
    """Flores table load, short film, quasi-static, coarse: a run in ~0.1 s."""
    case = example_dict("flores2006_table_load")
    case["load"]["table"] = str(FLORES_TABLE)
    case["solver"] = {"film": "short", "integrator": "quasi_static",
                      "quasi_static_step_deg": 2.5, "output_step_deg": 5.0, "max_cycles": 2,
                      "min_cycles": 1}
    return case


def cheap_engine_run() -> dict:
    """Passenger-car diesel at 2000 rpm, short film, quasi-static, coarse."""
    case = example_dict("passenger_car_diesel_2000rpm")
    case["solver"] = {**case.get("solver", {}), "film": "short", "integrator": "quasi_static",
                      "quasi_static_step_deg": 2.5, "output_step_deg": 5.0, "max_cycles": 2,
                      "min_cycles": 1}
    return case


def cheap_mechanism() -> dict:
    """Worn-shell mechanism example, one cycle, coarse output and loose tolerance."""
    case = example_dict("kulayev_worn_rod_bearings")
    case["clearance"].update(cycles=1, tolerance=1.0e-3, output_step_deg=2.0)
    return case


def write_case(folder: Path, data: dict, name: str = "case.toml") -> Path:
    """Write ``data`` as TOML (enough of TOML for the cases above)."""
    path = folder / name
    path.write_text(_toml(data), encoding="utf-8")
    return path


def _toml(data: dict, prefix: str = "") -> str:
    scalars, tables = [], []
    for key, value in data.items():
        if isinstance(value, dict):
            tables.append((key, value))
        elif isinstance(value, list) and value and all(isinstance(v, dict) for v in value):
            tables.extend((f"[{key}]", item) for item in value)
        else:
            scalars.append(f"{key} = {json.dumps(value)}")
    text = "\n".join(scalars) + "\n"
    for key, value in tables:
        if key.startswith("["):
            name = f"{prefix}{key[1:-1]}"
            text += f"\n[[{name}]]\n" + _toml(value, f"{name}.")
        else:
            name = f"{prefix}{key}"
            text += f"\n[{name}]\n" + _toml(value, f"{name}.")
    return text


def mutated(case: dict, path: tuple, value) -> dict:
    """Copy of ``case`` with the value at ``path`` replaced (or removed for ``DELETE``)."""
    out = copy.deepcopy(case)
    node = out
    for part in path[:-1]:
        node = node.setdefault(part, {})
    if value is DELETE:
        node.pop(path[-1], None)
    else:
        node[path[-1]] = value
    return out


DELETE = object()
"""Marker: remove the key."""


def all_finite(columns: dict) -> bool:
    """True when every numeric column holds only finite numbers."""
    return all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in columns.values()
               if np.asarray(v).dtype.kind in "fiub")
