"""Random worn rod-bearing shells: seed vs exact contact geometry (seeded, reproducible).

    python benchmarks/worn_shells.py [N]      # → benchmarks/worn_shells.md

The shipped mechanism example with random wear of the big end (Δmax 60–300 µm,
Δmin/Δmax 0.3–1, major axis −90…90° to the rod), speed 1000–4000 rpm and load scale
0.3–1. Each shell runs with both geometries; reported: wall time, impacts per cycle, the
largest impact velocity against the crank-pin surface speed, the largest contact force and
the plausibility warnings (conrod.results.plausibility).
"""

from __future__ import annotations

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
    return {"seconds": seconds, "impacts": summary["impacts_per_cycle"],
            "velocity": summary["max_impact_velocity_big_end_m_s"], "surface": surface,
            "force": summary["max_contact_force_big_end_N"],
            "warnings": check_mechanism(results, base.mechanism)}


def main(count: int) -> None:
    rng = random.Random(33)
    rows = ["| # | Δmax [µm] | Δmin/Δmax | γ [deg] | rpm | load | geometry | time [s] | "
            "impacts/cycle | v_max / ωD/2 | F_max [kN] | warnings |",
            "| ---: | ---: | ---: | ---: | ---: | ---: | --- | ---: | ---: | ---: | ---: | --- |"]
    for index in range(count):
        clearance_max = rng.uniform(60e-6, 300e-6)
        ratio, angle = rng.uniform(0.3, 1.0), rng.uniform(-90.0, 90.0)
        speed, load = rng.uniform(1000.0, 4000.0), rng.uniform(0.3, 1.0)
        for geometry in ("seed", "exact"):
            data = Case.from_toml(REPO / "examples" / "kulayev_worn_rod_bearings.toml")
            raw = data.model_dump(exclude_none=True)
            big = raw["clearance"]["big_end"]
            big.update(clearance_max=clearance_max, clearance_min=ratio * clearance_max,
                       ellipse_angle_deg=angle)
            raw["clearance"].update(contact_geometry=geometry, load_scale=load, cycles=2)
            raw["engine"]["speed"] = speed
            result = run(Case.from_dict(raw, base_dir=REPO / "examples"))
            if "error" in result:
                cells = f"{result['seconds']:.1f} | – | – | – | {result['error'][:60]}"
            else:
                cells = (f"{result['seconds']:.1f} | {result['impacts']:g} | "
                         f"{result['velocity'] / result['surface']:.3g} | "
                         f"{result['force'] / 1e3:.3g} | {len(result['warnings'])}")
            rows.append(f"| {index} | {clearance_max * 1e6:.0f} | {ratio:.2f} | {angle:.0f} | "
                        f"{speed:.0f} | {load:.2f} | {geometry} | {cells} |")
            print(rows[-1], flush=True)
    (REPO / "benchmarks" / "worn_shells.md").write_text(
        "# Random worn shells: seed vs exact contact geometry\n\n"
        f"`python benchmarks/worn_shells.py {count}` (seed 33, 2 cycles each).\n\n"
        + "\n".join(rows) + "\n")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 12)
