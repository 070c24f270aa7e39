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
    """

    housing: Any
    summary: dict
    test_load: float
    bore: tuple[BoreDeformation, ...]
    inertia: tuple[BoreDeformation, ...] = ()
    case_record: Any = None

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
