"""Random worn rod-bearing shells through the clearance mechanism (seeded, reproducible).

    python benchmarks/worn_shells.py [N] [LABEL]      # → benchmarks/worn_shells.md

The shipped mechanism example with random wear of both rod bearings — big end Δmax
60–300 µm, small end Δmax 15–60 µm, each Δmin/Δmax 0.3–1 and its major axis −90…90° to
the rod — at a speed of 1000–4000 rpm and a load scale of 0.3–1, 2 cycles each, with the
default (exact) contact geometry. Reported per shell pair: wall time, integrator
steps per cycle, impacts per cycle, the largest impact velocity against the crank-pin
surface speed ωD/2, the largest contact force, the plausibility warnings
(conrod.results.plausibility), or the error. ``LABEL`` (default ``after``) names the column
set in the stored JSON (``benchmarks/worn_shells.json``) so that runs of two versions of
the code can be put side by side.
"""

from __future__ import annotations

import json
import random
import sys
import time
from pathlib import Path

from conrod import Case
from conrod.errors import ConvergenceError
from conrod.mechanism.setup import mechanism_case
from conrod.mechanism.simulation import simulate
from conrod.results.plausibility import check_mechanism

REPO = Path(__file__).resolve().parents[1]
STORE = REPO / "benchmarks" / "worn_shells.json"
SEED = 33
CYCLES = 2


def run(case: Case) -> dict:
    base = mechanism_case(case)
    start = time.perf_counter()
    try:
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
    except ConvergenceError as error:
        return {"seconds": time.perf_counter() - start, "error": str(error)}
    seconds = time.perf_counter() - start
    summary = results.summary()
    surface = base.mechanism.crank.crank_speed * 0.5 * base.mechanism.big_end.diameter
    velocity = max(summary["max_impact_velocity_big_end_m_s"],
                   summary["max_impact_velocity_small_end_m_s"])
    force = max(summary["max_contact_force_big_end_N"],
                summary["max_contact_force_small_end_N"])
    return {"seconds": seconds, "steps": summary["integrator_steps"] / CYCLES,
            "impacts": summary["impacts_per_cycle"], "velocity": velocity / surface,
            "force": force, "warnings": len(check_mechanism(results, base.mechanism))}


def draws(count: int) -> list[dict]:
    """The random shell pairs and operating points (seeded)."""
    rng = random.Random(SEED)
    out = []
    for _ in range(count):
        out.append({"big": (rng.uniform(60e-6, 300e-6), rng.uniform(0.3, 1.0),
                            rng.uniform(-90.0, 90.0)),
                    "small": (rng.uniform(15e-6, 60e-6), rng.uniform(0.3, 1.0),
                              rng.uniform(-90.0, 90.0)),
                    "speed": rng.uniform(1000.0, 4000.0), "load": rng.uniform(0.3, 1.0)})
    return out


def case_of(draw: dict, geometry: str = "exact") -> Case:
    data = Case.from_toml(REPO / "examples" / "kulayev_worn_rod_bearings.toml")
    raw = data.model_dump(exclude_none=True)
    for joint in ("big", "small"):
        clearance_max, ratio, angle = draw[joint]
        raw["clearance"][f"{joint}_end"].update(
            clearance_max=clearance_max, clearance_min=ratio * clearance_max,
            ellipse_angle_deg=angle)
    raw["clearance"].update(contact_geometry=geometry, load_scale=draw["load"],
                            cycles=CYCLES)
    raw["engine"]["speed"] = draw["speed"]
    return Case.from_dict(raw, base_dir=REPO / "examples")


def cell(result: dict | None) -> str:
    if result is None:
        return "– | – | – | – | – | –"
    if "error" in result:
        return f"{result['seconds']:.1f} | – | – | – | – | exit 3: {result['error'][:70]}"
    return (f"{result['seconds']:.1f} | {result['steps']:.0f} | {result['impacts']:g} | "
            f"{result['velocity']:.3g} | {result['force'] / 1e3:.3g} | {result['warnings']}")


def main(count: int, label: str) -> None:
    store = json.loads(STORE.read_text(encoding="utf-8")) if STORE.exists() else {}
    results = []
    for index, draw in enumerate(draws(count)):
        results.append(run(case_of(draw)))
        print(index, results[-1], flush=True)
    store[label] = {"count": count, "results": results}
    STORE.write_text(json.dumps(store, indent=1), encoding="utf-8")
    write_table(store, count)


def write_table(store: dict, count: int) -> None:
    labels = [label for label in store if store[label]["count"] == count]
    rows = ["| # | big end Δmax [µm], Δmin/Δmax, γ [deg] | small end Δmax [µm], Δmin/Δmax, "
            "γ [deg] | rpm | load | code | time [s] | steps/cycle | impacts/cycle | "
            "v_max / ωD/2 | F_max [kN] | warnings |",
            "| ---: | --- | --- | ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | --- |"]
    failed = {label: 0 for label in labels}
    slowest = {label: 0.0 for label in labels}
    for index, draw in enumerate(draws(count)):
        big, small = draw["big"], draw["small"]
        for label in labels:
            result = store[label]["results"][index]
            failed[label] += "error" in result
            slowest[label] = max(slowest[label], result["seconds"])
            rows.append(f"| {index} | {big[0] * 1e6:.0f}, {big[1]:.2f}, {big[2]:.0f} | "
                        f"{small[0] * 1e6:.0f}, {small[1]:.2f}, {small[2]:.0f} | "
                        f"{draw['speed']:.0f} | {draw['load']:.2f} | {label} | "
                        f"{cell(result)} |")
    summary = [f"- `{label}`: {failed[label]} of {count} failed, slowest "
               f"{slowest[label]:.1f} s" for label in labels]
    (REPO / "benchmarks" / "worn_shells.md").write_text(
        "# Random worn shells through the clearance mechanism\n\n"
        f"`python benchmarks/worn_shells.py {count} LABEL` (seed {SEED}, {CYCLES} cycles each, "
        "default exact contact geometry, both rod bearings worn; method in the script's "
        "docstring). Shared 2-core machine, timings ±30 %.\n\n" + "\n".join(summary) + "\n\n"
        + "\n".join(rows) + "\n", encoding="utf-8")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 16,
         sys.argv[2] if len(sys.argv) > 2 else "after")
