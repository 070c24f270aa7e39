"""How every film × integrator pair ends on random plausible fed and plain bearings.

Run from the repository root (``PYTHONPATH`` choosing the code measured):

    python benchmarks/solver_outcomes.py run LABEL [N] [SEED]   # measure, store under LABEL
    python benchmarks/solver_outcomes.py table                  # write the .md

Bearings (seeded): the engine, masses and oil of ``examples/passenger_car_diesel_2000rpm.toml``
with journal diameter 40–75 mm, L/D 0.25–0.5, c/R 0.5–1.5 ‰, peak specific load 15–70 MPa
(the engine's load diagram scaled), viscosity 3–15 mPa s (log-uniform), 900–4500 rpm; every
second bearing fed at 0.3 MPa through a full central groove of a tenth of the width (two
lands); hard contact only at the clearance circle. Each pair runs the periodic orbit with
the default settings (grid films at 36 × 8, isothermal) in-process; outcome: ``ran``
(exit 0/4), ``refused`` (CaseError, exit 2, before the orbit), ``failed``
(ConvergenceError, exit 3), ``crash`` (any other exception, exit 1), with the wall time.
A failure where another pair ran on the same bearing is what the tool must not do.
"""

from __future__ import annotations

import dataclasses
import json
import math
import platform
import sys
import time
import tomllib
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
TEMPLATE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"
STORE = ROOT / "benchmarks" / "solver_outcomes.json"
REPORT = ROOT / "benchmarks" / "solver_outcomes.md"
PAIRS = (("short", "auto"), ("short", "adaptive"), ("short", "quasi_static"),
         ("short", "rk2"), ("reynolds", "auto"), ("reynolds", "adaptive"),
         ("reynolds", "quasi_static"), ("mass_conserving", "auto"),
         ("mass_conserving", "quasi_static"))
"""The pairs measured (rk2 with a grid film and the tabulated films, which refuse a fed
bearing, are covered by the property tests)."""
SETTINGS = {"n_theta": 36, "n_z": 8, "thermal_iterations": 0}


def draw(count: int, seed: int) -> list[dict]:
    """``count`` bearings drawn with ``seed`` (module docstring)."""
    rng = np.random.default_rng(seed)
    return [{"index": i, "diameter": rng.uniform(0.040, 0.075),
             "specific_load": rng.uniform(15e6, 70e6),
             "clearance_ratio": rng.uniform(0.5e-3, 1.5e-3),
             "viscosity": math.exp(rng.uniform(math.log(3e-3), math.log(15e-3))),
             "speed": rng.uniform(900.0, 4500.0), "width_ratio": rng.uniform(0.25, 0.5),
             "grooved": i % 2 == 0} for i in range(count)]


def label(b: dict) -> str:
    return (f"{b['index']}: D {b['diameter'] * 1e3:.0f} mm, L/D {b['width_ratio']:.2f}, c/R "
            f"{b['clearance_ratio'] * 1e3:.2f}‰, {b['specific_load'] / 1e6:.0f} MPa, "
            f"{b['viscosity'] * 1e3:.1f} mPa s, {b['speed']:.0f} rpm, "
            f"{'fed, two lands' if b['grooved'] else 'plain'}")


def case_of(b: dict):
    """(Case, LoadCycle) of bearing ``b``."""
    from conrod.cases.case import Case
    from conrod.loads.engine_loads import compute_engine_loads

    data = tomllib.loads(TEMPLATE.read_text(encoding="utf-8"))
    diameter, width = b["diameter"], b["width_ratio"] * b["diameter"]
    data["engine"]["speed"] = b["speed"]
    data["bearing"].update(diameter=diameter, width=width,
                           radial_clearance=b["clearance_ratio"] * diameter / 2)
    if b["grooved"]:
        data["bearing"].update(supply_pressure=0.3e6, grooves=[
            {"start_angle": 0.0, "extent": 360.0, "width": 0.1 * width}])
    data["lubricant"]["viscosity"] = b["viscosity"]
    data["solver"]["contact_film_thickness"] = 0.0
    case = Case.from_dict(data, base_dir=TEMPLATE.parent)
    loads = compute_engine_loads(case).to_load_cycle()
    scale = b["specific_load"] * width * diameter / float(
        np.max(np.hypot(loads.load_x, loads.load_y)))
    return case, dataclasses.replace(loads, load_x=loads.load_x * scale,
                                     load_y=loads.load_y * scale)


def one(case, loads, film: str, integrator: str) -> dict:
    from conrod.errors import CaseError, ConvergenceError
    from conrod.simulation.simulation import Simulation

    start = time.perf_counter()
    try:
        results = Simulation(case, loads=loads, film=film, integrator=integrator,
                             **SETTINGS).run()
    except CaseError as error:
        return {"kind": "refused", "seconds": time.perf_counter() - start,
                "message": str(error)[:200]}
    except ConvergenceError as error:
        return {"kind": "failed", "seconds": time.perf_counter() - start,
                "message": str(error)[:200]}
    except Exception as error:  # a defect: recorded, not hidden
        return {"kind": "crash", "seconds": time.perf_counter() - start,
                "message": f"{type(error).__name__}: {str(error)[:150]}"}
    summary = results.summary
    return {"kind": "ran", "seconds": time.perf_counter() - start,
            "p_max_MPa": summary.p_max / 1e6, "h_min_um": summary.h_min * 1e6,
            "periodic": bool(summary.periodic)}


def measure(name: str, count: int, seed: int) -> None:
    rows = []
    for b in draw(count, seed):
        case, loads = case_of(b)
        outcomes = {}
        for film, integrator in PAIRS:
            outcomes[f"{film}/{integrator}"] = one(case, loads, film, integrator)
            print(label(b), film, integrator, outcomes[f"{film}/{integrator}"], flush=True)
        rows.append({"bearing": label(b), "outcomes": outcomes})
    store = json.loads(STORE.read_text(encoding="utf-8")) if STORE.exists() else {}
    store[name] = {"count": count, "seed": seed, "rows": rows,
                   "machine": f"{platform.machine()}, Python {sys.version.split()[0]}, "
                              "shared 2-core machine (timings ±30 %)"}
    STORE.write_text(json.dumps(store, indent=1), encoding="utf-8")


def cell(outcome: dict) -> str:
    if outcome["kind"] == "ran":
        return f"ran {outcome['seconds']:.0f} s"
    return f"**{outcome['kind']}** {outcome['seconds']:.0f} s"


def write_table() -> None:
    store = json.loads(STORE.read_text(encoding="utf-8"))
    pairs = [f"{f}/{i}" for f, i in PAIRS]
    lines = ["# Film × integrator outcomes on random plausible bearings", "",
             "Written by `python benchmarks/solver_outcomes.py table` from "
             "`benchmarks/solver_outcomes.json` (method in the script's docstring).", "",
             "## Summary", "", "| pair | " + " | ".join(store) + " |",
             "| --- | " + " | ".join("---" for _ in store) + " |"]
    for pair in pairs:
        cells = []
        for content in store.values():
            counts = Counter(row["outcomes"][pair]["kind"] for row in content["rows"])
            slowest = max(row["outcomes"][pair]["seconds"] for row in content["rows"])
            cells.append(", ".join(f"{k} {n}" for k, n in sorted(counts.items()))
                         + f" (slowest {slowest:.0f} s)")
        lines.append(f"| {pair} | " + " | ".join(cells) + " |")
    lines += ["", "Failures on a bearing where another pair ran (the defect class):", ""]
    for name, content in store.items():
        bad = [(row["bearing"], pair, row["outcomes"][pair]["message"])
               for row in content["rows"] for pair in pairs
               if row["outcomes"][pair]["kind"] in ("failed", "crash")
               and any(o["kind"] == "ran" for o in row["outcomes"].values())]
        lines.append(f"- `{name}`: {len(bad)}")
        lines += [f"  - {b} — {p}: {m}" for b, p, m in bad]
    for name, content in store.items():
        lines += ["", f"## {name}", "", f"{content['count']} bearings, seed "
                  f"{content['seed']}; {content['machine']}.", "",
                  "| bearing | " + " | ".join(pairs) + " |",
                  "| --- | " + " | ".join("---" for _ in pairs) + " |"]
        lines += [f"| {row['bearing']} | " + " | ".join(cell(row["outcomes"][p]) for p in pairs)
                  + " |" for row in content["rows"]]
        refusals = sorted({row["outcomes"][p]["message"].split(" (allowed")[0][:120]
                           for row in content["rows"] for p in pairs
                           if row["outcomes"][p]["kind"] == "refused"})
        if refusals:
            lines += ["", "Refusals:", ""] + [f"- {message}" for message in refusals]
    REPORT.write_text("\n".join(lines) + "\n", encoding="utf-8")


def main() -> None:
    command = sys.argv[1] if len(sys.argv) > 1 else "table"
    if command == "run":
        measure(sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 8,
                int(sys.argv[4]) if len(sys.argv) > 4 else 7)
    write_table()


if __name__ == "__main__":
    main()
