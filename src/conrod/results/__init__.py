"""Typed, frozen results with units; their tables and figures are registered in
:mod:`conrod.output`."""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from conrod.results.cycle_results import CycleResults, RunResults, RunSummary

_PUBLIC = {
    **dict.fromkeys(("CycleResults", "RunResults", "RunSummary"), "conrod.results.cycle_results"),
}
"""Public name → the module that defines it (imported when the name is first used)."""


def __getattr__(name: str) -> Any:
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_PUBLIC[name]), name)
    globals()[name] = value
    return value


__all__ = ["CycleResults", "RunResults", "RunSummary"]
