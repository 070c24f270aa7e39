"""The Newton iteration of the coupled bore (:mod:`conrod.ehd.newton`) on a system with
a known root: a stiffening spring bed, f(u) = −(u + u³) at every node, against the bore
u = P C f + U, i.e. G(u) = u + (u + u³)·k − U = 0 node by node (k the diagonal compliance),
whose root is the real root of a cubic (numpy.roots)."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.ehd.newton import ChordJacobian, newton_balance
from conrod.ehd.response import FilmResponse

COMPLIANCE = np.array([0.5, 1.0, 2.0])
"""Diagonal compliance k of the three nodes [m/N]."""
INERTIA = np.array([0.3, 0.8, 1.5])
"""Imposed displacement U [m]."""


def _evaluate(u: np.ndarray, _v: np.ndarray):
    return -(u + u**3), np.zeros(2), 1e3, u.copy()


def _respond(u: np.ndarray) -> FilmResponse:
    n = len(u)
    return FilmResponse(-np.diag(1.0 + 3.0 * u**2), np.zeros((n, 2)), np.zeros((2, n)),
                        np.zeros((2, 2)))


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
    return newton_balance(_evaluate, _respond, start, np.zeros(2), np.zeros(2), INERTIA,
                          np.diag(COMPLIANCE), 1.0, 1.0, 1e-13, 60, 0.5,
                          with_velocity=False, chord=chord, refresh_after_first=refresh)


@pytest.mark.parametrize("refresh", [False, True])
def test_newton_reaches_the_root_of_the_cubic(refresh):
    root = _roots()
    outcome = _solve(refresh, root + 0.05, 1.0 / _jacobian(np.zeros(3)))  # stale: from u = 0
    assert outcome.converged
    np.testing.assert_allclose(outcome.deformation, root, rtol=0, atol=1e-12)
    assert 1 <= outcome.updates <= outcome.iterations - 1  # the start value costs a solve


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
        np.testing.assert_allclose(outcome.deformation, root, rtol=0, atol=1e-12)
    assert refreshed.updates == 3
    assert chord_only.updates == 4
