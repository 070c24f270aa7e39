"""conrod — connecting-rod bearing dynamics.

Data flows one way: case file → loads → film model → orbit solver → contact/EHD →
results → output → plots/report. See ``docs/conventions.md`` for frames and signs.

Docstrings cite the five source documents as [D0]–[D4] (with their section or equation
numbers) and the literature by author and year; the full list is ``docs/references.md``.

The names below are imported when first used, so that ``import conrod`` (and
``conrod --version``) does not load the numerical stack.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr
from conrod._version import __version__
from conrod.io.numba_cache import default_optimisation_level, tolerate_unreadable_cache

tolerate_unreadable_cache()  # an unreadable cached kernel is compiled again, not an error
default_optimisation_level()  # LLVM level 2: 3/4 of the compile time, the same kernels' speed

_PUBLIC = {
    "BearingGeometry": "conrod.film.base",
    "Case": "conrod.cases.case",
    "CaseError": "conrod.errors",
    "ConrodError": "conrod.errors",
    "ConvergenceError": "conrod.errors",
    "CycleResults": "conrod.results.cycle_results",
    "FilmState": "conrod.film.base",
    "RunResults": "conrod.results.cycle_results",
    "RunSummary": "conrod.results.cycle_results",
    "Simulation": "conrod.simulation.simulation",
    "write_results": "conrod.output.registry",
}
"""Public name → the module that defines it."""

if TYPE_CHECKING:  # pragma: no cover
    from conrod.cases.case import Case
    from conrod.results.cycle_results import RunResults


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


def __dir__() -> list[str]:
    return sorted([*globals(), *_PUBLIC])


def run(case: Case | str | os.PathLike[str], **options) -> RunResults:
    """Periodic orbit and characteristics of ``case`` (a :class:`Case` or a case file):
    ``Simulation(case, **options).run()``; ``options`` as :class:`Simulation` (``film``,
    ``integrator``, ``max_cycles``, ...)."""
    from conrod.cases.case import Case
    from conrod.errors import CaseError
    from conrod.simulation.simulation import Simulation

    if not isinstance(case, Case | str | os.PathLike):
        raise CaseError(f"run: case = {type(case).__name__}: a conrod.Case or a case-file path "
                        "is required (Case.from_dict(data) for a dict)")
    if not isinstance(case, Case):
        case = Case.from_toml(case)
    return Simulation(case, **options).run()


__all__ = ["BearingGeometry", "Case", "CaseError", "ConrodError", "ConvergenceError",
           "CycleResults", "FilmState", "RunResults", "RunSummary", "Simulation", "run",
           "write_results", "__version__"]
