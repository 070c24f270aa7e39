"""conrod — connecting-rod bearing dynamics.

Data flows one way: case file → loads → film model → orbit solver → contact/EHD →
results → plots/report. See ``docs/conventions.md`` for frames and signs.

Docstrings cite the five source documents as [D0]–[D4] (with their section or equation
numbers) and the literature by author and year; the full list is ``docs/references.md``.
"""

from __future__ import annotations

import os

__version__ = "0.1.0"

from conrod.cases import Case  # noqa: E402
from conrod.errors import CaseError, ConrodError, ConvergenceError  # noqa: E402
from conrod.film.base import BearingGeometry, FilmState  # noqa: E402
from conrod.results.cycle_results import CycleResults, RunResults, RunSummary  # noqa: E402
from conrod.results.output import write_results  # noqa: E402
from conrod.simulation import Simulation  # noqa: E402


def run(case: Case | str | os.PathLike[str], **options) -> RunResults:
    """Periodic orbit and characteristics of ``case`` (a :class:`Case` or a case file):
    ``Simulation(case, **options).run()``; ``options`` as :class:`Simulation` (``film``,
    ``integrator``, ``max_cycles``, ...)."""
    if not isinstance(case, Case):
        case = Case.from_toml(case)
    return Simulation(case, **options).run()


__all__ = ["BearingGeometry", "Case", "CaseError", "ConrodError", "ConvergenceError",
           "CycleResults", "FilmState", "RunResults", "RunSummary", "Simulation", "run",
           "write_results", "__version__"]
