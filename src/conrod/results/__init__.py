"""Typed, frozen results with units; their tables and figures are registered in
:mod:`conrod.output`."""

from conrod.results.cycle_results import CycleResults, RunResults, RunSummary

__all__ = ["CycleResults", "RunResults", "RunSummary"]
