"""conrod — connecting-rod bearing dynamics.

Data flows one way: case file → loads → film model → orbit solver → contact/EHD →
results → plots/report. See ``docs/conventions.md`` for frames and signs.

Docstrings cite the five source documents as [D0]–[D4] (with their section or equation
numbers) and the literature by author and year; the full list is ``docs/references.md``.
"""

from conrod.cases import Case
from conrod.errors import CaseError, ConrodError, ConvergenceError
from conrod.simulation import Simulation

__all__ = ["Case", "CaseError", "ConrodError", "ConvergenceError", "Simulation"]
__version__ = "0.1.0"
