"""Results of the housing study (``conrod housing``) and of the rod-stress study
(``conrod stress``): what the structure of the elastic big end does under test loads, its
own inertia and a run's film pressure. Their tables and figures are registered in
:mod:`conrod.output.housing_tables`."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np


@dataclass(frozen=True)
class BoreDeformation:
    """Radial bore displacement at the film nodes under one load, outward + [m].

    label : str  What loads the bore, in words (e.g. "load towards θ = 90°").
    raw : ndarray  As the clamped model gives it [m].
    corrected : ndarray  With the rigid-body translation removed [m].
    direction : float or None  Direction θ_W of a test load [rad]; None for another load.
    """

    label: str
    raw: np.ndarray
    corrected: np.ndarray
    direction: float | None = None


@dataclass(frozen=True)
class HousingResults:
    """The elastic big end as a structure.

    housing : Housing  Angles θ [rad], radius [m], compliance [m/N], inertia base fields
        [m], correction and (finite-element models) the structure with its mesh.
    summary : dict  ``housing_summary.json`` (units in the key names).
    test_load : float  Size of the cosine test loads of ``bore`` [N].
    bore : tuple of BoreDeformation  Bore under the test load in four directions.
    inertia : tuple of BoreDeformation  Bore under the rod's own inertia at TDC and BDC
        (empty without ``[engine]``).
    case_record : CaseRecord or None  The case (:mod:`conrod.results.case_record`).
    assembly : AssembledBoreReport or None  The assembled bore and joint
        (``[housing.assembly]``).
    """

    housing: Any
    summary: dict
    test_load: float
    bore: tuple[BoreDeformation, ...]
    inertia: tuple[BoreDeformation, ...] = ()
    case_record: Any = None
    assembly: Any = None

    @property
    def has_mesh(self) -> bool:
        """True for a finite-element housing (built-in rod or imported mesh) [-]."""
        return getattr(self.housing, "structure", None) is not None


@dataclass(frozen=True)
class StressResults:
    """Von Mises stresses of the rod under two load schemes at chosen crank angles.

    structure : object  The finite-element rod (mesh and regions).
    schemes : dict  Crank angle [deg] → :func:`conrod.housing.stresses.compare_schemes`
        (``pressure`` and ``cosine`` StressFields, resultant [N], ratios [-]).
    pressure_source : str  Which film pressure loads the rod, in words.
    run : dict  The run that pressure comes from: film model, bore, grid, its h_min [m],
        p_max [Pa] and warnings.
    case_record : CaseRecord or None  The case (:mod:`conrod.results.case_record`).
    """

    structure: Any
    schemes: dict[float, dict]
    pressure_source: str
    run: dict = field(default_factory=dict)
    case_record: Any = None


@dataclass(frozen=True)
class AssembledBoreReport:
    """The big end as assembled (bolt preload, shell crush) and its joint over the cycle.

    angles : ndarray  Film-node angles θ_j [rad].
    raw : ndarray  Assembled radial bore displacement, clamped model, outward + [m].
    profile : ndarray  What the film sees: the bore profile h₀(θ_j) [m] (corrected; mean
        removed for an assembled clearance).
    crush_pressure : float  Contact pressure of the crushed shell [Pa].
    bolt_preload : float  Preload per bolt [N].
    clearance_reference : str  ``assembled`` or ``nominal`` [-].
    joint_distance : ndarray  Joint sample points: distance from the bore centre [m].
    joint_side : ndarray  +1 (towards +y_rod) or −1 [-].
    joint_stress : ndarray  σ_nn across the joint as assembled, negative pressing [Pa].
    joint_force : ndarray  Normal force across each side (+, −) as assembled [N].
    cycle_max_stress : ndarray or None  Largest σ_nn over the cycle at each point [Pa].
    cycle_worst_angle : ndarray or None  Crank angle of that largest σ_nn [rad].
    load_source : str  Which running loads the cycle check used, in words.
    """

    angles: np.ndarray
    raw: np.ndarray
    profile: np.ndarray
    crush_pressure: float
    bolt_preload: float
    clearance_reference: str
    joint_distance: np.ndarray | None = None
    joint_side: np.ndarray | None = None
    joint_stress: np.ndarray | None = None
    joint_force: np.ndarray | None = None
    cycle_max_stress: np.ndarray | None = None
    cycle_worst_angle: np.ndarray | None = None
    load_source: str = ""

    @property
    def out_of_roundness(self) -> float:
        """Largest minus smallest h₀ of the film's bore profile [m]."""
        return float(np.ptp(self.profile))

    @property
    def joint_opens(self) -> bool | None:
        """True when the bonded joint carries tension somewhere over the cycle (a real joint
        opens there); None without a cycle [-]."""
        if self.cycle_max_stress is None:
            return None
        return bool(np.any(self.cycle_max_stress > 0.0))
