"""``conrod loads CASE.toml --out DIR [--step DEG]``: engine loads, polar and wear diagrams.

Writes (atomically, only after every input check passed):
``loads.csv``, ``loads_summary.json``, ``polar_load_diagram.png``,
``load_vs_crank_angle.png``, ``wear_diagram.png``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from conrod.cases.case import Case
from conrod.cli.app import exits_cleanly
from conrod.io.atomic import write_csv, write_json
from conrod.io.result_folder import check_output_folder, staged_result_folder
from conrod.loads.engine_loads import EngineLoads, compute_engine_loads

LOADS_CSV_COLUMNS = (
    ("crank_angle_deg", lambda r: r.crank_angle_deg),
    ("cylinder_pressure_Pa", lambda r: r.cylinder_pressure),
    ("gas_force_N", lambda r: r.gas_force),
    ("reciprocating_inertia_force_N", lambda r: r.reciprocating_inertia_force),
    ("rod_force_N", lambda r: r.rod_force),
    ("radial_force_N", lambda r: r.radial_force),
    ("tangential_force_N", lambda r: r.tangential_force),
    ("load_magnitude_N", lambda r: r.load_magnitude),
    ("load_rod_x_N", lambda r: r.load_rod_x),
    ("load_rod_y_N", lambda r: r.load_rod_y),
    ("load_crank_x_N", lambda r: r.load_crank_x),
    ("load_crank_y_N", lambda r: r.load_crank_y),
    ("load_engine_x_N", lambda r: r.load_engine_x),
    ("load_engine_y_N", lambda r: r.load_engine_y),
    ("rod_angle_deg", lambda r: np.degrees(r.rod_angle)),
    ("rod_angular_velocity_rad_s", lambda r: r.rod_angular_velocity),
    ("journal_speed_rad_s", lambda r: r.journal_speed),
    ("shell_speed_rad_s", lambda r: r.shell_speed),
)
"""Columns of ``loads.csv``: name (unit in the suffix) and how to get it from EngineLoads."""


def loads_table(loads: EngineLoads) -> dict[str, np.ndarray]:
    """The ``loads.csv`` columns as a dict name → array."""
    # "+ 0.0" turns -0.0 into 0.0 so that the table does not show "-0"
    return {name: np.asarray(get(loads), dtype=float) + 0.0 for name, get in LOADS_CSV_COLUMNS}


def write_loads_outputs(loads: EngineLoads, out: Path) -> list[Path]:
    """Build every figure first, then write all result files atomically."""
    from conrod.plotting import loads_plots
    from conrod.plotting.save import save_figure

    summary = loads.summary()
    figures = {
        "polar_load_diagram.png": loads_plots.polar_load_diagram(loads),
        "load_vs_crank_angle.png": loads_plots.load_vs_crank_angle(loads),
        "wear_diagram.png": loads_plots.wear_diagram_figure(loads),
    }
    with staged_result_folder(out, manifest=False) as stage:  # always these five files
        written = [
            write_csv(stage / "loads.csv", loads_table(loads)),
            write_json(stage / "loads_summary.json", summary),
        ]
        written += [save_figure(figure, stage / name) for name, figure in figures.items()]
    return [out / path.name for path in written]


def register(app: typer.Typer) -> None:
    """Add the ``loads`` command to ``app``."""

    @app.command("loads")
    @exits_cleanly
    def loads_command(
        case_file: Annotated[
            Path, typer.Argument(help="Case file (TOML) with [engine] and [bearing]")
        ],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        step: Annotated[
            float, typer.Option("--step", help="Crank-angle step [deg]; divides 720")
        ] = 1.0,
    ) -> None:
        """Engine loads on the big-end bearing: table, summary, polar and wear diagrams."""
        check_output_folder(out)
        case = Case.from_toml(case_file)
        case.require("loads", "engine", "bearing")
        loads = compute_engine_loads(case, step_deg=step)
        write_loads_outputs(loads, out)
        summary = loads.summary()
        typer.echo(
            f"peak load {summary['peak_load_N'] / 1e3:.2f} kN at "
            f"{summary['peak_load_crank_angle_deg']:.1f} deg, "
            f"mean {summary['mean_load_N'] / 1e3:.2f} kN, "
            f"oil hole at {summary['oil_hole_angle_deg']:.1f} deg -> {out}"
        )
