"""``conrod run CASE.toml --out DIR``: periodic orbit, characteristics, figures, manifest."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated, Any

import typer

from conrod.cli.app import exits_cleanly
from conrod.registry import FILM_NAMES, INTEGRATOR_NAMES

PROGRESS_AFTER_S = 1.0
"""A progress bar appears on runs longer than this [s]."""


class _Progress:
    """rich progress on stderr, shown once the run has taken more than a second."""

    def __init__(self, max_cycles: int):
        self.max_cycles = max_cycles
        self.start = time.perf_counter()
        self.bar: Any = None
        self.task: Any = None

    def __call__(self, stage: str, cycle: int, error: float) -> None:
        if self.bar is None and time.perf_counter() - self.start > PROGRESS_AFTER_S:
            from rich.console import Console
            from rich.progress import Progress

            self.bar = Progress(console=Console(stderr=True), transient=True)
            self.bar.start()
            self.task = self.bar.add_task("orbit", total=self.max_cycles)
        if self.bar is not None:
            self.bar.update(self.task, completed=min(cycle, self.max_cycles),
                            description=f"{stage}: cycle {cycle}, Δe/c = {error:.2g}")

    def close(self) -> None:
        if self.bar is not None:
            self.bar.stop()


def register(app: typer.Typer) -> None:
    """Add the ``run`` command to ``app``."""

    @app.command("run")
    @exits_cleanly
    def run(
        case_file: Annotated[Path, typer.Argument(help="Case file (TOML).")],
        out: Annotated[Path, typer.Option("--out", help="Results folder.")] = Path("results"),
        film: Annotated[str | None, typer.Option(
            help=f"Film model: {'|'.join(FILM_NAMES)}.")] = None,
        integrator: Annotated[str | None, typer.Option(
            help=f"Orbit integrator: {'|'.join(INTEGRATOR_NAMES)}.")] = None,
        max_cycles: Annotated[int | None, typer.Option(help="Most cycles.")] = None,
        step_deg: Annotated[float | None, typer.Option(help="Fixed step of rk2 [deg].")] = None,
        grid: Annotated[str | None, typer.Option(help="Film grid NTHETAxNZ, e.g. 72x16.")] = None,
        figures: Annotated[bool, typer.Option(help="Write the figures.")] = True,
        rigid: Annotated[bool, typer.Option(
            "--rigid/--no-rigid", help="With an elastic [housing], also run the rigid bore "
            "and compare (cycle_rigid.csv, summary.json comparison).")] = True,
) -> None:
        """Periodic journal-centre orbit and bearing characteristics over the cycle."""
        import conrod.plotting  # noqa: F401  (registers the figures)
        from conrod.cases.case import Case
        from conrod.results.output import write_results
        from conrod.simulation import Simulation

        case = Case.from_toml(case_file)
        n_theta, n_z = _grid(grid)
        simulation = Simulation(case, film=film, integrator=integrator, max_cycles=max_cycles,
                                step_deg=step_deg, n_theta=n_theta, n_z=n_z,
                                rigid_companion=rigid)
        progress = _Progress(simulation.solver.max_cycles)
        try:
            results = simulation.run(progress=progress)
        finally:
            progress.close()
        write_results(results, out, figures=figures)
        s = results.summary
        typer.echo(
            f"h_min {s.h_min * 1e6:.3f} µm at {_deg(s.h_min_crank_angle)}°, "
            f"p_max {s.p_max / 1e6:.2f} MPa at {_deg(s.p_max_crank_angle)}°, "
            f"{s.cycles} cycles, {s.wall_time:.2f} s → {out}"
)
        for warning in s.warnings:
            typer.echo(f"warning: {warning}", err=True)


def _deg(angle: float) -> str:
    import math

    return f"{math.degrees(angle):.0f}"


def _grid(grid: str | None) -> tuple[int | None, int | None]:
    from conrod.errors import CaseError

    if grid is None:
        return None, None
    try:
        n_theta, n_z = (int(v) for v in grid.lower().split("x"))
    except ValueError:
        raise CaseError(f"--grid = {grid!r}: expected NTHETAxNZ, e.g. 72x16") from None
    return n_theta, n_z
