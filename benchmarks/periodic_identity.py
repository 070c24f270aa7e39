"""Bit-for-bit check of the periodic loop against an earlier conrod (e.g. main).

Run:  PYTHONPATH=OLD/src python benchmarks/periodic_identity.py record old.npz [--old]
      PYTHONPATH=src    python benchmarks/periodic_identity.py record new.npz
      python benchmarks/periodic_identity.py compare old.npz new.npz

For each example below the periodic orbit at the supply viscosity is computed with the
cycle acceleration off (plain repetition) and with the Anderson mixing (the default before
the shooting accelerator: ``--old`` runs the old defaults, else
``periodic_accelerator = "anderson"``); ``record`` stores the accepted cycle (x, y, vx,
vy), the error history and the cycles; ``compare`` says per run "identical" or the
largest difference.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = {
    "passenger_car_diesel_2000rpm": {},
    "passenger_car_diesel_1000rpm": {},
    "flores2006_table_load": {},
    "ruston_hornsby_6vebx_mk3": {},
    "passenger_car_diesel_2000rpm_crank_fed": {"n_theta": 24, "n_z": 8},
    "ruston_hornsby_6vebx_mk3@mass_conserving": {
        "n_theta": 24, "n_z": 8, "film": "mass_conserving", "integrator": "quasi_static"},
}
FED = {"ruston_hornsby_6vebx_mk3@mass_conserving": {"bearing__supply_pressure": 3.0e5}}
"""Case changes of a run (the mass-conserving film needs an oil feed: the groove at 3 bar,
as ``result_digests.py``)."""


def record(path: str, old: bool) -> None:
    from conrod import Case, Simulation
    from conrod.orbit.periodic import periodic_orbit

    arrays = {}
    for name, overrides in EXAMPLES.items():
        stem = name.split("@")[0]
        for label, extra in (("plain", {"accelerate_cycles": False, "massless_start": False}),
                             ("anderson", {} if old else {"periodic_accelerator": "anderson"})):
            case = Case.from_toml(ROOT / "examples" / f"{stem}.toml")
            if name in FED:
                case = case.with_(**FED[name])
            sim = Simulation(case, max_cycles=8, **overrides, **extra)
            key = f"{name}|{label}"
            try:
                orbit = periodic_orbit(sim.problem(), sim.solver, integrator=sim.integrator())
            except Exception as error:  # noqa: BLE001 - the same failure is the same answer
                arrays[key] = np.frombuffer(str(error).encode(), dtype=np.uint8).astype(float)
                print(key, "failed:", str(error)[:100], flush=True)
            else:
                last = orbit.last
                arrays[key] = np.concatenate([last.x, last.y, last.vx, last.vy,
                                              np.asarray(orbit.history), [orbit.cycles]])
                print(key, orbit.cycles, orbit.history, flush=True)
            np.savez(path, **arrays)


def compare(old: str, new: str) -> None:
    a, b = np.load(old), np.load(new)
    for key in a.files:
        same = a[key].shape == b[key].shape and np.array_equal(a[key], b[key])
        detail = "identical" if same else (
            f"differs: max {np.max(np.abs(a[key] - b[key])):.3e}"
            if a[key].shape == b[key].shape else "differs in length")
        print(f"{key}: {detail}")


if __name__ == "__main__":
    if sys.argv[1] == "record":
        record(sys.argv[2], "--old" in sys.argv)
    else:
        compare(sys.argv[2], sys.argv[3])
