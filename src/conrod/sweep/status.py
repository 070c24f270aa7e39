"""The status of a variant, and whether its smallest gap is a film thickness.

A variant's status says what ``conrod run`` (or ``conrod mechanism``) would have said about
the same case by its exit code:

=================  ==============================================================  =====
status             meaning                                                          exit
=================  ==============================================================  =====
``ok``             finished, periodic, no warning                                   0
``warning``        finished with warnings (``warnings`` column: contact carrying    4
                   the load, temperature out of the oil's range, film below the
                   roughness, ...): a doubtful result, not a design point
``not_periodic``   the orbit did not become periodic: written for diagnosis only    3
``failed``         no result (``error`` column: the solver's message)               3
=================  ==============================================================  =====

Where the journal touches the shell (hard contact), the smallest gap of the cycle is the
contact threshold h_c, a property of the contact model, not a film thickness:
:func:`h_min_set_by` says ``"contact"`` and the plots draw such points apart.
"""

from __future__ import annotations

from typing import Any

STATUS_OK = "ok"
STATUS_WARNING = "warning"
STATUS_NOT_PERIODIC = "not_periodic"
STATUS_FAILED = "failed"
STATUSES = (STATUS_OK, STATUS_WARNING, STATUS_NOT_PERIODIC, STATUS_FAILED)
"""Every status a variant can have, best first [-]."""

H_MIN_BY_FILM = "film"
H_MIN_BY_CONTACT = "contact"
WARNING_SEPARATOR = " | "
"""Between two warnings in the ``warnings`` column (a warning text may hold ';') [-]."""


def variant_status(summary: dict[str, Any]) -> str:
    """Status of a finished variant from its ``summary.json`` (see the module docstring)."""
    if summary.get("periodic") is False or summary.get("converged") is False:
        return STATUS_NOT_PERIODIC
    return STATUS_WARNING if variant_warnings(summary) else STATUS_OK


def variant_warnings(summary: dict[str, Any]) -> list[str]:
    """The warnings that make ``conrod run``/``conrod mechanism`` exit 4 (``summary.json``
    ``warnings``) [-]."""
    return [str(text) for text in summary.get("warnings") or []]


def h_min_set_by(summary: dict[str, Any]) -> str:
    """``"contact"`` when the journal touched the shell (hard contact in the orbit: the
    smallest gap is the contact threshold h_c), ``"film"`` otherwise; ``""`` without an
    h_min (a mechanism run or a failed variant)."""
    if summary.get("h_min_m") is None:
        return ""
    touching = summary.get("max_orbit_contact_force_N") or 0.0
    return H_MIN_BY_CONTACT if touching > 0.0 else H_MIN_BY_FILM
