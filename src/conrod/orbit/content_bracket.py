"""Bracketed force balance of one implicit massless step of a film with a content.

Where the pressurised part of a mass-conserving film is a narrow strip (one row of cells
next to a ruptured region), the film force points along that strip whatever the journal
velocity: its damping matrix ∂F/∂ė has rank one. The load's component across the strip
can then be balanced only by moving the journal far enough to fill further cells. The
massless journal jumps there; the implicit step (backward Euler or BDF2, both L-stable)
lands on the state after the jump, which lies far from any local Newton iterate: a damped
Newton or Levenberg–Marquardt iteration stalls with a residual that lies in the null
direction of the Jacobian.

This search finds that end position by two nested bracketed root searches (Brent [1]) in
the frame of the load: n̂ along the load W, t̂ across it. For an end position
e = g + α n̂ + β t̂ (g the stalled iterate) the inner search finds α(β) with (W + F)·n̂ = 0
(the film force along the load grows monotonically as the journal moves along the load
and squeezes the film); the outer search finds β with (W + F)·t̂ = 0 at α(β), expanding a
bracket from β = 0 in both directions. Every trial stays inside the contact circle.

[1] R.P. Brent, "Algorithms for Minimization without Derivatives", Prentice-Hall (1973),
    ch. 4.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq

from conrod.errors import ConvergenceError

FIRST_OFFSET = 1.0e-3
"""First trial offset of a bracket, relative to the radial clearance [-]."""
GROWTH = 3.0
"""Factor by which a bracket's trial offset grows [-]."""
POSITION_TOLERANCE = 1.0e-12
"""Tolerance of the end position in the root searches, relative to the clearance [-]."""

Residual = Callable[[float, float], tuple[np.ndarray, Any]]
"""(x, y) end position [m] → (residual W + F − m dv/dt [N], film memory at the end)."""


@dataclass
class Balanced:
    """End position [m] of a balanced step, its residual [N] and film memory."""

    x: float
    y: float
    residual: np.ndarray
    memory: Any


class _Frame:
    """Positions g + α n̂ + β t̂ inside the circle of radius ``radius`` [m]."""

    def __init__(self, guess, load, radius: float):
        self.g = np.asarray(guess, dtype=float)
        size = math.hypot(*load)
        self.n = np.asarray(load, dtype=float) / size if size > 0.0 else np.array([1.0, 0.0])
        self.t = np.array([-self.n[1], self.n[0]])
        self.radius = radius

    def point(self, alpha: float, beta: float) -> np.ndarray:
        return self.g + alpha * self.n + beta * self.t

    def chord(self, beta: float) -> tuple[float, float] | None:
        """Range of α that keeps g + α n̂ + β t̂ inside the circle; None off the circle."""
        centre = self.g + beta * self.t
        along = float(centre @ self.n)
        gap = self.radius**2 - float(centre @ centre) + along**2
        if gap <= 0.0:
            return None
        half = math.sqrt(gap)
        return -along - half, -along + half


class _Search:
    """The nested bracketed searches over one step's residual."""

    def __init__(self, residual: Residual, frame: _Frame, clearance: float):
        self.residual = residual
        self.frame = frame
        self.clearance = clearance
        self.alpha = 0.0  # inner root of the last outer trial: next inner start
        self.last: Balanced | None = None

    def evaluate(self, alpha: float, beta: float) -> np.ndarray | None:
        x, y = self.frame.point(alpha, beta)
        try:
            r, memory = self.residual(float(x), float(y))
        except ConvergenceError:
            return None
        self.last = Balanced(float(x), float(y), r, memory)
        return r

    def along(self, beta: float) -> float | None:
        """α(β) with (W + F)·n̂ = 0 inside the circle, None where there is none."""
        limits = self.frame.chord(beta)
        if limits is None:
            return None
        n = self.frame.n

        def normal(alpha):
            r = self.evaluate(alpha, beta)
            return math.nan if r is None else float(r @ n)

        bracket = _bracket(normal, min(max(self.alpha, limits[0]), limits[1]), limits,
                           FIRST_OFFSET * self.clearance)
        if bracket is None:
            return None
        alpha = bracket[0]
        if bracket[0] != bracket[1]:
            try:
                alpha = brentq(normal, *bracket, xtol=POSITION_TOLERANCE * self.clearance)
            except ValueError:  # the film failed somewhere inside the bracket
                return None
        self.alpha = alpha
        return alpha

    def across(self, beta: float) -> float:
        """(W + F)·t̂ [N] at (α(β), β); NaN where the inner search has no root."""
        alpha = self.along(beta)
        if alpha is None:
            return math.nan
        r = self.evaluate(alpha, beta)
        return math.nan if r is None else float(r @ self.frame.t)


def _bracket(f: Callable[[float], float], x0: float, limits: tuple[float, float],
             offset: float) -> tuple[float, float] | None:
    """(a, b) around x0 within ``limits`` with f(a), f(b) of opposite signs; trial offsets
    grow by :data:`GROWTH` on both sides; None when none is found."""
    f0 = f(x0)
    if f0 == 0.0:
        return x0, x0
    if math.isnan(f0):
        return None
    sides = {-1: (x0, f0), 1: (x0, f0)}
    while sides:
        for side in list(sides):
            x_old, f_old = sides[side]
            x = min(max(x0 + side * offset, limits[0]), limits[1])
            value = f(x)
            if math.isnan(value) or x == x_old:
                del sides[side]  # outside the admissible region on this side
                continue
            if value == 0.0 or (value > 0.0) != (f_old > 0.0):
                return (min(x_old, x), max(x_old, x))
            sides[side] = (x, value)
        offset *= GROWTH
    return None


def bracketed_balance(residual: Residual, guess, load, radius: float,
                      clearance: float) -> Balanced | None:
    """End position inside the circle of ``radius`` [m] where the residual vanishes, found
    from ``guess`` [m] by nested bracketed searches in the frame of ``load`` [N]; None when
    no bracket is found (the balance lies on the contact circle or nowhere)."""
    search = _Search(residual, _Frame(guess, load, radius), clearance)
    limits = (-2.0 * radius, 2.0 * radius)
    bracket = _bracket(search.across, 0.0, limits, FIRST_OFFSET * clearance)
    if bracket is None:
        return None
    beta = bracket[0]
    if bracket[0] != bracket[1]:
        try:
            beta = brentq(search.across, *bracket, xtol=POSITION_TOLERANCE * clearance)
        except ValueError:  # no inner root somewhere inside the bracket
            return None
    if math.isnan(search.across(beta)):
        return None
    return search.last
