"""The big-end housing seen by the film: compliance, inertia deformation, correction.

.. code-block:: python

    housing = Housing.from_case(case)
    forces = housing.nodal_forces(pressure, z)          # [N] at the film nodes
    delta = housing.deformation(forces, crank_angle)    # corrected radial displacement [m]

The film thickness of the elastic bearing is h = h_rigid + δ with δ positive outward.
One update δ = (P C) f + (P U) c(φ) is two small matrix-vector products: the correction P
(:mod:`conrod.housing.correction`) is folded into the precomputed matrices.

Plane or over the width. A plane housing (the built-in rod and an imported 2-D mesh, plane
stress; a compliance given on bore angles alone) has one bore node per film row θ_j: the
nodal force is the pressure integrated over the row's arc and the whole width, and the
deformation is uniform in z (``axial`` is None). A 3-D compliance (nodes (θ, z) of a solid
model, :mod:`conrod.housing.nodes3d`) has one bore node per film node (θ_j, z_k), ordered
row-major (j, then k): nodal forces per node and u(θ, z) at every node (``axial`` holds
the film's z_k).
"""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from conrod.housing.build import housing_from_case
from conrod.housing.correction import bore_correction_projector, correction_projector
from conrod.housing.inertia import CrankKinematics
from conrod.housing.transfer import interpolation_matrix, nodal_forces, node_forces


@dataclass
class Housing:
    """Compliance and inertia base fields of a housing at the film nodes.

    angles : ndarray  Film-node angles θ_j [rad] (film frame).
    radius : float  Film (journal) radius R [m].
    compliance : ndarray  C (n × n) [m/N]: radial displacement (outward +) of node i per unit
        outward nodal force at node j; n = n_θ (plane) or n_θ n_z (over the width).
    inertia_base : ndarray  (n, 4) radial displacements of the inertia base load cases per
        unit coefficient (see :mod:`conrod.housing.inertia`) [m per unit].
    correction : str  least_squares_circle, centroid or none.
    kinematics : CrankKinematics or None  Crank train for the inertia coefficients.
    info : dict  Build diagnostics (model, sizes, times, cache use).
    axial : ndarray or None  Axial positions z_k of the film nodes [m] (from mid-width) when
        the compliance has a node at every (θ_j, z_k); None: plane, uniform in z.
    assembly : AssembledBore or None  The bore and joint as assembled (bolt preload, shell
        crush; :mod:`conrod.housing.assembly`); None: round when unloaded.
    warm : WarmBore or None  Clearance change and thermal distortion at the running
        temperatures (:mod:`conrod.housing.thermal`); None: at the reference temperature.
    """

    angles: np.ndarray
    radius: float
    compliance: np.ndarray
    inertia_base: np.ndarray
    correction: str = "least_squares_circle"
    kinematics: CrankKinematics | None = None
    info: dict[str, Any] = field(default_factory=dict)
    structure_factory: Any = field(default=None, repr=False)
    axial: np.ndarray | None = None
    assembly: Any = None
    warm: Any = None
    projector: np.ndarray = field(init=False, repr=False)
    corrected_compliance: np.ndarray = field(init=False, repr=False)
    corrected_inertia: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        if self.axial is None:
            self.projector = correction_projector(self.angles, self.correction)  # type: ignore[arg-type]
        else:
            self.axial = np.asarray(self.axial, dtype=float)
            self.projector = bore_correction_projector(self.angles, self.axial,
                                                       self.correction)  # type: ignore[arg-type]
        self.corrected_compliance = self.projector @ self.compliance
        self.corrected_inertia = self.projector @ self.inertia_base

    # ------------------------------------------------------------------ bore nodes
    @property
    def uniform_in_z(self) -> bool:
        """True for a plane housing: one bore node per film row, the same deformation at
        every axial position [-]."""
        return self.axial is None

    @property
    def node_count(self) -> int:
        """Number of bore nodes n (the size of the compliance) [-]."""
        return len(self.angles) * (1 if self.axial is None else len(self.axial))

    @property
    def node_angles(self) -> np.ndarray:
        """θ of every bore node (n,) [rad]: the film rows, repeated over z_k over the width."""
        if self.axial is None:
            return self.angles
        return np.repeat(self.angles, len(self.axial))

    @property
    def node_axial(self) -> np.ndarray | None:
        """z of every bore node (n,) [m]; None for a plane housing."""
        if self.axial is None:
            return None
        return np.tile(self.axial, len(self.angles))

    def field_view(self, deformation: np.ndarray) -> np.ndarray:
        """u at the bore nodes (n,) [m] as (n_θ, n_z) over the width, (n_θ, 1) plane [m]."""
        return np.asarray(deformation).reshape(len(self.angles), -1)

    def plane_equivalent(self) -> Housing:
        """The plane housing of the same body: a row force spread uniformly over the width,
        the row's displacement its mean over the width, C₂ = Sᵀ C S with S_(jk),j = w_k/L
        (w_k the axial node widths), inertia fields averaged alike; itself when plane."""
        if self.axial is None:
            return self
        from conrod.housing.transfer import axial_weights

        share = axial_weights(self.axial) / np.ptp(self.axial)
        spread = np.kron(np.eye(len(self.angles)), share[:, None])
        compliance = spread.T @ self.compliance @ spread
        return Housing(self.angles, self.radius, 0.5 * (compliance + compliance.T),
                       spread.T @ self.inertia_base, self.correction, self.kinematics,
                       {**self.info, "axial": "width mean of a 3-D compliance"})

    def row_mean(self, deformation: np.ndarray) -> np.ndarray:
        """u per film row θ_j [m]: itself (plane) or its mean over the width, weighted by the
        axial node widths (over the width) [m]."""
        if self.axial is None:
            return np.asarray(deformation)
        from conrod.housing.transfer import axial_weights

        weights = axial_weights(self.axial)
        return self.field_view(deformation) @ weights / weights.sum()

    @classmethod
    def from_case(cls, case, *, cache_dir=None, use_cache: bool = True) -> Housing:
        """Build (or load from the cache) the housing of ``[housing]``; see docs/elastic.md."""
        return housing_from_case(case, cls, cache_dir=cache_dir, use_cache=use_cache)

    # ------------------------------------------------------------------ film side
    def assembled_profile(self) -> np.ndarray | None:
        """The assembled bore as the film's profile h₀(θ_j) [m] (corrected; its mean
        removed when the clearance is the assembled one), None without an assembly."""
        if self.assembly is None:
            return None
        return self.assembly.bore_profile(self.projector)

    def nodal_forces(self, pressure: np.ndarray, z: np.ndarray,
                     theta: np.ndarray | None = None) -> np.ndarray:
        """Film nodal forces f_j [N] from p(θ, z) (n_θ, n_z + 1) [Pa] on z [m]; θ [rad] of
        the rows when they are not the housing's film nodes."""
        if theta is not None and len(theta) == len(self.angles) and np.allclose(theta,
                                                                                 self.angles):
            theta = None
        if self.axial is None:
            return nodal_forces(pressure, z, self.angles, self.radius, theta)
        if theta is not None:  # rows at other angles: p interpolated periodic-linearly in θ
            pressure = interpolation_matrix(np.asarray(theta), self.angles) @ pressure
        if len(z) != len(self.axial) or not np.allclose(z, self.axial):
            from conrod.errors import CaseError

            raise CaseError(f"housing: the pressure has {len(z)} axial nodes, the 3-D "
                            f"compliance {len(self.axial)} (allowed: the film grid's n_z + 1)")
        return node_forces(pressure, z, self.angles, self.radius)

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

    def film_field(self, deformation: np.ndarray, n_axial_nodes: int | None = None
                   ) -> np.ndarray:
        """The (n_θ, n_z + 1) additive film-thickness field of
        :class:`conrod.film.base.FilmState` [m] from u at the bore nodes [m]: δ(θ_j)
        repeated over ``n_axial_nodes`` for a plane housing (it deforms alike at every z),
        u(θ_j, z_k) itself over the width."""
        if self.axial is None:
            assert n_axial_nodes is not None, "a plane housing needs the film's axial nodes"
            rows = np.asarray(deformation)
            field = np.empty((rows.shape[0], n_axial_nodes))  # np.repeat's copy, 2 µs sooner
            field[...] = rows[:, None]
            return field
        return self.field_view(deformation)

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
