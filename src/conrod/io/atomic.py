"""Atomic writes: write to a temporary file in the target folder, then rename.

``os.replace`` is atomic on POSIX and Windows when source and target are on the
same file system, which a sibling temporary file guarantees.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import tempfile
from collections.abc import Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np

from conrod.errors import NonFiniteResultError

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


def first_non_finite(data: Any, where: str = "") -> tuple[str, Any] | None:
    """(dotted key, value) of the first NaN or infinite number in nested data, else None."""
    if isinstance(data, Mapping):
        items: Any = ((f"{where}.{key}" if where else str(key), value)
                      for key, value in data.items())
    elif isinstance(data, list | tuple | np.ndarray):
        items = ((f"{where}[{index}]", value) for index, value in enumerate(data))
    else:
        if isinstance(data, float | np.floating) and not math.isfinite(data):
            return where, data
        return None
    for key, value in items:
        found = first_non_finite(value, key)
        if found is not None:
            return found
    return None


def write_json(target: str | os.PathLike[str], data: Mapping[str, Any]) -> Path:
    """Write ``data`` as indented JSON atomically.

    NaN and infinity are not JSON: a result holding one raises
    :class:`~conrod.errors.ConvergenceError` naming the file and the field, and nothing is
    written.
    """
    found = first_non_finite(data)
    if found is not None:
        raise NonFiniteResultError(f"non-finite result {found[0]} = {found[1]} in "
                               f"{Path(target).name}; nothing written")
    text = json.dumps(data, indent=2, default=_json_default, allow_nan=False)
    return write_text(target, text + "\n")


def _check_finite_columns(file: str, names: list[str], arrays: list[np.ndarray]) -> None:
    for name, values in zip(names, arrays, strict=True):
        if values.dtype.kind == "f" and not np.all(np.isfinite(values)):
            row = int(np.flatnonzero(~np.isfinite(values))[0])
            raise NonFiniteResultError(f"non-finite result {name} = {values[row]} in {file}, "
                                   f"row {row + 1}; nothing written")


def write_csv(
    target: str | os.PathLike[str],
    columns: Mapping[str, np.ndarray],
    *,
    float_format: str = "%.9g",
) -> Path:
    """Write equal-length 1-D ``columns`` (name → values) as CSV atomically.

    Only finite numbers are written: a NaN or infinite value raises
    :class:`~conrod.errors.ConvergenceError` naming the file, the column and the row.
    """
    names = list(columns)
    arrays = [np.asarray(columns[name]) for name in names]
    lengths = {a.shape for a in arrays}
    if len(lengths) != 1 or len(next(iter(lengths))) != 1:
        raise ValueError(f"CSV columns must be 1-D and equal length, got shapes {lengths}")
    _check_finite_columns(Path(target).name, names, arrays)
    with atomic_path(target) as tmp, open(tmp, "w", encoding="utf-8", newline="") as handle:
        handle.write(",".join(names) + "\n")
        table = np.column_stack(
            [a.astype(float) if a.dtype.kind in "biuf" else a for a in arrays]
)
        if all(a.dtype.kind in "biuf" for a in arrays):  # np.savetxt's text, one % for all
            row = ",".join([float_format] * table.shape[1]) + "\n"
            handle.write((row * table.shape[0]) % tuple(table.ravel().tolist()))
        else:
            for row in table:
                handle.write(",".join(str(v) for v in row) + "\n")
    return Path(target)


def write_npz(target: str | os.PathLike[str], arrays: Mapping[str, np.ndarray]) -> Path:
    """Write the named ``arrays`` as one uncompressed ``.npz`` to ``target`` atomically."""
    with atomic_path(target) as tmp, open(tmp, "wb") as handle:
        np.savez(handle, **{name: np.asarray(value) for name, value in arrays.items()})
    return Path(target)
