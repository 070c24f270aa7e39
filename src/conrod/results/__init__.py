"""Typed, frozen results with units; their tables and figures are registered in
:mod:`conrod.output`."""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.results.cycle_results import CycleResults, RunResults, RunSummary

_PUBLIC = {
    **dict.fromkeys(("CycleResults", "RunResults", "RunSummary"), "conrod.results.cycle_results"),
}
"""Public name → the module that defines it (imported when the name is first used)."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["CycleResults", "RunResults", "RunSummary"]
