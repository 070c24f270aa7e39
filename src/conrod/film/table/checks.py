"""Which bearings a force table (or a mobility map) can represent."""

from __future__ import annotations

import math

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry


def check_tabulable(geometry: BearingGeometry, film: str = "table") -> None:
    """CaseError unless the film is rotation-invariant and homogeneous in speed; the
    message names ``film``, the model that was asked for ('table' or 'mobility')."""
    if geometry.feed_holes:
        raise CaseError(f"film = {film!r}: feed holes break rotational symmetry "
                        "(allowed: none; use 'reynolds' or 'mass_conserving')")
    if any(g.extent < 2.0 * math.pi - 1e-9 for g in geometry.grooves):
        raise CaseError(f"film = {film!r}: partial grooves are not allowed "
                        "(allowed: full circumferential grooves only)")
    if geometry.grooves and geometry.supply_pressure != 0.0:
        raise CaseError(
            f"supply_pressure = {geometry.supply_pressure} Pa with film {film!r}: allowed "
            "0 Pa (the map is computed once and scaled with speed; a supply pressure adds "
            "a part that does not scale); use film 'reynolds' or 'mass_conserving'")
    if geometry.cavitation_pressure != 0.0:
        raise CaseError(f"cavitation_pressure = {geometry.cavitation_pressure} Pa with film "
                        f"{film!r}: allowed 0 Pa (ambient)")
    if geometry.profile is not None:
        raise CaseError(f"film = {film!r}: a bore profile breaks rotational symmetry (allowed: "
                        "none; use 'reynolds' or 'mass_conserving')")
