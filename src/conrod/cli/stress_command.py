"""``conrod stress CASE.toml --angles 25,360 --out DIR`` or ``conrod stress RUN_DIR --out
DIR``: rod stresses under the film pressure of a run (scheme a) and under the same
resultant as a cosine load (scheme b).

The pressure is the one of the run the command is given: a folder of an elastic run
(``conrod run`` with an elastic ``[housing]`` and a Reynolds or mass-conserving film keeps
the pressure fields at the largest load and the stress angles in ``film_pressure.npz``,
and its case in ``case.toml``), or the case file, whose run this command makes — the
coupled elastic run when its film takes the bore deformation (``--film reynolds``), else
the rigid-bore run, said so. Which pressure it used is printed and written
(``stress_summary.json["pressure_source"]``).

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


def _check_case(case: Case) -> None:
    case.require("stress", "engine", "bearing", "lubricant")
    if case.housing.model not in ("builtin", "mesh"):
        raise CaseError(f"housing.model = {case.housing.model!r}: stresses need a finite-"
                        "element housing (allowed: builtin or mesh)")


def _from_folder(folder: Path, angles: str | None):
    """The study under the pressure fields of the elastic run in ``folder``."""
    from conrod.housing.housing import Housing
    from conrod.output.folder import FILM_PRESSURE, film_pressure_fields, recorded_case
    from conrod.simulation.stress_study import nearest_angle, stress_study_from_fields

    stored = film_pressure_fields(folder)
    case = recorded_case(folder)
    if stored is None or case is None:
        raise CaseError(f"{str(folder)!r}: not the folder of an elastic run (it holds no "
                        f"{FILM_PRESSURE} and case.toml; conrod run CASE --film reynolds "
                        "writes them), or give the case file")
    _check_case(case)
    theta, z, fields = stored
    if angles:
        wanted = parse_angles(angles, case)
        missing = [a for a in wanted if abs(nearest_angle(sorted(fields), a) - a) > 1.0]
        if missing:
            raise CaseError(f"--angles = {angles!r}: the run kept the film pressure at "
                            f"{', '.join(f'{a:g}' for a in sorted(fields))} deg only (set "
                            "[housing] stress_angles before the run, or give the case file)")
        fields = {a: fields[nearest_angle(sorted(fields), a)] for a in wanted}
    source = (f"film pressure of the elastic run in {folder.name} ({FILM_PRESSURE}: the "
              "film on the deformed bore)")
    from conrod.simulation.recording import record_case

    summary = _run_summary(folder)
    return stress_study_from_fields(Housing.from_case(case), theta, z, fields, source,
                                    summary, record_case(case, case.solver))


def _run_summary(folder: Path) -> dict:
    import json

    try:
        summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
    keys = ("film_model", "film_h_min_m", "p_max_Pa", "p_max_crank_angle_deg", "warnings")
    return {key: summary.get(key) for key in keys}


def register(app: typer.Typer) -> None:
    """Add the ``stress`` command to ``app``."""

    @app.command("stress")
    @exits_cleanly
    def stress_command(
        source: Annotated[Path, typer.Argument(
            help="Case file with [engine], [bearing], [lubricant] and a builtin/mesh "
                 "[housing] (its run is made here), or the folder of an elastic run")],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        angles: Annotated[str | None, typer.Option(
            "--angles", help="Crank angles [deg], comma separated, e.g. 25,360")] = None,
        film: Annotated[str | None, typer.Option(
            help="Film model of the run made from a case file (default: the case's; "
                 "reynolds or mass_conserving couple the elastic bore).")] = None,
        grid: Annotated[str | None, typer.Option(
            help="Film grid NTHETAxNZ of that run, e.g. 36x8.")] = None,
    ) -> None:
        """Von Mises stresses of the rod under the film pressure of a run and a cosine load."""
        from conrod.cli.run_command import single_threaded_blas

        single_threaded_blas()
        from conrod.io.result_folder import check_output_folder

        inputs = (source,) if source.is_file() else ()
        check_output_folder(out, inputs=inputs)  # before any computation
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            from conrod.cases.case import Case
            from conrod.cli.run_command import parse_grid
            from conrod.housing.housing import Housing
            from conrod.output.registry import write_results
            from conrod.simulation.stress_study import stress_study

        if source.is_dir():
            if film or grid:
                raise CaseError("--film/--grid: only with a case file (a run folder's "
                                "pressure is the one of its run)")
            results = _from_folder(source, angles)
        else:
            case = Case.from_toml(source)
            _check_case(case)
            crank_angles = parse_angles(angles, case)
            n_theta, n_z = parse_grid(grid)
            results = stress_study(case, Housing.from_case(case), crank_angles, film=film,
                                   n_theta=n_theta, n_z=n_z)
        write_results(results, out)
        with printing_after_results(out):
            typer.echo(f"rod loaded by the {results.pressure_source}")
            for angle, comparison in results.schemes.items():
                typer.echo(f"{angle:g} deg: max von Mises "
                           f"{comparison['pressure'].maximum / 1e6:.0f} MPa (pressure) vs "
                           f"{comparison['cosine'].maximum / 1e6:.0f} MPa (cosine)")
            typer.echo(f"-> {out}")
