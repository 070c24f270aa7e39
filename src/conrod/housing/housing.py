"""The big-end housing seen by the film: compliance, inertia deformation, correction.

.. code-block:: python

    housing = Housing.from_case(case)
    forces = housing.nodal_forces(pressure, z)          # [N] at the film nodes
    delta = housing.deformation(forces, crank_angle)    # corrected radial displacement [m]

The film thickness of the elastic bearing is h = h_rigid + δ with δ positive outward.
One update δ = (P C) f + (P U) c(φ) is two small matrix-vector products: the correction P
(:mod:`conrod.housing.correction`) is folded into the precomputed matrices.
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from conrod.housing.build import housing_from_case
from conrod.housing.correction import correction_projector
from conrod.housing.inertia import CrankKinematics
from conrod.housing.transfer import nodal_forces


@dataclass
class Housing:
    """Compliance and inertia base fields of a housing at the film nodes.

    angles : ndarray  Film-node angles θ_j [rad] (film frame).
    radius : float  Film (journal) radius R [m].
    compliance : ndarray  C (n × n) [m/N]: radial displacement (outward +) of node i per unit
        outward nodal force at node j.
    inertia_base : ndarray  (n, 4) radial displacements of the inertia base load cases per
        unit coefficient (see :mod:`conrod.housing.inertia`) [m per unit].
    correction : str  least_squares_circle, centroid or none.
    kinematics : CrankKinematics or None  Crank train for the inertia coefficients.
    info : dict  Build diagnostics (model, sizes, times, cache use).
    """

    angles: np.ndarray
    radius: float
    compliance: np.ndarray
    inertia_base: np.ndarray
    correction: str = "least_squares_circle"
    kinematics: CrankKinematics | None = None
    info: dict[str, Any] = field(default_factory=dict)
    structure_factory: Any = field(default=None, repr=False)
    projector: np.ndarray = field(init=False, repr=False)
    corrected_compliance: np.ndarray = field(init=False, repr=False)
    corrected_inertia: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        self.projector = correction_projector(self.angles, self.correction)  # type: ignore[arg-type]
        self.corrected_compliance = self.projector @ self.compliance
        self.corrected_inertia = self.projector @ self.inertia_base

    @classmethod
    def from_case(cls, case, *, cache_dir=None, use_cache: bool = True) -> Housing:
        """Build (or load from the cache) the housing of ``[housing]``; see docs/elastic.md."""
        return housing_from_case(case, cls, cache_dir=cache_dir, use_cache=use_cache)

    # ------------------------------------------------------------------ film side
    def nodal_forces(self, pressure: np.ndarray, z: np.ndarray,
                     theta: np.ndarray | None = None) -> np.ndarray:
        """Film nodal forces f_j [N] from p(θ, z) (n_θ, n_z + 1) [Pa] on z [m]; θ [rad] of
        the rows when they are not the housing's film nodes."""
        if theta is not None and len(theta) == len(self.angles) and np.allclose(theta,
                                                                                 self.angles):
            theta = None
        return nodal_forces(pressure, z, self.angles, self.radius, theta)

    def correct(self, displacement: np.ndarray) -> np.ndarray:
        """Rigid-body corrected radial displacement(s) [m] of (n,) or (n, k) [m]."""
        return self.projector @ displacement

    def pressure_deformation(self, forces: np.ndarray, corrected: bool = True) -> np.ndarray:
        """Radial displacement C f [m] of nodal forces f [N], corrected or raw."""
        matrix = self.corrected_compliance if corrected else self.compliance
        return matrix @ forces

    def inertia_coefficients(self, crank_angle: float) -> np.ndarray:
        """c_k(φ) of the four base fields at φ [rad]; needs ``[engine]``."""
        if self.kinematics is None:
            from conrod.errors import CaseError

            raise CaseError("housing inertia deformation needs the [engine] section "
                            "(crank speed, stroke, rod length)")
        return self.kinematics.coefficients(crank_angle)

    def inertia_deformation(self, crank_angle: float, corrected: bool = True) -> np.ndarray:
        """Radial displacement from the rod's own inertia at φ [rad] [m], corrected or raw."""
        base = self.corrected_inertia if corrected else self.inertia_base
        return base @ self.inertia_coefficients(crank_angle)

    def deformation_from(self, forces: np.ndarray, coefficients: np.ndarray) -> np.ndarray:
        """Corrected δ = P(C f + U c) [m]: the cheap update for given f [N] and c(φ)."""
        return self.corrected_compliance @ forces + self.corrected_inertia @ coefficients

    def deformation(self, forces: np.ndarray, crank_angle: float | None = None) -> np.ndarray:
        """Corrected bore deformation [m] from nodal forces [N] (+ inertia at φ [rad])."""
        if crank_angle is None or self.kinematics is None:
            return self.corrected_compliance @ forces
        return self.deformation_from(forces, self.inertia_coefficients(crank_angle))

    @staticmethod
    def film_field(deformation: np.ndarray, n_axial_nodes: int) -> np.ndarray:
        """δ(θ_j) [m] repeated over the axial nodes: the (n, n_z + 1) additive film-thickness
        field of :class:`conrod.film.base.FilmState` (a 2-D housing deforms alike at every z)."""
        return np.repeat(np.asarray(deformation)[:, None], n_axial_nodes, axis=1)

    # ------------------------------------------------------------------ structure side
    @cached_property
    def structure(self):
        """The FE model behind the compliance (built-in rod or mesh), rebuilt on demand."""
        if self.structure_factory is None:
            from conrod.errors import CaseError

            raise CaseError(f"housing.model = {self.info.get('model')!r}: stresses need a "
                            "finite-element housing (allowed: builtin or mesh)")
        start = time.perf_counter()
        structure = self.structure_factory()
        self.info["structure_seconds"] = time.perf_counter() - start
        return structure

    def stresses(self, pressure: np.ndarray, z: np.ndarray, crank_angle: float,
                 theta: np.ndarray | None = None):
        """Von Mises stresses of both load schemes at φ [rad] for the film pressure p(θ, z)
        [Pa] (see :func:`conrod.housing.stresses.compare_schemes`)."""
        from conrod.housing.stresses import compare_schemes

        return compare_schemes(self, self.nodal_forces(pressure, z, theta), crank_angle)
