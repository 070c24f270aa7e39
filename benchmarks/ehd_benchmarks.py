"""Elastohydrodynamic run times: the KamAZ-740 example on the deforming bore.

    PYTHONPATH=src python3 benchmarks/ehd_benchmarks.py [--grids 36x8,72x16,144x32]
        [--stiffening 1] [--step 0.5] [--films reynolds,mass_conserving] [--integrator quasi_static]
        [--case kamaz | ruston_hornsby_fed] [--output benchmarks/ehd_benchmarks.md]

Writes benchmarks/ehd_benchmarks.md: per film grid (bore nodes = n_θ), the wall time of the
elastic periodic run (massless orbit, the case's default 0.5° steps) and of its rigid
companion, cycles, film solves per step (the corrector's and the next predictor's force
balance at one crank angle) and h_min / p_max of both. ``--stiffening`` divides the shipped
rod's compliance and inertia fields (1: the shipped rod itself). ``--case
ruston_hornsby_fed`` runs the Ruston & Hornsby example instead, its central groove fed at
0.3 MPa (an assumption of the benchmark: the example has no feed pressure, which the
mass-conserving film needs), so that the Reynolds and the mass-conserving EHD film run
the same case.

``--integrator implicit`` runs the journal with mass instead (BDF2 steps of the journal and
the bore together at ``--step`` ≤ 1°, rigid companion by TR-BDF2 with mass) and writes
benchmarks/ehd_benchmarks_with_mass.md, with the massless elastic run of the same grid
timed in the same invocation for the ratio.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


CASES = {"kamaz": ("kamaz_740_truck_diesel.toml", None),
         "ruston_hornsby_fed": ("ruston_hornsby_6vebx_mk3.toml", 3.0e5)}
"""Case file and the supply pressure the benchmark sets [Pa] (None: the file's)."""


def run(n_theta: int, n_z: int, stiffening: float, step: float, film: str,
        integrator: str = "quasi_static", rigid: bool = True, case_name: str = "kamaz") -> dict:
    import tomllib

    from conrod.cases.case import Case
    from conrod.housing.housing import Housing
    from conrod.simulation.simulation import Simulation

    examples = ROOT / "examples"
    file_name, supply = CASES[case_name]
    data = tomllib.loads((examples / file_name).read_text())
    if supply is not None:
        data["bearing"]["supply_pressure"] = supply
    data["solver"] = {"film": film, "integrator": integrator, "n_theta": n_theta,
                      "n_z": n_z, "quasi_static_step_deg": step,
                      "max_step_deg": min(step, 1.0), "output_step_deg": max(1.0, step)}
    case = Case.from_dict(data, base_dir=examples)
    built = Housing.from_case(case)
    housing = Housing(built.angles, built.radius, built.compliance / stiffening,
                      built.inertia_base / stiffening, built.correction, built.kinematics)
    start = time.perf_counter()
    results = Simulation(case, housing=housing, rigid_companion=rigid).run()
    total = time.perf_counter() - start
    elastic_time = results.info["elastic_wall_time_s"]
    companion = results.rigid.summary if results.rigid is not None else results.summary
    return {"grid": f"{n_theta}x{n_z}", "film": film, "elastic_s": elastic_time,
            "rigid_s": total - elastic_time, "cycles": results.summary.cycles,
            "solves": float(np.mean(results.columns["coupling_iterations"])),
            "updates": float(np.mean(results.columns.get("newton_updates", np.nan))),
            "h_min": (companion.h_min * 1e6, results.summary.h_min * 1e6),
            "p_max": (companion.p_max * 1e-6, results.summary.p_max * 1e-6),
            "h_min_angle": results.summary.h_min_angle_deg
            if hasattr(results.summary, "h_min_angle_deg") else float("nan")}


def main() -> None:
    from conrod.errors import ConvergenceError

    parser = argparse.ArgumentParser()
    parser.add_argument("--stiffening", type=float, default=1.0)
    parser.add_argument("--grids", default="36x8,72x16,144x32")
    parser.add_argument("--step", type=float, default=0.5)
    parser.add_argument("--films", default="reynolds")
    parser.add_argument("--integrator", default="quasi_static")
    parser.add_argument("--case", default="kamaz", choices=sorted(CASES))
    parser.add_argument("--output", default=str(ROOT / "benchmarks" / "ehd_benchmarks.md"))
    args = parser.parse_args()
    if args.integrator != "quasi_static":
        with_mass(args)
        return
    rows = []
    for film in args.films.split(","):
        for grid in args.grids.split(","):
            n_theta, n_z = (int(v) for v in grid.split("x"))
            try:
                row = run(n_theta, n_z, args.stiffening, args.step, film,
                          case_name=args.case)
            except ConvergenceError as error:  # reported in the table, not hidden
                row = {"grid": grid, "film": film, "failed": str(error)}
            rows.append(row)
            print(row, flush=True)
    rod = "shipped rod" if args.stiffening == 1.0 else f"rod modulus x {args.stiffening:g}"
    title = {"kamaz": "KamAZ-740", "ruston_hornsby_fed": "Ruston & Hornsby fed at 0.3 MPa"}
    lines = [f"# EHD benchmarks ({title[args.case]}, {rod}, massless orbit, "
             f"{args.step:g} deg steps)",
             "", "| film | grid | elastic [s] | rigid [s] | cycles | film solves / step | "
             "h_min rigid / elastic [µm] | p_max rigid / elastic [MPa] |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        if "failed" in r:
            lines.append(f"| {r['film']} | {r['grid']} | {r['failed']} | | | | | |")
            continue
        lines.append(f"| {r['film']} | {r['grid']} | {r['elastic_s']:.1f} | {r['rigid_s']:.1f} | "
                     f"{r['cycles']} | {r['solves']:.1f} | {r['h_min'][0]:.3f} / "
                     f"{r['h_min'][1]:.3f} | {r['p_max'][0]:.1f} / {r['p_max'][1]:.1f} |")
    Path(args.output).write_text("\n".join(lines) + "\n")


def with_mass(args) -> None:
    """The with-mass table: per grid the elastic run with mass (and its rigid companion
    with mass) and the massless elastic run of the same grid, in one invocation."""
    rows = []
    for grid in args.grids.split(","):
        n_theta, n_z = (int(v) for v in grid.split("x"))
        mass = run(n_theta, n_z, args.stiffening, args.step, "reynolds", args.integrator)
        massless = run(n_theta, n_z, args.stiffening, 0.5, "reynolds", "quasi_static",
                       rigid=False)
        rows.append((grid, mass, massless))
        print(grid, mass, massless, flush=True)
    rod = "shipped rod" if args.stiffening == 1.0 else f"rod modulus x {args.stiffening:g}"
    lines = [f"# EHD benchmarks with mass (KamAZ-740, {rod}, Reynolds film)", "",
             f"Journal with mass: `{args.integrator}` (BDF2 steps of the journal and the bore "
             f"together, {min(args.step, 1.0):g} deg); rigid companion: the same integrator "
             "on the rigid bore (TR-BDF2 with mass); massless: `quasi_static`, 0.5 deg, no "
             "companion. One invocation, same machine state.", "",
             "| grid | with mass: elastic [s] | rigid [s] | cycles | film solves / Newton "
             "updates per step | "
             "h_min rigid / elastic [µm] | p_max rigid / elastic [MPa] | massless elastic "
             "[s] | massless h_min [µm] | massless p_max [MPa] |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for grid, m, q in rows:
        lines.append(
            f"| {grid} | {m['elastic_s']:.1f} | {m['rigid_s']:.1f} | {m['cycles']} | "
            f"{m['solves']:.2f} / {m['updates']:.2f} | {m['h_min'][0]:.3f} / {m['h_min'][1]:.3f} | "
            f"{m['p_max'][0]:.1f} / {m['p_max'][1]:.1f} | {q['elastic_s']:.1f} | "
            f"{q['h_min'][1]:.3f} | {q['p_max'][1]:.1f} |")
    (ROOT / "benchmarks" / "ehd_benchmarks_with_mass.md").write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
