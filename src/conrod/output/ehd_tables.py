"""Tables of an elastohydrodynamic run (:class:`conrod.results.ehd.ElasticRunResults`),
registered in :func:`conrod.output.registry.tables`.

``cycle.csv`` and ``summary.json`` hold the elastic answer (the run columns plus the coupling
diagnostics); ``cycle_rigid.csv`` the rigid companion run; ``summary.json["comparison"]``
the rigid-vs-elastic comparison of :func:`conrod.results.ehd.comparison`.
"""

from __future__ import annotations

import numpy as np

from conrod.output.registry import TableSpec, result_kind, tables
from conrod.output.signoff_tables import signoff_tables
from conrod.output.tables import case_tables, contact_tables, cycle_table, summary_items
from conrod.output.thermal_tables import thermal_outputs
from conrod.results.ehd import ElasticRunResults, comparison


def elastic_cycle_table(results: ElasticRunResults) -> dict[str, np.ndarray]:
    """cycle.csv: the run columns of the elastic answer and the coupling diagnostics."""
    return {**cycle_table(results.elastic), **results.columns}


def elastic_summary_items(results: ElasticRunResults) -> dict:
    """summary.json: the elastic summary, the coupling totals and the comparison."""
    items = summary_items(results.elastic)
    columns = results.columns
    items["elastic"] = {
        **(results.info or {}),
        "mean_coupling_iterations": float(np.mean(columns["coupling_iterations"])),
        **({"mean_newton_updates": float(np.mean(columns["newton_updates"]))}
           if "newton_updates" in columns else {}),
        "max_force_residual_N": float(np.max(columns["force_residual_N"])),
        "max_coupling_residual_m": float(np.max(columns["coupling_residual_m"])),
        "bore_displacement_min_m": float(np.min(columns["bore_displacement_min_m"])),
        "bore_displacement_max_m": float(np.max(columns["bore_displacement_max_m"])),
    }
    if results.rigid is not None:
        items["comparison"] = comparison(results.elastic, results.rigid)
        items["comparison"]["firing_stroke"] = results.firing_comparison()
    if results.bore_displacement is not None:  # beside the comparison, or the elastic totals
        items["comparison" if results.rigid is not None else "elastic"][
            "bore_displacement_at_elastic_h_min"] = dict(results.bore_displacement)
    return items


def film_pressure_table(results: ElasticRunResults) -> dict[str, np.ndarray]:
    """``film_pressure.npz``: the elastic film pressure p(θ, z) [Pa] at the crank angles
    [deg] the rod stresses use (largest load, ``[housing] stress_angles``), on the film grid
    θ [rad], z [m]."""
    angles = sorted(results.pressure_fields or {})
    theta, z = results.elastic.pressure_grid
    return {"crank_angle_deg": np.asarray(angles, dtype=float),
            "theta_rad": np.asarray(theta, dtype=float), "z_m": np.asarray(z, dtype=float),
            "pressure_Pa": np.asarray([results.pressure_fields[a] for a in angles],
                                      dtype=float)}


@tables.register
def _elastic_tables(results: ElasticRunResults) -> tuple[TableSpec, ...]:
    own: tuple[TableSpec, ...] = (
        TableSpec("cycle.csv", "Bearing characteristics over the cycle (elastic big end)",
                  "Orbit, film characteristics and loads on the deforming bore at each output "
                  "crank angle, with the coupling iterations [-], force-balance residual [N], "
                  "last deformation increment [m] and bore displacement range [m].",
                  lambda: elastic_cycle_table(results)),
        TableSpec("summary.json", "Cycle summary (elastic big end)",
                  "Elastic answer: extremes, means and diagnostics; 'elastic': coupling "
                  "totals; 'comparison': rigid vs elastic h_min [µm], p_max [MPa], friction "
                  "power [W], side flow [l/min], cycle means, difference [%], the same over "
                  "the firing stroke and the bore displacement at the elastic h_min [m].",
                  lambda: elastic_summary_items(results)),
    )
    if results.rigid is not None:
        own += (TableSpec("cycle_rigid.csv", "Bearing characteristics over the cycle (rigid)",
                          "The same case with a rigid bore (columns as cycle.csv).",
                          lambda: cycle_table(results.rigid)),)
    if results.pressure_fields and results.elastic.pressure_grid is not None:
        own += (TableSpec("film_pressure.npz", "Elastic film pressure for the rod stresses",
                          "Film pressure [Pa] on the deformed bore over θ [rad] and z [m] at "
                          "the crank angles [deg] of the largest load and of [housing] "
                          "stress_angles (read by conrod stress RUN_FOLDER).",
                          lambda: film_pressure_table(results)),)
    return (own + contact_tables(results.elastic) + signoff_tables(results.elastic)
            + case_tables(results.elastic) + thermal_outputs(results.elastic, tables))


@result_kind.register
def _elastic_kind(results: ElasticRunResults) -> str:
    return "run"
