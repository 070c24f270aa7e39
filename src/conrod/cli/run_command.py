"""``conrod run CASE.toml --out DIR``: periodic orbit, characteristics, figures, manifest."""

from __future__ import annotations

import enum
import math
import os
import time
from pathlib import Path
from typing import Annotated, Any

import typer

from conrod.cli.app import ACCEPT_WARNINGS_HELP, exits_cleanly, finish, printing_after_results
from conrod.cli.options import FIELDS_DEFAULT_DEG
from conrod.io.interrupts import interrupts_stop_at_once, raise_if_interrupted
from conrod.registry import FILM_NAMES, INTEGRATOR_NAMES

FilmChoice = enum.Enum("FilmChoice", {name: name for name in FILM_NAMES}, type=str)
"""The registered film model names, validated by the command line."""
IntegratorChoice = enum.Enum("IntegratorChoice", {n: n for n in INTEGRATOR_NAMES}, type=str)
"""The registered integrator names, validated by the command line."""

BLAS_THREAD_VARIABLES = ("OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS")
"""Thread counts of the BLAS libraries NumPy may use."""
HEADLINE_WIDTH = 16
"""Width of the label column of the plain headline [characters]."""
PROGRESS_AFTER_S = 1.0
"""Without a terminal, the first log line comes once the run has taken this long [s]."""


class _Progress:
    """Orbit progress on stderr. On a terminal: a rich bar from the start, moved by the
    integrator's in-cycle reports (crank angle in the cycle, cycle, periodicity error,
    estimated time left). Otherwise: one log line per cycle once the run has taken more
    than :data:`PROGRESS_AFTER_S`."""

    def __init__(self, max_cycles: int, tolerance: float):
        from rich.console import Console

        self.max_cycles, self.tolerance = max_cycles, tolerance
        self.console = Console(stderr=True)
        self.start = self.cycle_start = time.perf_counter()
        self.durations: list[float] = []
        self.errors: list[float] = []
        self.bar: Any = None
        self.task: Any = None
        if self.console.is_terminal:
            from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

            self.bar = Progress(TextColumn("{task.description}"), BarColumn(),
                                TimeElapsedColumn(), console=self.console, transient=True)
            self.bar.start()
            self.task = self.bar.add_task("orbit: starting", total=max_cycles)

    def __call__(self, stage: str, cycle: int, error: float) -> None:
        """End of ``cycle`` with its periodicity error [-]."""
        raise_if_interrupted()
        now = time.perf_counter()
        self.durations.append(now - self.cycle_start)
        self.cycle_start = now
        self.errors.append(error)
        if self.bar is not None:
            self.bar.update(self.task, completed=min(cycle, self.max_cycles),
                            description=self._text(stage, cycle, None, None, 1.0))
        elif now - self.start > PROGRESS_AFTER_S:
            self.console.print(
                f"{stage}: cycle {cycle} in {self.durations[-1]:.1f} s, periodicity error "
                f"{error:.2g} (tolerance {self.tolerance:g}), {now - self.start:.1f} s "
                "elapsed", highlight=False, soft_wrap=True)

    def in_cycle(self, stage: str, cycle: int, angle_deg: float, cycle_deg: float) -> None:
        """The integrator has reached ``angle_deg`` of ``cycle_deg`` in ``cycle`` [deg]."""
        raise_if_interrupted()
        if cycle == 0:  # the lead-in before the first cycle: cycle 1's clock starts after it
            self.cycle_start = time.perf_counter()
        if self.bar is None:
            return
        fraction = min(max(angle_deg / cycle_deg, 0.0), 1.0)
        self.bar.update(self.task, completed=min(max(cycle - 1 + fraction, 0.0),
                                                 self.max_cycles),
                        description=self._text(stage, cycle, angle_deg, cycle_deg, fraction))

    def _text(self, stage, cycle, angle_deg, cycle_deg, fraction) -> str:
        where = (f", {angle_deg:.0f}/{cycle_deg:.0f}°" if angle_deg is not None else " done")
        if cycle == 0:
            return f"{stage}: lead-in{where}"
        error = f", Δe/c {self.errors[-1]:.2g}" if self.errors else ""
        left = self._time_left(fraction)
        return (f"{stage}: cycle {cycle}{where}{error}"
                + (f", ~{left:.0f} s left" if left is not None else ""))

    def _time_left(self, fraction: float) -> float | None:
        """Rest of this cycle plus the cycles the error's decay still needs [s]."""
        elapsed = time.perf_counter() - self.cycle_start
        if self.durations:  # the last cycle: the first one includes numba compilation
            per_cycle = self.durations[-1]
        elif fraction > 0.05:
            per_cycle = elapsed / fraction
        else:
            return None
        errors = [e for e in self.errors if math.isfinite(e)]
        more = 1
        if len(errors) >= 2 and 0.0 < errors[-1] < errors[-2]:
            rate = errors[-1] / errors[-2]
            more = max(0, math.ceil(math.log(self.tolerance / errors[-1]) / math.log(rate)))
        elif errors and errors[-1] <= self.tolerance:
            more = 0
        more = min(more, max(self.max_cycles - len(self.durations) - 1, 0))
        current = max(per_cycle - elapsed, 0.0) if fraction < 1.0 else 0.0
        return current + more * per_cycle

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


def single_threaded_blas() -> None:
    """Run the dense linear algebra (the elastic bore's n_θ × n_θ Newton matrices) on one
    thread unless the user set the thread count: at these sizes a BLAS thread pool gains
    nothing, and on a machine whose cores are busy its spinning threads made one 108 × 108
    inverse take 170 ms instead of 1 ms (KamAZ-740 elastic run at 108×8: 299 s → 39 s).
    Must run before NumPy is imported (the commands import it only once they compute)."""
    for name in BLAS_THREAD_VARIABLES:
        os.environ.setdefault(name, "1")


def register(app: typer.Typer) -> None:
    """Add the ``run`` command to ``app``."""

    @app.command("run")
    @exits_cleanly
    def run(
        case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
        out: Annotated[Path | None, typer.Option(
            "--out", help="Results folder (default: results/<case file name>).")] = None,
        film: Annotated[FilmChoice | None, typer.Option(
            help="Film model (default: the case's).")] = None,
        integrator: Annotated[IntegratorChoice | None, typer.Option(
            help="Orbit integrator (default: the case's).")] = None,
        max_cycles: Annotated[int | None, typer.Option(help="Most cycles.")] = None,
        step_deg: Annotated[float | None, typer.Option(help="Fixed step of rk2 [deg].")] = None,
        grid: Annotated[str | None, typer.Option(help="Film grid NTHETAxNZ, e.g. 72x16.")] = None,
        figures: Annotated[bool, typer.Option(help="Write the figures.")] = True,
        accept_warnings: Annotated[bool, typer.Option(
            "--accept-warnings", help=ACCEPT_WARNINGS_HELP)] = False,
        step_check: Annotated[bool, typer.Option(
            help="rk2: rerun at half the step and warn when h_min moves by more than 2 %.")
        ] = True,
        rigid: Annotated[bool, typer.Option(
            "--rigid/--no-rigid", help="With an elastic [housing], also run the rigid bore "
            "and compare (cycle_rigid.csv, summary.json comparison).")] = True,
        grid_error: Annotated[bool, typer.Option(
            help="Grid films: run the orbit again on coarser grids and give the grid error "
            "of h_min and p_max (Richardson, observed order) in the headline.")] = True,
        fields: Annotated[float | None, typer.Option(
            "--fields", metavar="[STRIDE_DEG]",
            help="Write the film fields (pressure, film thickness, film fraction, "
            "deformation, asperity pressure, temperature: what the run has) over the last "
            "cycle every STRIDE_DEG of crank angle to fields.nc (netCDF; "
            f"conrod.open_fields(folder)); --fields alone: every {FIELDS_DEFAULT_DEG:g} deg."
        )] = None,
    ) -> None:
        """Periodic journal-centre orbit and bearing characteristics over the cycle."""
        single_threaded_blas()
        from conrod.io.result_folder import check_output_folder

        out = out if out is not None else Path("results") / case_file.stem
        check_output_folder(out, inputs=(case_file,))  # before any computation
        had_report = (out / "report.html").is_file() and (out / "manifest.json").is_file()
        with interrupts_stop_at_once():  # starting: nothing computed or written yet
            from conrod.cases.case import Case
            from conrod.output.registry import write_results
            from conrod.simulation.simulation import Simulation

            case = Case.from_toml(case_file)
        n_theta, n_z = parse_grid(grid)
        from conrod.io.cores import long_lived_objects_frozen
        from conrod.output.registry import FigureDraft
        from conrod.simulation.grid_error import coarse_jobs
        from conrod.simulation.side_runs import beside, fork

        with long_lived_objects_frozen() as freeze_alive:  # the modules, then the results
            simulation = Simulation(case, film=film and film.value,
                                    integrator=integrator and integrator.value,
                                    max_cycles=max_cycles, step_deg=step_deg, n_theta=n_theta,
                                    n_z=n_z, rigid_companion=rigid, fields=fields)
            draft = FigureDraft(fork) if figures else None  # drawn while coarse orbits run
            try:
                with beside(simulation, coarse_jobs(simulation) if grid_error else ()) as side:
                    results = _computed(simulation, step_check, grid_error,
                                        draft if side is not None else None)
                freeze_alive()
                write_results(results, out, figures=figures, draft=draft)
            finally:
                if draft is not None:
                    draft.close()
        note = _renew_report(out) if had_report else None
        with printing_after_results(out):
            print_headline(results, out)
            if note:
                typer.echo(note)
        finish(results.summary.warnings, accept_warnings, converged=results.summary.periodic)


def _computed(simulation: Any, step_check: bool, grid_error: bool, draft: Any = None) -> Any:
    """The run's results with the step check and the grid-error estimate asked for;
    ``draft`` (a :class:`~conrod.output.registry.FigureDraft`, where a second process
    computes beside the run) is given the results before the estimate, whose figures a
    forked process draws while the coarser orbits run."""
    progress = _Progress(simulation.solver.max_cycles, simulation.solver.periodicity_tolerance)
    try:
        results = simulation.run(progress=progress)
    finally:
        progress.close()
    if step_check and simulation.solver.integrator == "rk2":
        from conrod.simulation.step_check import with_step_check

        results = with_step_check(results, simulation)
    if grid_error:
        from conrod.simulation.grid_error import with_grid_error

        if draft is not None:
            draft.provisional(results)
        progress = _Progress(simulation.solver.max_cycles,
                             simulation.solver.periodicity_tolerance)
        try:
            results = with_grid_error(results, simulation, progress)
        finally:
            progress.close()
    return results


def _renew_report(out: Path) -> str:
    """The folder held a report of its previous result, which the new result replaced: write
    the report of the new one in its place (a stale report would contradict the files)."""
    from conrod.report import write_report

    write_report(out)
    return (f"{'report':<{HEADLINE_WIDTH}}  {out / 'report.html'} rewritten for this result "
            "(the previous one described the replaced result)")


def print_headline(results: Any, out: Path) -> None:
    """The headline block on stdout: a rich table on a terminal, plain lines otherwise."""
    import sys

    from conrod.results.summary import headline

    lines = headline(results)  # as in summary.json (reproducible: the wall time is not in it)
    if sys.stdout.isatty():
        from rich.console import Console
        from rich.table import Table

        table = Table(show_header=False, box=None,
                      title=f"conrod run → {out} ({results.summary.wall_time:.2f} s)")
        for label, text in lines.items():
            table.add_row(f"[bold]{label}[/bold]", escape(text))
        Console().print(table)
        return
    width = max(HEADLINE_WIDTH, *(len(label) for label in lines))
    for label, text in lines.items():
        typer.echo(f"{label:<{width}}  {text}")
    typer.echo(f"{'results':<{width}}  {out} ({results.summary.wall_time:.2f} s)")


def escape(text: str) -> str:
    """``text`` with rich markup escaped (units in brackets stay visible)."""
    from rich.markup import escape as rich_escape

    return rich_escape(text)


def _deg(angle: float) -> str:
    import math

    return f"{math.degrees(angle):.0f}"


def parse_grid(grid: str | None) -> tuple[int | None, int | None]:
    from conrod.errors import CaseError

    if grid is None:
        return None, None
    try:
        n_theta, n_z = (int(v) for v in grid.lower().split("x"))
    except ValueError:
        raise CaseError(f"--grid = {grid!r}: expected NTHETAxNZ, e.g. 72x16") from None
    return n_theta, n_z
