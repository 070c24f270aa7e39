"""Reading a result folder back: its manifest, the case it records (the case file, its
tables and the values the run set, :mod:`conrod.results.case_record`) and the film pressure
fields an elastic run keeps for the rod stresses."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import CaseError, ConrodError

MANIFEST = "manifest.json"
FILM_PRESSURE = "film_pressure.npz"
"""Film pressure fields of an elastic run at the stress angles [-]."""


def read_manifest(folder: str | Path) -> dict[str, Any] | None:
    """``manifest.json`` of a result folder, None when it has none (or not a readable one)."""
    try:
        data = json.loads((Path(folder) / MANIFEST).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return data if isinstance(data, dict) else None


def recorded_case(folder: str | Path) -> Any:
    """The case a result folder was computed from (``manifest.json["case"]``): its copy of
    the case file, with the copied tables and the values the run set on top; None when the
    folder records no case. A copy that no longer validates raises :class:`CaseError`
    naming the folder."""
    from conrod.cases.case import Case

    folder = Path(folder)
    item = (read_manifest(folder) or {}).get("case")
    if not isinstance(item, dict) or not (folder / str(item.get("file", ""))).is_file():
        return None
    changes = {key.replace(".", "__"): value for key, value in item.get("set", {}).items()}
    changes.update({key.replace(".", "__"): name
                    for key, name in item.get("tables", {}).items()})
    try:
        case = Case.from_toml(folder / item["file"])
        return case.with_(**changes) if changes else case
    except ConrodError as error:
        raise CaseError(f"{str(folder)!r}: the case it records does not validate ({error})"
                        ) from None


def film_pressure_fields(folder: str | Path
                         ) -> tuple[np.ndarray, np.ndarray, dict[float, np.ndarray]] | None:
    """(θ [rad], z [m], crank angle [deg] → film pressure p(θ, z) [Pa]) of the elastic run
    in ``folder`` (``film_pressure.npz``); None when it holds none."""
    path = Path(folder) / FILM_PRESSURE
    if not path.is_file():
        return None
    with np.load(path) as data:
        angles = [float(a) for a in data["crank_angle_deg"]]
        fields = {angle: np.array(data["pressure_Pa"][k]) for k, angle in enumerate(angles)}
        return np.array(data["theta_rad"]), np.array(data["z_m"]), fields
