"""Bore nodes of an imported compliance or stiffness: their coordinates, the radial
compliance at them, and the transfer to the film nodes (θ_j, z_k).

**Node file** (``[housing] node_file``, CSV with a header line): one row per bore node,
``node_id`` and either ``angle_deg, axial_position_m`` or ``x_m, y_m, z_m`` — the rod (film)
frame of docs/conventions.md: x along the rod axis towards the small end, y = z × x, z along
the bore axis from the bearing's mid-plane, origin on the bore axis; θ = atan2(y, x). Nodes
must lie on the bore: radius between 0.98 × the bearing radius d/2 and 1.02 × the housing
bore radius d_b/2 (``[housing] shell_thickness``), |z| ≤ 0.51 × the bearing width.

**Matrix rows.** A row is (node, component): component 1, 2, 3 are the translations along
(r, θ, z) of the node (``dof_frame = "cylindrical"``, the nodal transform FE codes apply at
a bore) or along (x, y, z) of the rod frame (``"cartesian"``); 4–6 rotations. A matrix
without labels (Matrix Market, OP4) has 1, 3 or 6 rows per node, node-major in the node
file's order.

**Radial compliance** C_r (n × n) [m/N]: the radial displacement of node a per unit outward
radial force at node b, all other forces zero: C_r = Tᵀ C T with T the radial direction of
each node in the components, C the compliance — or C = K⁻¹ of a stiffness K, which must be
positive definite (a held model: a free-free stiffness has no compliance).

**To the film nodes** (a node set over the width): u_film = L u, f = Lᵀ f_film, so
C_film = L C_r Lᵀ — L the piecewise-linear interpolation on a Delaunay triangulation of the
nodes in the unrolled bore (R θ, z), periodic in θ (the nodes repeated at θ ± 2π); film
nodes beyond the axial range of the bore nodes take the value at the nearest edge (constant
in z). Film nodes that coincide with bore nodes take their values exactly.
"""

from __future__ import annotations

import csv
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from conrod.errors import CaseError
from conrod.housing.matrix_formats import LabelledMatrix

RADIUS_BAND = (0.98, 1.02)
"""Nodes must lie between 0.98 × the bearing radius and 1.02 × the housing bore radius [-]."""
WIDTH_SHARE = 0.51
"""|z| of a node at most this share of the bearing width [-]."""
DEFINITE_TOLERANCE = 1.0e-12
"""A stiffness whose smallest eigenvalue is below this share of its largest is singular
(a model that is not held) [-]."""


@dataclass(frozen=True)
class BoreNodes:
    """Bore nodes of an imported matrix, in the node file's order.

    ids : ndarray  Node ids (n,) [-].
    angles : ndarray  θ (n,) in [0, 2π) [rad].
    axial : ndarray  z (n,) from the bearing mid-plane [m] (zeros when the file has none).
    has_axial : bool  The file gives axial positions.
    """

    ids: np.ndarray
    angles: np.ndarray
    axial: np.ndarray
    has_axial: bool

    @property
    def plane(self) -> bool:
        """True when every node lies in one axial section (a 2-D compliance) [-]."""
        return not self.has_axial or bool(np.ptp(self.axial) == 0.0)


def _error(field: str, path: Path, message: str) -> CaseError:
    return CaseError(f"housing.{field} {str(path)!r}: {message}")


def read_node_file(path: Path, radius: float, bore_radius: float, width: float) -> BoreNodes:
    """Bore nodes of the CSV ``path`` (module docstring), checked to lie on the bore of
    bearing radius ``radius`` [m], housing bore radius ``bore_radius`` [m] and ``width``
    [m]; CaseError naming the row otherwise."""
    try:
        with path.open(encoding="utf-8", newline="") as handle:
            rows = [row for row in csv.reader(handle) if any(cell.strip() for cell in row)]
    except (OSError, UnicodeDecodeError) as error:
        raise _error("node_file", path, f"cannot be read ({error})") from None
    if len(rows) < 2:
        raise _error("node_file", path, "needs a header line and one row per node")
    header = [name.strip().lower() for name in rows[0]]
    columns = _columns(path, header)
    table = np.empty((len(rows) - 1, len(columns)))
    for number, row in enumerate(rows[1:], 2):
        try:
            table[number - 2] = [float(row[columns[name]]) for name in columns]
        except (ValueError, IndexError):
            raise _error("node_file", path, f"row {number} is not {len(columns)} numbers "
                         f"({', '.join(columns)})") from None
    if not np.all(np.isfinite(table)):
        bad = int(np.argmax(~np.all(np.isfinite(table), axis=1))) + 2
        raise _error("node_file", path, f"row {bad} contains NaN or infinity")
    ids = table[:, 0].astype(np.int64)
    if np.any(ids != table[:, 0]) or len(np.unique(ids)) != len(ids):
        raise _error("node_file", path, "node_id must be distinct integers")
    nodes = _coordinates(path, columns, table, ids, radius, bore_radius)
    check_nodes(path, nodes, radius, width)
    return nodes


def check_nodes(path: Path, nodes: BoreNodes, radius: float, width: float,
                field: str = "node_file") -> None:
    """Nodes within the bearing width and at distinct positions; CaseError otherwise."""
    _check_axial(path, nodes, width, field)
    _check_distinct(path, nodes, radius, field)


def _columns(path: Path, header: list[str]) -> dict[str, int]:
    for names in (("node_id", "angle_deg", "axial_position_m"), ("node_id", "x_m", "y_m", "z_m"),
                  ("node_id", "angle_deg")):
        if all(name in header for name in names):
            return {name: header.index(name) for name in names}
    raise _error("node_file", path, f"has the columns {', '.join(header)} (allowed: node_id "
                 "with angle_deg, axial_position_m or with x_m, y_m, z_m)")


def _coordinates(path, columns, table, ids, radius, bore_radius) -> BoreNodes:
    if "x_m" in columns:
        x, y, z = table[:, 1], table[:, 2], table[:, 3]
        node_radius = np.hypot(x, y)
        low, high = RADIUS_BAND[0] * radius, RADIUS_BAND[1] * bore_radius
        off = np.flatnonzero((node_radius < low) | (node_radius > high))
        if off.size:
            k = int(off[0])
            raise _error("node_file", path, f"node {ids[k]} (row {k + 2}) lies at radius "
                         f"{1e3 * node_radius[k]:.4g} mm, off the bore (allowed: "
                         f"{1e3 * low:.4g}..{1e3 * high:.4g} mm, the bearing radius to the "
                         "housing bore radius ±2 %)")
        return BoreNodes(ids, np.mod(np.arctan2(y, x), 2.0 * np.pi), z, True)
    angles = table[:, 1]
    if np.any(angles < 0.0) or np.any(angles >= 360.0):
        k = int(np.argmax((angles < 0.0) | (angles >= 360.0)))
        raise _error("node_file", path, f"node {ids[k]} (row {k + 2}) has angle_deg = "
                     f"{angles[k]:g} (allowed: >= 0 and < 360 deg)")
    axial = table[:, 2] if "axial_position_m" in columns else np.zeros(len(ids))
    return BoreNodes(ids, np.radians(angles), axial, "axial_position_m" in columns)


def _check_axial(path: Path, nodes: BoreNodes, width: float, field: str) -> None:
    limit = WIDTH_SHARE * width
    off = np.flatnonzero(np.abs(nodes.axial) > limit)
    if off.size:
        k = int(off[0])
        raise _error(field, path, f"node {nodes.ids[k]} (row {k + 2}) lies at z = "
                     f"{1e3 * nodes.axial[k]:.4g} mm, off the bore (allowed: |z| <= "
                     f"{1e3 * limit:.4g} mm, half the bearing width, from its mid-plane)")


def _check_distinct(path: Path, nodes: BoreNodes, radius: float, field: str) -> None:
    keys = np.column_stack([np.round(radius * nodes.angles / 1e-9),
                            np.round(nodes.axial / 1e-9)])
    _, first, counts = np.unique(keys, axis=0, return_index=True, return_counts=True)
    if np.any(counts > 1):
        k = int(first[np.argmax(counts > 1)])
        raise _error(field, path, f"two nodes share the position of node {nodes.ids[k]}"
                     f" (θ = {np.degrees(nodes.angles[k]):.4g} deg, z = "
                     f"{1e3 * nodes.axial[k]:.4g} mm; allowed: distinct positions)")


# --------------------------------------------------------------- radial compliance
def row_nodes(matrix: LabelledMatrix, nodes: BoreNodes, field: str, path: Path
              ) -> tuple[np.ndarray, np.ndarray]:
    """(node index into ``nodes``, component 1..6) of every matrix row; CaseError when the
    rows and the node file do not match."""
    size = matrix.matrix.shape[0]
    count = len(nodes.ids)
    if matrix.labels is None:
        per_node = size // count if count else 0
        if per_node not in (1, 3, 6) or per_node * count != size:
            raise _error(field, path, f"has {size} rows, the node file lists {count} nodes "
                         f"(allowed: {count}, {3 * count} or {6 * count} rows: 1, 3 or 6 per "
                         "node in the node file's order)")
        return np.repeat(np.arange(count), per_node), np.tile(np.arange(1, per_node + 1), count)
    position = {int(node): k for k, node in enumerate(nodes.ids)}
    index, component = np.empty(size, dtype=int), np.empty(size, dtype=int)
    for row, (node, dof) in enumerate(matrix.labels):
        key = node - 1 if matrix.nodes_in_order else position.get(node)
        if key is None or not 0 <= key < count:
            raise _error(field, path, f"row {row + 1} belongs to node {node}, which the node "
                         f"file does not list ({count} nodes)")
        if not 1 <= dof <= 6:
            raise _error(field, path, f"row {row + 1} (node {node}) has component {dof} "
                         "(allowed: 1..6)")
        index[row], component[row] = key, dof
    missing = sorted(set(range(count)) - set(index.tolist()))
    if missing:
        raise _error(field, path, f"has no row of node {nodes.ids[missing[0]]} of the node "
                     f"file ({len(missing)} of its {count} nodes missing)")
    return index, component


def radial_directions(index: np.ndarray, component: np.ndarray, nodes: BoreNodes,
                      frame: str) -> np.ndarray:
    """T (m × n): the components of a unit outward radial force at each node [-]."""
    theta = nodes.angles[index]
    if frame == "cylindrical":
        share = (component == 1).astype(float)
    else:
        share = np.where(component == 1, np.cos(theta),
                         np.where(component == 2, np.sin(theta), 0.0))
    directions = np.zeros((len(index), len(nodes.ids)))
    directions[np.arange(len(index)), index] = share
    return directions


def radial_compliance(matrix: LabelledMatrix, nodes: BoreNodes, kind: str, frame: str,
                      path: Path, field: str = "compliance_file") -> np.ndarray:
    """C_r (n × n) [m/N] at the nodes from a compliance [m/N] or stiffness [N/m] (module
    docstring); the matrix is checked square, finite and symmetric first."""
    from conrod.housing.compliance_io import SYMMETRY_TOLERANCE

    values = matrix.matrix
    if values.ndim != 2 or values.shape[0] != values.shape[1]:
        raise _error(field, path, f"holds a {values.shape} matrix (allowed: square)")
    if not np.all(np.isfinite(values)):
        raise _error(field, path, "contains NaN or infinity")
    scale = np.abs(values).max()
    asymmetry = np.abs(values - values.T).max() / scale if scale > 0 else 0.0
    if asymmetry > SYMMETRY_TOLERANCE:
        raise _error(field, path, f"is not symmetric: max|A - A^T|/max|A| = {asymmetry:.3g} "
                     f"(allowed: <= {SYMMETRY_TOLERANCE:g})")
    index, component = row_nodes(matrix, nodes, field, path)
    if frame == "cylindrical" and not np.all(np.isin(np.arange(len(nodes.ids)),
                                                     index[component == 1])):
        raise _error(field, path, "has a node without component 1, the radial one (with "
                     "dof_frame = 'cylindrical')")
    symmetric = 0.5 * (values + values.T)
    if kind == "stiffness":
        symmetric = _compliance_of_stiffness(symmetric, field, path)
    directions = radial_directions(index, component, nodes, frame)
    radial = directions.T @ symmetric @ directions
    return 0.5 * (radial + radial.T)


def _compliance_of_stiffness(stiffness: np.ndarray, field: str, path: Path) -> np.ndarray:
    eigenvalues = np.linalg.eigvalsh(stiffness)
    if eigenvalues[-1] <= 0.0 or eigenvalues[0] <= DEFINITE_TOLERANCE * eigenvalues[-1]:
        raise _error(field, path, f"the stiffness is not positive definite (smallest "
                     f"eigenvalue {eigenvalues[0]:.3g} N/m = {eigenvalues[0] / eigenvalues[-1]:.3g}"
                     " × the largest): the model is not held — export it from a model held at "
                     "the small end or the shank (allowed: a positive definite stiffness)")
    return np.linalg.inv(stiffness)


# ---------------------------------------------------------------- to the film nodes
def film_interpolation(nodes: BoreNodes, radius: float, film_angles: np.ndarray,
                       film_axial: np.ndarray) -> np.ndarray:
    """L (N_film × n): u at the film nodes (θ_j, z_k) (row-major) from u at the bore nodes
    (module docstring) [-]."""
    theta = np.repeat(film_angles, len(film_axial))
    z = np.tile(film_axial, len(film_angles))
    exact = _coincident(nodes, radius, theta, z)
    if exact is not None:
        matrix = np.zeros((len(theta), len(nodes.ids)))
        matrix[np.arange(len(theta)), exact] = 1.0
        return matrix
    from scipy.spatial import Delaunay

    count = len(nodes.ids)
    arc = radius * np.concatenate([nodes.angles - 2 * np.pi, nodes.angles,
                                   nodes.angles + 2 * np.pi])
    points = np.column_stack([arc, np.tile(nodes.axial, 3)])
    triangulation = Delaunay(points)
    low, high = nodes.axial.min(), nodes.axial.max()
    inset = 1e-12 * (high - low)  # on the hull's edge a point may be found outside it
    target = np.column_stack([radius * theta, np.clip(z, low + inset, high - inset)])
    simplex = triangulation.find_simplex(target)
    if np.any(simplex < 0):
        raise CaseError("housing.node_file: the bore nodes do not cover the bore around its "
                        "circumference (a film node lies outside their triangulation)")
    transform = triangulation.transform[simplex]
    partial = np.einsum("kij,kj->ki", transform[:, :2], target - transform[:, 2])
    weights = np.column_stack([partial, 1.0 - partial.sum(axis=1)])
    corners = triangulation.simplices[simplex] % count
    matrix = np.zeros((len(theta), count))
    np.add.at(matrix, (np.repeat(np.arange(len(theta)), 3), corners.ravel()), weights.ravel())
    return matrix


def _coincident(nodes: BoreNodes, radius: float, theta: np.ndarray, z: np.ndarray
                ) -> np.ndarray | None:
    """The bore node at each film node when every film node is one (within 1 µm) [-]."""
    gap = np.abs(np.angle(np.exp(1j * (theta[:, None] - nodes.angles[None, :])))) * radius
    distance = np.hypot(gap, z[:, None] - nodes.axial[None, :])
    nearest = np.argmin(distance, axis=1)
    if np.all(distance[np.arange(len(theta)), nearest] < 1e-6):
        return nearest
    return None
