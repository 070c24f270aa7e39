"""``conrod sweep STUDY.toml --out DIR [--scheduler tcp://HOST:PORT] [--workers N]``.

Validates every variant first (a bad axis key or value: exit 2, nothing run), runs the
unfinished ones on Dask distributed with a progress bar, writes ``DIR/sweep.parquet`` and
prints the best and worst variant per characteristic.
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from conrod.cli.app import exits_cleanly


class _Bar:
    """rich progress bar across variants, on stderr."""

    def __init__(self):
        from rich.console import Console
        from rich.progress import BarColumn, MofNCompleteColumn, Progress, TimeRemainingColumn

        self.bar = Progress("variants", BarColumn(), MofNCompleteColumn(), TimeRemainingColumn(),
                            console=Console(stderr=True), transient=True)
        self.task = None

    def __call__(self, done: int, total: int) -> None:
        if self.task is None:
            self.bar.start()
            self.task = self.bar.add_task("variants", total=total)
        self.bar.update(self.task, completed=done, total=total)

    def close(self) -> None:
        if self.task is not None:
            self.bar.stop()


def print_best_and_worst(frame) -> None:
    """A table of the best and worst finished variant per characteristic (stdout)."""
    from rich.console import Console
    from rich.table import Table

    from conrod.sweep.table import best_and_worst

    table = Table(title="best and worst variant per characteristic")
    for column in ("characteristic", "best", "variant", "worst", "variant "):
        table.add_column(column)
    for row in best_and_worst(frame):
        table.add_row(row["characteristic"], f"{row['best']:.4g}", row["best_variant"],
                      f"{row['worst']:.4g}", row["worst_variant"])
    Console(width=160).print(table)


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
            help="Worker processes of the local cluster (default: one per core).")] = None,
        figures: Annotated[bool, typer.Option(
            help="Write every variant's figures (slower).")] = False,
    ) -> None:
        """Run every variant of a study on Dask; one row per variant in DIR/sweep.parquet."""
        from conrod.io.result_folder import check_output_folder
        from conrod.sweep import Sweep
        from conrod.sweep.runner import STUDY_FILE

        check_output_folder(out, marker=STUDY_FILE, inputs=(study_file,))  # before computing

        runner = Sweep(study_file, out, scheduler=scheduler, workers=workers, figures=figures)
        variants = runner.variants()
        typer.echo(f"{len(variants)} variants validated", err=True)
        bar = _Bar()
        try:
            frame = runner.run(progress=bar)
        finally:
            bar.close()
        failed = frame[frame["status"] != "ok"]
        print_best_and_worst(frame)
        for _, row in failed.iterrows():
            typer.echo(f"variant {row['variant']} failed: {row['error']}", err=True)
        typer.echo(f"{len(frame) - len(failed)} of {len(frame)} variants finished "
                   f"({int(frame['cached'].sum())} from earlier runs) → {out / 'sweep.parquet'}")
