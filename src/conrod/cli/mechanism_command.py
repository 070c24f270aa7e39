"""``conrod mechanism CASE.toml --out DIR [--sweep speed=A:B:N --sweep load=A:B:N] [--jobs N]``.

Single run writes ``mechanism.csv`` (last cycle), ``impacts.csv`` (every cycle but the
first, which holds the start-up transient),
``summary.json`` and the figures ``gaps_and_forces.png``, ``journal_orbits.png``,
``impact_velocities.png``. With ``--sweep`` it writes ``sweep.csv``, ``sweep.json``
(the most informative regime) and ``sweep_map.png``. All files are written atomically
after the computation succeeded, ``manifest.json`` last.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import TYPE_CHECKING, Annotated

import typer

from conrod.cli.app import ACCEPT_WARNINGS_HELP, exits_cleanly, finish, printing_after_results
from conrod.errors import CaseError
from conrod.io.interrupts import interrupts_stop_at_once, raise_if_interrupted

if TYPE_CHECKING:  # pragma: no cover
    import numpy as np

    from conrod.mechanism.setup import MechanismCase

SWEEP_LIMITS = {"speed": (">=", 1.0, 30000.0, "rpm"), "load": (">", 0.0, 5.0, "-")}
"""Allowed lower bound (inclusive or not), inclusive upper bound and unit of swept values
(speeds as ``engine.speed``)."""


def sweep_values(options: list[str], base: MechanismCase) -> tuple[np.ndarray, np.ndarray]:
    """Speeds [rpm] and load scales [-] from ``--sweep`` options (defaults: the case's)."""
    import numpy as np

    from conrod.cases.base import range_error
    from conrod.sweep.mechanism import parse_sweep_option

    values = {"speed": np.array([base.speed_rpm]), "load": np.array([base.load_scale])}
    for option in options:
        try:
            name, numbers = parse_sweep_option(option)
        except ValueError as error:
            raise CaseError(str(error)) from None
        relation, low, high, unit = SWEEP_LIMITS[name]
        too_low = numbers < low if relation == ">=" else numbers <= low
        bad = numbers[too_low | (numbers > high)]
        if bad.size:
            raise range_error(f"--sweep {name}", float(bad[0]),
                              f"{relation} {low:g} and <= {high:g}", unit)
        values[name] = numbers
    return values["speed"], values["load"]


def register(app: typer.Typer) -> None:
    """Add the ``mechanism`` command to ``app``."""

    @app.command("mechanism")
    @exits_cleanly
    def mechanism_command(
        case_file: Annotated[Path, typer.Argument(
            help="Case file with [engine] and [clearance]")],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        sweep: Annotated[list[str] | None, typer.Option(
            "--sweep", help="speed=START:STOP:COUNT [rpm] or load=START:STOP:COUNT [-]; "
            "repeatable")] = None,
        jobs: Annotated[int, typer.Option(
            "--jobs", min=1, help="Worker processes for --sweep (1 = in this process)")] = 1,
        accept_warnings: Annotated[bool, typer.Option(
            "--accept-warnings", help=ACCEPT_WARNINGS_HELP)] = False,
    ) -> None:
        """Slider-crank with clearances in both rod bearings: gaps, forces, impacts ([D3])."""
        from conrod.io.result_folder import check_output_folder

        check_output_folder(out, inputs=(case_file,))
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            from conrod.cases.case import Case
            from conrod.mechanism.regimes import SweepRun
            from conrod.mechanism.results import MechanismRun
            from conrod.mechanism.setup import mechanism_case
            from conrod.mechanism.simulation import simulate
            from conrod.results.plausibility import check_mechanism
            from conrod.sweep.mechanism import run_sweep

            case = Case.from_toml(case_file)
        base = mechanism_case(case)
        if sweep:
            speeds, loads = sweep_values(sweep, base)
            started = time.perf_counter()
            with typer.progressbar(length=speeds.size * loads.size, label="sweep") as bar:
                result = run_sweep(base, speeds, loads, jobs=jobs,
                                   progress=lambda done, total: _advance(bar))
            finished = SweepRun(result, time.perf_counter() - started)
            _write(finished, out)
            best = result.best()
            with printing_after_results(out):
                typer.echo(f"most informative regime: {best['speed_rpm']:g} rpm, load "
                           f"{best['load_scale']:g} ({best['in_words']}) "
                           f"-> {out}")
            return
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
        run = MechanismRun(results, base.speed_rpm, base.load_scale,
                           tuple(check_mechanism(results, base.mechanism)))
        summary = run.summary()
        _write(run, out)
        with printing_after_results(out):
            typer.echo(f"{summary['impacts_per_cycle']} impacts/cycle; max impact velocity big "
                       f"end {summary['max_impact_velocity_big_end_m_s']:.3g} m/s, small end "
                       f"{summary['max_impact_velocity_small_end_m_s']:.3g} m/s -> {out}")
        finish(summary["warnings"], accept_warnings)


def _advance(bar) -> None:
    raise_if_interrupted()
    bar.update(1)


def _write(results, out: Path) -> None:
    from conrod.output.registry import write_results

    write_results(results, out)
