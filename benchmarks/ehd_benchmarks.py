"""Elastohydrodynamic run times: the KamAZ-740 example on the deforming bore.

    PYTHONPATH=src python3 benchmarks/ehd_benchmarks.py [--stiffening 100] [--grids 36x8,72x16]

Writes benchmarks/ehd_benchmarks.md: per film grid (bore nodes = n_θ), the wall time of the
elastic periodic run and of its rigid companion, cycles, film solves per output angle and
h_min / p_max of both. The shipped rod's compliance is divided by ``--stiffening`` (the
coupled orbit does not yet converge with the estimated rod itself; see docs/ehd.md).
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))


def run(n_theta: int, n_z: int, stiffening: float, step: float) -> dict:
    from conrod.elastic.housing import Housing
    from conrod.simulation import Simulation
    from elastic_helpers import kamaz_case

    case = kamaz_case(n_theta=n_theta, n_z=n_z, film="reynolds", integrator="quasi_static",
                      quasi_static_step_deg=step, output_step_deg=2 * step)
    built = Housing.from_case(case)
    housing = Housing(built.angles, built.radius, built.compliance / stiffening,
                      built.inertia_base / stiffening, built.correction, built.kinematics)
    start = time.perf_counter()
    results = Simulation(case, housing=housing).run()
    total = time.perf_counter() - start
    elastic_time = results.info["elastic_wall_time_s"]
    return {"grid": f"{n_theta}x{n_z}", "elastic_s": elastic_time,
            "rigid_s": total - elastic_time, "cycles": results.summary.cycles,
            "solves": float(np.mean(results.columns["coupling_iterations"])),
            "h_min": (results.rigid.summary.h_min * 1e6, results.summary.h_min * 1e6),
            "p_max": (results.rigid.summary.p_max * 1e-6, results.summary.p_max * 1e-6)}


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--stiffening", type=float, default=100.0)
    parser.add_argument("--grids", default="36x8,72x16")
    parser.add_argument("--step", type=float, default=2.0)
    args = parser.parse_args()
    rows = []
    for grid in args.grids.split(","):
        n_theta, n_z = (int(v) for v in grid.split("x"))
        row = run(n_theta, n_z, args.stiffening, args.step)
        rows.append(row)
        print(row, flush=True)
    lines = [f"# EHD benchmarks (KamAZ-740, rod modulus x {args.stiffening:g}, "
             f"{args.step:g} deg steps)", "",
             "| grid | elastic [s] | rigid [s] | cycles | film solves / output angle | "
             "h_min rigid / elastic [µm] | p_max rigid / elastic [MPa] |",
             "| --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        lines.append(f"| {r['grid']} | {r['elastic_s']:.1f} | {r['rigid_s']:.1f} | "
                     f"{r['cycles']} | {r['solves']:.1f} | {r['h_min'][0]:.3f} / "
                     f"{r['h_min'][1]:.3f} | {r['p_max'][0]:.1f} / {r['p_max'][1]:.1f} |")
    (ROOT / "benchmarks" / "ehd_benchmarks.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
