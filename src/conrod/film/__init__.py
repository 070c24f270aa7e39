"""Oil-film models behind one interface (:class:`conrod.film.base.FilmModel`) and the
optional capabilities a model declares (:mod:`conrod.film.capabilities`).

The names below are imported when first used, so that reading a case file (which needs
:class:`BearingGeometry`) does not compile or load a film model.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.film.base import (
        BearingGeometry,
        FeedHole,
        FilmModel,
        FilmResult,
        FilmState,
        Groove,
    )
    from conrod.film.capabilities import (
        CompiledKernel,
        HasCompiledKernel,
        HasMemory,
        QuasiStaticRequest,
        SupportsDeformation,
    )
    from conrod.film.short.film import ShortBearingFilm
    from conrod.film.wrapper import FilmWrapper

_PUBLIC = {
    **dict.fromkeys(("BearingGeometry", "FeedHole", "FilmModel", "FilmResult", "FilmState",
                     "Groove"), "conrod.film.base"),
    **dict.fromkeys(("CompiledKernel", "HasCompiledKernel", "HasMemory", "QuasiStaticRequest",
                     "SupportsDeformation"), "conrod.film.capabilities"),
    "ShortBearingFilm": "conrod.film.short.film",
    "FilmWrapper": "conrod.film.wrapper",
}
"""Public name → the module that defines it."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = [
    "BearingGeometry",
    "CompiledKernel",
    "FeedHole",
    "FilmModel",
    "FilmResult",
    "FilmState",
    "FilmWrapper",
    "Groove",
    "HasCompiledKernel",
    "HasMemory",
    "QuasiStaticRequest",
    "ShortBearingFilm",
    "SupportsDeformation",
]
