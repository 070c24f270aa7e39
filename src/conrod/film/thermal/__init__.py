"""The film's temperature field (thermal film, THD): cycle-mean flows and dissipation on the
film grid (:mod:`conrod.film.thermal.flows`) and the steady energy equation averaged across
the film thickness (:mod:`conrod.film.thermal.energy`)."""
