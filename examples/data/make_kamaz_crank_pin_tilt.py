"""Synthesise the crank-pin tilt table of the KamAZ-740-like tilt example from ASSUMED
crank-pin bending.

Run from the repository root:  python examples/data/make_kamaz_crank_pin_tilt.py
Writes examples/data/kamaz_740_crank_pin_tilt.csv: the tilt of the crank pin in the big-end
bearing, film (rod) frame, every 5° over 720°, from the engine loads of
examples/kamaz_740_truck_diesel.toml and an ASSUMED linear angular compliance of the crank pin
and its webs: γ_y = K W_x, γ_x = −K W_y (the pin bends in the plane of the load; the journal
axis at z moves along the load, x(z) = z γ_y, y(z) = −z γ_x; docs/conventions.md).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.loads.engine_loads import compute_engine_loads

HERE = Path(__file__).resolve().parent
COMPLIANCE = 1.8e-9
"""Angular compliance of crank pin and webs under the big-end load [rad/N], ASSUMED: 0.15 mrad
at the 80 kN firing peak, within the 0.1-0.5 mrad of crank-pin misalignment usually quoted for
heavy-duty crankshafts; no measured value of the KamAZ-740 crankshaft was found."""
HEADER = """\
# KamAZ-740-like crank-pin tilt in the big-end bearing, SYNTHESISED (not measured).
# Made by examples/data/make_kamaz_crank_pin_tilt.py from the engine loads of
# examples/kamaz_740_truck_diesel.toml and an ASSUMED crank-pin + web angular compliance of
# 1.8e-9 rad/N: tilt_y = K load_x, tilt_x = -K load_y (0.15 mrad at the 80 kN firing peak).
# Frame: connecting-rod (bearing) frame, x towards the small end; right-handed tilt angles of the
# journal about x and y; replace by the tilt of a crankshaft FE or multibody model when available.
"""


def main() -> None:
    case = Case.from_toml(HERE.parent / "kamaz_740_truck_diesel.toml")
    loads = compute_engine_loads(case, step_deg=5.0)
    table = np.column_stack([np.degrees(loads.crank_angle), -COMPLIANCE * loads.load_rod_y,
                             COMPLIANCE * loads.load_rod_x])
    path = HERE / "kamaz_740_crank_pin_tilt.csv"
    with open(path, "w", encoding="utf-8") as handle:
        handle.write(HEADER)
        handle.write("crank_angle_deg,tilt_x_rad,tilt_y_rad\n")
        np.savetxt(handle, table, delimiter=",", fmt="%.6g")
    print(f"wrote {path}: tilt up to {1e3 * np.abs(table[:, 1:]).max():.3f} mrad")


if __name__ == "__main__":
    main()
