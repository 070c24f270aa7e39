"""Figures: one function per figure, each taking results and returning a matplotlib Figure.

Plotting lives here only; models and results never import matplotlib, and a figure only
draws what its results hold (it computes nothing). The figures are registered with their
result types in :mod:`conrod.output.figures`.
"""

from conrod.plotting.save import save_figure

__all__ = ["save_figure"]
