"""Figures: one function per figure, each taking results and returning a matplotlib Figure.

Plotting lives here only; models and results never import matplotlib, and a figure only
draws what its results hold (it computes nothing). The figures are registered with their
result types in :mod:`conrod.output.figures`.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.plotting.save import save_figure

_PUBLIC = {
    "save_figure": "conrod.plotting.save",
}
"""Public name → the module that defines it (imported when the name is first used)."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["save_figure"]
