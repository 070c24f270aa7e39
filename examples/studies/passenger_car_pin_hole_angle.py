"""Where to drill the crank-pin oil hole: the hole angle swept around the pin for the
passenger-car big end (examples/passenger_car_diesel_2000rpm_crank_fed.toml), on the
mass-conserving film (default: the film may starve downstream of the hole) or the Reynolds
film (``--film reynolds``: a flooded film, no starvation columns).

Run from the repository root:

    python examples/studies/passenger_car_pin_hole_angle.py [--out DIR] [--grid 36x8]
                                                            [--step 30] [--film F]

For every hole angle on the pin (from the outward crank radius towards rotation, every
``--step`` degrees, plus the wear diagram's least-worn angle of ``conrod loads``) it runs
the periodic orbit (with mass, the default integrator) and writes one row of
``pin_hole_angle_<film>.csv``: the film's h_min and p_max over the cycle, the mean flow through
the hole and the share of the cycle with backflow, the smallest film fraction at the
loaded zone's inlet and the share of the cycle the load zone runs partially filled
(starved, below 0.9). ``docs/figures/make_crank_feed_figures.py`` draws it
(docs/figures/pin_hole_angle_study.png) with the wear diagram's angle marked.
"""

from __future__ import annotations

import argparse
import copy
import csv
import math
import time
import tomllib
from pathlib import Path

from conrod.cases.case import Case
from conrod.errors import ConrodError
from conrod.loads.oil_feed import wear_diagram_angle
from conrod.simulation import Simulation

ROOT = Path(__file__).resolve().parents[2]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm_crank_fed.toml"
COLUMNS = ("hole_angle_deg", "wear_diagram", "h_min_m", "p_max_Pa",
           "journal_hole_flow_mean_m3_s", "journal_hole_backflow_share",
           "inlet_film_fraction_min", "starved_share", "exit_code")


def case_at(data: dict, angle_deg: float) -> Case:
    """The crank-fed case with its pin hole at ``angle_deg`` [deg]."""
    variant = copy.deepcopy(data)
    variant["bearing"]["journal_holes"][0]["angle"] = float(angle_deg)
    return Case.from_dict(variant, base_dir=CASE.parent)


def row(case: Case, angle_deg: float, wear: bool, grid: tuple[int, int],
        film: str = "mass_conserving") -> dict:
    """One study row: the orbit's figures at one hole angle (SI units)."""
    simulation = Simulation(case, film=film, n_theta=grid[0], n_z=grid[1])
    try:
        results = simulation.run()
    except ConrodError as error:  # a located refusal: the row says so
        print(f"hole at {angle_deg:6.1f} deg: {error}", flush=True)
        return {"hole_angle_deg": angle_deg, "wear_diagram": int(wear), "exit_code": 3,
                **{name: math.nan for name in COLUMNS[2:-1]}}
    s, feed = results.summary, results.cycle.feed
    items = {"hole_angle_deg": angle_deg, "wear_diagram": int(wear),
             "h_min_m": float(results.cycle.h_min.min()), "p_max_Pa": float(s.p_max),
             "exit_code": 4 if s.warnings else 0}
    flow = feed["journal_hole_flow"]
    fraction = feed.get("inlet_film_fraction")  # the mass-conserving film's only
    items.update(journal_hole_flow_mean_m3_s=float(flow.mean()),
                 journal_hole_backflow_share=float((flow < 0.0).mean()),
                 inlet_film_fraction_min=math.nan if fraction is None else float(fraction.min()),
                 starved_share=math.nan if fraction is None else float((fraction < 0.9).mean()))
    return items


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="results/pin_hole_angle")
    parser.add_argument("--grid", default="36x8")
    parser.add_argument("--step", type=float, default=30.0)
    parser.add_argument("--film", default="mass_conserving",
                        choices=("mass_conserving", "reynolds"))
    args = parser.parse_args()
    grid = tuple(int(n) for n in args.grid.split("x"))
    data = tomllib.loads(CASE.read_text())
    wear = math.degrees(wear_diagram_angle(Case.from_toml(CASE)))
    angles = [k * args.step for k in range(int(round(360.0 / args.step)))]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    rows = []
    for angle, is_wear in sorted([(a, False) for a in angles] + [(wear, True)]):
        start = time.perf_counter()
        rows.append(row(case_at(data, angle), angle, is_wear, grid, args.film))
        if rows[-1]["exit_code"] == 3:
            continue
        print(f"hole at {angle:6.1f} deg: h_min {rows[-1]['h_min_m'] * 1e6:.3f} um, "
              f"p_max {rows[-1]['p_max_Pa'] / 1e6:.0f} MPa, inlet film fraction >= "
              f"{rows[-1]['inlet_film_fraction_min']:.2f} ({time.perf_counter() - start:.0f} s)",
              flush=True)
    table = out / f"pin_hole_angle_{args.film}.csv"
    with open(table, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=COLUMNS)
        writer.writeheader()
        writer.writerows(rows)
    print(f"wrote {table}")


if __name__ == "__main__":
    main()
