"""Quasi-Newton solve of the elastohydrodynamic coupling at one film state.

The corrected bore deformation u [m] at the film nodes solves

.. math:: G(u) = u - P\\,(C f(p(h_{rigid} + u)) + U c(φ)) = 0

with f the nodal film forces [N] of the pressure on the deformed film, C the compliance,
U c(φ) the inertia deformation and P the rigid-body correction (Rodin 2004, ch. 2). A plain
under-relaxed fixed point u ← u + ω G stalls when the rod is compliant (deformation
comparable with the clearance); here the update is a Newton step

.. math:: Δu = -H\\,G(u),\\qquad H ≈ (I - P C\\,∂f/∂u)^{-1}

with H built from finite differences of the film along the m dominant left singular
vectors W of P C (a deformation lives in their span), J ≈ I − (P C ∂f/∂u W) Wᵀ, improved
by Broyden's rank-one updates ("good" Broyden, on the inverse) and carried from step to
step. A safeguard scales the increment when it exceeds a share of the current minimum film
thickness (Rodin's relaxation factor Δ of the deformation increment).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.film.base import FilmResult

CHORD_CONTRACTION = 0.1
"""Keep a Jacobian while a step reduces max|G| to at most this share [-]."""

CUTS = 4
"""Halvings of a secant step before the best trial is taken [-]."""

Evaluate = Callable[[np.ndarray], tuple[np.ndarray, float, object]]
"""u [m] → (nodal forces f [N], minimum film thickness h_min [m], film payload)."""


@dataclass(frozen=True)
class CouplingSettings:
    """Controls of the coupling iteration.

    tolerance : float  Stop when max|G(u)| ≤ tolerance [m].
    max_iterations : int  Quasi-Newton updates per coupling before ConvergenceError [-].
    increment_share : float  Largest deformation increment as a share of the current
        minimum film thickness (Rodin's Δ safeguard) [-].
    modes : int  Largest number of finite-difference directions of the Jacobian [-].
    contraction : float  Rebuild the Jacobian (once per solve) when an update reduces
        max|G| by less than this factor [-].
    """

    tolerance: float
    max_iterations: int = 40
    increment_share: float = 0.5
    modes: int = 24
    contraction: float = 0.5


@dataclass(frozen=True)
class CouplingOutcome:
    """Converged coupling: deformation, film payload and diagnostics.

    deformation : ndarray  Corrected bore deformation u [m].
    payload : object  What ``evaluate`` returned at u (film result and memory).
    iterations : int  Film solves of this coupling [-].
    residual : float  max|G(u)| at the answer [m].
    increment : float  max|Δu| of the last update (0 when none was needed) [m].
    converged : bool  residual ≤ tolerance.
    """

    deformation: np.ndarray
    payload: object
    iterations: int
    residual: float
    increment: float
    converged: bool


def dominant_directions(corrected_compliance: np.ndarray, modes: int) -> np.ndarray:
    """Orthonormal columns W (n, m): left singular vectors of P C above 1e-3 of the
    largest singular value, at most ``modes`` [-]."""
    left, singular, _ = np.linalg.svd(corrected_compliance)
    if singular.size == 0 or singular[0] <= 0.0:
        return left[:, :0]
    count = int(min(modes, np.count_nonzero(singular > 1e-4 * singular[0])))
    return left[:, :count]


class JacobianCache:
    """The inverse Jacobian H carried between film states (a solver aid, not film state:
    the converged answer does not depend on it beyond the tolerance)."""

    def __init__(self, directions: np.ndarray):
        self.directions = directions
        self.inverse: np.ndarray | None = None
        self.builds = 0

    def rebuild(self, evaluate: Evaluate, u: np.ndarray, forces: np.ndarray,
                operator: np.ndarray, step: float) -> int:
        """H from finite differences of the film along W at u; returns the film solves."""
        w = self.directions
        columns = np.empty_like(w)
        for k in range(w.shape[1]):
            shifted, _, _ = evaluate(u + step * w[:, k])
            columns[:, k] = operator @ (shifted - forces) / step
        jacobian = np.eye(u.size) - columns @ w.T
        self.inverse = np.linalg.inv(jacobian)
        self.builds += 1
        return w.shape[1]

    def broyden(self, s: np.ndarray, y: np.ndarray) -> None:
        """Good Broyden update of H from the step s and the residual change y."""
        assert self.inverse is not None
        hy = self.inverse @ y
        denominator = float(s @ hy)
        if abs(denominator) > 1e-30 * float(s @ s):
            self.inverse += np.outer(s - hy, s @ self.inverse) / denominator


def solve_coupling(evaluate: Evaluate, start: np.ndarray, inertia: np.ndarray,
                   operator: np.ndarray, cache: JacobianCache, settings: CouplingSettings,
                   clearance: float) -> CouplingOutcome:
    """Deformation u with G(u) = 0 from ``start`` [m]; ``operator`` = P C [m/N],
    ``inertia`` = P U c(φ) [m]. Returns the last iterate when it does not converge."""
    u = np.array(start, dtype=float)
    solves, updates, increment, fresh = 0, 0, 0.0, False
    previous: tuple[np.ndarray, np.ndarray] | None = None
    last = np.inf
    while True:
        forces, h_min, payload = evaluate(u)
        solves += 1
        residual_vector = u - operator @ forces - inertia
        residual = float(np.max(np.abs(residual_vector)))
        if residual <= settings.tolerance or updates >= settings.max_iterations:
            return CouplingOutcome(u, payload, solves, residual, increment,
                                   residual <= settings.tolerance)
        slow = residual > settings.contraction * last
        if cache.inverse is None or (slow and not fresh):
            solves += cache.rebuild(evaluate, u, forces, operator, 1e-4 * clearance)
            fresh, previous = True, None
        elif previous is not None:
            cache.broyden(u - previous[0], residual_vector - previous[1])
        assert cache.inverse is not None
        step = -cache.inverse @ residual_vector
        step *= _safeguard(step, h_min, settings.increment_share)
        previous, last = (u, residual_vector), residual
        u = u + step
        updates += 1
        increment = float(np.max(np.abs(step)))


def _safeguard(step: np.ndarray, h_min: float, share: float) -> float:
    """Scale ≤ 1 keeping max|Δu| ≤ share × h_min [-]."""
    largest = float(np.max(np.abs(step)))
    limit = share * max(h_min, 0.0)
    if largest <= limit or largest == 0.0:
        return 1.0
    return limit / largest


def fixed_point_coupling(evaluate: Evaluate, start: np.ndarray, inertia: np.ndarray,
                         operator: np.ndarray, relaxation: float, tolerance: float,
                         max_iterations: int) -> CouplingOutcome:
    """Under-relaxed fixed point u ← u − ω G(u): the slow reference of the tests."""
    u = np.array(start, dtype=float)
    for iteration in range(1, max_iterations + 1):
        forces, _, payload = evaluate(u)
        residual_vector = u - operator @ forces - inertia
        residual = float(np.max(np.abs(residual_vector)))
        if residual <= tolerance:
            return CouplingOutcome(u, payload, iteration, residual, 0.0, True)
        u = u - relaxation * residual_vector
    return CouplingOutcome(u, payload, max_iterations, residual, 0.0, False)


def secant_coupling(evaluate: Evaluate, respond, start: np.ndarray, inertia: np.ndarray,
                    operator: np.ndarray, settings: CouplingSettings, chord,
                    difference_step: float) -> CouplingOutcome:
    """G(u) = 0 from ``start`` [m] by Newton steps with line search (halving, :data:`CUTS`)
    and good Broyden updates of J⁻¹ along the steps taken, J = I − P C ∂f/∂u.

    A new Jacobian comes first from ``respond(payload)`` (∂f/∂u of the film on its converged
    set [N/m]; payload as returned by ``evaluate``); when a step taken with it contracts
    max|G| by less than half — the linearisation misses part of the film's response (a
    mass-conserving film's broken-film cells, or an answer on a switch of its set) — the
    next one is built once by forward differences of ``difference_step`` [m] along every
    node (n film solves, not counted in ``settings.max_iterations``). A step that does
    not reduce max|G| with a carried or secant Jacobian is refused and the Jacobian
    rebuilt at the current u.

    Converged when max|G| ≤ tolerance or, with a fresh Jacobian, when the Newton correction
    max|J⁻¹G| — the error left in u — is: a film step that is nearly incompressible in its
    content makes ∂G/∂u large (entries of 700 measured), so G itself need not fall to the
    tolerance while u is already exact to it. ``chord.inverse`` carries J⁻¹ to the next
    call; ``chord.builds`` counts the Jacobians built.
    """
    u = np.array(start, dtype=float)
    forces, h_min, payload = evaluate(u)
    g = u - operator @ forces - inertia
    solves, updates, increment, correction = 1, 0, 0.0, np.inf
    fresh, exact, differenced = "", False, False
    inverse = chord.inverse if chord.inverse is not None and (
        chord.inverse.shape[0] == u.size) else None
    while float(np.max(np.abs(g))) > settings.tolerance and updates < settings.max_iterations:
        if inverse is None:
            if exact:
                jacobian = _difference_jacobian(evaluate, u, g, operator, inertia,
                                                difference_step)
                solves, exact, differenced = solves + u.size, False, True
            else:
                jacobian = np.eye(u.size) - operator @ respond(payload)
            inverse, fresh = np.linalg.inv(jacobian), "exact" if exact else "response"
            chord.builds += 1
        step = -inverse @ g
        if fresh and float(np.max(np.abs(step))) <= settings.tolerance:
            correction = float(np.max(np.abs(step)))
            break  # the Newton correction (the error left in u) is within the tolerance
        step *= _safeguard(step, h_min, settings.increment_share)
        norm = float(np.max(np.abs(g)))
        step, trial_g, trial_h, trial_payload, tried = _line_search(
            evaluate, u, step, norm, operator, inertia)
        solves, updates = solves + tried, updates + tried
        reduced = float(np.max(np.abs(trial_g)))
        if reduced >= norm and not fresh:
            inverse = None  # a poor secant Jacobian: rebuild here
            continue
        inverse = _broyden(inverse, step, trial_g - g)
        exact = exact or (fresh == "response" and reduced > 0.5 * norm
                          and difference_step is not None and not differenced)
        if fresh == "response" and reduced > 0.5 * norm:
            inverse = None  # the film's linearisation is not enough here
        u, g, h_min, payload = u + step, trial_g, trial_h, trial_payload
        increment, fresh = float(np.max(np.abs(step))), ""
    chord.inverse = inverse
    residual = float(np.max(np.abs(g)))
    return CouplingOutcome(u, payload, solves, residual, increment,
                           min(residual, correction) <= settings.tolerance)


def _line_search(evaluate, u, step, norm, operator, inertia):
    """Halve ``step`` until max|G| falls below ``norm`` (at most :data:`CUTS` trials);
    (step, G, h_min, payload, film solves) of the first such trial, else of the best."""
    best, tried = None, 0
    for _ in range(CUTS):
        forces, h_min, payload = evaluate(u + step)
        tried += 1
        g = u + step - operator @ forces - inertia
        if best is None or np.max(np.abs(g)) < np.max(np.abs(best[1])):
            best = (step, g, h_min, payload)
        if float(np.max(np.abs(g))) < norm:
            break
        step = 0.5 * step
    return (*best, tried)


def _broyden(inverse: np.ndarray, step: np.ndarray, change: np.ndarray) -> np.ndarray:
    """Good Broyden update of J⁻¹ from the step and the residual change."""
    hy = inverse @ change
    denominator = float(step @ hy)
    if abs(denominator) > 1e-30 * float(step @ step):
        return inverse + np.outer(step - hy, step @ inverse) / denominator
    return inverse


def _difference_jacobian(evaluate, u, g, operator, inertia, step: float) -> np.ndarray:
    """J = ∂G/∂u by forward differences of ``step`` [m] along every node."""
    jacobian = np.empty((u.size, u.size))
    for k in range(u.size):
        shifted = u.copy()
        shifted[k] += step
        forces = evaluate(shifted)[0]
        jacobian[:, k] = (shifted - operator @ forces - inertia - g) / step
    return jacobian


def semismooth_coupling(evaluate: Evaluate, respond, start: np.ndarray, inertia: np.ndarray,
                        operator: np.ndarray, settings: CouplingSettings,
                        chord) -> CouplingOutcome:
    """G(u) = 0 from ``start`` [m] by Newton steps with the film's exact ∂f/∂u on the
    cavitation set of an iterate (``respond(payload)`` [N/m]): a semismooth Newton
    iteration. The inverse Jacobian ``chord.inverse`` is kept, also from call to call,
    while a step reduces max|G| to a tenth (chord steps) and rebuilt otherwise
    (``chord.builds`` counts the builds). A step that does not reduce max|G| is halved (at
    most :data:`CUTS` trials); with a fresh Jacobian the best trial is then taken (the next
    Jacobian sees the new set), with an old one the Jacobian is rebuilt first. Rodin's Δ
    safeguard scales a step whose max|Δu| exceeds a share of h_min. Converged when
    max|G| ≤ tolerance or, with a fresh Jacobian, the Newton correction max|J⁻¹G| (the
    error left in u) is. Where the answer sits on a switch of the set the Jacobians of
    its two sides can send the iterate back and forth; :func:`secant_coupling` then takes
    over."""
    u = np.array(start, dtype=float)
    forces, h_min, payload = evaluate(u)
    g = u - operator @ forces - inertia
    solves, increment, fresh = 1, 0.0, False
    residual, correction = float(np.max(np.abs(g))), np.inf
    inverse = chord.inverse if chord.inverse is not None and (
        chord.inverse.shape[0] == u.size) else None
    while residual > settings.tolerance and solves < settings.max_iterations:
        if inverse is None:
            inverse = np.linalg.inv(np.eye(u.size) - operator @ respond(payload))
            chord.builds += 1
            fresh = True
        step = -inverse @ g
        if fresh and float(np.max(np.abs(step))) <= settings.tolerance:
            correction = float(np.max(np.abs(step)))
            break
        step *= _safeguard(step, h_min, settings.increment_share)
        step, trial, trial_h, trial_payload, tried = _line_search(
            evaluate, u, step, residual, operator, inertia)
        solves += tried
        reduced = float(np.max(np.abs(trial)))
        if reduced >= residual and not fresh:
            inverse = None
            continue
        if reduced > CHORD_CONTRACTION * residual:
            inverse = None
        u, g, h_min, payload = u + step, trial, trial_h, trial_payload
        residual, increment, fresh = reduced, float(np.max(np.abs(step))), False
    chord.inverse = inverse
    return CouplingOutcome(u, payload, solves, residual, increment,
                           min(residual, correction) <= settings.tolerance)


@dataclass(frozen=True)
class SolvedPayload:
    """A full solve of the base film (the coupling without the exact response): its result
    with the pressure, and the base film's memory after it."""

    result: FilmResult
    memory: Any

    def force(self) -> np.ndarray:
        """Film force on the journal (F_x, F_y) [N]."""
        return np.array([self.result.force_x, self.result.force_y])

    def finish(self) -> tuple[FilmResult, Any]:
        """(film result, base film memory)."""
        return self.result, self.memory


def film_closing(payload, carries_asperity: bool) -> str:
    """h_min on the deformed film of the last trial [m] and, without asperity contact,
    the fix for a film too thin to carry the load ('' when the payload does not say)."""
    if isinstance(payload, SolvedPayload):
        return ""
    h_min = payload.min_film_thickness()
    advice = ("" if carries_asperity else "; if the film closes, enable mixed lubrication "
              "([contact] model = 'greenwood_tripp') so that asperity contact carries the load")
    return f"; h_min {h_min:.3g} m on the deformed film{advice}"

