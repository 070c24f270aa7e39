"""``conrod stress CASE.toml --angles 25,360 --out DIR``: rod stresses under the film pressure
of the rigid run (scheme a) and under the same resultant as a cosine load (scheme b).

Writes, as one result set with ``manifest.json``, the tables and figures registered for
:class:`conrod.results.housing.StressResults`: ``stress_maxima.csv``, ``stress_summary.json``
and ``von_mises_<scheme>_<angle>deg.png`` for every angle.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from conrod.cli.app import exits_cleanly, printing_after_results
from conrod.errors import CaseError
from conrod.io.interrupts import interrupts_stop_at_once

if TYPE_CHECKING:  # pragma: no cover
    from conrod.cases.case import Case


def parse_angles(text: str | None, case: Case) -> list[float]:
    """Crank angles [deg] from ``--angles``, ``[housing] stress_angles`` or the defaults
    (angle of the peak bearing load and 360°)."""
    if text:
        try:
            angles = [float(item) for item in text.split(",") if item.strip()]
        except ValueError:
            raise CaseError(f"--angles = {text!r}: not a comma-separated list of numbers "
                            "(allowed: 0..720 deg, e.g. 25,360)") from None
        bad = [a for a in angles if not 0.0 <= a <= 720.0]
        if bad or not angles:
            raise CaseError(f"--angles = {text!r}: out of range (allowed: >= 0 and <= 720 deg)")
        return angles
    if case.housing.stress_angles:
        return list(case.housing.stress_angles)
    import numpy as np

    from conrod.loads.engine_loads import compute_engine_loads

    loads = compute_engine_loads(case)
    return [float(loads.crank_angle_deg[int(np.argmax(loads.load_magnitude))]), 360.0]


def register(app: typer.Typer) -> None:
    """Add the ``stress`` command to ``app``."""

    @app.command("stress")
    @exits_cleanly
    def stress_command(
        case_file: Annotated[Path, typer.Argument(help="Case file with [engine], [bearing], "
                                                  "[lubricant] and a builtin/mesh [housing]")],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        angles: Annotated[str | None, typer.Option(
            "--angles", help="Crank angles [deg], comma separated, e.g. 25,360")] = None,
    ) -> None:
        """Von Mises stresses of the rod under the film pressure and a cosine load."""
        from conrod.io.result_folder import check_output_folder

        check_output_folder(out, inputs=(case_file,))  # before any computation
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            from conrod.cases.case import Case
            from conrod.housing.housing import Housing
            from conrod.output.registry import write_results
            from conrod.simulation.stress_study import stress_study

            case = Case.from_toml(case_file)
        case.require("stress", "engine", "bearing", "lubricant")
        if case.housing.model not in ("builtin", "mesh"):
            raise CaseError(f"housing.model = {case.housing.model!r}: stresses need a finite-"
                            "element housing (allowed: builtin or mesh)")
        crank_angles = parse_angles(angles, case)
        housing = Housing.from_case(case)
        results = stress_study(case, housing, crank_angles)
        write_results(results, out)
        with printing_after_results(out):
            typer.echo(f"rod loaded by the {results.pressure_source}")
            for angle, comparison in results.schemes.items():
                typer.echo(f"{angle:g} deg: max von Mises "
                           f"{comparison['pressure'].maximum / 1e6:.0f} MPa (pressure) vs "
                           f"{comparison['cosine'].maximum / 1e6:.0f} MPa (cosine)")
            typer.echo(f"-> {out}")
