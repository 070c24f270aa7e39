"""``conrod sweep STUDY.toml --out DIR [--scheduler tcp://HOST:PORT] [--workers N]``.

Validates every variant first (a bad axis key or value: exit 2, nothing run), runs the
unfinished ones in parallel with a progress bar, writes ``DIR/sweep.parquet``, prints the
best and worst variant with status ``ok`` per characteristic and names every variant that
is not ``ok``. Ctrl-C stops the workers at once and exits 130; the variants finished so far
stay in ``DIR/variants`` and the next run computes only the rest.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Annotated

import typer

from conrod.cli.app import exits_cleanly
from conrod.io.interrupts import EXIT_INTERRUPTED

SHOWN_PROBLEMS = 20
"""Variants that are not ``ok`` named one per line at the end (the rest are counted) [-]."""


class _Bar:
    """rich progress bar across variants, on stderr, redrawn at most ten times a second
    from this thread (no drawing thread: worker processes are forked from this one)."""

    def __init__(self):
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

        self.bar = Progress("variants", BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                            console=Console(stderr=True), transient=True, auto_refresh=False)
        self.task = None
        self.drawn = 0.0

    def __call__(self, done: int, total: int) -> None:
        if self.task is None:
            self.bar.start()
            self.task = self.bar.add_task("variants", total=total)
        self.bar.update(self.task, completed=done, total=total)
        if done == total or time.monotonic() - self.drawn > 0.1:
            self.bar.refresh()
            self.drawn = time.monotonic()

    def close(self) -> None:
        if self.task is not None:
            self.bar.stop()
            self.task = None


def print_best_and_worst(frame) -> None:
    """A table of the best and worst variant with status ``ok`` per characteristic."""
    from rich.console import Console
    from rich.table import Table

    from conrod.sweep.table import best_and_worst

    table = Table(title="best and worst variant per characteristic (status ok)")
    for column in ("characteristic", "best", "variant", "worst", "variant "):
        table.add_column(column)
    for row in best_and_worst(frame):
        table.add_row(row["characteristic"], f"{row['best']:.4g}", row["best_variant"],
                      f"{row['worst']:.4g}", row["worst_variant"])
    Console(width=160).print(table)


def report_problems(frame) -> None:
    """One stderr line per variant that is not ``ok``: its status and why."""
    from conrod.sweep.status import STATUS_OK

    problems = frame[frame["status"] != STATUS_OK]
    for _, row in problems.head(SHOWN_PROBLEMS).iterrows():
        why = row["error"] or row.get("warnings", "") or "orbit not periodic"
        typer.echo(f"variant {row['variant']} {row['status']}: {why}", err=True)
    if len(problems) > SHOWN_PROBLEMS:
        typer.echo(f"... and {len(problems) - SHOWN_PROBLEMS} more variants that are not ok "
                   "(column status of sweep.parquet)", err=True)


def register(app: typer.Typer) -> None:
    """Add the ``sweep`` command to ``app``."""

    @app.command("sweep")
    @exits_cleanly
    def sweep(
        study_file: Annotated[Path, typer.Argument(help="Study file (TOML).")],
        out: Annotated[Path, typer.Option("--out", help="Sweep folder.")] = Path("sweep"),
        scheduler: Annotated[str | None, typer.Option(
            help="Address of a running Dask scheduler, e.g. tcp://host:8786.")] = None,
        workers: Annotated[int | None, typer.Option(
            help="Worker processes on this machine (default: one per core).")] = None,
        figures: Annotated[bool, typer.Option(
            help="Write every variant's figures (slower).")] = False,
    ) -> None:
        """Run every variant of a study in parallel; one row per variant in
        DIR/sweep.parquet."""
        from conrod.io.result_folder import check_output_folder
        from conrod.sweep import Sweep
        from conrod.sweep.runner import STUDY_FILE
        from conrod.sweep.table import status_counts

        check_output_folder(out, marker=STUDY_FILE, inputs=(study_file,))  # before computing
        runner = Sweep(study_file, out, scheduler=scheduler, workers=workers, figures=figures)
        typer.echo(f"validating the variants of {study_file}", err=True)
        variants = runner.variants()
        typer.echo(f"{len(variants)} variants validated", err=True)
        bar = _Bar()
        try:
            frame = runner.run(progress=bar)
        except KeyboardInterrupt:
            bar.close()
            _stopped(runner, len(variants))
        finally:
            bar.close()
        print_best_and_worst(frame)
        report_problems(frame)
        counts = ", ".join(f"{n} {status.replace('_', ' ')}"
                           for status, n in status_counts(frame).items())
        typer.echo(f"{len(frame)} variants: {counts} ({int(frame['cached'].sum())} from "
                   f"earlier runs) → {out / 'sweep.parquet'}")


def _stopped(runner, total: int) -> None:
    """Ctrl-C: say what is kept, exit 130."""
    from conrod.sweep.store import RECORD, variants_dir

    root = variants_dir(runner.out)
    kept = sum((root / v.key / RECORD).is_file() for v in runner.variants())
    typer.echo(f"interrupted: {kept} of {total} variants finished and kept in {root} "
               "(the same command computes the rest)", err=True)
    raise typer.Exit(code=EXIT_INTERRUPTED)
