"""Many-variant studies: study files, the variant store, the table.

``Sweep(study, out).run()`` returns a pandas DataFrame with one row per variant and writes
``out/sweep.parquet``; the variants run in worker processes on this machine
(:mod:`conrod.sweep.pool`) or on a Dask cluster (:mod:`conrod.sweep.cluster`). See
:mod:`conrod.sweep.runner`, :mod:`conrod.sweep.study` and, for what a variant's status
means, :mod:`conrod.sweep.status`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.sweep.runner import Sweep, read_table
    from conrod.sweep.study import Study

_PUBLIC = {
    **dict.fromkeys(("Sweep", "read_table"), "conrod.sweep.runner"),
    "Study": "conrod.sweep.study",
}
"""Public name → the module that defines it (imported when the name is first used)."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["Study", "Sweep", "read_table"]
