"""Compliance matrices exported from other FE codes: read, validate, write.

Format (``.npz``): ``angle_deg`` (n,) — bore-node angles θ in the film frame
(docs/conventions.md), strictly increasing in [0, 360); ``compliance_m_per_N`` (n, n) —
radial displacement of node i [m], positive outward (film thicker), per unit outward radial
force on node j [N], a nodal force being the film pressure integrated over node j's arc and
the whole bearing width. ``.csv``: n rows, first column ``angle_deg``, then the n columns of
the matrix (an optional header line is skipped).

Inertia base fields (``inertia_file``, ``.npz``): ``angle_deg`` (n,) and ``inertia_base_m``
(n, 4), the radial displacements of the four base load cases of
:mod:`conrod.housing.inertia` per unit coefficient.

Matrices on other angles than the film grid are interpolated with the periodic linear
interpolation L of :mod:`conrod.housing.transfer`: C_film = L C Lᵀ.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import CaseError
from conrod.io.atomic import write_npz

SYMMETRY_TOLERANCE = 1.0e-6
"""Largest max|C − Cᵀ| / max|C| accepted [-]."""
SEMIDEFINITE_TOLERANCE = 1.0e-9
"""Most negative eigenvalue accepted, relative to the largest [-]: a compliance with its
rigid-body modes removed (a free-free FE condensation with the rigid-body correction
applied, a ring's Fourier kernel without its translation terms) is positive semi-definite,
its zero eigenvalues round-off of either sign."""


def _error(field: str, path: Path, message: str) -> CaseError:
    return CaseError(f"housing.{field} {str(path)!r}: {message}")


def _load_npz(field: str, path: Path, names: tuple[str, str]) -> tuple[np.ndarray, np.ndarray]:
    try:
        with np.load(path, allow_pickle=False) as stored:
            missing = [name for name in names if name not in stored]
            if missing:
                raise _error(field, path, f"lacks the array(s) {', '.join(missing)} (found: "
                             f"{', '.join(stored.files) or 'none'})")
            return (np.asarray(stored[names[0]], dtype=float),
                    np.asarray(stored[names[1]], dtype=float))
    except CaseError:
        raise
    except (OSError, ValueError) as error:
        raise _error(field, path, f"cannot be read as .npz ({error})") from None


def _load_csv(path: Path) -> tuple[np.ndarray, np.ndarray]:
    try:
        lines = path.read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError) as error:
        raise _error("compliance_file", path, f"cannot be read ({error})") from None
    rows = [line for line in lines if line.strip()]
    if rows and not _is_number(rows[0].split(",")[0]):
        rows = rows[1:]
    try:
        table = np.array([[float(value) for value in row.split(",")] for row in rows])
    except ValueError as error:
        raise _error("compliance_file", path, f"has a value that is not a number ({error})"
                     ) from None
    if table.ndim != 2 or table.shape[1] < 2:
        raise _error("compliance_file", path, "needs rows of angle_deg followed by the "
                     "matrix columns")
    return table[:, 0], table[:, 1:]


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def check_angles(field: str, path: Path, angle_deg: np.ndarray) -> None:
    """Angles must be finite, 1-D, strictly increasing in [0, 360) [deg]."""
    if angle_deg.ndim != 1 or len(angle_deg) < 3:
        raise _error(field, path, f"angle_deg has shape {angle_deg.shape} (allowed: (n,), "
                     "n >= 3)")
    if not np.all(np.isfinite(angle_deg)):
        raise _error(field, path, "angle_deg contains NaN or infinity")
    if angle_deg.min() < 0.0 or angle_deg.max() >= 360.0:
        raise _error(field, path, f"angle_deg spans {angle_deg.min():g}..{angle_deg.max():g} "
                     "(allowed: >= 0 and < 360 deg)")
    steps = np.diff(angle_deg)
    if np.any(steps <= 0.0):
        k = int(np.argmax(steps <= 0.0))
        raise _error(field, path, f"angle_deg is not strictly increasing at row {k + 1}: "
                     f"{angle_deg[k]:g} then {angle_deg[k + 1]:g} deg")


def check_compliance(path: Path, angle_deg: np.ndarray, matrix: np.ndarray) -> None:
    """Square n × n, finite, symmetric within :data:`SYMMETRY_TOLERANCE` and positive
    semi-definite relative to its largest eigenvalue (:data:`SEMIDEFINITE_TOLERANCE`), with
    at least one positive eigenvalue; else CaseError."""
    field = "compliance_file"
    check_angles(field, path, angle_deg)
    check_matrix(path, matrix, len(angle_deg))


def check_matrix(path: Path, matrix: np.ndarray, n: int) -> None:
    """The matrix checks of :func:`check_compliance` for ``n`` nodes (any node set)."""
    field = "compliance_file"
    if matrix.shape != (n, n):
        raise _error(field, path, f"compliance_m_per_N has shape {matrix.shape} (allowed: "
                     f"({n}, {n}), square with one row per angle)")
    if not np.all(np.isfinite(matrix)):
        raise _error(field, path, "compliance_m_per_N contains NaN or infinity")
    scale = np.abs(matrix).max()
    asymmetry = np.abs(matrix - matrix.T).max() / scale if scale > 0 else 0.0
    if asymmetry > SYMMETRY_TOLERANCE:
        raise _error(field, path, f"compliance_m_per_N is not symmetric: max|C - C^T|/max|C| "
                     f"= {asymmetry:.3g} (allowed: <= {SYMMETRY_TOLERANCE:g})")
    eigenvalues = np.linalg.eigvalsh(0.5 * (matrix + matrix.T))
    smallest, largest = float(eigenvalues.min()), float(eigenvalues.max())
    if largest <= 0.0:
        raise _error(field, path, f"compliance_m_per_N has no positive eigenvalue (largest "
                     f"{largest:.3g} m/N; allowed: a positive semi-definite matrix)")
    if smallest < -SEMIDEFINITE_TOLERANCE * largest:
        raise _error(field, path, f"compliance_m_per_N is not positive semi-definite: "
                     f"smallest eigenvalue {smallest:.3g} m/N = {smallest / largest:.3g} × the "
                     f"largest (allowed: >= {-SEMIDEFINITE_TOLERANCE:g} × the largest)")


def read_compliance(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """(angles [rad], compliance [m/N]) from .npz or .csv, validated."""
    if path.suffix.lower() == ".csv":
        angle_deg, matrix = _load_csv(path)
    else:
        angle_deg, matrix = _load_npz("compliance_file", path,
                                      ("angle_deg", "compliance_m_per_N"))
    check_compliance(path, angle_deg, matrix)
    return np.radians(angle_deg), 0.5 * (matrix + matrix.T)


def read_inertia(path: Path) -> tuple[np.ndarray, np.ndarray]:
    """(angles [rad], base fields (n, 4) [m per unit coefficient]) from .npz, validated."""
    angle_deg, fields = _load_npz("inertia_file", path, ("angle_deg", "inertia_base_m"))
    check_angles("inertia_file", path, angle_deg)
    if fields.shape != (len(angle_deg), 4):
        raise _error("inertia_file", path, f"inertia_base_m has shape {fields.shape} "
                     f"(allowed: ({len(angle_deg)}, 4))")
    if not np.all(np.isfinite(fields)):
        raise _error("inertia_file", path, "inertia_base_m contains NaN or infinity")
    return np.radians(angle_deg), fields


def write_compliance(path: Path, angles: np.ndarray, compliance: np.ndarray,
                     inertia_base: np.ndarray | None = None) -> Path:
    """Write the import format (.npz, plus ``inertia_base_m`` when given) atomically."""
    arrays: dict[str, Any] = {"angle_deg": np.degrees(angles),
                              "compliance_m_per_N": compliance}
    if inertia_base is not None:
        arrays["inertia_base_m"] = inertia_base
    return write_npz(path, arrays)
