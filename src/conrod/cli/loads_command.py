"""``conrod loads CASE.toml --out DIR [--step DEG]``: engine loads, polar and wear diagrams.

Writes (atomically, only after every input check passed):
``loads.csv``, ``loads_summary.json``, ``polar_load_diagram.png``,
``load_vs_crank_angle.png``, ``wear_diagram.png`` and ``manifest.json``.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from conrod.cli.app import exits_cleanly, printing_after_results
from conrod.io.interrupts import interrupts_stop_at_once

if TYPE_CHECKING:  # pragma: no cover
    from conrod.cases.case import Case


def register(app: typer.Typer) -> None:
    """Add the ``loads`` command to ``app``."""

    @app.command("loads")
    @exits_cleanly
    def loads_command(
        case_file: Annotated[
            Path, typer.Argument(help="Case file (TOML) with [engine] and [bearing], or [load]")
        ],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        step: Annotated[
            float, typer.Option("--step", help="Crank-angle step [deg]; divides 720")
        ] = 1.0,
    ) -> None:
        """Engine loads on the big-end bearing: table, summary, polar and wear diagrams."""
        from conrod.io.result_folder import check_output_folder

        check_output_folder(out, inputs=(case_file,))
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            from conrod.cases.case import Case
            from conrod.loads.engine_loads import check_step, compute_engine_loads

            check_step(step, "--step")
            case = Case.from_toml(case_file)
        if case.load is not None:  # the table is the bearing load, as in `conrod run`
            _table_loads(case, out)
            return
        case.require("loads", "engine", "bearing")
        loads = compute_engine_loads(case, step_deg=step)
        _write(loads, out)
        summary = loads.summary()
        with printing_after_results(out):
            typer.echo(f"peak load {summary['peak_load_N'] / 1e3:.2f} kN at "
                       f"{summary['peak_load_crank_angle_deg']:.1f} deg, "
                       f"mean {summary['mean_load_N'] / 1e3:.2f} kN, "
                       f"oil hole at {summary['oil_hole_angle_deg']:.1f} deg -> {out}")


def _write(loads, out: Path) -> None:
    from conrod.output.registry import write_results

    write_results(loads, out)


def _table_loads(case: Case, out: Path) -> None:
    """A bearing given by its load table: the table's load in the bearing frame."""
    from conrod.loads.table_load import load_cycle_from_table
    from conrod.output.tables import table_load_summary

    loads = load_cycle_from_table(case.load, case.resolve(case.load.table))
    _write(loads, out)
    summary = table_load_summary(loads)
    with printing_after_results(out):
        typer.echo(f"peak load {summary['peak_load_N'] / 1e3:.2f} kN at "
                   f"{summary['peak_load_crank_angle_deg']:.1f} deg, mean "
                   f"{summary['mean_load_N'] / 1e3:.2f} kN (load table, bearing frame) -> {out}")
