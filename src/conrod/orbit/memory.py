"""Film memory as an integrator holds it: initialised, threaded, advanced, snapshot, restored.

A film that declares :class:`~conrod.film.capabilities.HasMemory` (Reynolds warm start,
mass-conserving film content) answers from an explicit memory value and returns the next
one. :class:`FilmSession` is that value in the integrator's hand: every solve goes through
it, a fixed-step integrator advances it after an accepted step, and a trial evaluation
(finite-difference Jacobian, rejected step) is wrapped in :meth:`FilmSession.snapshot` /
:meth:`FilmSession.restore`. Memory values are immutable, so a snapshot is the value itself
and restoring it gives a bit-identical continuation.
"""

from __future__ import annotations

from typing import Any

from conrod.film.base import FilmModel, FilmResult, FilmState
from conrod.film.capabilities import HasAcceptedAnswer, HasMemory, accepted_film


class FilmSession:
    """A film model and its current memory (None for a memoryless film).

    film : FilmModel  The film.
    memory : object or None  Start memory; None: ``film.initial_memory()``.
    """

    def __init__(self, film: FilmModel, memory: Any = None):
        self.film: Any = film
        self.has_memory = isinstance(film, HasMemory)
        self.answers = isinstance(film, HasAcceptedAnswer)  # asked once (accepted_film)
        if isinstance(film, HasMemory) and memory is None:
            memory = film.initial_memory()
        self.memory = memory if self.has_memory else None

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force (F_x, F_y) [N]; the memory moves on."""
        if not self.has_memory:
            return self.film.force(state)
        fx, fy, self.memory = self.film.force_with_memory(state, self.memory)
        return fx, fy

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Full film result; the memory moves on."""
        if not self.has_memory:
            return self.film.solve(state, with_pressure=with_pressure)
        result, self.memory = self.film.solve_with_memory(
            state, self.memory, with_pressure=with_pressure)
        return result

    def accepted(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Full film result at a state the integrator accepted with the current memory: the
        answer of the step that ended there when the memory holds it
        (:class:`~conrod.film.capabilities.HasAcceptedAnswer`), else a solve."""
        if not self.has_memory:
            return self.film.solve(state, with_pressure=with_pressure)
        result, self.memory = accepted_film(self.film, state, self.memory,
                                            with_pressure=with_pressure, answers=self.answers)
        return result

    def advance(self, state: FilmState, dt: float) -> None:
        """Advance the memory over an accepted step ``dt`` [s] taken from ``state``."""
        if self.has_memory:
            self.memory = self.film.advance_memory(state, self.memory, dt)

    def snapshot(self) -> Any:
        """The current memory (an immutable value)."""
        return self.memory

    def restore(self, memory: Any) -> None:
        """Continue from a snapshot."""
        self.memory = memory
