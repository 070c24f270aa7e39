"""A bore that deforms along the width against its plane equivalent: the KamAZ-740 solid big
end (examples/kamaz_740_solid_big_end.toml, a 3-D compliance at 180 bore nodes on a 36 × 8
film, 324 film nodes coupled) and the plane housing of the same body
(:meth:`conrod.housing.housing.Housing.plane_equivalent`: a row force spread over the width,
the row's mean displacement), each run alone in this process, no rigid companion.

    PYTHONPATH=src python3 benchmarks/housing3d_benchmarks.py [--output FILE.md]

Writes the markdown table: the elastic orbit's wall time and cycles, film solves and Newton
updates per step, h_min and p_max, and on the 3-D bore the film thickness at the two faces
and at mid-width at the angle and crank angle of the smallest film, with the load average
before and after (a shared machine: compare the ratio within one invocation). The dense
linear algebra of the 3-D coupling (a 326 × 326 Jacobian per build) is timed with one BLAS
thread (``OPENBLAS_NUM_THREADS=1`` is set here): on a loaded machine OpenBLAS's threads
made one 326 × 326 inverse 25 × slower (0.70 s against 0.027 s, load average 9).
"""

from __future__ import annotations

import argparse
import os
import time
from pathlib import Path

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def run(solid: bool) -> dict:
    from conrod.cases.case import Case
    from conrod.housing.housing import Housing
    from conrod.simulation.simulation import Simulation

    case = Case.from_toml(ROOT / "examples" / "kamaz_740_solid_big_end.toml")
    housing = Housing.from_case(case)
    if not solid:
        housing = housing.plane_equivalent()
    start = time.perf_counter()
    results = Simulation(case, housing=housing, rigid_companion=False).run()
    seconds = time.perf_counter() - start
    cycle, columns = results.cycle, results.columns
    row = {"bore": "3-D (324 film nodes)" if solid else "plane equivalent (36 rows)",
           "seconds": seconds, "cycles": results.summary.cycles,
           "solves": float(np.mean(columns["coupling_iterations"])),
           "updates": float(np.mean(columns.get("newton_updates", [np.nan]))),
           "h_min": results.summary.h_min, "p_max": results.summary.p_max,
           "angle": float(cycle.crank_angle_deg[int(np.argmin(cycle.h_min))])}
    if solid:
        index = int(np.argmin(cycle.h_min))
        gap = results.gap_field(index)
        theta = int(np.argmin(gap.min(axis=1)))
        row["faces"] = (gap[theta, 0], gap[theta, gap.shape[1] // 2], gap[theta, -1],
                        float(np.degrees(results.bore_angles[theta])))
    return row


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--output", type=Path,
                        default=ROOT / "benchmarks" / "housing3d_benchmarks.md")
    args = parser.parse_args()
    load_before = os.getloadavg()[0]
    rows = [run(solid=True), run(solid=False)]
    load_after = os.getloadavg()[0]
    lines = [
        "# A bore that deforms along the width against its plane equivalent",
        "",
        "KamAZ-740 solid big end (`examples/kamaz_740_solid_big_end.toml`): Reynolds film "
        "36 × 8, the journal with mass (1° BDF2 steps), no rigid companion; "
        f"load average {load_before:.1f} before, {load_after:.1f} after; "
        f"OPENBLAS_NUM_THREADS={os.environ['OPENBLAS_NUM_THREADS']}.",
        "",
        "| bore | elastic orbit [s] | cycles | s per cycle | film solves / step | Newton "
        "updates / step | h_min [µm] (φ) | p_max [MPa] |",
        "| --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |",
    ]
    for row in rows:
        lines.append(
            f"| {row['bore']} | {row['seconds']:.1f} | {row['cycles']} | "
            f"{row['seconds'] / row['cycles']:.1f} | {row['solves']:.2f} | "
            f"{row['updates']:.2f} | {row['h_min'] * 1e6:.3f} ({row['angle']:.0f}°) | "
            f"{row['p_max'] / 1e6:.1f} |")
    lines.append("")
    lines.append(f"Cost of the 3-D coupling: {rows[0]['seconds'] / rows[1]['seconds']:.1f} × "
                 "the plane equivalent's orbit.")
    rear, middle, front, theta = rows[0]["faces"]
    lines.append(f"On the 3-D bore at the smallest film (θ = {theta:.0f}°, film nodes): h = "
                 f"{rear * 1e6:.3f} µm at the rear face (z = −15 mm), {middle * 1e6:.3f} µm at "
                 f"mid-width, {front * 1e6:.3f} µm at the front face (z = +15 mm).")
    args.output.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
