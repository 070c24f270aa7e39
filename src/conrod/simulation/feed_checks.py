"""What a run with oil holes in the crank pin (``[[bearing.journal_holes]]``) can be
combined with: refused before the run where the hole would be ignored or left where it
was; and the oil feed the mass-conserving film's orbit needs (both used by
:class:`conrod.simulation.simulation.Simulation`)."""

from __future__ import annotations

from typing import Any

from conrod.errors import CaseError

JOURNAL_HOLE_FILMS = ("reynolds", "mass_conserving")
"""Films whose grid holds the journal's turning oil holes [-]."""


def check_journal_holes(geometry: Any, film: str, tilt: Any, elastic: bool = False) -> None:
    """CaseError (one line) when ``geometry`` has journal holes and the film named ``film``
    would ignore them (not a grid film of :data:`JOURNAL_HOLE_FILMS`), with a solved
    journal ``tilt`` or, with ``elastic``, on an elastic bore (their step systems do not
    pass the feed on)."""
    if not geometry.journal_holes:
        return
    if film not in JOURNAL_HOLE_FILMS:
        raise CaseError(f"bearing.journal_holes with solver.film = {film!r}: the hole "
                        "would be ignored (allowed: reynolds, mass_conserving)")
    if tilt is not None:
        raise CaseError("bearing.journal_holes with a journal tilt ([misalignment]): not "
                        "available (allowed: an aligned journal, or the feed through shell "
                        "grooves and holes)")
    if elastic:
        raise CaseError("bearing.journal_holes with an elastic [housing]: not available "
                        "(allowed: housing.model = 'rigid', or the feed through shell "
                        "grooves and holes)")


def check_oil_feed(geometry: Any, film: str) -> None:
    """The mass-conserving film in an orbit needs oil fed above the cavitation pressure
    through a groove or a hole: without it the lands starve over the cycle and the orbit
    cannot converge (a steady film solve does not need it)."""
    fed = (geometry.grooves or geometry.feed_holes) and (
        geometry.supply_pressure > geometry.cavitation_pressure) or geometry.journal_holes
    if film == "mass_conserving" and not fed:
        raise CaseError(
            "solver.film = 'mass_conserving': needs an oil feed above the cavitation pressure "
            f"(bearing.supply_pressure = {geometry.supply_pressure:g} Pa, cavitation "
            f"{geometry.cavitation_pressure:g} Pa, {len(geometry.grooves)} groove(s), "
            f"{len(geometry.feed_holes)} hole(s)): add a groove or feed hole to [bearing] and "
            "set bearing.supply_pressure, or use film = 'reynolds'")
