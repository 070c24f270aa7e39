"""``conrod housing CASE.toml --out DIR``: compliance, inertia base fields and figures of the
elastic big-end housing.

Writes (atomically, after every input check passed): ``compliance.npz`` (the import format
of ``[housing] compliance_file``), ``inertia.npz`` (``inertia_file`` format),
``housing_summary.json`` and the figures ``housing_mesh.png`` (finite-element models),
``bore_deformation.png`` and ``inertia_deformation.png`` (with ``[engine]``).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from conrod.cases.case import Case
from conrod.cli.app import exits_cleanly
from conrod.errors import CaseError

MICRO_PER_KILO = 1.0e9
"""m/N → µm/kN."""


def _inertia_summary(housing) -> dict[str, Any]:
    from conrod.housing.inertia import BASE_FIELD_NAMES, BASE_FIELD_UNITS

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


def housing_summary(housing, case: Case) -> dict[str, Any]:
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
            from conrod.housing.inertia import rigid_rod_load_difference

            summary["fe_rod_mass_properties"]["case_rod_mass_kg"] = case.engine.rod_mass
            summary["bearing_load_distributed_vs_two_mass"] = rigid_rod_load_difference(
                case, summary["fe_rod_mass_properties"])
    return summary


def write_housing_outputs(housing, case: Case, out: Path) -> list[Path]:
    """Build the figures first, then write every file atomically."""
    from conrod.housing.compliance_io import write_compliance
    from conrod.io.atomic import atomic_path, write_json
    from conrod.io.result_folder import staged_result_folder
    from conrod.plotting import housing_plots
    from conrod.plotting.save import save_figure

    summary = housing_summary(housing, case)
    figures = {"bore_deformation.png": housing_plots.bore_deformation_figure(housing)}
    if case.housing.model in ("builtin", "mesh"):
        figures["housing_mesh.png"] = housing_plots.housing_mesh_figure(housing.structure)
    if housing.kinematics is not None:
        figures["inertia_deformation.png"] = housing_plots.inertia_deformation_figure(housing)
    with staged_result_folder(out) as stage:  # the whole set swapped in at once
        write_compliance(stage / "compliance.npz", housing.angles, housing.compliance)
        with atomic_path(stage / "inertia.npz") as tmp:
            np.savez(tmp, angle_deg=np.degrees(housing.angles),
                     inertia_base_m=housing.inertia_base)
        write_json(stage / "housing_summary.json", summary)
        for name, figure in figures.items():
            save_figure(figure, stage / name)
    names = ["compliance.npz", "inertia.npz", "housing_summary.json", *figures]
    return [Path(out) / name for name in names]


def register(app: typer.Typer) -> None:
    """Add the ``housing`` command to ``app``."""

    @app.command("housing")
    @exits_cleanly
    def housing_command(
        case_file: Annotated[Path, typer.Argument(help="Case file (TOML) with [bearing] and "
                                                  "[housing]")],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        cache: Annotated[bool, typer.Option(help="Read/write the compliance cache.")] = True,
    ) -> None:
        """Compliance matrix, inertia base fields and figures of the elastic big end."""
        from conrod.io.result_folder import check_output_folder

        check_output_folder(out, inputs=(case_file,))  # before any computation
        from conrod.housing.housing import Housing

        case = Case.from_toml(case_file)
        case.require("housing", "bearing")
        if case.housing.model == "rigid":
            raise CaseError("housing.model = 'rigid': nothing to compute (allowed: builtin, "
                            "mesh or compliance)")
        housing = Housing.from_case(case, use_cache=cache)
        write_housing_outputs(housing, case, out)
        diagonal = np.diag(housing.corrected_compliance) * MICRO_PER_KILO
        typer.echo(f"{case.housing.model} housing, {len(housing.angles)} film nodes, "
                   f"corrected compliance diagonal {diagonal.min():.2f}..{diagonal.max():.2f} "
                   f"um/kN ({housing.info.get('seconds', 0.0):.2f} s) -> {out}")
