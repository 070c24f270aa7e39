"""Polar load diagram data, journal wear diagram and oil-hole angle ([D1]).

Wear diagram ([D1], lecture 16): wear is assumed proportional to the load and
spread uniformly over ±60° about the instantaneous load direction on the journal.
For every crank angle a ring strip of height ∝ |R| is added over that sector; the sum
is the (conventional) wear diagram. Its least-worn zone is where the oil-supply hole
should be drilled.

Angles on the journal are measured in the crank frame (journal-fixed): from the crank
radius pointing outward (crank axis → crankpin centre) towards the direction of
rotation. The loaded point on the journal lies in the direction of the load W pressing
the journal against the shell (W = −force of the rod on the crankpin).
"""

from __future__ import annotations

import math

import numpy as np

WEAR_HALF_WIDTH = math.radians(60.0)
"""Half-width of the sector worn by one load ([D1]) [rad]."""


def wrap_angle(angle: np.ndarray | float) -> np.ndarray:
    """Angle wrapped to [−π, π) [rad]."""
    return np.mod(np.asarray(angle, dtype=float) + math.pi, 2.0 * math.pi) - math.pi


def wear_diagram(
    load_angle: np.ndarray,
    load_magnitude: np.ndarray,
    *,
    bins: int = 360,
    half_width: float = WEAR_HALF_WIDTH,
) -> tuple[np.ndarray, np.ndarray]:
    """Summed ring strips: returns (journal angle [rad] at bin centres, wear sum [N]).

    wear(θ) = Σ_φ |R(φ)| · [ |θ − θ_W(φ)| ≤ half_width ]  (one strip per crank angle)

    load_angle : ndarray  Direction θ_W of the load on the journal, crank frame [rad].
    load_magnitude : ndarray  |R| [N].  bins : int  Number of journal angles [-].
    """
    journal_angle = (np.arange(bins) + 0.5) * (2.0 * math.pi / bins)
    offset = wrap_angle(journal_angle[None, :] - np.asarray(load_angle, dtype=float)[:, None])
    inside = np.abs(offset) <= half_width + 1e-12
    wear = np.asarray(load_magnitude, dtype=float) @ inside.astype(float)
    return journal_angle, wear


def least_worn_angle(journal_angle: np.ndarray, wear: np.ndarray) -> float:
    """Centre [rad, in [0, 2π)] of the widest circular arc where the wear is minimal.

    Bins within 1e-9 of the range above the minimum count as minimal; ties between arcs
    of equal width go to the first arc from θ = 0 (deterministic).
    """
    tolerance = 1e-9 * max(float(np.ptp(wear)), 1e-300)
    minimal = wear <= wear.min() + tolerance
    if minimal.all():
        return 0.0
    start = int(np.argmin(minimal))  # a worn bin: arcs do not wrap past it
    rolled = np.roll(minimal, -start)
    best_len, best_mid, run_start = 0, 0.0, None
    for index, flag in enumerate(np.append(rolled, False)):
        if flag and run_start is None:
            run_start = index
        elif not flag and run_start is not None:
            if index - run_start > best_len:
                best_len, best_mid = index - run_start, 0.5 * (run_start + index - 1)
            run_start = None
    step = journal_angle[1] - journal_angle[0]
    return float(np.mod(journal_angle[0] + (best_mid + start) * step, 2.0 * math.pi))


def polar_diagram_points(
    radial_force: np.ndarray, tangential_force: np.ndarray, rotating_force: float
) -> tuple[np.ndarray, np.ndarray, tuple[float, float]]:
    """Polar diagram of the rod force S on the crankpin ([D1]), crank frame.

    Returns (T [N], outward radial component of S [N], pole O' [N]): the points are the
    tips of S drawn from the pole O = (0, 0); the resultant on the crankpin (S plus the
    centrifugal K_R) is the vector from O' = (0, P_r) to the same point.
    """
    outward_s = -(np.asarray(radial_force) - rotating_force)
    return np.asarray(tangential_force), outward_s, (0.0, float(rotating_force))
