"""The Newton iteration of a step system (:mod:`conrod.numerics.newton`) on a system with
a known root: a stiffening spring bed, f(u) = −(u + u³) at every node, against the bore
u = P C f + U, i.e. G(u) = u + (u + u³)·k − U = 0 node by node (k the diagonal compliance),
whose root is the real root of a cubic (numpy.roots)."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.numerics.newton import (
    ChordJacobian,
    NewtonControls,
    StepBlocks,
    UpdateLimits,
    solve_step,
)

COMPLIANCE = np.array([0.5, 1.0, 2.0])
"""Diagonal compliance k of the three nodes [m/N]."""
INERTIA = np.array([0.3, 0.8, 1.5])
"""Imposed displacement U [m]."""


class _SpringBed:
    """G(u) = u − k f(u) − U with f(u) = −(u + u³), no journal degree of freedom."""

    limits = UpdateLimits(0.5)

    def __init__(self, start: np.ndarray):
        self.start = start

    def evaluate(self, u: np.ndarray, _v: np.ndarray):
        return u + COMPLIANCE * (u + u**3) - INERTIA, np.zeros(0), 1e3, u.copy()

    def respond(self, u: np.ndarray) -> StepBlocks:
        n = len(u)
        return StepBlocks(np.diag(_jacobian(u)), np.zeros((n, 0)), np.zeros((0, n)),
                          np.zeros((0, 0)))


def _roots() -> np.ndarray:
    """Real root of k u³ + (1 + k) u − U = 0 at every node [m]."""
    return np.array([np.real(next(r for r in np.roots([k, 0.0, 1.0 + k, -load])
                                  if abs(r.imag) < 1e-12))
                     for k, load in zip(COMPLIANCE, INERTIA, strict=True)])


def _jacobian(u: np.ndarray) -> np.ndarray:
    """dG/du = 1 + k (1 + 3u²), diagonal [-]."""
    return 1.0 + COMPLIANCE * (1.0 + 3.0 * u**2)


def _solve(refresh: bool, start: np.ndarray, carried: np.ndarray):
    chord = ChordJacobian()
    chord.inverse = np.diag(carried)
    return solve_step(_SpringBed(start), np.zeros(0), np.zeros(0),
                      NewtonControls(1.0, 1.0, 1e-13, 60, chord, refresh_after_first=refresh))


@pytest.mark.parametrize("refresh", [False, True])
def test_newton_reaches_the_root_of_the_cubic(refresh):
    root = _roots()
    outcome = _solve(refresh, root + 0.05, 1.0 / _jacobian(np.zeros(3)))  # stale: from u = 0
    assert outcome.converged
    np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert 1 <= outcome.updates <= outcome.solves - 1  # the start value costs a solve


def test_a_fresh_jacobian_after_the_first_update_saves_the_stalling_chord_updates():
    """The situation of a step of the orbit with mass: the carried Jacobian is right where
    the start value's error is large (node 0, 1e-2 m off) and stale where it is small
    (node 2, 1e-5 m off, its inverse 0.4 of the true one: contraction 0.6 per update).
    The first chord update takes node 0 to 2e-5 m; the second leaves node 2 at 0.6 of its
    error, the residual norm falls by only 0.19 > CONTRACTION, and the Jacobian is rebuilt
    there (4 updates). Rebuilt right after the first update instead, Newton finishes
    quadratically (3 updates: errors 1e-2 → 2e-5 → 7e-11 → 5e-16 m). Same root both ways."""
    root = _roots()
    carried = 1.0 / _jacobian(root) * np.array([1.0, 1.0, 0.4])
    start = root + np.array([1e-2, 0.0, 1e-5])
    chord_only, refreshed = _solve(False, start, carried), _solve(True, start, carried)
    for outcome in (chord_only, refreshed):
        np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert refreshed.updates == 3
    assert chord_only.updates == 4
