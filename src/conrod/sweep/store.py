"""The variant store: ``DIR/variants/<hash>/``, one folder per finished variant.

A variant's files are written by the one writer of every command
(:func:`conrod.output.registry.write_results`): into a hidden staging folder that is swapped
in as ``DIR/variants/<hash>`` whole. Its record ``variant.json`` is written last (itself
atomically, a temporary file renamed): a folder counts as a finished variant only once it
holds that record. A worker killed half-way leaves a staging folder or a folder without
a record; the next run removes both.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

from conrod.io.atomic import write_json

RECORD = "variant.json"
"""The record of a finished variant, written last: axes, case, status, summary [-]."""


def variants_dir(out: Path) -> Path:
    """Folder of the variant store of a sweep folder."""
    return Path(out) / "variants"


def read_record(out: Path, key: str) -> dict[str, Any] | None:
    """The record of a finished variant, or None if it has not finished."""
    path = variants_dir(out) / key / RECORD
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None


def variant_folder(out: Path, key: str) -> Path:
    """Folder of the variant ``key`` (written as a whole by the one writer, then committed)."""
    return variants_dir(out) / key


def commit_variant(folder: Path, record: dict[str, Any]) -> Path:
    """Write the record last: from now on ``folder`` counts as a finished variant."""
    write_json(folder / RECORD, record)
    return folder


def discard_unfinished(folder: Path) -> None:
    """Remove a variant folder that holds no record (a write or commit that failed)."""
    if folder.is_dir() and not (folder / RECORD).is_file():
        shutil.rmtree(folder, ignore_errors=True)


def remove_stale(out: Path) -> int:
    """Remove temporary folders left by interrupted runs and unfinished hash folders."""
    root = variants_dir(out)
    if not root.is_dir():
        return 0
    removed = 0
    for entry in root.iterdir():
        if entry.is_dir() and (entry.name.startswith(".") or not (entry / RECORD).is_file()):
            shutil.rmtree(entry, ignore_errors=True)
            removed += 1
    return removed
