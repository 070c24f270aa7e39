"""``conrod housing CASE.toml --out DIR``: compliance, inertia base fields and figures of the
elastic big-end housing.

Writes, as one result set with ``manifest.json`` (:func:`conrod.output.registry.write_results`,
after every input check passed), the tables and figures registered for
:class:`conrod.results.housing.HousingResults`: ``compliance.npz`` (the import format of
``[housing] compliance_file``), ``inertia.npz`` (``inertia_file`` format),
``housing_summary.json`` and the figures ``housing_mesh.png`` (finite-element models),
``bore_deformation.png`` and ``inertia_deformation.png`` (with ``[engine]``); with
``[housing.assembly]`` ``assembled_bore.csv``, ``joint_pressure.csv`` and
``assembled_bore.png``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from conrod.cli.app import exits_cleanly, printing_after_results
from conrod.errors import CaseError
from conrod.io.interrupts import interrupts_stop_at_once


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
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            import numpy as np

            from conrod.cases.case import Case
            from conrod.housing.housing import Housing
            from conrod.output.registry import write_results
            from conrod.simulation.assembly_study import as_built_lines
            from conrod.simulation.housing_study import MICRO_PER_KILO, housing_study

            case = Case.from_toml(case_file)
        case.require("housing", "bearing")
        if case.housing.model == "rigid":
            raise CaseError("housing.model = 'rigid': nothing to compute (allowed: builtin, "
                            "mesh or compliance)")
        housing = Housing.from_case(case, use_cache=cache)
        study = housing_study(housing, case)
        write_results(study, out)
        diagonal = np.diag(housing.corrected_compliance) * MICRO_PER_KILO
        with printing_after_results(out):
            typer.echo(f"{case.housing.model} housing, {len(housing.angles)} film nodes, "
                       f"corrected compliance diagonal {diagonal.min():.2f}.."
                       f"{diagonal.max():.2f} um/kN ({housing.info.get('seconds', 0.0):.2f} s) "
                       f"-> {out}")
            for line in as_built_lines(study.summary):
                typer.echo(line)
