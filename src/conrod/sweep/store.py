"""The variant store: ``DIR/variants/<hash>/``, one folder per finished variant.

A variant is computed into a temporary sibling folder ``DIR/variants/.<hash>.<random>``;
its record ``variant.json`` is written last, then the folder is renamed onto
``<hash>`` with ``os.replace`` (atomic on one file system). A folder named by its hash
therefore always holds a complete variant; a worker killed half-way leaves only a
temporary folder, which the next run removes.
"""

from __future__ import annotations

import json
import os
import shutil
import tempfile
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


def new_variant_folder(out: Path, key: str) -> Path:
    """A fresh temporary folder next to the final one."""
    root = variants_dir(out)
    root.mkdir(parents=True, exist_ok=True)
    return Path(tempfile.mkdtemp(prefix=f".{key}.", dir=root))


def commit_variant(tmp: Path, record: dict[str, Any]) -> Path:
    """Write the record last and rename ``tmp`` onto its final name.

    If another worker finished the same variant first, its folder is kept and ``tmp``
    is removed (both hold the same content: same case, same version).
    """
    final = tmp.parent / record["hash"]
    write_json(tmp / RECORD, record)
    os.chmod(tmp, 0o755)
    try:
        os.replace(tmp, final)
    except OSError:
        if not (final / RECORD).is_file():
            raise
        shutil.rmtree(tmp, ignore_errors=True)
    return final


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
