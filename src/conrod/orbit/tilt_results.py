"""The tilt of an orbit's trajectory in its film states and results (a tilted journal or a
profiled bore: :mod:`conrod.results.axial`)."""

from __future__ import annotations

import numpy as np

from conrod.orbit.problem import OrbitProblem
from conrod.orbit.trajectory import CycleTrajectory
from conrod.results.axial import axial_columns


def tilt_items(tilt: np.ndarray | None, i: int) -> dict[str, float]:
    """FilmState keywords of the tilt at output angle ``i`` ({} when aligned)."""
    if tilt is None:
        return {}
    row = tilt[i]
    return {"tilt_x": float(row[0]), "tilt_y": float(row[1]), "tilt_rate_x": float(row[2]),
            "tilt_rate_y": float(row[3])}


def axial_of(problem: OrbitProblem, traj: CycleTrajectory,
             results: list) -> dict[str, np.ndarray] | None:
    """Per-angle axial arrays of a tilted journal or a profiled bore (None otherwise) from
    the film results at the output angles."""
    tilt = problem.tilt
    if tilt is None and getattr(problem.film.geometry, "profile", None) is None:
        return None
    external = None
    if tilt is not None and tilt.free:
        load_x, load_y = problem.loads.load(traj.crank_angle)
        external = np.array([tilt.moment_at(float(phi), (wx, wy)) for phi, wx, wy
                             in zip(traj.crank_angle, load_x, load_y, strict=True)])
    return axial_columns(results, traj.tilt, external, problem.film.geometry.width)
