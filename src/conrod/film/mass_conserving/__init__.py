"""The mass-conserving (JFO, Elrod–Adams) film: the cell balance, the film content carried by
the integrator, its implicit content step and its response to a film-thickness change."""
