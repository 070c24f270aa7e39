"""Dry-friction work over the cycle and its distribution over surface elements of the
journal and of the shell ([D4] §4.5, eq. 4.5.1).

Work is friction force × sliding distance. At the contact point the journal surface
slides over the shell by R·dψ (ψ = journal rotation relative to the shell,
∫(ω_j − ω_b) dt; the orbiting of the centre adds only c·dθ_c, a share c/R ≈ 10⁻³, which
is neglected). Over a step between two output angles the trapezoidal rule gives

.. math:: ΔA_i = \\tfrac12 (P_{f,i} + P_{f,i+1}) \\, R \\, |ψ_{i+1} - ψ_i|,
          \\qquad A = \\sum_i ΔA_i .

[D4] writes A = μ_dry R Σ P_c Δφ, i.e. it takes the relative rotation equal to the
crank-angle step (dψ = dφ) and P_f = μ_dry P_c. In the rod frame dψ = dφ − dβ, so the
[D4]'s form ignores the rod swing (|dβ/dφ| ≤ λ ≈ 0.3, zero on average over a cycle);
for ψ = φ and a periodic cycle both sums are identical (:func:`seed_friction_work`).

Distribution: during a step the contact point moves on the shell from θ_i to θ_{i+1}
(θ = contact angle, film frame) and on the journal from θ_i − ψ_i to θ_{i+1} − ψ_{i+1}
(journal-fixed angle). The step's work is spread uniformly along each of these two paths
over N equal elements; each distribution therefore sums exactly to the total A.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba as nb
import numpy as np


@nb.njit(cache=True)
def deposit_along_arc(bins: np.ndarray, start: float, end: float, amount: float) -> None:
    """Add ``amount`` spread uniformly along the arc ``start`` → ``end`` [rad] to ``bins``,
    element k covering [2πk/N, 2π(k+1)/N) (periodic). Degenerate arcs go to one element."""
    count = bins.size
    width = 2.0 * math.pi / count
    low = min(start, end)
    high = max(start, end)
    length = high - low
    if length <= 1.0e-12 * width:
        bins[int(math.floor(low / width)) % count] += amount
        return
    first = int(math.floor(low / width))
    last = int(math.floor(high / width))
    for k in range(first, last + 1):
        overlap = min(high, (k + 1) * width) - max(low, k * width)
        if overlap > 0.0:
            bins[k % count] += amount * overlap / length


@nb.njit(cache=True)
def _raise_along_arc(bins: np.ndarray, start: float, end: float, value: float) -> None:
    """bins[k] = max(bins[k], value) for every element the arc start → end [rad] touches."""
    count = bins.size
    width = 2.0 * math.pi / count
    first = int(math.floor(min(start, end) / width))
    last = int(math.floor(max(start, end) / width))
    for k in range(first, last + 1):
        bins[k % count] = max(bins[k % count], value)


@nb.njit(cache=True)
def _element_maximum(values, shell_path, journal_path, elements):
    shell = np.zeros(elements)
    journal = np.zeros(elements)
    for i in range(values.size - 1):
        peak = max(values[i], values[i + 1])
        if peak > 0.0:
            _raise_along_arc(shell, shell_path[i], shell_path[i + 1], peak)
            _raise_along_arc(journal, journal_path[i], journal_path[i + 1], peak)
    return journal, shell


def element_maximum(
    values: np.ndarray, contact_angle: np.ndarray, journal_rotation: np.ndarray,
    crank_angle: np.ndarray, elements: int, cycle: float | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Largest value (e.g. contact stress [Pa]) each journal and shell element sees over the
    cycle while the contact point passes over it ([D4] Fig. 4.4.1); (journal, shell)."""
    cycle = cycle_length(crank_angle) if cycle is None else cycle
    _, psi = close_cycle(crank_angle, journal_rotation, cycle)
    theta = np.unwrap(np.append(contact_angle, contact_angle[0]).astype(float))
    closed = np.append(values, values[0]).astype(float)
    return _element_maximum(closed, theta, theta - psi, int(elements))


@nb.njit(cache=True)
def _distribute(step_work, shell_path, journal_path, elements):
    shell = np.zeros(elements)
    journal = np.zeros(elements)
    for i in range(step_work.size):
        if step_work[i] != 0.0:
            deposit_along_arc(shell, shell_path[i], shell_path[i + 1], step_work[i])
            deposit_along_arc(journal, journal_path[i], journal_path[i + 1], step_work[i])
    return journal, shell


@dataclass(frozen=True)
class FrictionWork:
    """Friction work of one cycle and where it goes.

    element_angle : ndarray  Centre angle of each surface element [rad]; shell angles are
        film-frame θ, journal angles are journal-fixed (θ − ψ) [rad].
    journal : ndarray  Friction work received by each journal element [J].
    shell : ndarray  Friction work received by each shell element [J].
    step_work : ndarray  Work of each step i → i+1 (the last step closes the cycle) [J].
    cumulative : ndarray  Work done from the cycle start up to each output angle [J].
    """

    element_angle: np.ndarray
    journal: np.ndarray
    shell: np.ndarray
    step_work: np.ndarray
    cumulative: np.ndarray

    @property
    def total(self) -> float:
        """Friction work over the cycle A [J]."""
        return float(np.sum(self.step_work))


def cycle_length(crank_angle: np.ndarray) -> float:
    """Length of the cycle [rad] for uniformly spaced angles with the end point excluded."""
    crank_angle = np.asarray(crank_angle, dtype=float)
    step = float(np.median(np.diff(crank_angle)))
    return float(crank_angle[-1] - crank_angle[0] + step)


def close_cycle(crank_angle, journal_rotation, cycle):
    """Append the cycle's closing point φ₀ + cycle; its journal rotation is extrapolated
    with the mean of the first and last step rates dψ/dφ [rad]."""
    phi = np.asarray(crank_angle, dtype=float)
    psi = np.asarray(journal_rotation, dtype=float)
    rate_last = (psi[-1] - psi[-2]) / (phi[-1] - phi[-2])
    rate_first = (psi[1] - psi[0]) / (phi[1] - phi[0])
    closing = phi[0] + cycle
    psi_end = psi[-1] + 0.5 * (rate_last + rate_first) * (closing - phi[-1])
    return np.append(phi, closing), np.append(psi, psi_end)


def friction_work_distribution(
    crank_angle: np.ndarray,
    friction_force: np.ndarray,
    contact_angle: np.ndarray,
    journal_rotation: np.ndarray,
    radius: float,
    elements: int,
    cycle: float | None = None,
) -> FrictionWork:
    """Friction work per step and per surface element over one periodic cycle.

    crank_angle : uniformly spaced output angles of one cycle, end point excluded [rad].
    friction_force : dry-friction force P_f ≥ 0 at each angle [N].
    contact_angle : shell angle θ of the contact point, film frame [rad].
    journal_rotation : ψ, rotation of the journal relative to the shell [rad].
    radius : journal radius R [m]. elements : number N of surface elements [-].
    cycle : cycle length [rad]; inferred from the spacing when None.
    """
    cycle = cycle_length(crank_angle) if cycle is None else cycle
    _, psi = close_cycle(crank_angle, journal_rotation, cycle)
    force = np.append(friction_force, friction_force[0]).astype(float)
    theta = np.unwrap(np.append(contact_angle, contact_angle[0]).astype(float))
    step_work = 0.5 * (force[:-1] + force[1:]) * radius * np.abs(np.diff(psi))
    journal, shell = _distribute(step_work, theta, theta - psi, int(elements))
    cumulative = np.concatenate(([0.0], np.cumsum(step_work[:-1])))
    element_angle = (np.arange(elements) + 0.5) * (2.0 * math.pi / elements)
    return FrictionWork(element_angle, journal, shell, step_work, cumulative)


def seed_friction_work(contact_force: np.ndarray, crank_step: float, friction_coefficient: float,
                       radius: float) -> float:
    """[D4] eq. 4.5.1: A = μ_dry R Σ P_c Δφ [J] (contact force [N], crank step [rad],
    μ_dry [-], radius [m])."""
    return float(friction_coefficient * radius * np.sum(contact_force) * crank_step)
