"""Many-variant studies on Dask distributed: study files, the variant store, the table.

``Sweep(study, out).run()`` returns a pandas DataFrame with one row per variant and writes
``out/sweep.parquet``; see :mod:`conrod.sweep.runner` and :mod:`conrod.sweep.study`.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from conrod.sweep.runner import Sweep, read_table
    from conrod.sweep.study import Study

_PUBLIC = {
    **dict.fromkeys(("Sweep", "read_table"), "conrod.sweep.runner"),
    "Study": "conrod.sweep.study",
}
"""Public name → the module that defines it (imported when the name is first used)."""


def __getattr__(name: str) -> Any:
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_PUBLIC[name]), name)
    globals()[name] = value
    return value


__all__ = ["Study", "Sweep", "read_table"]
