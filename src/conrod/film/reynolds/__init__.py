"""The finite-length Reynolds film: finite differences, Swift–Stieber cavitation by projection,
projected multigrid, warm start, its compiled force for the orbit and its response to a
film-thickness change."""
