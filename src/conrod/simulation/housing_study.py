"""The housing study (``conrod housing``): compliance and inertia summaries of the elastic
big end, and its bore under test loads and under the rod's own inertia
(:class:`conrod.results.housing.HousingResults`)."""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.cases.case import Case
from conrod.housing.inertia import BASE_FIELD_NAMES, BASE_FIELD_UNITS, rigid_rod_load_difference
from conrod.housing.stresses import cosine_forces
from conrod.results.housing import BoreDeformation, HousingResults

MICRO_PER_KILO = 1.0e9
"""m/N → µm/kN."""

TEST_LOAD = 1.0e4
"""Cosine test load on the bore [N]."""

TEST_DIRECTIONS_DEG = (0.0, 90.0, 180.0, 270.0)
"""Directions θ_W of the test loads [deg]."""


def housing_study(housing: Any, case: Case) -> HousingResults:
    """Summary, bore under the test loads and under the rod's inertia of ``housing``."""
    if not housing.uniform_in_z:  # test loads and figures are per film row
        from conrod.errors import CaseError

        raise CaseError(f"housing.compliance_file: a 3-D compliance ({housing.node_count} "
                        "film nodes over the width) is not summarised by conrod housing "
                        "(allowed: a plane housing); conrod run draws its u(θ, z)")
    from conrod.simulation.assembly_study import (
        assembly_report,
        assembly_summary,
        warm_summary,
    )
    from conrod.simulation.recording import record_case

    summary, assembly = housing_summary(housing, case), assembly_report(housing, case)
    if assembly is not None:
        summary["assembly"] = assembly_summary(assembly)
    if housing.warm is not None:
        summary["thermal"] = warm_summary(housing)
    return HousingResults(housing, summary, TEST_LOAD, _test_loads(housing),
                          _inertia_cases(housing), record_case(case, case.solver), assembly)


def _test_loads(housing: Any) -> tuple[BoreDeformation, ...]:
    cases = []
    for direction in TEST_DIRECTIONS_DEG:
        theta = np.radians(direction)
        forces = cosine_forces(housing.angles,
                               TEST_LOAD * np.array([np.cos(theta), np.sin(theta)]))
        raw = housing.pressure_deformation(forces, corrected=False)
        cases.append(BoreDeformation(f"load towards θ = {direction:.0f}°", raw,
                                     housing.correct(raw), theta))
    return tuple(cases)


def _inertia_cases(housing: Any) -> tuple[BoreDeformation, ...]:
    if housing.kinematics is None:
        return ()
    return tuple(BoreDeformation(f"φ = {crank:.0f}°",
                                 housing.inertia_deformation(np.radians(crank), corrected=False),
                                 housing.inertia_deformation(np.radians(crank)))
                 for crank in (0.0, 180.0))


def _inertia_summary(housing: Any) -> dict[str, Any]:
    summary: dict[str, Any] = {
        "base_field_max_abs": {f"{name} [{unit}]": float(np.abs(housing.inertia_base[:, k]).max())
                               for k, (name, unit) in enumerate(zip(BASE_FIELD_NAMES,
                                                                    BASE_FIELD_UNITS,
                                                                    strict=True))}}
    if housing.kinematics is not None:
        for label, phi in (("tdc", 0.0), ("bdc", np.pi)):
            summary[f"{label}_max_abs_raw_um"] = float(
                np.abs(housing.inertia_deformation(phi, corrected=False)).max() * 1e6)
            summary[f"{label}_max_abs_corrected_um"] = float(
                np.abs(housing.inertia_deformation(phi)).max() * 1e6)
    return summary


def housing_summary(housing: Any, case: Case) -> dict[str, Any]:
    """Everything written to ``housing_summary.json`` (units in the key names)."""
    raw, corrected = np.diag(housing.compliance), np.diag(housing.corrected_compliance)
    summary: dict[str, Any] = {
        "model": case.housing.model, "correction": housing.correction,
        "film_nodes": len(housing.angles),
        "build": {key: value for key, value in housing.info.items() if key != "model"},
        "compliance_diagonal_um_per_kN": {
            "raw_min": float(raw.min() * MICRO_PER_KILO),
            "raw_max": float(raw.max() * MICRO_PER_KILO),
            "corrected_min": float(corrected.min() * MICRO_PER_KILO),
            "corrected_max": float(corrected.max() * MICRO_PER_KILO)},
        "inertia": _inertia_summary(housing),
    }
    if case.housing.model in ("builtin", "mesh"):
        summary["fe_rod_mass_properties"] = housing.structure.model.mass_properties()
        if case.engine is not None:
            summary["fe_rod_mass_properties"]["case_rod_mass_kg"] = case.engine.rod_mass
            summary["bearing_load_distributed_vs_two_mass"] = rigid_rod_load_difference(
                case, summary["fe_rod_mass_properties"])
    return summary
