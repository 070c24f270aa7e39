"""Oil-film models behind one interface (:class:`conrod.film.base.FilmModel`)."""

from conrod.film.base import BearingGeometry, FeedHole, FilmModel, FilmResult, FilmState, Groove
from conrod.film.short_bearing import ShortBearingFilm

__all__ = [
    "BearingGeometry",
    "FeedHole",
    "FilmModel",
    "FilmResult",
    "FilmState",
    "Groove",
    "ShortBearingFilm",
]
