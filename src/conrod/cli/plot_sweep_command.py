"""``conrod plot-sweep DIR --x KEY --y COLUMN [--hue KEY] [--out FILE.png]``: one
characteristic of a sweep against one axis, a line per value of another.

``--x``/``--hue`` take an axis by its case key (``engine.speed``) or by its table column
(``engine.speed_rpm``). Variants with warnings are hollow markers, a contact-set h_min is a
"hard contact" marker, failed variants are not drawn
(:mod:`conrod.plotting.sweep_plots`).
"""

from __future__ import annotations

import difflib
from pathlib import Path
from typing import Annotated, Any

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


def resolve_column(frame, option: str, name: str, axis_columns: dict[str, Any]) -> str:
    """The table column of ``name``: a column, or an axis given by its case key."""
    from conrod.sweep.columns import axis_column

    if name in frame.columns:
        return name
    column = str(axis_columns.get(name) or axis_column(name))
    if column in frame.columns:
        return column
    check_column(frame, option, name)
    return name


def register(app: typer.Typer) -> None:
    """Add the ``plot-sweep`` command to ``app``."""

    @app.command("plot-sweep")
    @exits_cleanly
    def plot_sweep(
        folder: Annotated[Path, typer.Argument(help="Sweep folder (with sweep.parquet).")],
        x: Annotated[str, typer.Option(
            "--x", help="Axis on the x axis: case key or column, e.g. engine.speed.")],
        y: Annotated[str, typer.Option("--y", help="Column on the y axis, e.g. h_min_m.")],
        hue: Annotated[str | None, typer.Option(
            "--hue", help="Axis (case key or column): one line per value.")] = None,
        out: Annotated[Path | None, typer.Option(
            "--out", help="Figure file (default: DIR/<y>_vs_<x column>.png).")] = None,
    ) -> None:
        """Plot one column of a sweep table against one axis (doubtful variants marked)."""
        from conrod.plotting.save import save_figure
        from conrod.plotting.sweep_plots import sweep_figure
        from conrod.sweep import read_table
        from conrod.sweep.columns import axis_label
        from conrod.sweep.runner import read_description

        frame = read_table(folder)
        axis_columns = read_description(folder).get("axis_columns") or {}
        x = resolve_column(frame, "--x", x, axis_columns)
        y = resolve_column(frame, "--y", y, axis_columns)
        hue = None if hue is None else resolve_column(frame, "--hue", hue, axis_columns)
        labels = {str(column): axis_label(key) for key, column in axis_columns.items()}
        target = out or folder / f"{y}_vs_{x}.png"
        save_figure(sweep_figure(frame, x, y, hue, labels), target)
        typer.echo(str(target))
