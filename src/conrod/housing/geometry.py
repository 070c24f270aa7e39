"""Parametric 2-D connecting rod in the rod frame (docs/conventions.md), SI units.

Origin at the big-end bore centre, x along the rod axis towards the small end, y = z × x.
The outline is the smooth union of three pieces — the big-end head (rod side of the split
line with the head wall, cap side with the cap thickness), a straight tapered shank and the
small-end eye — minus the two bores. The union is blended with a fillet (a polynomial smooth
minimum of the signed distances), so that the model has no re-entrant corners whose stress
would be singular.

All shapes are described by signed distance functions (negative inside), the input of the
mesher in :mod:`conrod.housing.mesher` (Persson & Strang 2004).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from conrod.cases.housing import outline_problems

REGIONS = ("cap", "head", "shank", "small_end")
"""Region names, in the order of :meth:`RodGeometry.region_of`."""


@dataclass(frozen=True)
class RodGeometry:
    """Dimensions of the built-in rod [m, rad].

    bore_radius : float  Radius of the big-end bore (shell back) r_b [m].
    head_outer_radius : float  Outer radius of the head on the rod side of the split line [m].
    cap_outer_radius : float  Outer radius of the cap [m].
    split_angle : float  Inclination of the split line from the perpendicular to the rod axis
        [rad] (0 = straight split).
    shank_width_big_end, shank_width_small_end : float  Shank width at the big-end and
        small-end centres [m].
    centre_distance : float  Big-end to small-end centre L [m].
    small_end_bore_radius, small_end_outer_radius : float  Small-end eye radii [m].
    fillet_radius : float  Blend radius of the union of head, shank and eye [m].
    """

    bore_radius: float
    head_outer_radius: float
    cap_outer_radius: float
    split_angle: float
    shank_width_big_end: float
    shank_width_small_end: float
    centre_distance: float
    small_end_bore_radius: float
    small_end_outer_radius: float
    fillet_radius: float

    def split_normal(self) -> np.ndarray:
        """Unit normal of the split line pointing to the rod side [-]."""
        return np.array([math.cos(self.split_angle), math.sin(self.split_angle)])

    def signed_distance(self, points: np.ndarray) -> np.ndarray:
        """Approximate signed distance to the rod outline [m], negative inside; points (n, 2)."""
        outer = smooth_min(
            smooth_min(self._head(points), self._shank(points), self.fillet_radius),
            self._eye(points), self.fillet_radius,
        )
        x_small = points - np.array([self.centre_distance, 0.0])
        big_hole = self.bore_radius - np.hypot(points[:, 0], points[:, 1])
        small_hole = self.small_end_bore_radius - np.hypot(x_small[:, 0], x_small[:, 1])
        return np.maximum(outer, np.maximum(big_hole, small_hole))

    def _head(self, points: np.ndarray) -> np.ndarray:
        radius = np.hypot(points[:, 0], points[:, 1])
        side = points @ self.split_normal()
        rod_side = np.maximum(radius - self.head_outer_radius, -side)
        cap_side = np.maximum(radius - self.cap_outer_radius, side)
        return smooth_min(rod_side, cap_side, self.fillet_radius)

    def _shank(self, points: np.ndarray) -> np.ndarray:
        x, y = points[:, 0], points[:, 1]
        half_big, half_small = 0.5 * self.shank_width_big_end, 0.5 * self.shank_width_small_end
        slope = (half_small - half_big) / self.centre_distance
        norm = math.hypot(1.0, slope)
        side = (np.abs(y) - half_big - slope * x) / norm
        return np.maximum(np.maximum(side, -x), x - self.centre_distance)

    def _eye(self, points: np.ndarray) -> np.ndarray:
        return np.hypot(points[:, 0] - self.centre_distance, points[:, 1]) - (
            self.small_end_outer_radius
        )

    def region_of(self, points: np.ndarray) -> np.ndarray:
        """Region index (into :data:`REGIONS`) of points (n, 2) [-]."""
        radius = np.hypot(points[:, 0], points[:, 1])
        in_head = radius <= self.head_outer_radius + 0.5 * self.fillet_radius
        on_cap_side = points @ self.split_normal() < 0.0
        eye = np.hypot(points[:, 0] - self.centre_distance, points[:, 1])
        in_eye = eye <= self.small_end_outer_radius + 0.5 * self.fillet_radius
        region = np.full(len(points), 2)
        region[in_eye] = 3
        region[in_head] = 1
        region[in_head & on_cap_side] = 0
        return region

    def bounding_box(self) -> tuple[float, float, float, float]:
        """(x_min, x_max, y_min, y_max) of the outline [m]."""
        reach = max(self.head_outer_radius, self.cap_outer_radius) + self.fillet_radius
        half = max(reach, self.small_end_outer_radius, 0.5 * self.shank_width_big_end)
        return (-reach, self.centre_distance + self.small_end_outer_radius + self.fillet_radius,
                -half, half)

    def closure_problems(self) -> list[tuple[str, float, str]]:
        """Why the rod does not close: (field, value, allowed) triples, empty when it does
        (the rules of :func:`conrod.cases.housing.outline_problems`)."""
        return outline_problems(dataclasses.asdict(self))


def smooth_min(first: np.ndarray, second: np.ndarray, radius: float) -> np.ndarray:
    """Polynomial smooth minimum of two signed distances: a fillet of about ``radius`` [m].

    .. math:: \\min(a, b) - \\frac{k}{4} \\max(1 - |a - b|/k, 0)^2
    """
    if radius <= 0.0:
        return np.minimum(first, second)
    blend = np.maximum(radius - np.abs(first - second), 0.0) / radius
    return np.minimum(first, second) - 0.25 * radius * blend**2
