"""In-cycle progress of the orbit integrators, for a progress display.

An integrator calls :func:`report_angle` with the crank angle it has reached in the
current cycle (the implicit integrator after every :data:`REPORT_EVERY_DEG` of crank
angle); whoever wants to know (the command line's progress display, through
:func:`conrod.orbit.periodic.periodic_orbit`) installs a hook with :func:`reporting`.
Without a hook a report costs one context-variable lookup; the hook never changes what
is computed.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from contextvars import ContextVar

REPORT_EVERY_DEG = 30.0
"""Crank angle between two reports of the implicit integrator [deg]; its free flight is
integrated in chunks ending on these angles (with or without a hook, so the result does
not depend on the display)."""

_HOOK: ContextVar[Callable[[float], None] | None] = ContextVar("orbit_angle_hook",
                                                               default=None)


def report_angle(phi: float) -> None:
    """Crank angle reached in the current cycle [rad], to the installed hook if any."""
    hook = _HOOK.get()
    if hook is not None:
        hook(phi)


@contextmanager
def reporting(hook: Callable[[float], None] | None) -> Iterator[None]:
    """Install ``hook`` (crank angle in the cycle [rad] → None) while the block runs."""
    token = _HOOK.set(hook)
    try:
        yield
    finally:
        _HOOK.reset(token)


class AngleReports:
    """Reports of a fixed-step loop: call :meth:`reached` after each step; it reports
    the crank angle once every :data:`REPORT_EVERY_DEG` [deg] of the cycle."""

    def __init__(self) -> None:
        self.next = math.radians(REPORT_EVERY_DEG)

    def reached(self, phi: float) -> None:
        """The loop has reached crank angle ``phi`` [rad] in the current cycle."""
        if phi >= self.next:
            report_angle(phi)
            step = math.radians(REPORT_EVERY_DEG)
            self.next = (math.floor(phi / step + 1e-9) + 1) * step
