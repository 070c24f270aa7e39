"""The one registry of tables and figures of every result type, and the one writer of a
result folder (:func:`conrod.output.registry.write_results`).

Importing this package registers every table (:mod:`conrod.output.tables`) and figure
(:mod:`conrod.output.figures`; matplotlib is imported only when a figure is built).
"""

from conrod.output import ehd_tables as _ehd_tables  # noqa: F401  (registers the tables)
from conrod.output import figures as _figures  # noqa: F401  (registers the figures)
from conrod.output import housing_tables as _housing_tables  # noqa: F401  (registers both)
from conrod.output import tables as _tables  # noqa: F401,I001  (registers the tables)
from conrod.output import thermal_tables as _thermal_tables  # noqa: F401,I001  (registers both)
from conrod.output.registry import (
    FigureSpec,
    TableSpec,
    figures,
    result_kind,
    tables,
    write_results,
)

__all__ = ["FigureSpec", "TableSpec", "figures", "result_kind", "tables", "write_results"]
