"""Read and write 2-D housing meshes with named boundaries (meshio; gmsh .msh first).

A mesh for ``[housing] model = "mesh"``: triangles or quadrilaterals (six-node triangles
are read by their corners) in metres in the rod frame, big-end bore centred at the origin;
boundary lines in physical groups, ``big_end_bore`` required, the clamp in ``clamp``
(default) or ``small_end_bore``. Quadrilaterals are split into two triangles; the bore edge
mid-points are placed on the fitted bore circle.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from conrod.errors import CaseError
from conrod.housing.mesher import Circle, FeMesh, quadratic_mesh

BORE_GROUP = "big_end_bore"
_ROUND_TOLERANCE = 0.01
"""Largest spread of the bore node radii relative to their mean [-]."""


def _error(path: Path, message: str) -> CaseError:
    return CaseError(f"housing.mesh_file {str(path)!r}: {message}")


def _read(path: Path):
    import meshio

    try:
        return meshio.read(path)
    except (Exception, SystemExit) as error:  # meshio raises many types, even SystemExit
        raise _error(path, f"cannot be read as a mesh ({type(error).__name__}: {error})"
                     ) from None


def _triangles(path: Path, mesh) -> np.ndarray:
    blocks = []
    for block in mesh.cells:
        if block.type in ("triangle", "triangle6"):
            blocks.append(block.data[:, :3])
        elif block.type in ("quad", "quad8", "quad9"):
            quads = block.data[:, :4]
            blocks += [quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]]
    if not blocks:
        raise _error(path, "has no triangle or quadrilateral cells (allowed: a 2-D mesh)")
    return np.vstack(blocks)


def _group_lines(path: Path, mesh) -> dict[str, np.ndarray]:
    tags = mesh.cell_data.get("gmsh:physical")
    names = {int(value[0]): name for name, value in mesh.field_data.items()
             if len(value) > 1 and int(value[1]) == 1}
    groups: dict[str, list[np.ndarray]] = {}
    for k, block in enumerate(mesh.cells):
        if block.type not in ("line", "line3") or tags is None:
            continue
        for tag, name in names.items():
            chosen = block.data[np.asarray(tags[k]) == tag][:, :2]
            if len(chosen):
                groups.setdefault(name, []).append(chosen)
    return {name: np.vstack(lines) for name, lines in groups.items()}


def _circle_of(path: Path, points: np.ndarray, lines: np.ndarray, name: str) -> Circle:
    nodes = points[np.unique(lines)]
    centre = nodes.mean(axis=0)
    radii = np.hypot(*(nodes - centre).T)
    spread = float(np.ptp(radii) / radii.mean())
    if spread > _ROUND_TOLERANCE:
        raise _error(path, f"group {name!r} is not a circle: radius spread {spread:.3g} "
                     f"of the mean (allowed: <= {_ROUND_TOLERANCE})")
    return Circle(float(centre[0]), float(centre[1]), float(radii.mean()))


def read_housing_mesh(path: Path, thickness: float, clamp_group: str = "clamp") -> FeMesh:
    """FeMesh from a file with physical groups; CaseError naming the file when unusable."""
    mesh = _read(path)
    points = np.asarray(mesh.points, dtype=float)[:, :2]
    if not np.all(np.isfinite(points)):
        raise _error(path, "contains non-finite coordinates")
    triangles = _triangles(path, mesh)
    groups = _group_lines(path, mesh)
    if BORE_GROUP not in groups:
        raise _error(path, f"lacks the physical group {BORE_GROUP!r} (found: "
                     f"{', '.join(sorted(groups)) or 'no named line groups'})")
    bore = _circle_of(path, points, groups[BORE_GROUP], BORE_GROUP)
    if np.hypot(bore.centre_x, bore.centre_y) > 0.01 * bore.radius:
        raise _error(path, f"the big-end bore is centred at ({bore.centre_x:.4g}, "
                     f"{bore.centre_y:.4g}) m (allowed: the origin, within 1 % of its radius)")
    clamp_name = clamp_group if clamp_group in groups else "small_end_bore"
    if clamp_name not in groups:
        raise _error(path, f"lacks a clamp group {clamp_group!r} or 'small_end_bore'")
    bore = Circle(0.0, 0.0, bore.radius)
    _check_bore_elements(path, points, triangles, groups[BORE_GROUP], bore.radius)
    quadratic, _ = quadratic_mesh(points, triangles, {BORE_GROUP: bore})
    boundaries = {name: _facets_of(quadratic, lines) for name, lines in groups.items()}
    boundaries["clamp"] = boundaries[clamp_name]
    n_elements = quadratic.t.shape[1]
    return FeMesh(quadratic, boundaries, np.full(n_elements, thickness),
                  np.zeros(n_elements, dtype=int), ("all",), bore.radius)


def _check_bore_elements(path: Path, points: np.ndarray, triangles: np.ndarray,
                         lines: np.ndarray, radius: float) -> None:
    """The bore edges become arcs (their mid-nodes move onto the circle by the sagitta
    R(1 − cos(Δα/2))): an element thinner than twice that would fold over; CaseError."""
    edge_to_height = {}
    for triangle in triangles:
        corners = points[triangle]
        first, second = corners[1] - corners[0], corners[2] - corners[0]
        area = 0.5 * abs(first[0] * second[1] - first[1] * second[0])
        for a, b in ((0, 1), (1, 2), (2, 0)):
            length = float(np.hypot(*(corners[b] - corners[a])))
            edge_to_height[frozenset((triangle[a], triangle[b]))] = 2.0 * area / length
    worst = 0.0
    for a, b in lines:
        height = edge_to_height.get(frozenset((a, b)))
        chord = float(np.hypot(*(points[b] - points[a])))
        span = 2.0 * np.arcsin(min(0.5 * chord / radius, 1.0))
        sagitta = radius * (1.0 - np.cos(0.5 * span))
        if height is not None and height > 0.0:
            worst = max(worst, sagitta / height)
    if worst > 0.5:
        raise _error(path, f"the elements along {BORE_GROUP!r} are too thin for their curved "
                     f"edges: an edge's bulge onto the circle is {worst:.2g} of its element's "
                     "height (allowed: <= 0.5; refine the mesh along the bore)")


def _facets_of(mesh, lines: np.ndarray) -> np.ndarray:
    """Facet indices of the mesh matching the (unordered) node pairs in ``lines``."""
    size = int(mesh.facets.max()) + 1
    facets = np.sort(mesh.facets, axis=0)
    keys = facets[0].astype(np.int64) * size + facets[1]
    wanted = np.sort(lines, axis=1).astype(np.int64)
    wanted_keys = wanted[:, 0] * size + wanted[:, 1]
    order = np.argsort(keys)
    position = np.clip(np.searchsorted(keys[order], wanted_keys), 0, len(keys) - 1)
    found = keys[order][position] == wanted_keys
    return order[position[found]]


def write_housing_mesh(path: Path, points: np.ndarray, triangles: np.ndarray,
                       groups: dict[str, np.ndarray]) -> None:
    """Write corner points (n, 2) [m], triangles (m, 3) and named line groups (k, 2) as gmsh
    2.2 (physical groups kept)."""
    import meshio

    names = list(groups)
    cells = [("triangle", triangles)] + [("line", groups[name]) for name in names]
    physical = [np.zeros(len(triangles), dtype=int)] + [
        np.full(len(groups[name]), k + 1, dtype=int) for k, name in enumerate(names)]
    mesh = meshio.Mesh(
        np.column_stack([points, np.zeros(len(points))]), cells,
        cell_data={"gmsh:physical": physical, "gmsh:geometrical": physical},
        field_data={name: np.array([k + 1, 1]) for k, name in enumerate(names)},
    )
    meshio.write(path, mesh, file_format="gmsh22", binary=False)
