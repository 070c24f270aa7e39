"""Condense a solid (3-D) KamAZ-740-like big end to its bore nodes (θ, z) and write it in
the formats FE codes write: the compliance as Matrix Market with its node file.

Run from the repository root:  python examples/data/make_kamaz_solid_big_end.py
Writes examples/data/kamaz_740_solid_big_end.mtx (radial compliance [m/N] at 36 × 5 = 180
bore nodes: every 10° around, every 7.5 mm across the width) and
examples/data/kamaz_740_solid_big_end_nodes.csv (node_id, x_m, y_m, z_m in the rod frame),
read by examples/kamaz_740_solid_big_end.toml (whose 36 × 8 film grid has a node at every
bore node and one between each two across the width: interpolated).

The body is ASSUMED, not a drawing of the KamAZ-740 rod: a ring round the 85 mm housing bore
(80 mm crankpin + 2 × 2.5 mm shell), 30 mm wide, whose wall thins linearly from 26 mm at the
rear face (z = −15 mm) to 12 mm at the front face (z = +15 mm) — a big end stiffer at one
face than the other — held over the outer surface within ±35° of the rod axis (where the
shank joins it), steel E = 210 GPa, ν = 0.3. scikit-fem, quadratic tetrahedra on a
36 × 3 × 8 grid of hexahedra (conrod.housing.ring3d); the bore nodes' loads are consistent
(their hat functions integrated on the curved bore faces).
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from conrod.housing.matrix_formats import write_matrix_market
from conrod.housing.ring3d import RingGeometry, SolidRing

HERE = Path(__file__).resolve().parent
BORE, WIDTH = 0.0425, 0.030
"""Housing bore radius and width [m]."""
WALLS = (0.026, 0.012)
"""Wall thickness at z = −L/2 and z = +L/2 [m] (ASSUMED)."""
GRID = (36, 3, 8)
"""Hexahedra around, through the wall, over the width [-]."""
BORE_NODES = (36, 5)
"""Bore nodes around and across the width [-]."""
HELD_HALF_ANGLE = np.radians(35.0)


def main() -> None:
    start = time.perf_counter()
    ring = SolidRing(RingGeometry(BORE, (BORE + WALLS[0], BORE + WALLS[1]), WIDTH),
                     2.1e11, 0.3, *GRID, held_half_angle=HELD_HALF_ANGLE)
    theta = 2 * np.pi * np.arange(BORE_NODES[0]) / BORE_NODES[0]
    axial = np.linspace(-0.5 * WIDTH, 0.5 * WIDTH, BORE_NODES[1])
    compliance = ring.bore_compliance(theta, axial)
    angle, z = np.repeat(theta, len(axial)), np.tile(axial, len(theta))
    write_matrix_market(HERE / "kamaz_740_solid_big_end.mtx", compliance, comment=(
        "Radial compliance [m/N] of an ASSUMED solid KamAZ-740-like big end at 180 bore "
        "nodes; rows follow kamaz_740_solid_big_end_nodes.csv. Made by "
        "examples/data/make_kamaz_solid_big_end.py"))
    with open(HERE / "kamaz_740_solid_big_end_nodes.csv", "w", encoding="utf-8") as handle:
        handle.write("node_id,x_m,y_m,z_m\n")
        for k, (t, zk) in enumerate(zip(angle, z, strict=True)):
            handle.write(f"{1001 + k},{float(BORE * np.cos(t))!r},"
                         f"{float(BORE * np.sin(t))!r},{float(zk)!r}\n")
    print(f"{ring.n_dofs} unknowns, {len(angle)} bore nodes, "
          f"{time.perf_counter() - start:.1f} s")


if __name__ == "__main__":
    main()
