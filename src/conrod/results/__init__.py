"""Typed results and the one registry of their tables and figures."""

from conrod.results import tables as _tables  # noqa: F401  (registers the tables)
from conrod.results.cycle_results import CycleResults, RunResults, RunSummary
from conrod.results.output import FigureSpec, TableSpec, figures, tables, write_results

__all__ = ["CycleResults", "FigureSpec", "RunResults", "RunSummary", "TableSpec", "figures",
           "tables", "write_results"]
