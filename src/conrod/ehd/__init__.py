"""The elastohydrodynamic film: a deformable film on the bore of an elastic housing
(:class:`conrod.ehd.film.ElasticFilm`), the film–bore coupling and the film capabilities it
implements for the orbit (docs/ehd.md)."""
