"""Base of a film model that wraps another one and declares what the inner model declares.

A wrapper (worn shell, mixed lubrication, elastic housing) changes the state handed to its
``base`` film (:meth:`FilmWrapper.adjust_state`, e.g. adds a deformation field) and/or the
force and result it returns (:meth:`adjust_force`, :meth:`adjust_result`). The optional
capabilities of :mod:`conrod.film.capabilities` are delegated *only when the base declares
them*: ``isinstance(wrapper, HasMemory)`` is true exactly when ``base`` has a memory, and
the memory passes through the wrapper untouched. A compiled kernel is not delegated by
default (the base kernel knows nothing of the wrapper's change); a subclass that can
express its change in compiled form overrides :meth:`compiled_kernel` itself.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.film.base import BearingGeometry, FilmResult, FilmState

DELEGATED = ("initial_memory", "solve_with_memory", "force_with_memory", "advance_memory",
             "deformation_shape", "compiled_kernel")
"""Capability methods a wrapper declares when its base does [-]."""


class FilmWrapper:
    """Film model around ``self.base``; subclasses set ``base`` (e.g. a dataclass field)."""

    base: Any

    # ------------------------------------------------------------------- hooks
    def adjust_state(self, state: FilmState) -> FilmState:
        """State handed to the base film (default: unchanged)."""
        return state

    def adjust_force(self, state: FilmState, fx: float, fy: float) -> tuple[float, float]:
        """Force [N] returned for ``state`` from the base film's (default: unchanged)."""
        return fx, fy

    def adjust_result(self, state: FilmState, result: FilmResult) -> FilmResult:
        """Result returned for ``state`` from the base film's (default: unchanged)."""
        return result

    # --------------------------------------------------------------- interface
    @property
    def name(self) -> str:
        """Name of the base film model [-]."""
        return self.base.name

    @property
    def geometry(self) -> BearingGeometry:
        """Bearing geometry of the base film."""
        return self.base.geometry

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """Grid of the base film [rad], [m]."""
        return self.base.grid()

    def initial_history(self) -> np.ndarray | None:
        """Film-content history of the base film."""
        return self.base.initial_history()

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]."""
        fx, fy = self.base.force(self.adjust_state(state))
        return self.adjust_force(state, float(fx), float(fy))

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Full result of the base film, adjusted."""
        result = self.base.solve(self.adjust_state(state), with_pressure=with_pressure)
        return self.adjust_result(state, result)

    # ----------------------------------------------------- delegated capabilities
    def __getattr__(self, name: str) -> Any:
        if name not in DELEGATED or name.startswith("__"):
            raise AttributeError(name)
        inner = getattr(self.__dict__.get("base"), name)  # AttributeError: not declared
        return getattr(self, f"_delegate_{name}")(inner)

    def _delegate_initial_memory(self, inner):
        return inner

    def _delegate_deformation_shape(self, inner):
        return inner

    def _delegate_compiled_kernel(self, inner):
        return lambda: None

    def _delegate_advance_memory(self, inner):
        def advance_memory(state: FilmState, memory: Any, dt: float) -> Any:
            return inner(self.adjust_state(state), memory, dt)
        return advance_memory

    def _delegate_solve_with_memory(self, inner):
        def solve_with_memory(state: FilmState, memory: Any, *, with_pressure: bool = False):
            result, memory = inner(self.adjust_state(state), memory, with_pressure=with_pressure)
            return self.adjust_result(state, result), memory
        return solve_with_memory

    def _delegate_force_with_memory(self, inner):
        def force_with_memory(state: FilmState, memory: Any):
            fx, fy, memory = inner(self.adjust_state(state), memory)
            return (*self.adjust_force(state, float(fx), float(fy)), memory)
        return force_with_memory
