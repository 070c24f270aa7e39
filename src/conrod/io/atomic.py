"""Atomic writes: write to a temporary file in the target folder, then rename.

``os.replace`` is atomic on POSIX and Windows when source and target are on the
same file system, which a sibling temporary file guarantees.
"""

from __future__ import annotations

import contextlib
import json
import os
import tempfile
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

_FILE_MODE = 0o644
"""Permissions of result files (mkstemp creates 0600)."""


@contextlib.contextmanager
def atomic_path(target: str | os.PathLike[str]) -> Iterator[Path]:
    """Yield a temporary path next to ``target``; rename it onto ``target`` on success.

    On any exception the temporary file is removed and ``target`` is untouched.
    The temporary name keeps the target's suffix so that writers which infer the
    format from the suffix (matplotlib's ``savefig``) still work.
    """
    target = Path(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(
        prefix=f".{target.stem}.", suffix=target.suffix, dir=target.parent
)
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        os.chmod(tmp, _FILE_MODE)
        os.replace(tmp, target)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise


def write_text(target: str | os.PathLike[str], text: str) -> Path:
    """Write ``text`` to ``target`` atomically and return the path."""
    with atomic_path(target) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return Path(target)


def _json_default(value: Any) -> Any:
    if isinstance(value, np.generic):
        return value.item()
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"cannot write {type(value).__name__} to JSON")


def write_json(target: str | os.PathLike[str], data: Mapping[str, Any]) -> Path:
    """Write ``data`` as indented JSON atomically; NaN/inf are refused (not valid JSON)."""
    text = json.dumps(data, indent=2, default=_json_default, allow_nan=False)
    return write_text(target, text + "\n")


def write_csv(
    target: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    *,
    float_format: str = "%.9g",
) -> Path:
    """Write equal-length 1-D ``columns`` (name → values) as CSV atomically."""
    names = list(columns)
    arrays = [np.asarray(columns[name]) for name in names]
    lengths = {a.shape for a in arrays}
    if len(lengths) != 1 or len(next(iter(lengths))) != 1:
        raise ValueError(f"CSV columns must be 1-D and equal length, got shapes {lengths}")
    with atomic_path(target) as tmp, open(tmp, "w", encoding="utf-8", newline="") as handle:
        handle.write(",".join(names) + "\n")
        table = np.column_stack(
            [a.astype(float) if a.dtype.kind in "biuf" else a for a in arrays]
)
        if all(a.dtype.kind in "biuf" for a in arrays):
            np.savetxt(handle, table, delimiter=",", fmt=float_format)
        else:
            for row in table:
                handle.write(",".join(str(v) for v in row) + "\n")
    return Path(target)
