"""``conrod plot-sweep DIR --x KEY --y COLUMN [--hue KEY] [--out FILE.png]``: one
characteristic of a sweep against one axis, a line per value of another."""

from __future__ import annotations

import difflib
from pathlib import Path
from typing import Annotated

import typer

from conrod.cli.app import exits_cleanly
from conrod.errors import CaseError


def check_column(frame, option: str, name: str) -> None:
    """:class:`CaseError` naming the option, the value and the columns there are."""
    if name in frame.columns:
        return
    names = [str(c) for c in frame.columns]
    hint = difflib.get_close_matches(name, names, n=1, cutoff=0.5)
    suggestion = f"; did you mean '{hint[0]}'?" if hint else ""
    raise CaseError(f"{option} {name!r}: no such column in sweep.parquet{suggestion} "
                    f"(columns: {', '.join(names)})")


def register(app: typer.Typer) -> None:
    """Add the ``plot-sweep`` command to ``app``."""

    @app.command("plot-sweep")
    @exits_cleanly
    def plot_sweep(
        folder: Annotated[Path, typer.Argument(help="Sweep folder (with sweep.parquet).")],
        x: Annotated[str, typer.Option("--x", help="Axis key on the x axis.")],
        y: Annotated[str, typer.Option("--y", help="Column on the y axis, e.g. h_min_m.")],
        hue: Annotated[str | None, typer.Option(
            "--hue", help="Axis key: one line per value.")] = None,
        out: Annotated[Path | None, typer.Option(
            "--out", help="Figure file (default: DIR/<y>_vs_<x>.png).")] = None,
    ) -> None:
        """Plot one column of a sweep table against one axis (finished variants)."""
        from conrod.plotting.save import save_figure
        from conrod.plotting.sweep_plots import sweep_figure
        from conrod.report.inputs import unit_of
        from conrod.sweep import read_table

        frame = read_table(folder)
        for option, name in (("--x", x), ("--y", y), ("--hue", hue)):
            if name is not None:
                check_column(frame, option, name)
        units = {key: unit_of(key) for key in (x, hue) if key}
        target = out or folder / f"{y}_vs_{x}.png"
        save_figure(sweep_figure(frame, x, y, hue, units), target)
        typer.echo(str(target))
