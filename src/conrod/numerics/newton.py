"""Damped Newton iteration of a step system: unknowns y of their own and k journal degrees
of freedom v, solved together.

A step system (:class:`NewtonSystem`) answers ``evaluate(y, v)`` with its own residual
G(y, v) (n,) in the units of y, the force F(y, v) (k,) [N] that the load W balances, a film
thickness h_min [m] for the update limits and a payload, and ``respond(payload)`` with the
exact Jacobian blocks at that evaluation (:class:`StepBlocks`). The iteration runs on the
scaled unknowns z = (y/s_y, v/s_v) and residuals r = (G/s_y, (F + W)/W_s), W_s = |W| + 1 N:

.. math:: J = \\begin{pmatrix} ∂G/∂y & ∂G/∂v\\, s_v/s_y \\\\
                               ∂F/∂y\\, s_y/W_s & ∂F/∂v\\, s_v/W_s \\end{pmatrix}

With k = 0 it solves G(y) = 0 alone; with n = 0 (a film without unknowns of its own, e.g. a
rigid film under a tilted journal) the journal's balance alone. The inverse Jacobian is
built from the exact blocks, improved after every full update by Broyden's rank-one update
(superlinear convergence without a new film response) and carried across calls through
:class:`ChordJacobian` while a full update reduces the residual norm to at most
:data:`CONTRACTION` of its value; it is rebuilt after an update that contracts less or
needed a cut, and at once where the full update of a carried (not freshly built) inverse
does not lower the residual norm: no cut of a stale direction is tried (on the README's
main job 9833 → 9489 film solves with the same Jacobians, 839 → 837). An update from a
fresh Jacobian is cut back
(halving, :data:`LINE_SEARCH_CUTS` trials) until the residual norm decreases — across a
switch of a film's cavitation set, where no cut may decrease it, the best trial is taken
(semismooth Newton) — and scaled by the system's :class:`UpdateLimits`: the change of the
film thickness, max|Δy_gap + T Δv|, at most a share of the current h_min (Rodin 2004: the
relaxation factor Δ of the deformation increment), and |Δv| ≤ :data:`VELOCITY_LIMIT` s_v.

A system that declares ``inexact`` (True) solves its inner problem (a film) per evaluation
only as accurately as the iteration needs there (inexact Newton [3]): ``evaluate(y, v,
accuracy)`` is asked for a relative accuracy of :data:`FIRST_ACCURACY` at the first
evaluation of a call and :data:`FORCING` times the smallest scaled residual max|r| so far
after it (never looser than the first), which the system tightens to its own tolerance
where that is looser. Far from the answer a film is then solved to 1e-8 instead of 1e-12;
the evaluations that end the iteration, whose residual before them is ≤ 1e-7, are solved
to the film's own tolerance, so the answer is that of exact evaluations within the
iteration's tolerances (measured on the README's main job below :data:`FORCING`).

[1] F. Rodin, "Elastohydrodynamic lubrication of connecting-rod big-end bearings",
    PhD thesis (2004), ch. 4 (the coupled algorithm and its increment safeguard).
[2] C.G. Broyden, "A class of methods for solving nonlinear simultaneous equations",
    Math. Comp. 19 (1965) 577–593 (the rank-one update of the inverse Jacobian).
[3] R.S. Dembo, S.C. Eisenstat, T. Steihaug, "Inexact Newton methods", SIAM J. Numer.
    Anal. 19 (1982) 400–408 (the forcing term: the inner solve's accuracy tied to the
    residual).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, NamedTuple, Protocol

import numba as nb
import numpy as np

from conrod.errors import CaseError, ConvergenceError

CONTRACTION = 0.5
"""Keep the (Broyden-updated) inverse Jacobian while a full update reduces the residual
norm to at most this share [-]. On the README's main job (KamAZ-740, elastic big end,
144 × 16, two cycles) 0.5 builds 839 Jacobians in 1440 steps against 1787 with a
Jacobian rebuilt after the first update of every step (0.3: 1165, 0.8: 608 with more film
solves), the orbit 16.0 s against 19.6 s, every cycle.csv column within 1e-8."""

LINE_SEARCH_CUTS = 6
"""Trials of an update (halving the step) before the best one is taken [-]."""

FORCE_TOLERANCE = 1e-8
"""Force balance reached: |F + W| ≤ this × (|W| + 1 N) [-]."""

ACCEPTABLE = 1e-4
"""At the iteration limit an answer within this relative force residual and within
1000 × the own tolerance is still accepted [-]."""

VELOCITY_LIMIT = 10.0
"""Largest update of the journal degrees of freedom, in units of their scale s_v [-]."""

FIRST_ACCURACY = 1.0e-8
"""Relative accuracy asked of the first evaluation of an inexact system (module
docstring), and the loosest asked of any [-]: the first residual of an implicit step of
the README's main job is ~1e-2 of the clearance, so its film needs no more than 1e-8."""

FORCING = 1.0e-5
"""Relative accuracy asked of an inexact system's later evaluations per unit of the
smallest scaled residual max|r| so far [-]. An evaluation's error then moves r by at most
about this share of the residual before it: the Broyden differences stay exact to 1e-5 and
the accepted residual, below 1e-9 after one of ≤ 1e-4, within the tolerance. On the
README's main job (KamAZ-740, elastic big end, 1° implicit steps): multigrid cycles
55 007 → 38 737 at 102 × 12 (film solves 7138 → 7194); the elastic orbit alone 6.09 →
5.52 s at 144 × 16, 3.45–3.63 → 3.30–3.44 s at 102 × 12, 2.55 → 2.41–2.48 s at 72 × 8
(3–4 runs each); every cycle.csv column of the answer within 1e-8 of its largest value,
h_min within 1e-9 and p_max within 3e-9 (relative) of exact evaluations. With 1e-4 / 1e-7
and 1e-3 / 1e-6 (forcing / first) fewer cycles but more film solves: no faster."""


@dataclass(frozen=True)
class StepBlocks:
    """Exact Jacobian blocks of a step system at one evaluation.

    own_by_own : ndarray  ∂G/∂y (n × n) [-, in the units of G per unit of y].
    own_by_journal : ndarray  ∂G/∂v (n × k).
    force_by_own : ndarray  ∂F/∂y (k × n).
    force_by_journal : ndarray  ∂F/∂v (k × k).
    """

    own_by_own: np.ndarray
    own_by_journal: np.ndarray
    force_by_own: np.ndarray
    force_by_journal: np.ndarray


@dataclass(frozen=True)
class UpdateLimits:
    """How far one update may move the film thickness.

    share : float  Largest change of the film thickness per update, share of the current
        h_min [-].
    travel : ndarray or None  Film-thickness change per unit update of v (n_gap × k) [s]
        when v also moves the film (the journal's end position of an implicit step); None:
        v does not move it.
    gap : slice, ndarray or None  The components of y that are film-thickness changes
        [m] (a bore displacement); None: all of y. An unknown of another kind (a
        temperature) is left out of the limit.
    """

    share: float
    travel: np.ndarray | None = None
    gap: Any = None


class NewtonSystem(Protocol):
    """What :func:`solve_step` iterates on (module docstring)."""

    start: np.ndarray
    limits: UpdateLimits

    def evaluate(self, own: np.ndarray, velocity: np.ndarray
                 ) -> tuple[np.ndarray, np.ndarray, float, Any]:
        """(G (n,), F (k,) [N], h_min [m], payload) at (y, v); a system that declares
        ``inexact`` is called with a third argument, the relative accuracy of its inner
        solve [-] (module docstring)."""
        ...

    def respond(self, payload: Any) -> StepBlocks:
        """The exact Jacobian blocks at the evaluation of ``payload``."""
        ...


class ChordJacobian:
    """The inverse Jacobian of the last Newton iteration, carried to the next call (the next
    step) while it keeps contracting; ``builds`` counts the Jacobians built [-]."""

    def __init__(self) -> None:
        self.inverse: np.ndarray | None = None
        self.builds = 0


@dataclass(frozen=True)
class NewtonControls:
    """Scales and limits of one iteration.

    scale : float  s_y, the scale of y and G (the radial clearance for a bore) [unit of y].
    velocity_scale : float  s_v, the scale of v (c ω for the journal velocity) [m/s].
    tolerance : float  max|G| that ends the iteration [unit of y].
    max_solves : int  Evaluations before giving up [-].
    chord : ChordJacobian or None  The Jacobian carried from the last call (updated in
        place); None: a fresh one.
    force_tolerance : float  |F + W|/W_s that ends the iteration [-] (default
        :data:`FORCE_TOLERANCE`).
    """

    scale: float
    velocity_scale: float
    tolerance: float
    max_solves: int
    chord: ChordJacobian | None = None
    force_tolerance: float = FORCE_TOLERANCE


@dataclass(frozen=True)
class NewtonOutcome:
    """End of an iteration.

    own : ndarray  y [unit of y].  velocity : ndarray  v (k,) [m/s].
    payload : object  The system's payload at the answer.  solves : int  Evaluations [-].
    residual : float  max|G| [unit of y].  force_residual : float  max|F + W|/W_s [-].
    increment : float  Last max|Δy| [unit of y].
    converged : bool  Acceptable: max|G| ≤ 1000 × tolerance and the force residual
        ≤ :data:`ACCEPTABLE`.
    settled : bool  Within the tolerances themselves (max|G| ≤ tolerance, force residual
        ≤ :data:`FORCE_TOLERANCE`).
    updates : int  Updates taken; ``solves`` also counts the start value's evaluation and
        the line-search trials [-].
    """

    own: np.ndarray
    velocity: np.ndarray
    payload: Any
    solves: int
    residual: float
    force_residual: float
    increment: float
    converged: bool
    settled: bool = False
    updates: int = 0


def length(vector: np.ndarray) -> float:
    """Euclidean length of a short vector (the C library's hypot for two components, as
    numpy's) [-]."""
    if vector.size == 2:
        return _hypot(vector[0], vector[1])
    return _euclidean(vector)


@nb.njit(cache=True)
def _hypot(x: float, y: float) -> float:
    """√(x² + y²) by the C library's ``hypot``, numpy's ``np.hypot`` bit for bit without its
    dispatch on two scalars (0.4 against 2.5 µs, once or twice per update of a step) [-]."""
    return math.hypot(x, y)


def solve_step(system: NewtonSystem, velocity: np.ndarray, load: np.ndarray,
               controls: NewtonControls) -> NewtonOutcome:
    """(y, v) with G = 0 and F + W = 0 from (``system.start``, ``velocity`` [m/s]);
    ``load`` W (k,) [N] (module docstring)."""
    iteration = _Iteration(system, np.asarray(velocity, dtype=float),
                           np.asarray(load, dtype=float), controls)
    return iteration.run()


class _Trial(NamedTuple):
    """One evaluation of the iteration: the scaled residual r, h_min [m], the system's
    payload and ‖r‖₂ (computed once, compared up to three times)."""

    r: np.ndarray
    h_min: float
    payload: Any
    norm: float


class _Iteration:
    """The state of one :func:`solve_step` call."""

    def __init__(self, system, velocity, load, controls: NewtonControls):
        self.system, self.controls = system, controls
        self.n, self.k = system.start.size, velocity.size
        self.v0, self.load = velocity, load
        self.w_scale = length(load) + 1.0
        self.solves = 0
        self.inexact = bool(getattr(system, "inexact", False))
        travel = system.limits.travel  # in the scaled unknowns, once
        self.travel = None if travel is None else travel * controls.velocity_scale / controls.scale
        self.smallest = math.inf  # the smallest max|r| so far (the inexact accuracy)

    def residual(self, z: np.ndarray) -> _Trial:
        """The trial at the scaled unknowns z."""
        c, n = self.controls.scale, self.n
        own = c * z[:n]
        velocity = self.controls.velocity_scale * z[n:] if self.k else self.v0
        accuracy = (min(FIRST_ACCURACY, FORCING * self.smallest),) if self.inexact else ()
        g, force, h_min, payload = self.system.evaluate(own, velocity, *accuracy)
        self.solves += 1
        r = g / c
        if self.k:
            r = np.concatenate([r, (force + self.load) / self.w_scale])
        if self.inexact:
            self.smallest = min(self.smallest, _largest(r))
        return _Trial(r, h_min, payload, _euclidean(r))

    def done(self, r: np.ndarray) -> bool:
        own, force = self.residuals(r)
        return own <= self.controls.tolerance and force <= self.controls.force_tolerance

    def residuals(self, r: np.ndarray) -> tuple[float, float]:
        """(max|G| [unit of y], max|F + W|/W_s [-]) of the scaled residual."""
        own = self.controls.scale * _largest(r[:self.n]) if self.n else 0.0
        force = _largest(r[self.n:]) if self.k else 0.0
        return own, force

    def run(self) -> NewtonOutcome:
        controls, n, c = self.controls, self.n, self.controls.scale
        z = np.asarray(self.system.start, dtype=float) / c
        if self.k:
            z = np.concatenate([z, self.v0 / controls.velocity_scale])
        r, h_min, payload, norm = self.residual(z)
        chord = controls.chord if controls.chord is not None else ChordJacobian()
        inverse, increment, updates = chord.inverse, 0.0, 0
        if inverse is not None and inverse.shape[0] != z.size:
            inverse = None
        fresh = False
        while self.solves < controls.max_solves and not self.done(r):
            if inverse is None:
                inverse, fresh = self.inverse(self.system.respond(payload)), True
                chord.builds += 1
            step = -inverse @ r
            self.limit(step, h_min)
            if fresh:
                best, best_lam = self.line_search(z, step, norm)
            else:  # a carried inverse is not cut back: where its full update fails, rebuild
                best, best_lam = _attempt(self.residual, z + step), 1.0
                if best is None or best.norm >= norm:
                    inverse = None
                    continue
            if best is None:
                break
            fresh = False
            # the best trial is taken even when it does not descend: across a switch of the
            # film's cavitation set the residual is only piecewise smooth (semismooth Newton)
            z = z + best_lam * step
            increment = c * _largest(best_lam * step[:n]) if n else 0.0
            change = best.r - r
            stalled = best.norm > CONTRACTION * norm or best_lam < 1.0
            r, h_min, payload, norm = best
            updates += 1
            inverse = None if stalled else broyden_update(inverse, step, change)
        chord.inverse = inverse
        return self.outcome(z, r, payload, increment, updates)

    def line_search(self, z: np.ndarray, step: np.ndarray, norm: float):
        """(best trial, its step length) of up to :data:`LINE_SEARCH_CUTS` halvings; the
        first trial that lowers the residual norm ends the search."""
        best, best_lam, lam = None, 1.0, 1.0
        for _ in range(LINE_SEARCH_CUTS):
            trial = _attempt(self.residual, z + lam * step)
            if trial is not None and (best is None or trial.norm < best.norm):
                best, best_lam = trial, lam
            if best is not None and (best.norm < norm
                                     or self.solves >= self.controls.max_solves):
                break
            lam *= 0.5
        return best, best_lam

    def outcome(self, z, r, payload, increment, updates) -> NewtonOutcome:
        controls, n = self.controls, self.n
        own, force = self.residuals(r)
        velocity = controls.velocity_scale * z[n:] if self.k else self.v0
        return NewtonOutcome(
            controls.scale * z[:n], velocity, payload, self.solves, own, force, increment,
            own <= 1e3 * controls.tolerance and force <= ACCEPTABLE,
            own <= controls.tolerance and force <= controls.force_tolerance, updates)

    def inverse(self, blocks: StepBlocks) -> np.ndarray:
        """J⁻¹ of the scaled system from the exact blocks (module docstring)."""
        jac = scaled_jacobian(blocks, self.controls.scale, self.controls.velocity_scale,
                              self.w_scale, self.k)
        try:
            return np.linalg.inv(jac)
        except np.linalg.LinAlgError:  # a force insensitive to the velocity: least squares
            return np.linalg.pinv(jac)

    def limit(self, step: np.ndarray, h_min: float) -> None:
        """Scale ``step`` in place by the system's limits (module docstring)."""
        limits, c, n = self.system.limits, self.controls.scale, self.n
        step *= update_limit(_gap(step[:n], limits.gap), step[n:], h_min / c, limits.share)
        if self.travel is not None:
            step *= travel_limit(_gap(step[:n], limits.gap), step[n:], self.travel, h_min / c,
                                 limits.share)


def broyden_update(inverse: np.ndarray, step: np.ndarray, change: np.ndarray) -> np.ndarray:
    """Broyden's ("good") update of the inverse Jacobian H after the update s that changed
    the residual by y: H + (s − H y) sᵀH / (sᵀH y), the inverse (Sherman–Morrison) of
    J + (y − J s) sᵀ/(sᵀs), so that the new H maps y to s (the secant condition) and
    differs from H by rank one; H unchanged where sᵀH y vanishes."""
    hy = inverse @ change
    denominator = float(step @ hy)
    if not abs(denominator) > 1e-300:
        return inverse
    return inverse + np.outer((step - hy) / denominator, step @ inverse)


def scaled_jacobian(blocks: StepBlocks, scale: float, velocity_scale: float,
                    force_scale: float, journal: int) -> np.ndarray:
    """J of the scaled unknowns z = (y/s_y, v/s_v) and residuals r = (G/s_y, (F + W)/W_s)
    from the exact blocks (module docstring); ``force_scale`` W_s = |W| + 1 N [N];
    ``journal`` k, the journal degrees of freedom (0: G alone)."""
    n, k = blocks.own_by_own.shape[0], journal
    jac = np.zeros((n + k, n + k))
    jac[:n, :n] = blocks.own_by_own
    if k:
        jac[:n, n:] = blocks.own_by_journal * velocity_scale / scale
        jac[n:, :n] = blocks.force_by_own * scale / force_scale
        jac[n:, n:] = blocks.force_by_journal * velocity_scale / force_scale
    return jac


def update_limit(gap: np.ndarray, journal: np.ndarray, h_min_scaled: float,
                 share: float) -> float:
    """Scale ≤ 1 keeping max|Δy_gap| ≤ share h_min and |Δv| ≤ :data:`VELOCITY_LIMIT`
    (scaled units) [-]."""
    scale = 1.0
    largest = _largest(gap) if gap.size else 0.0
    allowed = share * max(h_min_scaled, 0.0)
    if largest > allowed and largest > 0.0:
        scale = allowed / largest
    if journal.size:
        largest_v = length(journal)
        if largest_v * scale > VELOCITY_LIMIT:
            scale = VELOCITY_LIMIT / largest_v
    return scale


def travel_limit(gap: np.ndarray, journal: np.ndarray, travel_scaled: np.ndarray,
                 h_min_scaled: float, share: float) -> float:
    """Scale ≤ 1 keeping the change of the film thickness by y and the journal together,
    max|Δy_gap + T Δv|, ≤ share h_min (Rodin's Δ safeguard on the whole gap) [-]."""
    moved = travel_scaled @ journal
    change = _largest(gap + moved if gap.size else moved)
    allowed = share * max(h_min_scaled, 0.0)
    return allowed / change if change > allowed and change > 0.0 else 1.0


def _gap(own_step: np.ndarray, gap) -> np.ndarray:
    """The film-thickness components of an update of y."""
    return own_step if gap is None else own_step[gap]


def _euclidean(vector: np.ndarray) -> float:
    """‖v‖₂ of a 1-D vector, as numpy's ``norm`` computes it (√(v·v), the same bits)
    without its dispatch (a few µs a call, thousands of calls an orbit)."""
    return math.sqrt(vector.dot(vector))


@nb.njit(cache=True)
def _largest(vector: np.ndarray) -> float:
    """max|v_i| of a non-empty 1-D vector, NaN where one is NaN: numpy's
    ``np.abs(v).max()`` without its two dispatches and the array between them (~1 µs
    instead of ~4 µs, several times per film solve of an implicit step) [-]."""
    largest = 0.0
    for value in vector:
        size = abs(value)
        if size != size:
            return size
        if size > largest:
            largest = size
    return largest


def _attempt(residual, z: np.ndarray):
    """residual(z), or None where the film closes or its solve fails."""
    try:
        return residual(z)
    except (CaseError, ConvergenceError):
        return None
