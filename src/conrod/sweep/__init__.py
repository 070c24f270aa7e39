"""Many-variant studies on Dask distributed: study files, the variant store, the table.

``Sweep(study, out).run()`` returns a pandas DataFrame with one row per variant and writes
``out/sweep.parquet``; see :mod:`conrod.sweep.runner` and :mod:`conrod.sweep.study`.
"""

from conrod.sweep.runner import Sweep, read_table
from conrod.sweep.study import Study

__all__ = ["Study", "Sweep", "read_table"]
