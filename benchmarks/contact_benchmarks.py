"""Timing of the contact kernels and post-processing. Run:
``python benchmarks/contact_benchmarks.py`` — prints a Markdown table (after compilation).
"""

from __future__ import annotations

import math
import time

import numpy as np

from conrod.cases.case import Case
from conrod.contact.analysis import analyse_contact
from conrod.contact.asperity import AsperityParameters, asperity_force, f52
from conrod.contact.friction_work import friction_work_distribution


def _best_of(function, repeats: int = 5) -> float:
    best = math.inf
    for _ in range(repeats):
        start = time.perf_counter()
        function()
        best = min(best, time.perf_counter() - start)
    return best


class _Cycle:
    def __init__(self, points: int):
        phi = np.arange(points) * 4.0 * math.pi / points
        deg = np.degrees(phi)
        force = np.where((deg > 10) & (deg < 92), 2.0e4 * np.sin(np.pi * (deg - 10) / 82), 0.0)
        self.crank_angle = phi
        self.contact_force, self.friction_force = force, 0.1 * force
        self.contact_angle = np.full(points, 0.1)
        self.journal_rotation = phi - 0.3 * np.sin(phi)
        self.eccentricity_x = np.full(points, 24.5e-6)
        self.eccentricity_y = np.zeros(points)
        self.load_x, self.load_y = force + 1e3, np.zeros(points)
        self.h_min, self.p_max = np.full(points, 1e-6), np.full(points, 1e8)


def main() -> None:
    params = AsperityParameters(0.38e-6, 5.5e9, 19e-6, 5.9e10).kernel_parameters(0.0239, 0.02)
    asperity_force(24.6e-6, 0.0, 25e-6, params)
    f52(0.5)
    calls = 20000
    per_call = _best_of(lambda: [asperity_force(24.6e-6, 1e-7, 25e-6, params)
                                 for _ in range(calls)]) / calls
    cycle = _Cycle(720)
    case = Case.from_dict({"bearing": {"diameter": 0.0478, "width": 0.02,
                                       "radial_clearance": 25e-6}})
    gt_case = Case.from_dict({"bearing": {"diameter": 0.0478, "width": 0.02,
                                          "radial_clearance": 25e-6},
                              "contact": {"model": "greenwood_tripp"}})
    args = (cycle.crank_angle, cycle.friction_force, cycle.contact_angle,
            cycle.journal_rotation, 0.0239, 360)
    friction_work_distribution(*args)
    analyse_contact(case, cycle)
    analyse_contact(gt_case, cycle)
    rows = [
        ("asperity_force, one call from Python (incl. dispatch)", per_call * 1e6, "µs"),
        ("friction_work_distribution, 720 angles, 360 elements",
         _best_of(lambda: friction_work_distribution(*args)) * 1e3, "ms"),
        ("analyse_contact, hard, 720 angles", _best_of(lambda: analyse_contact(case, cycle)) * 1e3,
         "ms"),
        ("analyse_contact, Greenwood-Tripp, 720 angles",
         _best_of(lambda: analyse_contact(gt_case, cycle)) * 1e3, "ms"),
    ]
    print("| operation | time | unit |\n| --- | --- | --- |")
    for name, value, unit in rows:
        print(f"| {name} | {value:.3g} | {unit} |")


if __name__ == "__main__":
    main()
