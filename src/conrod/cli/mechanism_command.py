"""``conrod mechanism CASE.toml --out DIR [--sweep speed=A:B:N --sweep load=A:B:N] [--jobs N]``.

Single run writes ``mechanism.csv`` (last cycle), ``impacts.csv`` (every cycle but the
first, which holds the start-up transient),
``summary.json`` and the figures ``gaps_and_forces.png``, ``journal_orbits.png``,
``impact_velocities.png``. With ``--sweep`` it writes ``sweep.csv``, ``sweep.json``
(the most informative regime) and ``sweep_map.png``. All files are written atomically
after the computation succeeded.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated

import numpy as np
import typer

from conrod.cases.base import range_error
from conrod.cases.case import Case
from conrod.cli.app import exits_cleanly
from conrod.errors import CaseError
from conrod.io.atomic import write_csv, write_json
from conrod.io.interrupts import raise_if_interrupted
from conrod.io.result_folder import check_output_folder, staged_result_folder
from conrod.mechanism.results import JOINT_NAMES, MechanismResults
from conrod.mechanism.setup import MechanismCase, mechanism_case
from conrod.mechanism.simulation import simulate
from conrod.mechanism.sweep import SweepResults, parse_sweep_option, run_sweep
from conrod.results.plausibility import check_mechanism

SWEEP_LIMITS = {"speed": (0.0, 30000.0, "rpm"), "load": (0.0, 5.0, "-")}
"""Allowed (exclusive lower, inclusive upper) bounds of swept values and their unit."""


def mechanism_table(results: MechanismResults) -> dict[str, np.ndarray]:
    """Columns of ``mechanism.csv`` over the last cycle (crank angle 0…720°)."""
    mask = results.last_cycle()
    start = (results.cycles - 1) * results.cycle_length
    table = {
        "crank_angle_deg": np.degrees(results.crank_angle[mask] - start),
        "piston_position_m": results.piston_position[mask],
        "piston_position_rigid_m": results.piston_position_rigid[mask],
        "rod_obliquity_deg": np.degrees(results.rod_obliquity[mask]),
        "gas_force_N": results.gas_force[mask],
    }
    for index, name in enumerate(JOINT_NAMES):
        table[f"{name}_gap_m"] = results.gap[index, mask]
        table[f"{name}_journal_along_rod_m"] = results.journal_offset[index, 0, mask]
        table[f"{name}_journal_across_rod_m"] = results.journal_offset[index, 1, mask]
        table[f"{name}_force_N"] = results.contact_force[index, mask]
        table[f"{name}_friction_N"] = results.friction_force[index, mask]
    table["energy_residual_J"] = results.energy_residual[mask]
    return table


def impacts_table(results: MechanismResults) -> dict[str, np.ndarray]:
    """Columns of ``impacts.csv``: every impact of the settled cycles (all but the first),
    crank angle within its cycle, joint 0 big end / 1 small end, cycle number from 1."""
    impacts = results.settled_impacts()
    cycle = np.floor(impacts.crank_angle / results.cycle_length)
    return {"crank_angle_deg": np.degrees(impacts.crank_angle - cycle * results.cycle_length),
            "joint": np.asarray(impacts.joint, dtype=int),
            "impact_velocity_m_s": impacts.velocity,
            "cycle": cycle.astype(int) + 1}


def write_run_outputs(results: MechanismResults, summary: dict, out: Path) -> None:
    """Build the figures, then write every file atomically."""
    from conrod.plotting import mechanism_plots as plots
    from conrod.plotting.save import save_figure

    figures = {"gaps_and_forces.png": plots.plot_gaps_and_forces(results),
               "journal_orbits.png": plots.plot_journal_orbits(results),
               "impact_velocities.png": plots.plot_impacts(results)}
    with staged_result_folder(out) as stage:
        write_csv(stage / "mechanism.csv", mechanism_table(results))
        _write_impacts(stage / "impacts.csv", impacts_table(results))
        write_json(stage / "summary.json", summary)
        for name, figure in figures.items():
            save_figure(figure, stage / name)


def _write_impacts(path: Path, columns: dict[str, np.ndarray]) -> None:
    """impacts.csv with the joint written by name (big_end / small_end)."""
    from conrod.io.atomic import write_text

    lines = ["crank_angle_deg,joint,impact_velocity_m_s,cycle"]
    for angle, joint, speed, cycle in zip(columns["crank_angle_deg"], columns["joint"],
                                          columns["impact_velocity_m_s"], columns["cycle"],
                                          strict=True):
        lines.append(f"{angle:.6f},{JOINT_NAMES[int(joint)]},{speed:.9g},{cycle}")
    write_text(path, "\n".join(lines) + "\n")


def _advance(bar) -> None:
    raise_if_interrupted()
    bar.update(1)


def sweep_values(options: list[str], base: MechanismCase) -> tuple[np.ndarray, np.ndarray]:
    """Speeds [rpm] and load scales [-] from ``--sweep`` options (defaults: the case's)."""
    values = {"speed": np.array([base.speed_rpm]), "load": np.array([base.load_scale])}
    for option in options:
        try:
            name, numbers = parse_sweep_option(option)
        except ValueError as error:
            raise CaseError(str(error)) from None
        low, high, unit = SWEEP_LIMITS[name]
        bad = numbers[(numbers <= low) | (numbers > high)]
        if bad.size:
            raise range_error(f"--sweep {name}", float(bad[0]), f"> {low:g} and <= {high:g}", unit)
        values[name] = numbers
    return values["speed"], values["load"]


def write_sweep_outputs(sweep: SweepResults, out: Path, seconds: float) -> dict:
    """sweep.csv, sweep.json and the map figure; returns the best regime."""
    from conrod.plotting.mechanism_plots import plot_sweep_map
    from conrod.plotting.save import save_figure

    figure = plot_sweep_map(sweep)
    best = sweep.best()
    with staged_result_folder(out) as stage:
        write_csv(stage / "sweep.csv", sweep.columns())
        write_json(stage / "sweep.json", {"most_informative_regime": best,
                                          "runs": int(sweep.ratio.size),
                                          "wall_time_s": round(seconds, 2)})
        save_figure(figure, stage / "sweep_map.png")
    return best


def register(app: typer.Typer) -> None:
    """Add the ``mechanism`` command to ``app``."""

    @app.command("mechanism")
    @exits_cleanly
    def mechanism_command(
        case_file: Annotated[Path, typer.Argument(
            help="Case file with \\[engine] and \\[clearance]")],
        out: Annotated[Path, typer.Option("--out", help="Output folder (created if absent)")],
        sweep: Annotated[list[str] | None, typer.Option(
            "--sweep", help="speed=START:STOP:COUNT \\[rpm] or load=START:STOP:COUNT \\[-]; "
            "repeatable")] = None,
        jobs: Annotated[int, typer.Option(
            "--jobs", min=1, help="Worker processes for --sweep (1 = in this process)")] = 1,
    ) -> None:
        """Slider-crank with clearances in both rod bearings: gaps, forces, impacts (seed 003)."""
        check_output_folder(out)
        case = Case.from_toml(case_file)
        base = mechanism_case(case)
        if sweep:
            speeds, loads = sweep_values(sweep, base)
            started = time.perf_counter()
            with typer.progressbar(length=speeds.size * loads.size, label="sweep") as bar:
                result = run_sweep(base, speeds, loads, jobs=jobs,
                                   progress=lambda done, total: _advance(bar))
            best = write_sweep_outputs(result, out, time.perf_counter() - started)
            typer.echo(f"most informative regime: {best['speed_rpm']:g} rpm, load "
                       f"{best['load_scale']:g} (κ = {best['impact_velocity_ratio']:.3g}) -> {out}")
            return
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
        summary = {"speed_rpm": base.speed_rpm, "load_scale": base.load_scale,
                   **results.summary(), "warnings": check_mechanism(results, base.mechanism)}
        write_run_outputs(results, summary, out)
        typer.echo(
            f"{summary['impacts_per_cycle']} impacts/cycle; max impact velocity big end "
            f"{summary['max_impact_velocity_big_end_m_s']:.3g} m/s, small end "
            f"{summary['max_impact_velocity_small_end_m_s']:.3g} m/s -> {out}")
        for warning in summary["warnings"]:
            typer.echo(f"warning: {warning}", err=True)
