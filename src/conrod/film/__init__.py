"""Oil-film models behind one interface (:class:`conrod.film.base.FilmModel`) and the
optional capabilities a model declares (:mod:`conrod.film.capabilities`)."""

from conrod.film.base import BearingGeometry, FeedHole, FilmModel, FilmResult, FilmState, Groove
from conrod.film.capabilities import (
    CompiledKernel,
    HasCompiledKernel,
    HasMemory,
    QuasiStaticRequest,
    SupportsDeformation,
)
from conrod.film.short_bearing import ShortBearingFilm
from conrod.film.wrapper import FilmWrapper

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
