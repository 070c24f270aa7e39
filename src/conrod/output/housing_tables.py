"""Tables and figures of the housing study and the rod-stress study
(:mod:`conrod.results.housing`), registered in :mod:`conrod.output.registry`."""

from __future__ import annotations

import importlib
from typing import Any

import numpy as np

from conrod.output.registry import FigureSpec, TableSpec, figures, result_kind, tables
from conrod.output.tables import case_tables
from conrod.results.housing import HousingResults, StressResults

SCHEMES = ("pressure", "cosine")
"""Load schemes of the stress study: the film pressure, and its resultant as a cosine."""


def _plots() -> Any:
    return importlib.import_module("conrod.plotting.housing_plots")


@tables.register
def _housing_tables(results: HousingResults) -> tuple[TableSpec, ...]:
    housing = results.housing
    return (
        TableSpec("compliance.npz", "Bore compliance",
                  "Compliance matrix of the bore at the film nodes [m/N] against the node "
                  "angles [deg] (the import format of [housing] compliance_file).",
                  lambda: {"angle_deg": np.degrees(housing.angles),
                           "compliance_m_per_N": housing.compliance}),
        TableSpec("inertia.npz", "Inertia base fields",
                  "Bore displacement per unit rod acceleration [m per base-field unit] against "
                  "the node angles [deg] (the import format of [housing] inertia_file).",
                  lambda: {"angle_deg": np.degrees(housing.angles),
                           "inertia_base_m": housing.inertia_base}),
        TableSpec("housing_summary.json", "Housing summary",
                  "Compliance diagonal range [µm/kN], inertia fields [µm], finite-element "
                  "mass properties [kg, m] and the build information.",
                  lambda: results.summary),
    ) + _assembly_tables(results.assembly) + case_tables(results)


def _assembly_tables(report) -> tuple[TableSpec, ...]:
    if report is None:
        return ()
    own = (TableSpec("assembled_bore.csv", "Assembled bore",
                     "Bore as assembled (bolt preload, shell crush) against the shell angle "
                     "[deg]: raw radial displacement of the clamped model and the bore profile "
                     "the film sees [m] (outward + = more clearance).",
                     lambda: {"angle_deg": np.degrees(report.angles),
                              "raw_displacement_m": report.raw,
                              "film_profile_m": report.profile}),)
    if report.joint_stress is not None:
        def joint() -> dict[str, np.ndarray]:
            columns = {"side": report.joint_side,
                       "distance_from_bore_centre_m": report.joint_distance,
                       "assembled_pressure_Pa": -report.joint_stress}
            if report.cycle_max_stress is not None:
                columns["cycle_min_pressure_Pa"] = -report.cycle_max_stress
                columns["cycle_min_at_crank_angle_deg"] = np.degrees(report.cycle_worst_angle)
            return columns

        own += (TableSpec("joint_pressure.csv", "Joint pressure",
                          "Normal pressure across the bonded rod/cap joint [Pa] along each side "
                          "(+1 towards +y_rod) against the distance from the bore centre [m]: "
                          "as assembled and its smallest over the cycle with the crank angle "
                          "[deg] (negative: the joint opens there).", joint),)
    return own


@figures.register
def _housing_figures(results: HousingResults) -> tuple[FigureSpec, ...]:
    own = (FigureSpec("bore_deformation.png", "Bore under test loads",
                      f"Magnified bore under a {results.test_load / 1e3:.0f} kN cosine load "
                      "(±90°) in four directions θ_W [deg]: raw (clamped model) and rigid-body "
                      "corrected radial displacement [µm].",
                      lambda: _plots().bore_deformation_figure(results)),)
    if results.has_mesh:
        own = (FigureSpec("housing_mesh.png", "Finite-element rod",
                          "Mesh of the rod [m] by region, with the bore nodes.",
                          lambda: _plots().housing_mesh_figure(results.housing.structure)),
               *own)
    if results.assembly is not None:
        own += (FigureSpec("assembled_bore.png", "Assembled bore",
                           "Magnified bore as assembled (bolt preload, shell crush): raw and "
                           "as the film sees it [µm]; pressure across the joint [MPa] as "
                           "assembled and its smallest over the cycle.",
                           lambda: _plots().assembled_bore_figure(results)),)
    warm = getattr(results.housing, "warm", None)
    if results.has_mesh and warm is not None and warm.corner_temperature is not None:
        own += (FigureSpec("housing_temperature.png", "Housing temperature",
                           "Temperature of the housing [°C] conducting from its shell-side "
                           "temperature to the crankcase, on the rod [m].",
                           lambda: _plots().housing_temperature_figure(
                               results.housing.structure, warm)),)
    if results.inertia:
        own += (FigureSpec("inertia_deformation.png", "Bore under the rod's inertia",
                           "Radial bore displacement [µm] from the rod's own inertia at TDC "
                           "and BDC against the shell angle θ [deg], raw and corrected.",
                           lambda: _plots().inertia_deformation_figure(results)),)
    return own


@result_kind.register
def _housing_kind(results: HousingResults) -> str:
    return "housing"


def _scheme_row(angle: float, scheme: str, field) -> dict[str, Any]:
    x, y = field.maximum_location
    return {"crank_angle_deg": angle, "scheme": scheme, "max_von_mises_Pa": field.maximum,
            "max_x_m": x, "max_y_m": y,
            "big_end_max_von_mises_Pa": field.maximum_in(("cap", "head")),
            "largest_displacement_m": field.largest_displacement}


def stress_maxima(results: StressResults) -> dict[str, np.ndarray]:
    """``stress_maxima.csv``: one row per crank angle and load scheme."""
    rows = [_scheme_row(angle, scheme, comparison[scheme])
            for angle, comparison in results.schemes.items() for scheme in SCHEMES]
    return {key: np.array([row[key] for row in rows]) for key in rows[0]}


def stress_summary(results: StressResults) -> dict[str, Any]:
    """``stress_summary.json``: resultant, ratios and zones per crank angle."""
    summary: dict[str, Any] = {"pressure_source": results.pressure_source,
                               "pressure_run": results.run}
    for angle, comparison in results.schemes.items():
        summary[f"{angle:g}"] = {
            "resultant_N": comparison["resultant_N"].tolist(),
            "stress_ratio_pressure_to_cosine": comparison["stress_ratio"],
            "big_end_stress_ratio_pressure_to_cosine": comparison["big_end_stress_ratio"],
            "displacement_ratio_pressure_to_cosine": comparison["displacement_ratio"],
            "zones": {scheme: comparison[scheme].zones() for scheme in SCHEMES}}
    return summary


@tables.register
def _stress_tables(results: StressResults) -> tuple[TableSpec, ...]:
    return (
        TableSpec("stress_maxima.csv", "Rod stress maxima",
                  "Largest von Mises stress [Pa] and where [m], big-end maximum [Pa] and "
                  "largest displacement [m] per crank angle [deg] and load scheme.",
                  lambda: stress_maxima(results)),
        TableSpec("stress_summary.json", "Rod stress summary",
                  "Which film pressure loads the rod (and the run it comes from); per crank "
                  "angle the load resultant [N], pressure-to-cosine ratios [-] and the stress "
                  "zones [Pa, m].",
                  lambda: stress_summary(results)),
    ) + case_tables(results)


@figures.register
def _stress_figures(results: StressResults) -> tuple[FigureSpec, ...]:
    def figure(angle: float, scheme: str) -> FigureSpec:
        field = results.schemes[angle][scheme]
        return FigureSpec(
            f"von_mises_{scheme}_{angle:g}deg.png", f"Rod stress, {scheme} load, {angle:g}°",
            f"Von Mises stress [MPa] per element of the rod [m] at φ = {angle:g} deg under "
            f"the {scheme} load scheme, maximum marked.",
            lambda: _plots().von_mises_figure(
                results.structure, field, f"von Mises, {scheme} load scheme, φ = {angle:g}°"))

    return tuple(figure(angle, scheme) for angle in results.schemes for scheme in SCHEMES)


@result_kind.register
def _stress_kind(results: StressResults) -> str:
    return "stress"
