"""Figures: one function per figure, each taking results and returning a matplotlib Figure.

Plotting lives here only; models and results never import matplotlib, and a figure only
draws what its results hold (it computes nothing). The figures are registered with their
result types in :mod:`conrod.output.figures`.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from conrod.plotting.save import save_figure

_PUBLIC = {
    "save_figure": "conrod.plotting.save",
}
"""Public name → the module that defines it (imported when the name is first used)."""


def __getattr__(name: str) -> Any:
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_PUBLIC[name]), name)
    globals()[name] = value
    return value


__all__ = ["save_figure"]
