"""Matrices written by finite-element codes: read and write Matrix Market, Nastran DMIG and
OP4, and Abaqus substructure matrices (the formats are described in docs/elastic.md).

Each reader returns a :class:`LabelledMatrix`: the square matrix and, where the file says
so, the (node id, component) of every row — DMIG rows name their grid point and component,
an Abaqus ``*USER ELEMENT`` lists the active degrees of freedom per node (and, in its
``** ELEMENT NODES`` comment, the node numbers). Matrix Market and OP4 hold the matrix
alone: its rows follow the node file, one or more components per node.

* **Matrix Market** (NIST; ``scipy.io.mmread``/``mmwrite``): ``%%MatrixMarket matrix
  coordinate|array real general|symmetric``.
* **Nastran DMIG and OP4**: :mod:`conrod.housing.nastran_formats`.
* **Abaqus** ``*SUBSTRUCTURE MATRIX OUTPUT, OUTPUT FILE=USER DEFINED, STIFFNESS=YES``
  (``.mtx``, the format of ``*USER ELEMENT, LINEAR``): ``*USER ELEMENT, NODES=n, LINEAR``,
  optional ``** ELEMENT NODES`` comment lines with the node numbers, the data lines of the
  active degrees of freedom (the first node's, then ``position, dofs`` where they change),
  then ``*MATRIX,TYPE=STIFFNESS`` with the lower triangle row by row.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np


class FormatError(ValueError):
    """A matrix file that does not hold what its format says (the message names why)."""


@dataclass(frozen=True)
class LabelledMatrix:
    """A square matrix read from a file.

    matrix : ndarray  (m, m) values in the file's units.
    labels : list of (int, int) or None  (node id, component 1..6) of each row; None: the
        rows follow the node file (Matrix Market, OP4).
    nodes_in_order : bool  Labels hold node positions 1..n (an Abaqus file without its node
        numbers): position k is the k-th node of the node file.
    """

    matrix: np.ndarray
    labels: list[tuple[int, int]] | None = None
    nodes_in_order: bool = False


# ---------------------------------------------------------------------------- helpers
_NASTRAN_REAL = re.compile(r"^([-+]?(?:\d+\.?\d*|\.\d+))([-+]\d+)$")


def nastran_real(text: str) -> float:
    """A Nastran real field: ``1.5``, ``1.5E-3``, ``1.5D-3``, ``1.5-3`` or ``.15+1`` [-]."""
    text = text.strip().upper().replace("D", "E")
    if not text:
        return 0.0
    implicit = _NASTRAN_REAL.match(text)
    if implicit and "E" not in text:
        return float(f"{implicit.group(1)}E{implicit.group(2)}")
    try:
        return float(text)
    except ValueError:
        raise FormatError(f"{text!r} is not a number") from None


def integer_field(text: str, what: str) -> int:
    """An integer field (blank: 0); FormatError naming ``what`` otherwise."""
    try:
        return int(text.strip() or "0")
    except ValueError:
        raise FormatError(f"{what} {text.strip()!r} is not an integer") from None


def symmetric_from_triangle(matrix: np.ndarray, given: np.ndarray) -> np.ndarray:
    """Fill the entries not ``given`` from their mirror (a symmetric matrix stored by one
    triangle) [-]."""
    mirror = given.T & ~given
    filled = matrix.copy()
    filled[mirror] = matrix.T[mirror]
    return filled


# ---------------------------------------------------------------------- Matrix Market
def read_matrix_market(path: Path) -> LabelledMatrix:
    """The real square matrix of a Matrix Market file (rows follow the node file)."""
    from scipy.io import mminfo, mmread

    try:
        rows, cols, _, _, field, _ = mminfo(str(path))
        matrix = mmread(str(path))
    except (OSError, ValueError, IndexError) as error:
        raise FormatError(f"cannot be read as Matrix Market ({error})") from None
    if field not in ("real", "integer", "double"):
        raise FormatError(f"holds a {field} matrix (allowed: real)")
    dense = np.asarray(matrix.toarray() if hasattr(matrix, "toarray") else matrix, dtype=float)
    return LabelledMatrix(dense)


def write_matrix_market(path: Path, matrix: np.ndarray, comment: str = "") -> Path:
    """Write ``matrix`` as a dense symmetric Matrix Market array (17 significant digits)."""
    from scipy.io import mmwrite

    mmwrite(str(path), np.asarray(matrix, dtype=float), comment=comment, field="real",
            precision=17, symmetry="symmetric")
    return path


# ---------------------------------------------------------------------- Abaqus .mtx
def read_abaqus(path: Path) -> LabelledMatrix:
    """The stiffness matrix of an Abaqus substructure / user-element ``.mtx`` file, rows
    labelled (node, dof) by its ``*USER ELEMENT`` data lines."""
    try:
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
    except OSError as error:
        raise FormatError(f"cannot be read ({error})") from None
    nodes, node_ids, dof_lines, values = None, [], [], []
    section, listing = "", False
    for number, raw in enumerate(lines, 1):
        line = raw.strip()
        if not line:
            continue
        upper = line.upper().replace(" ", "")
        if upper.startswith("**"):
            listing = "ELEMENTNODES" in upper or (listing and _integers(line[2:]) is not None)
            if listing and "ELEMENTNODES" not in upper:
                node_ids += _integers(line[2:]) or []
            continue
        listing = False
        if upper.startswith("*"):
            section = upper
            if upper.startswith("*USERELEMENT"):
                found = re.search(r"NODES=(\d+)", upper)
                nodes = int(found.group(1)) if found else None
            continue
        if section.startswith("*USERELEMENT"):
            dof_lines.append((number, _integers(line)))
        elif section.startswith("*MATRIX") and "TYPE=STIFFNESS" in section:
            values += [nastran_real(token) for token in line.replace(",", " ").split()]
    if nodes is None:
        raise FormatError("has no '*USER ELEMENT, NODES=n' line")
    if not values:
        raise FormatError("has no '*MATRIX,TYPE=STIFFNESS' block")
    dofs = _abaqus_dofs(nodes, dof_lines)
    size = len(dofs)
    if len(values) != size * (size + 1) // 2:
        raise FormatError(f"'*MATRIX,TYPE=STIFFNESS' has {len(values)} values; the "
                          f"{nodes} nodes' {size} degrees of freedom need {size * (size + 1) // 2}"
                          " (the lower triangle)")
    matrix = np.zeros((size, size))
    rows, cols = np.tril_indices(size)
    matrix[rows, cols] = values
    matrix[cols, rows] = values
    if node_ids and len(node_ids) != nodes:
        raise FormatError(f"'** ELEMENT NODES' lists {len(node_ids)} nodes, NODES={nodes}")
    if node_ids:
        return LabelledMatrix(matrix, [(node_ids[p - 1], c) for p, c in dofs])
    return LabelledMatrix(matrix, dofs, nodes_in_order=True)


def _integers(text: str) -> list[int] | None:
    tokens = [token for token in text.replace(",", " ").split()]
    if not tokens or not all(re.fullmatch(r"-?\d+", token) for token in tokens):
        return None
    return [int(token) for token in tokens]


def _abaqus_dofs(nodes: int, dof_lines) -> list[tuple[int, int]]:
    """(node position, dof) of every matrix row from the ``*USER ELEMENT`` data lines."""
    if not dof_lines or dof_lines[0][1] is None:
        raise FormatError("'*USER ELEMENT' lacks the line of active degrees of freedom")
    active = {1: dof_lines[0][1]}
    for number, values in dof_lines[1:]:
        if values is None or len(values) < 2:
            raise FormatError(f"line {number}: expected 'node position, dofs'")
        active[values[0]] = values[1:]
    dofs, current = [], active[1]
    for position in range(1, nodes + 1):
        current = active.get(position, current)
        dofs += [(position, dof) for dof in current]
    return dofs


def write_abaqus(path: Path, matrix: np.ndarray, node_ids: list[int], dofs: list[int]) -> Path:
    """Write a symmetric stiffness over ``node_ids`` with the same active ``dofs`` at every
    node as Abaqus writes ``*SUBSTRUCTURE MATRIX OUTPUT`` (lower triangle, four values a
    line)."""
    lines = ["**", "** SUBSTRUCTURE MATRIX OUTPUT (written by conrod)",
             f"*USER ELEMENT, NODES={len(node_ids)}, LINEAR", "** ELEMENT NODES"]
    for k in range(0, len(node_ids), 10):
        lines.append("** " + ", ".join(str(node) for node in node_ids[k:k + 10]))
    lines += [", ".join(str(dof) for dof in dofs), "*MATRIX,TYPE=STIFFNESS"]
    for i in range(matrix.shape[0]):
        row = [repr(float(value)) for value in matrix[i, :i + 1]]
        for k in range(0, len(row), 4):
            lines.append(" , ".join(row[k:k + 4]) + (" ," if k + 4 < len(row) else ""))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path
