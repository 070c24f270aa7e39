"""Oil-supply features rasterised onto the film grid as Dirichlet regions.

Grooves and feed holes of :class:`~conrod.film.base.BearingGeometry` hold the supply
pressure; the bearing edges z = ±L/2 hold ambient (gauge 0) pressure. A feature
smaller than the grid spacing still marks its nearest node, so it is never lost.
"""

from __future__ import annotations

import math

import numpy as np

from conrod.film.base import BearingGeometry, FeedHole, Groove
from conrod.film.characteristics import FilmGrid


def _angular_distance(theta: np.ndarray, angle: float) -> np.ndarray:
    """Shortest signed angle θ − angle wrapped into [−π, π) [rad]."""
    return (theta - angle + math.pi) % (2.0 * math.pi) - math.pi


def groove_mask(groove: Groove, grid: FilmGrid) -> np.ndarray:
    """Nodes covered by a full or partial circumferential groove, (n_θ, n_z + 1) bool."""
    theta, z = grid.theta, grid.z
    if groove.extent >= 2.0 * math.pi - 0.5 * grid.d_theta:
        in_arc = np.ones(grid.n_theta, dtype=bool)
    else:
        offset = (theta - groove.start_angle) % (2.0 * math.pi)
        in_arc = offset <= groove.extent + 1e-12
        if not in_arc.any():
            in_arc[int(np.argmin(np.abs(_angular_distance(theta, groove.start_angle))))] = True
    axial_gap = np.abs(z - groove.axial_position)
    in_band = axial_gap <= 0.5 * groove.width + 1e-12 * grid.width
    if not in_band.any():
        in_band[int(np.argmin(axial_gap))] = True
    return in_arc[:, None] & in_band[None, :]


def hole_mask(hole: FeedHole, grid: FilmGrid) -> np.ndarray:
    """Nodes inside a circular feed hole (distance on the unrolled shell), bool."""
    arc = grid.radius * _angular_distance(grid.theta, hole.angle)[:, None]
    axial = (grid.z - hole.axial_position)[None, :]
    distance = np.hypot(arc, axial)
    inside = distance <= 0.5 * hole.diameter
    if not inside.any():
        inside[np.unravel_index(int(np.argmin(distance)), distance.shape)] = True
    return inside


def supply_mask(geometry: BearingGeometry, grid: FilmGrid) -> np.ndarray:
    """Union of all groove and hole regions (edge rows excluded), bool (n_θ, n_z + 1)."""
    mask = np.zeros((grid.n_theta, grid.n_z + 1), dtype=bool)
    for groove in geometry.grooves:
        mask |= groove_mask(groove, grid)
    for hole in geometry.feed_holes:
        mask |= hole_mask(hole, grid)
    mask[:, [0, -1]] = False
    return mask


def edge_mask(grid: FilmGrid) -> np.ndarray:
    """The two bearing-edge rows z = ±L/2 (ambient pressure), bool (n_θ, n_z + 1)."""
    mask = np.zeros((grid.n_theta, grid.n_z + 1), dtype=bool)
    mask[:, [0, -1]] = True
    return mask


def nearest_theta_index(angle: float, grid: FilmGrid) -> int:
    """Index of the θ node closest to ``angle`` [rad]."""
    return int(round((angle % (2.0 * math.pi)) / grid.d_theta)) % grid.n_theta
