"""Figures: one function per figure, each taking results and returning a matplotlib Figure.

Plotting lives here only; models and results never import matplotlib.
"""

from conrod.plotting.save import save_figure

__all__ = ["save_figure"]
