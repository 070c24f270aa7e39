"""An imported housing (``[housing] model = "compliance"``): the matrix file in its format,
the bore nodes, and the compliance and inertia fields on the film nodes (docs/elastic.md).

* ``.npz`` / ``.csv`` of :mod:`conrod.housing.compliance_io` (bore angles, and for a 3-D
  ``.npz`` the axial positions ``axial_position_m``): read as they are;
* Matrix Market, Nastran DMIG and OP4, Abaqus ``.mtx`` (:mod:`conrod.housing.matrix_formats`)
  with the node file of :mod:`conrod.housing.nodes3d`: a compliance or a stiffness, its
  rows per node and component, reduced to the radial compliance at the nodes.

Nodes in one axial section give a plane housing (uniform in z, the film rows interpolated
in θ as before); nodes over the width a 3-D one, on the film nodes (θ_j, z_k).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.housing import matrix_formats as formats
from conrod.housing import nastran_formats as nastran
from conrod.housing.compliance_io import (
    check_compliance,
    check_matrix,
    read_compliance,
    read_inertia,
)
from conrod.housing.nodes3d import (
    BoreNodes,
    check_nodes,
    film_interpolation,
    radial_compliance,
    read_node_file,
)
from conrod.housing.transfer import interpolation_matrix

SUFFIXES = {".npz": "npz", ".csv": "csv", ".op4": "nastran_op4", ".dmig": "nastran_dmig",
            ".bdf": "nastran_dmig", ".dat": "nastran_dmig", ".pch": "nastran_dmig",
            ".inc": "nastran_dmig", ".blk": "nastran_dmig"}
"""File suffix → format (``.mtx`` is Matrix Market when it starts with ``%%MatrixMarket``,
else Abaqus)."""

NODE_FORMATS = ("matrix_market", "nastran_dmig", "nastran_op4", "abaqus")
"""Formats whose bore nodes come from ``node_file``."""


def matrix_format(path: Path, declared: str) -> str:
    """The format of the matrix file ``path``: ``declared`` unless 'auto', else by its
    suffix (and first line for ``.mtx``); CaseError for an unknown one."""
    if declared != "auto":
        return declared
    suffix = path.suffix.lower()
    if suffix == ".mtx":
        try:
            with path.open("rb") as handle:
                start = handle.read(14)
        except OSError as error:
            raise CaseError(f"housing.compliance_file {str(path)!r}: cannot be read ({error})"
                            ) from None
        return "matrix_market" if start.startswith(b"%%MatrixMarket") else "abaqus"
    if suffix not in SUFFIXES:
        raise CaseError(f"housing.compliance_file {str(path)!r}: unknown format {suffix!r} "
                        "(allowed: .npz, .csv, .mtx (Matrix Market or Abaqus), .op4, .dmig, "
                        ".bdf, .dat, .pch, .inc, .blk; or set housing.compliance_format)")
    return SUFFIXES[suffix]


def read_labelled(path: Path, fmt: str, name: str | None) -> formats.LabelledMatrix:
    """The matrix of ``path`` in format ``fmt``; CaseError naming the file otherwise."""
    if not path.exists():
        raise CaseError(f"housing.compliance_file {str(path)!r}: no such file")
    readers = {"matrix_market": lambda: formats.read_matrix_market(path),
               "nastran_dmig": lambda: nastran.read_dmig(path, name),
               "nastran_op4": lambda: nastran.read_op4(path, name),
               "abaqus": lambda: formats.read_abaqus(path)}
    try:
        return readers[fmt]()
    except formats.FormatError as error:
        raise CaseError(f"housing.compliance_file {str(path)!r} ({fmt}): {error}") from None


def imported_housing(case, make: Any, angles: np.ndarray, radius: float,
                     common: dict) -> Any:
    """The housing of ``[housing] model = "compliance"`` on the film nodes ``angles`` [rad]
    (and the film's axial nodes for a 3-D matrix), built by ``make``."""
    section = case.housing
    path = case.resolve(section.compliance_file)
    fmt = matrix_format(path, section.compliance_format)
    if fmt in ("npz", "csv"):
        return _own_format(case, make, angles, radius, common, path, fmt)
    if section.node_file is None:
        raise CaseError(f"housing.node_file is required with compliance_format = {fmt!r} "
                        "(CSV of node_id with angle_deg, axial_position_m or x_m, y_m, z_m)")
    node_path = case.resolve(section.node_file)
    bore_radius = 0.5 * section.bore_diameter(case.bearing.diameter)
    nodes = read_node_file(node_path, radius, bore_radius, case.bearing.width)
    labelled = read_labelled(path, fmt, section.matrix_name)
    compliance = radial_compliance(labelled, nodes, section.matrix_kind, section.dof_frame,
                                   path)
    _check_definite(path, nodes, compliance)
    info = {"model": "compliance", "format": fmt, "source_nodes": len(nodes.ids),
            "matrix_kind": section.matrix_kind}
    return _on_film(case, make, angles, radius, common, nodes, compliance, info)


def _own_format(case, make, angles, radius, common, path: Path, fmt: str) -> Any:
    section = case.housing
    axial = _npz_axial(path) if fmt == "npz" else None
    if axial is None:  # the plane import, as it always was
        source_angles, matrix = read_compliance(path)
        interpolate = interpolation_matrix(source_angles, angles)
        inertia = np.zeros((len(angles), 4))
        if section.inertia_file is not None:
            inertia_angles, fields = read_inertia(case.resolve(section.inertia_file))
            inertia = interpolation_matrix(inertia_angles, angles) @ fields
        info = {"model": "compliance", "source_nodes": len(source_angles),
                "axial": "uniform in z (a plane compliance)"}
        compliance = interpolate @ matrix @ interpolate.T
        return make(angles, radius, 0.5 * (compliance + compliance.T), inertia, info=info,
                    **common)
    angle_deg, matrix = _npz_arrays(path, "compliance_m_per_N", axial)
    nodes = BoreNodes(np.arange(1, len(angle_deg) + 1), np.radians(angle_deg), axial, True)
    check_nodes(path, nodes, radius, case.bearing.width, "compliance_file")
    compliance = radial_compliance(formats.LabelledMatrix(matrix), nodes, "compliance",
                                   "cylindrical", path)
    _check_definite(path, nodes, compliance)
    info = {"model": "compliance", "format": "npz", "source_nodes": len(angle_deg)}
    return _on_film(case, make, angles, radius, common, nodes, compliance, info)


def _npz_axial(path: Path) -> np.ndarray | None:
    try:
        with np.load(path, allow_pickle=False) as stored:
            if "axial_position_m" not in stored:
                return None
            return np.asarray(stored["axial_position_m"], dtype=float)
    except (OSError, ValueError):
        return None  # read_compliance names the problem


def _npz_arrays(path: Path, name: str, axial: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(angle_deg, ``name``) of a 3-D ``.npz`` with one axial position per node."""
    field = "compliance_file" if name == "compliance_m_per_N" else "inertia_file"
    try:
        with np.load(path, allow_pickle=False) as stored:
            if name not in stored or "angle_deg" not in stored:
                raise CaseError(f"housing.{field} {str(path)!r}: lacks angle_deg or {name}")
            angle_deg = np.asarray(stored["angle_deg"], dtype=float)
            values = np.asarray(stored[name], dtype=float)
    except (OSError, ValueError) as error:
        raise CaseError(f"housing.{field} {str(path)!r}: cannot be read as .npz ({error})"
                        ) from None
    if axial.shape != angle_deg.shape or angle_deg.ndim != 1:
        raise CaseError(f"housing.{field} {str(path)!r}: axial_position_m has shape "
                        f"{axial.shape}, angle_deg {angle_deg.shape} (allowed: one per node)")
    if not (np.all(np.isfinite(angle_deg)) and np.all(np.isfinite(axial))):
        raise CaseError(f"housing.{field} {str(path)!r}: node coordinates contain NaN or "
                        "infinity")
    if angle_deg.min() < 0.0 or angle_deg.max() >= 360.0:
        raise CaseError(f"housing.{field} {str(path)!r}: angle_deg spans "
                        f"{angle_deg.min():g}..{angle_deg.max():g} (allowed: >= 0 and < 360 deg)")
    return angle_deg, values


def _check_definite(path: Path, nodes: BoreNodes, compliance: np.ndarray) -> None:
    """Symmetric, positive semi-definite radial compliance (the checks of
    :func:`conrod.housing.compliance_io.check_compliance`)."""
    if nodes.plane:
        order = np.argsort(nodes.angles)
        angles = np.degrees(nodes.angles[order])
        check_compliance(path, angles, compliance[np.ix_(order, order)])
        return
    check_matrix(path, compliance, len(nodes.ids))


def _on_film(case, make, angles, radius, common, nodes: BoreNodes, compliance: np.ndarray,
             info: dict) -> Any:
    if nodes.plane:
        order = np.argsort(nodes.angles)
        interpolate = interpolation_matrix(nodes.angles[order], angles)
        film = interpolate @ compliance[np.ix_(order, order)] @ interpolate.T
        inertia = _inertia(case, angles, None, radius)
        info["axial"] = "uniform in z (all nodes in one section)"
        return make(angles, radius, 0.5 * (film + film.T), inertia, info=info, **common)
    axial = film_axial_nodes(case)
    interpolate = film_interpolation(nodes, radius, angles, axial)
    film = interpolate @ compliance @ interpolate.T
    inertia = _inertia(case, angles, axial, radius)
    info["axial"] = f"{len(axial)} axial nodes"
    return make(angles, radius, 0.5 * (film + film.T), inertia, info=info, axial=axial,
                **common)


def film_axial_nodes(case) -> np.ndarray:
    """z_k of the film grid [m]: n_z + 1 nodes from −L/2 to L/2 (as
    :class:`conrod.film.characteristics.FilmGrid`)."""
    width = case.bearing.width
    return np.linspace(-0.5 * width, 0.5 * width, case.solver.n_z + 1)


def _inertia(case, angles: np.ndarray, axial: np.ndarray | None, radius: float) -> np.ndarray:
    """Inertia base fields on the film nodes (zero without ``inertia_file``); a plane field
    repeats over the width of a 3-D housing."""
    count = len(angles) * (1 if axial is None else len(axial))
    section = case.housing
    if section.inertia_file is None:
        return np.zeros((count, 4))
    path = case.resolve(section.inertia_file)
    stored_axial = _npz_axial(path)
    if stored_axial is None:
        inertia_angles, fields = read_inertia(path)
        plane = interpolation_matrix(inertia_angles, angles) @ fields
        return plane if axial is None else np.repeat(plane, len(axial), axis=0)
    if axial is None:
        raise CaseError(f"housing.inertia_file {str(path)!r}: has axial positions, the "
                        "compliance has none (allowed: a plane inertia file with a plane "
                        "compliance)")
    angle_deg, fields = _npz_arrays(path, "inertia_base_m", stored_axial)
    if fields.shape != (len(angle_deg), 4) or not np.all(np.isfinite(fields)):
        raise CaseError(f"housing.inertia_file {str(path)!r}: inertia_base_m has shape "
                        f"{fields.shape} or is not finite (allowed: ({len(angle_deg)}, 4))")
    nodes = BoreNodes(np.arange(1, len(angle_deg) + 1), np.radians(angle_deg), stored_axial,
                      True)
    check_nodes(path, nodes, radius, case.bearing.width, "inertia_file")
    return film_interpolation(nodes, radius, angles, axial) @ fields
