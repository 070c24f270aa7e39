"""Synthesise the Ruston & Hornsby big-end load table from ASSUMED engine data.

Run from the repository root:  python examples/data/make_ruston_hornsby_load.py
Writes examples/data/ruston_hornsby_6vebx_mk3_load.csv: rod-frame load on the journal
(film frame of the big end) and the rod-frame journal speed ω − dβ/dt, every 2° over 720°.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.loads.engine_loads import compute_engine_loads

HERE = Path(__file__).resolve().parent
HEADER = """\
# Ruston & Hornsby 6VEB-X Mk III big-end load, SYNTHESISED (not the published diagram).
# Made by examples/data/make_ruston_hornsby_load.py from ruston_hornsby_engine_assumed.toml with
# conrod's engine-load model ([D3] pressure model, two-mass rod). All engine data ASSUMED;
# the published load diagram (Campbell et al. 1967, Booker 1971) was not found in open sources.
# Frame: connecting-rod (bearing) frame, x towards the small end; load pressing journal on shell.
"""


def main() -> None:
    case = Case.from_toml(HERE / "ruston_hornsby_engine_assumed.toml")
    loads = compute_engine_loads(case, step_deg=2.0)
    table = np.column_stack([
        np.degrees(loads.crank_angle), loads.load_rod_x, loads.load_rod_y,
        loads.journal_speed, loads.shell_speed,
    ])
    path = HERE / "ruston_hornsby_6vebx_mk3_load.csv"
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(HEADER)
        handle.write("crank_angle_deg,load_x_N,load_y_N,journal_speed_rad_s,shell_speed_rad_s\n")
        np.savetxt(handle, table, delimiter=",", fmt="%.6g")
    print(f"wrote {path}: peak load {np.max(np.hypot(table[:, 1], table[:, 2])) / 1e3:.0f} kN")


if __name__ == "__main__":
    main()
