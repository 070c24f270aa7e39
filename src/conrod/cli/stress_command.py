"""``conrod stress CASE.toml --angles 25,360 --out DIR``: rod stresses under the film pressure
of the rigid run (scheme a) and under the same resultant as a cosine load (scheme b).

Writes (atomically): ``stress_maxima.csv``, ``stress_summary.json`` and
``von_mises_<scheme>_<angle>deg.png`` for every angle.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

import numpy as np
import typer

from conrod.cases.case import Case
from conrod.cli.app import exits_cleanly
from conrod.errors import CaseError

SCHEMES = ("pressure", "cosine")


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
    from conrod.loads.engine_loads import compute_engine_loads

    loads = compute_engine_loads(case)
    return [float(loads.crank_angle_deg[int(np.argmax(loads.load_magnitude))]), 360.0]


def _scheme_row(angle: float, scheme: str, field) -> dict[str, Any]:
    x, y = field.maximum_location
    return {"crank_angle_deg": angle, "scheme": scheme, "max_von_mises_Pa": field.maximum,
            "max_x_m": x, "max_y_m": y,
            "big_end_max_von_mises_Pa": field.maximum_in(("cap", "head")),
            "largest_displacement_m": field.largest_displacement}


def write_stress_outputs(results: dict[float, dict], structure, out: Path) -> None:
    """Figures first, then the table and the summary, all atomically."""
    from conrod.io.atomic import write_csv, write_json
    from conrod.io.result_folder import staged_result_folder
    from conrod.plotting.housing_plots import von_mises_figure
    from conrod.plotting.save import save_figure

    figures, rows, summary = {}, [], {}
    for angle, comparison in results.items():
        for scheme in SCHEMES:
            field = comparison[scheme]
            figures[f"von_mises_{scheme}_{angle:g}deg.png"] = von_mises_figure(
                structure, field, f"von Mises, {scheme} load scheme, φ = {angle:g}°")
            rows.append(_scheme_row(angle, scheme, field))
        summary[f"{angle:g}"] = {
            "resultant_N": comparison["resultant_N"].tolist(),
            "stress_ratio_pressure_to_cosine": comparison["stress_ratio"],
            "big_end_stress_ratio_pressure_to_cosine": comparison["big_end_stress_ratio"],
            "displacement_ratio_pressure_to_cosine": comparison["displacement_ratio"],
            "zones": {scheme: comparison[scheme].zones() for scheme in SCHEMES}}
    columns = {key: np.array([row[key] for row in rows]) for key in rows[0]}
    with staged_result_folder(out) as stage:  # the whole set swapped in at once
        write_csv(stage / "stress_maxima.csv", columns)
        write_json(stage / "stress_summary.json", summary)
        for name, figure in figures.items():
            save_figure(figure, stage / name)


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
        from conrod.housing.housing import Housing
        from conrod.simulation.stress_study import rigid_run_pressures

        case = Case.from_toml(case_file)
        case.require("stress", "engine", "bearing", "lubricant")
        if case.housing.model not in ("builtin", "mesh"):
            raise CaseError(f"housing.model = {case.housing.model!r}: stresses need a finite-"
                            "element housing (allowed: builtin or mesh)")
        crank_angles = parse_angles(angles, case)
        housing = Housing.from_case(case)
        theta, z, pressures = rigid_run_pressures(case, crank_angles)
        results = {angle: housing.stresses(p, z, np.radians(angle), theta)
                   for angle, p in zip(crank_angles, pressures, strict=True)}
        write_stress_outputs(results, housing.structure, out)
        for angle, comparison in results.items():
            typer.echo(f"{angle:g} deg: max von Mises {comparison['pressure'].maximum / 1e6:.0f} "
                       f"MPa (pressure) vs {comparison['cosine'].maximum / 1e6:.0f} MPa (cosine)")
        typer.echo(f"-> {out}")
