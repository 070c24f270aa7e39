"""``conrod report DIR``: one self-contained HTML page (and optionally PDF) of a run or a
sweep folder; figures embedded, nothing fetched from the network.

.. code-block:: python

    from conrod.report import write_report
    write_report("results/pc_sweep")            # → results/pc_sweep/report.html
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from conrod.errors import CaseError
from conrod.io.atomic import write_text

REPORT_FILE = "report.html"


def build_report(folder: str | os.PathLike[str], case_file: str | os.PathLike[str] | None = None
                 ) -> str:
    """The HTML of the report of a result folder: a run (``conrod run``, a sweep variant), a
    sweep, a housing or stress study, engine loads or a mechanism run, each with its own
    page. A run folder records its case (``case.toml``), so ``case_file`` is needed only for
    folders written by an older conrod."""
    from conrod.report.html import render_page
    from conrod.report.run_report import read_manifest, run_sections
    from conrod.report.structure_report import other_sections
    from conrod.report.sweep_report import sweep_sections

    folder = Path(folder)
    case = Path(case_file) if case_file is not None else None
    if case is not None and not case.is_file():
        raise CaseError(f"--case {str(case)!r}: no such file")
    manifest = read_manifest(folder) or {}
    kind = str(manifest.get("kind", "run"))
    if (folder / "sweep.parquet").is_file():
        title, sections = sweep_sections(folder, case)
        kind = "sweep"
    elif kind != "run" and manifest:
        title, sections = other_sections(folder, manifest)
    elif (folder / "summary.json").is_file() or manifest:
        title, sections = run_sections(folder, case)
        title = _case_title(case) or title
    else:
        raise CaseError(f"{str(folder)!r}: not a results folder (no summary.json, manifest.json "
                        "or sweep.parquet)")
    return render_page(title, f"conrod {kind.replace('_', ' ')} folder {folder.name}",
                       sections)


def write_report(folder: str | os.PathLike[str], out: str | os.PathLike[str] | None = None, *,
                 case_file: str | os.PathLike[str] | None = None, pdf: bool = False
                 ) -> list[Path]:
    """Write ``report.html`` (default inside ``folder``) and, with ``pdf``, the PDF next to it."""
    html = build_report(folder, case_file)
    target = Path(out) if out is not None else Path(folder) / REPORT_FILE
    paths = [write_text(target, html)]
    if pdf:
        from conrod.report.pdf import html_to_pdf

        paths.append(html_to_pdf(target, target.with_suffix(".pdf")))
    return paths


def _case_title(case: Path | None) -> str:
    if case is None:
        return ""
    try:
        return str(tomllib.loads(case.read_text(encoding="utf-8")).get("title", ""))
    except (OSError, tomllib.TOMLDecodeError):
        return ""


__all__ = ["build_report", "write_report"]
