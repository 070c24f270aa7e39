"""The Newton iteration of a step system (:mod:`conrod.numerics.newton`) on a system with
a known root: a stiffening spring bed, f(u) = −(u + u³) at every node, against the bore
u = P C f + U, i.e. G(u) = u + (u + u³)·k − U = 0 node by node (k the diagonal compliance),
whose root is the real root of a cubic (numpy.roots)."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.numerics import newton
from conrod.numerics.newton import (
    ChordJacobian,
    NewtonControls,
    StepBlocks,
    UpdateLimits,
    broyden_update,
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


def _solve(start: np.ndarray, carried: np.ndarray):
    chord = ChordJacobian()
    chord.inverse = np.diag(carried)
    return solve_step(_SpringBed(start), np.zeros(0), np.zeros(0),
                      NewtonControls(1.0, 1.0, 1e-13, 60, chord)), chord


def test_newton_reaches_the_root_of_the_cubic():
    root = _roots()
    outcome, _ = _solve(root + 0.05, 1.0 / _jacobian(np.zeros(3)))  # stale: from u = 0
    assert outcome.converged
    np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert 1 <= outcome.updates <= outcome.solves - 1  # the start value costs a solve


def test_broyden_update_meets_the_secant_condition_with_a_rank_one_change():
    rng = np.random.default_rng(3)
    inverse = rng.normal(size=(5, 5)) + 5.0 * np.eye(5)
    step, change = rng.normal(size=5), rng.normal(size=5)
    updated = broyden_update(inverse, step, change)
    np.testing.assert_allclose(updated @ change, step, rtol=0, atol=1e-12)
    assert np.linalg.matrix_rank(updated - inverse, tol=1e-10) == 1
    # Broyden's update of J itself, J + (y − J s) sᵀ / (sᵀ s), inverted directly
    jac = np.linalg.inv(inverse)
    direct = jac + np.outer(change - jac @ step, step) / (step @ step)
    np.testing.assert_allclose(np.linalg.inv(direct), updated, rtol=1e-9, atol=1e-12)


def test_a_stale_jacobian_converges_superlinearly_without_being_rebuilt():
    """The carried inverse from u = 0 is off by 5–50 % at the root: a chord iteration with
    it contracts the error by those shares per update, linearly; Broyden's updates learn
    the secant and the error falls faster each update, with no Jacobian built."""
    root = _roots()
    errors = []

    class _Recorded(_SpringBed):
        def evaluate(self, u, v):
            errors.append(float(np.max(np.abs(u - root))))
            return super().evaluate(u, v)

    chord = ChordJacobian()
    chord.inverse = np.diag(1.0 / _jacobian(np.zeros(3)))
    outcome = solve_step(_Recorded(root + 0.05), np.zeros(0), np.zeros(0),
                         NewtonControls(1.0, 1.0, 1e-13, 60, chord))
    np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert chord.builds == 0
    chord_rate = np.max(np.abs(1.0 - _jacobian(root) / _jacobian(np.zeros(3))))
    ratios = [b / a for a, b in zip(errors, errors[1:], strict=False) if a > 1e-13]
    assert ratios[0] == pytest.approx(chord_rate, rel=0.2)  # the first update is a chord one
    assert min(ratios[-3:]) < 0.1 * chord_rate  # superlinear at the end


def test_a_carried_jacobian_whose_update_fails_is_rebuilt_not_cut_back():
    """A carried inverse of the wrong sign points uphill: its full update raises the
    residual, and the iteration builds the Jacobian there at once (one wasted solve) instead
    of halving the uphill update :data:`~conrod.numerics.newton.LINE_SEARCH_CUTS` times."""
    root = _roots()
    outcome, chord = _solve(root + 1e-3, -1.0 / _jacobian(root))
    np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert chord.builds == 1
    # the start, the failed carried update, then four updates from the exact Jacobian (with
    # Broyden's updates after the first): 6 solves, where halving the uphill update first
    # took 11
    assert (outcome.solves, outcome.updates) == (6, 4)


class _InexactSpringBed(_SpringBed):
    """The spring bed whose G comes from an inner solve converged to a relative accuracy:
    off by max(accuracy, 1e-15) × (1 + u) at every node; records the accuracies asked and
    where."""

    inexact = True

    def __init__(self, start: np.ndarray):
        super().__init__(start)
        self.asked: list[float] = []
        self.evaluated: list[np.ndarray] = []

    def evaluate(self, u: np.ndarray, v: np.ndarray, accuracy: float):
        self.asked.append(accuracy)
        self.evaluated.append(u.copy())
        g, force, h_min, payload = super().evaluate(u, v)
        return g + max(accuracy, 1e-15) * (1.0 + u), force, h_min, payload


def test_an_inexact_system_is_asked_for_the_accuracy_its_residual_needs():
    """Inexact Newton: the first evaluation at FIRST_ACCURACY, each later one at FORCING
    times the smallest max|r| before it (capped at the first); the root as exact
    evaluations find it within the tolerance, in at most two more evaluations."""
    root = _roots()
    start = root + 0.05
    exact, _ = _solve(start, 1.0 / _jacobian(np.zeros(3)))
    system = _InexactSpringBed(start)
    chord = ChordJacobian()
    chord.inverse = np.diag(1.0 / _jacobian(np.zeros(3)))
    outcome = solve_step(system, np.zeros(0), np.zeros(0),
                         NewtonControls(1.0, 1.0, 1e-13, 60, chord))
    assert outcome.converged
    np.testing.assert_allclose(outcome.own, root, rtol=0, atol=1e-12)
    assert outcome.solves <= exact.solves + 2
    assert system.asked[0] == newton.FIRST_ACCURACY
    # replay: the residual of each evaluation (its error included) sets the next accuracy
    smallest = np.inf
    for k, accuracy in enumerate(system.asked):
        if k:
            assert accuracy == min(newton.FIRST_ACCURACY, newton.FORCING * smallest)
        u = system.evaluated[k]
        residual = np.max(np.abs(u + COMPLIANCE * (u + u**3) - INERTIA
                                 + max(accuracy, 1e-15) * (1.0 + u)))
        smallest = min(smallest, residual)
    assert system.asked[-1] < 1e-10  # the accepted answer from an almost exact solve
