"""The assembled big end in the housing study: its bore profile and its joint over the cycle
(:class:`conrod.results.housing.AssembledBoreReport`).

Over the cycle the bonded joint carries its assembled normal stress plus that of the running
loads at each crank angle of the load cycle: the film load, the bearing load of the load
diagram spread over the bore as a cosine over ±90° about its direction (the quasi-static film
resultant, :func:`conrod.housing.stresses.cosine_forces`), and the rod's own inertia (the
inertia base fields). Where their sum is tension, a real joint opens.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.housing.stresses import cosine_forces
from conrod.results.housing import AssembledBoreReport

LOAD_SOURCE = ("bearing load of the load diagram as a cosine over ±90° (the quasi-static film "
               "resultant) and the rod's own inertia, at every crank angle of the load cycle")


def assembly_report(housing: Any, case: Any) -> AssembledBoreReport | None:
    """The assembled bore of ``housing`` (None without ``[housing.assembly]``) and, on the
    built-in rod with a load cycle, its joint over the cycle (module docstring)."""
    assembled = housing.assembly
    if assembled is None:
        return None
    report = {"angles": housing.angles, "raw": assembled.displacement,
              "profile": housing.assembled_profile(),
              "crush_pressure": assembled.crush_pressure,
              "bolt_preload": assembled.bolt_preload,
              "clearance_reference": assembled.clearance_reference}
    joint = assembled.joint
    if joint is not None:
        report.update(joint_distance=joint["distance_m"], joint_side=joint["side"],
                      joint_stress=joint["stress_Pa"], joint_force=assembled.joint_force())
        if case.engine is not None or case.load is not None:
            report.update(_over_cycle(housing, case))
    return AssembledBoreReport(**report)


def _over_cycle(housing: Any, case: Any) -> dict[str, Any]:
    loads = _load_cycle(case)
    forces = np.array([cosine_forces(housing.angles, np.array([x, y]))
                       for x, y in zip(loads.load_x, loads.load_y, strict=True)])
    coefficients = None
    if housing.kinematics is not None:
        coefficients = np.array([housing.inertia_coefficients(phi)
                                 for phi in loads.crank_angle])
    stress = housing.assembly.joint_stress(forces, coefficients)
    worst = np.argmax(stress, axis=0)
    return {"cycle_max_stress": stress.max(axis=0),
            "cycle_worst_angle": np.asarray(loads.crank_angle)[worst],
            "load_source": LOAD_SOURCE if coefficients is not None else LOAD_SOURCE.replace(
                " and the rod's own inertia", "")}


def _load_cycle(case: Any):
    """The case's load cycle (a ``[load]`` table, else the engine's loads), as a run reads
    it."""
    if case.load is not None:
        from conrod.loads.table_load import load_cycle_from_table

        return load_cycle_from_table(case.load, case.resolve(case.load.table))
    from conrod.loads.engine_loads import compute_engine_loads

    return compute_engine_loads(case).to_load_cycle()


def assembly_summary(report: AssembledBoreReport | None) -> dict[str, Any] | None:
    """The ``assembly`` entry of ``housing_summary.json`` (units in the key names)."""
    if report is None:
        return None
    summary: dict[str, Any] = {
        "bolt_preload_N": report.bolt_preload,
        "crush_pressure_Pa": report.crush_pressure,
        "clearance_reference": report.clearance_reference,
        "joint_model": "bonded (opening is reported where the bonded joint carries tension)",
        "raw_bore_displacement_range_um": [float(report.raw.min() * 1e6),
                                           float(report.raw.max() * 1e6)],
        "film_profile_range_um": [float(report.profile.min() * 1e6),
                                  float(report.profile.max() * 1e6)],
        "out_of_roundness_um": report.out_of_roundness * 1e6}
    if report.joint_stress is not None:
        pressure = -report.joint_stress
        summary["joint"] = {
            "normal_force_N": report.joint_force.tolist(),
            "pressure_mean_Pa": [float(pressure[report.joint_side == s].mean())
                                 for s in (1.0, -1.0)],
            "pressure_min_Pa": [float(pressure[report.joint_side == s].min())
                                for s in (1.0, -1.0)]}
    if report.cycle_max_stress is not None:
        worst = int(np.argmax(report.cycle_max_stress))
        summary["joint"]["over_cycle"] = {
            "opens": report.joint_opens,
            "open_share_of_joint": float(np.mean(report.cycle_max_stress > 0.0)),
            "smallest_pressure_Pa": float(-report.cycle_max_stress[worst]),
            "at_crank_angle_deg": float(np.degrees(report.cycle_worst_angle[worst])),
            "at_side": "+y" if report.joint_side[worst] > 0 else "-y",
            "at_distance_from_bore_centre_m": float(report.joint_distance[worst]),
            "running_loads": report.load_source}
    return summary


def warm_summary(housing: Any) -> dict[str, Any] | None:
    """The ``thermal`` entry of ``housing_summary.json``: temperatures, the bore's thermal
    growth and distortion, the clearance change (None without ``[housing.thermal]``)."""
    warm = housing.warm
    if warm is None:
        return None
    section = warm.section
    bore = np.atleast_1d(warm.bore_displacement(housing.projector))
    strain = section.housing_expansion * (warm.housing_temperature
                                          - section.reference_temperature)
    return {"journal_temperature_degC": section.journal_temperature,
            "housing_mean_temperature_degC": warm.housing_temperature,
            "shell_temperature_degC": warm.shell_temperature,
            "reference_temperature_degC": section.reference_temperature,
            "housing_temperature_field": ("conduction from the shell-side temperatures"
                                          if section.conducting else "uniform"),
            "bore_growth_mean_um": float(bore.mean() * 1e6),
            "bore_growth_free_ring_at_mean_um": strain * warm.bore_radius * 1e6,
            "bore_thermal_out_of_round_um": float(np.ptp(bore) * 1e6),
            "shell_thickness_growth_um": warm.shell_strain * warm.shell_thickness * 1e6,
            "journal_radius_growth_um": section.journal_strain * warm.journal_radius * 1e6,
            "clearance_change_um": warm.clearance_change(housing.projector) * 1e6}


def as_built_lines(summary: dict[str, Any]) -> list[str]:
    """Terminal lines of ``conrod housing`` on the assembled and warm bore (from
    ``housing_summary.json``: the numbers the files hold)."""
    lines = []
    assembly = summary.get("assembly")
    if assembly is not None:
        lines.append(f"assembled bore: {assembly['out_of_roundness_um']:.2f} um out of round "
                     f"(preload {assembly['bolt_preload_N'] / 1e3:.1f} kN per bolt, crush "
                     f"pressure {assembly['crush_pressure_Pa'] / 1e6:.2f} MPa)")
        cycle = assembly.get("joint", {}).get("over_cycle")
        if cycle is not None:
            verdict = (f"opens at {cycle['at_crank_angle_deg']:.0f} deg over "
                       f"{cycle['open_share_of_joint']:.0%} of the joint" if cycle["opens"]
                       else "stays closed over the cycle")
            lines.append(f"bonded joint {verdict} (load diagram as a cosine + inertia)")
    thermal = summary.get("thermal")
    if thermal is not None:
        lines.append(f"warm clearance change {thermal['clearance_change_um']:+.2f} um "
                     f"(journal {thermal['journal_temperature_degC']:g} degC, housing "
                     f"{thermal['housing_mean_temperature_degC']:.1f} degC), thermal "
                     f"out-of-round {thermal['bore_thermal_out_of_round_um']:.2f} um")
    return lines
