"""Typed results of ``conrod run`` and their writers."""

from conrod.results.cycle_results import CycleResults, RunResults, RunSummary

__all__ = ["CycleResults", "RunResults", "RunSummary"]
