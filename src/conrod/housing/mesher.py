"""Triangle meshes for the housing models: a signed-distance mesher and a structured ring.

:func:`distance_mesh` follows the force-equilibrium algorithm of P.-O. Persson and
G. Strang, "A simple mesh generator in MATLAB", SIAM Review 46 (2004) 329–345: points
start on an equilateral lattice thinned by the size function, edges act as springs
slightly longer than their target length, points that leave the domain are projected back
along the gradient of the signed distance, and the points are re-triangulated (Delaunay)
whenever they moved. Fixed points (the bore nodes) never move.

:func:`quadratic_mesh` turns the straight triangles into six-node triangles whose edge
mid-points on named circles are moved onto the circle (isoparametric P2 boundary), so that
the bore is exact to third order in the element size.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
from scipy.spatial import Delaunay, cKDTree
from skfem import MeshTri, MeshTri2

Field = Callable[[np.ndarray], np.ndarray]

_FORCE_SCALE = 1.2
_TIME_STEP = 0.2
_RETRIANGULATE = 0.1
"""Re-triangulate when a point moved this share of its local target edge length [-]."""
_STOP_MOVE = 2.0e-3


@dataclass(frozen=True)
class Circle:
    """A circular boundary: centre (x, y) [m] and radius [m]."""

    centre_x: float
    centre_y: float
    radius: float

    def distance(self, points: np.ndarray) -> np.ndarray:
        """|distance from the circle| of points (2, n) [m]."""
        return np.abs(np.hypot(points[0] - self.centre_x, points[1] - self.centre_y) - self.radius)

    def project(self, points: np.ndarray) -> np.ndarray:
        """Radial projection of points (2, n) onto the circle [m]."""
        centre = np.array([[self.centre_x], [self.centre_y]])
        offset = points - centre
        return centre + self.radius * offset / np.linalg.norm(offset, axis=0)


@dataclass
class FeMesh:
    """A six-node triangle mesh with named boundaries and per-element data.

    mesh : MeshTri2  The quadratic mesh (coordinates [m]).
    boundaries : dict  Name → facet indices (``big_end_bore`` always present).
    thickness : ndarray  Plane-stress thickness of each element [m].
    region : ndarray  Region index of each element (see ``region_names``) [-].
    region_names : tuple  Names of the regions [-].
    """

    mesh: MeshTri2
    boundaries: dict[str, np.ndarray]
    thickness: np.ndarray
    region: np.ndarray
    region_names: tuple[str, ...] = ("all",)
    bore_radius: float = field(default=0.0)

    @property
    def n_vertices(self) -> int:
        """Number of triangle corners [-]."""
        return int(self.mesh.t.max()) + 1


def _lattice(box: tuple[float, float, float, float], step: float) -> np.ndarray:
    xs = np.arange(box[0], box[1] + step, step)
    ys = np.arange(box[2], box[3] + step, step * math.sqrt(3.0) / 2.0)
    grid_x, grid_y = np.meshgrid(xs, ys)
    grid_x[1::2] += 0.5 * step
    return np.column_stack([grid_x.ravel(), grid_y.ravel()])


def _initial_points(distance: Field, size: Field, box, step: float, fixed: np.ndarray,
                    rng: np.random.Generator) -> np.ndarray:
    points = _lattice(box, step)
    points = points[distance(points) < -1.0e-3 * step]
    density = 1.0 / size(points) ** 2
    points = points[rng.random(len(points)) < density / density.max()]
    if len(fixed):
        near, _ = cKDTree(fixed).query(points)
        points = points[near > 0.6 * size(points)]
    return np.vstack([fixed, points])


def _triangulate(points: np.ndarray, distance: Field, step: float) -> np.ndarray:
    triangles = Delaunay(points).simplices
    centroids = points[triangles].mean(axis=1)
    return triangles[distance(centroids) < -1.0e-3 * step]


def _bars(triangles: np.ndarray) -> np.ndarray:
    pairs = np.sort(np.vstack([triangles[:, [0, 1]], triangles[:, [1, 2]],
                               triangles[:, [2, 0]]]), axis=1).astype(np.int64)
    size = int(pairs.max()) + 1
    keys = np.unique(pairs[:, 0] * size + pairs[:, 1])
    return np.column_stack([keys // size, keys % size])


def _spring_forces(points: np.ndarray, bars: np.ndarray, size: Field) -> np.ndarray:
    vectors = points[bars[:, 0]] - points[bars[:, 1]]
    lengths = np.hypot(vectors[:, 0], vectors[:, 1])
    target = size(0.5 * (points[bars[:, 0]] + points[bars[:, 1]]))
    target *= _FORCE_SCALE * math.sqrt(np.sum(lengths**2) / np.sum(target**2))
    push = (np.maximum(target - lengths, 0.0) / lengths)[:, None] * vectors
    total = np.zeros_like(points)
    for axis in range(2):
        total[:, axis] = (np.bincount(bars[:, 0], push[:, axis], len(points))
                          - np.bincount(bars[:, 1], push[:, axis], len(points)))
    return total


def _project_outside(points: np.ndarray, distance: Field, step: float) -> np.ndarray:
    values = distance(points)
    outside = values > 0.0
    if not outside.any():
        return points
    delta = math.sqrt(np.finfo(float).eps) * step
    moved = points[outside]
    grad_x = (distance(moved + [delta, 0.0]) - values[outside]) / delta
    grad_y = (distance(moved + [0.0, delta]) - values[outside]) / delta
    norm2 = grad_x**2 + grad_y**2 + 1.0e-30
    points = points.copy()
    points[outside] -= (values[outside] / norm2)[:, None] * np.column_stack([grad_x, grad_y])
    return points


def distance_mesh(distance: Field, size: Field, box: tuple[float, float, float, float],
                  step: float, fixed: np.ndarray | None = None, *, max_iterations: int = 120,
                  seed: int = 0) -> tuple[np.ndarray, np.ndarray]:
    """Triangle mesh of {distance < 0}: points (n, 2) [m] and triangles (m, 3) [-].

    distance : callable  Signed distance of points (n, 2), negative inside [m].
    size : callable  Relative target edge length at points (n, 2) [m] (only ratios matter).
    box : tuple  (x_min, x_max, y_min, y_max) enclosing the domain [m].
    step : float  Smallest target edge length h0 [m].
    fixed : ndarray or None  Points (k, 2) that are kept where they are [m].
    """
    fixed = np.zeros((0, 2)) if fixed is None else np.asarray(fixed, dtype=float)
    points = _initial_points(distance, size, box, step, fixed, np.random.default_rng(seed))
    n_fixed, last = len(fixed), np.full_like(points, np.inf)
    triangles = bars = None
    for _ in range(max_iterations):
        moved = np.hypot(*(points - last).T) / size(points)
        if triangles is None or np.max(moved) > _RETRIANGULATE:
            last = points.copy()
            triangles = _triangulate(points, distance, step)
            bars = _bars(triangles)
        move = _TIME_STEP * _spring_forces(points, bars, size)
        move[:n_fixed] = 0.0
        points = _project_outside(points + move, distance, step)
        inside = distance(points) < -1.0e-3 * step
        if np.max(np.hypot(*move[inside].T), initial=0.0) < _STOP_MOVE * step:
            break
    return _clean(points, _triangulate(points, distance, step))


def _clean(points: np.ndarray, triangles: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Drop unused points, renumber, orient counter-clockwise."""
    used, triangles = np.unique(triangles, return_inverse=True)
    triangles = triangles.reshape(-1, 3)
    points = points[used]
    a, b, c = (points[triangles[:, k]] for k in range(3))
    area2 = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    flip = area2 < 0.0
    triangles[flip] = triangles[flip][:, [0, 2, 1]]
    return points, triangles


def annulus_mesh(inner_radius: float, outer_radius: float, n_theta: int,
                 n_radial: int) -> tuple[np.ndarray, np.ndarray]:
    """Structured ring mesh: points (n, 2) [m] and triangles (m, 3), diagonals alternating."""
    theta = 2.0 * np.pi * np.arange(n_theta) / n_theta
    radius = np.linspace(inner_radius, outer_radius, n_radial + 1)
    points = np.column_stack([(radius[:, None] * np.cos(theta)).ravel(),
                              (radius[:, None] * np.sin(theta)).ravel()])
    ring, column = np.meshgrid(np.arange(n_radial), np.arange(n_theta), indexing="ij")
    a = ring * n_theta + column
    b = ring * n_theta + (column + 1) % n_theta
    c, d = a + n_theta, b + n_theta
    even = ((ring + column) % 2 == 0).ravel()
    first = np.where(even[:, None], np.column_stack([a.ravel(), b.ravel(), d.ravel()]),
                     np.column_stack([a.ravel(), b.ravel(), c.ravel()]))
    second = np.where(even[:, None], np.column_stack([a.ravel(), d.ravel(), c.ravel()]),
                      np.column_stack([b.ravel(), d.ravel(), c.ravel()]))
    return points, np.vstack([first, second])


def quadratic_mesh(points: np.ndarray, triangles: np.ndarray,
                   circles: dict[str, Circle]) -> tuple[MeshTri2, dict[str, np.ndarray]]:
    """Six-node mesh with each named circle's boundary facets and their mid-points on it.

    Returns the mesh and name → boundary facet indices of the facets whose two corners lie
    on the circle (within 1e-6 of its radius).
    """
    linear = MeshTri(np.ascontiguousarray(points.T), np.ascontiguousarray(triangles.T))
    boundary = linear.boundary_facets()
    facets = linear.facets[:, boundary]
    groups: dict[str, np.ndarray] = {}
    for name, circle in circles.items():
        tolerance = 1.0e-6 * circle.radius
        on = (circle.distance(linear.p[:, facets[0]]) < tolerance) & (
            circle.distance(linear.p[:, facets[1]]) < tolerance)
        groups[name] = boundary[on]
    quadratic = MeshTri2.from_mesh(linear)
    doflocs = quadratic.doflocs.copy()
    n_vertices = linear.p.shape[1]
    for name, circle in circles.items():
        columns = n_vertices + groups[name]
        doflocs[:, columns] = circle.project(doflocs[:, columns])
    return MeshTri2(doflocs, quadratic.t), groups
