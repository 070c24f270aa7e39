"""A small solid (3-D) ring on the KamAZ-740 bearing and cases that import it."""

from __future__ import annotations

import csv
import tomllib
from functools import lru_cache
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.housing.ring3d import RingGeometry, SolidRing

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
DIAMETER, WIDTH, SHELL = 0.080, 0.030, 0.0025
"""KamAZ-740 bearing: diameter, width and shell thickness [m]."""
BORE = 0.5 * DIAMETER + SHELL
"""Housing bore radius [m]."""
N_THETA, N_Z = 12, 4
"""Film grid of the format tests (the ring's bore corner nodes are its nodes) [-]."""


@lru_cache(maxsize=4)
def small_ring(held: bool = True, outer=(BORE + 0.022, BORE + 0.014)) -> SolidRing:
    """The ring of the format tests: 12 × 1 × 4 hexahedra (P2 tetrahedra), stiffer at
    z = −L/2 than at +L/2, held on the outer patch |θ| ≤ 30° (or at three points)."""
    return SolidRing(RingGeometry(BORE, outer, WIDTH), n_theta=N_THETA, n_radial=1,
                     n_axial=N_Z, held_half_angle=np.radians(30.0) if held else None)


def film_nodes(n_theta: int = N_THETA, n_z: int = N_Z) -> tuple[np.ndarray, np.ndarray]:
    """θ_j [rad] and z_k [m] of the film grid."""
    return (2.0 * np.pi * np.arange(n_theta) / n_theta,
            np.linspace(-0.5 * WIDTH, 0.5 * WIDTH, n_z + 1))


def write_nodes(path: Path, ids, angles, axial, cartesian: bool = False,
                radius: float = BORE) -> Path:
    """A node file of ``ids`` at (θ [rad], z [m]), as angles or as x, y, z on ``radius``."""
    with path.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        if cartesian:
            writer.writerow(["node_id", "x_m", "y_m", "z_m"])
            for node, theta, z in zip(ids, angles, axial, strict=True):
                writer.writerow([node, repr(float(radius * np.cos(theta))),
                                 repr(float(radius * np.sin(theta))),
                                 repr(float(z))])
        else:
            writer.writerow(["node_id", "angle_deg", "axial_position_m"])
            for node, theta, z in zip(ids, angles, axial, strict=True):
                writer.writerow([node, repr(float(np.degrees(theta))), repr(float(z))])
    return path


def grid_nodes(n_theta: int = N_THETA, n_z: int = N_Z) -> tuple[np.ndarray, np.ndarray,
                                                                   np.ndarray]:
    """Node ids 1001.. and (θ, z) of the film nodes, row-major (θ_j, then z_k)."""
    theta, z = film_nodes(n_theta, n_z)
    return (1001 + np.arange(n_theta * (n_z + 1)), np.repeat(theta, len(z)),
            np.tile(z, len(theta)))


def imported_case(housing: dict, n_theta: int = N_THETA, n_z: int = N_Z, **solver) -> Case:
    """The KamAZ-740 example with ``[housing] model = "compliance"`` and ``housing``."""
    data = tomllib.loads((EXAMPLES / "kamaz_740_truck_diesel.toml").read_text())
    data["housing"] = {"model": "compliance", "shell_thickness": SHELL, **housing}
    data["solver"] = {**data.get("solver", {}), "n_theta": n_theta, "n_z": n_z, **solver}
    return Case.from_dict(data, base_dir=EXAMPLES)
