"""``conrod report DIR [--case CASE.toml] [--out FILE.html] [--pdf]``: one self-contained
HTML page of a run or sweep folder (figures embedded), optionally printed to PDF."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated

import typer

from conrod.cli.app import exits_cleanly, printing_after_results


def register(app: typer.Typer) -> None:
    """Add the ``report`` command to ``app``."""

    @app.command("report")
    @exits_cleanly
    def report(
        folder: Annotated[Path, typer.Argument(help="Run or sweep results folder.")],
        out: Annotated[Path | None, typer.Option(
            "--out", help="HTML file (default: DIR/report.html).")] = None,
        case: Annotated[Path | None, typer.Option(
            "--case", help="Case file of a run folder (lists its inputs and sources).")] = None,
        pdf: Annotated[bool, typer.Option(
            "--pdf", help="Also print the page to PDF (needs Chromium or Chrome).")] = False,
    ) -> None:
        """Self-contained HTML report (figures embedded, no network needed) of a results folder."""
        from conrod.report import write_report

        paths = write_report(folder, out, case_file=case, pdf=pdf)
        with printing_after_results(paths[0].parent):
            typer.echo(" ".join(str(p) for p in paths))
