"""Figures: one function per figure, each taking results and returning a matplotlib Figure.

Plotting lives here only; models and results never import matplotlib. Importing this
package registers every figure in :func:`conrod.results.output.figures`.
"""

from conrod.plotting import registry as _registry  # noqa: F401  (registers the figures)
from conrod.plotting.save import save_figure

__all__ = ["save_figure"]
