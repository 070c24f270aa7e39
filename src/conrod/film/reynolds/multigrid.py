"""Projected multigrid for the Reynolds film (compiled; used by :mod:`conrod.film.reynolds.film`).

One cycle (Brandt & Cryer's projected multigrid in its simplest, correction form [1]):

1. ``PRE_SWEEPS`` projected Gauss–Seidel sweeps p := max(GS(p), p_cav) on the fine grid,
2. the residual on the nodes that are free *and* in full film (zero on Dirichlet and
   cavitated nodes) is summed onto coarser grids (restriction = transpose of bilinear
   prolongation, the finite-volume balance of the union of control volumes),
3. a linear V-cycle (Gauss–Seidel smoothing, ``COARSEST_SWEEPS`` SOR sweeps on the
   coarsest grid) solves the correction with zero correction on masked nodes; coarse
   conductances come from the film thickness at coinciding nodes (re-discretisation);
   with ``CUT_LEVELS`` coarse levels or more, a coarse face whose grid line meets the
   fine grid's free boundary before the masked coarse neighbour ends where the fine mask
   puts it (Shortley–Weller: conductance × 2^k/t for a boundary t fine cells away,
   :func:`~conrod.film.reynolds.multigrid_operators.cut_stencil`); the coarse masks and stencils
   are rebuilt only when the cavitated set moved,
4. the prolonged correction is added on the full-film nodes, projected, and
   ``POST_SWEEPS`` projected sweeps follow.

Measured (warm solves of a journal creeping at ε = 0.6, tolerance 1e-10; CPU time of the
compiled solve): V(1,1) with 40 coarsest sweeps, the previous scheme, 205 / 571 / 4057 µs
at 72×16 / 144×32 / 288×64 (11 / 11 / 23 cycles); V(2,1), 8 coarsest sweeps, cached
coarse operators and the W-cycle at 288×64: 122 / 481 / 3905 µs (9 / 10 / 14 cycles).
With coarse masks sampled from the fine one alone, the rupture line limited the finer
grids: the coarse problems put the free boundary up to one coarse cell off, and on 288×64
a warm-started cycle converged at 0.50 per cycle (V) or 0.27 (W) against 0.13 with a full
film. Ending the coarse faces at the fine boundary restores the full-film rate (0.12–0.13
per cycle with the rupture line, V-cycle; warm 288×64 at 1e-12: 15 → 11 cycles, 3.9 →
2.2 ms), and a V-cycle then beats the W-cycle per unit time (0.124 in 180 µs against
0.110 in 246 µs per cycle). With fewer coarse levels the sampled masks do as well (144×32
half grid: 0.11 per cycle either way) and the elastic KamAZ-740 orbit at 72×16 makes 3.8 %
fewer cycles with them, so the cut starts at four coarse levels (288×64 and finer).

Cycles stop when the largest change of one cycle is ≤ tolerance·max|p|, or earlier when
two successive cycles contracted the change by ρ < ``ESTIMATE_RATE`` and the remaining
error of a geometric sequence, change·ρ/(1 − ρ), is ≤ tolerance·max|p| (warm 72×16 and
144×32 at 1e-12: 11 → 10 cycles). The coarse cycle works in arrays allocated once per
solve (5–9 % faster than allocating per level visit). Everything runs in one compiled
call, lexicographic order, deterministic.

[1] A. Brandt, C.W. Cryer, "Multigrid algorithms for the solution of linear
    complementarity problems arising from free boundary problems", SIAM J. Sci. Stat.
    Comput. 4 (1983) 655–684.
"""

from __future__ import annotations

import numba as nb
import numpy as np

from conrod.film.reynolds.multigrid_operators import (
    add_prolongated,
    coarsen,
    coarsest_relaxation,
    conductances,
    cut_stencil,
    interpolated,
    relax,
    residual,
    restrict,
    stencil,
)

__all__ = ["add_prolongated", "coarse_levels", "coarsen", "coarsest_relaxation", "conductances",
           "gauss_seidel", "level_arrays", "multigrid_solve", "relax", "residual", "restrict",
           "read_only", "solve_on_grid", "stencil"]

PRE_SWEEPS = 2
POST_SWEEPS = 1
COARSEST_SWEEPS = 8
ESTIMATE_RATE = 0.5
"""Contraction per cycle below which (in two successive cycles) the remaining error is
estimated as change·ρ/(1 − ρ) and the cycles stop once that is ≤ tolerance [-]."""
CUT_LEVELS = 4
"""Coarse-level count from which the coarse faces are cut at the fine free boundary
(:func:`~conrod.film.reynolds.multigrid_operators.cut_stencil`) [-]; below it the sampled masks
(module docstring)."""
W_CYCLE_LEVELS = 5
"""Coarse-level count from which the correction is a W-cycle (V below) [-]; above the
:func:`coarse_levels` limit of 4, so every cycle is a V-cycle (module docstring)."""


@nb.njit(cache=True)
def _descend(k, errors, sources, work, stencils, masks, symmetric):
    """Pre-smooth the correction on coarse level k and restrict its residual to k + 1
    (``sources`` hold normalised sources b/a_P, ``work`` the residuals; no allocation)."""
    w_e, w_w, w_n, w_s, a_p = stencils[k]
    gauss_seidel(errors[k], w_e, w_w, w_n, w_s, sources[k], -np.inf, np.int64(PRE_SWEEPS))
    residual(errors[k], w_e, w_w, w_n, w_s, sources[k], a_p, masks[k], work[k])
    restrict(work[k], masks[k + 1], symmetric, stencils[k + 1][4], sources[k + 1])
    errors[k + 1][:] = 0.0


@nb.njit(cache=True)
def _ascend(k, errors, sources, stencils, masks):
    """Add the prolongated correction of level k + 1 to level k and post-smooth."""
    add_prolongated(errors[k + 1], errors[k], masks[k])
    w_e, w_w, w_n, w_s, _ = stencils[k]
    gauss_seidel(errors[k], w_e, w_w, w_n, w_s, sources[k], -np.inf, np.int64(POST_SWEEPS))


@nb.njit(cache=True)
def _row_residual(p, i, w_e, w_w, w_n, w_s, s, a_p, fixed, cavitation_pressure, mask, out):
    """Row i: mask := fixed | (p ≤ p_cav) and the flux residual of :func:`residual` on
    the unmasked nodes (0 elsewhere); returns True when a mask entry of the row changed."""
    changed = False
    n, m = p.shape
    ip = i + 1 if i + 1 < n else 0
    im = i - 1 if i > 0 else n - 1
    for j in range(m):
        value = fixed[i, j] or p[i, j] <= cavitation_pressure
        if value != mask[i, j]:
            mask[i, j] = value
            changed = True
        if value or j == 0 or j == m - 1:
            out[i, j] = 0.0
            continue
        target = (w_e[i, j] * p[ip, j] + w_w[i, j] * p[im, j]
                  + w_n[i, j] * p[i, j + 1] + w_s[i, j] * p[i, j - 1])
        out[i, j] = a_p[i, j] * (target + s[i, j] - p[i, j])
    return changed


@nb.njit(cache=True)
def _relax_row(p, i, w_e, w_w, w_n, w_s, s, floor):
    """One projected Gauss–Seidel update of row i (as :func:`relax` with ω = 1)."""
    n, m = p.shape
    row, up, down = p[i], p[i + 1 if i + 1 < n else 0], p[i - 1 if i > 0 else n - 1]
    we, ww, wn, ws, si = w_e[i], w_w[i], w_n[i], w_s[i], s[i]
    for j in range(1, m - 1):
        new = we[j] * up[j] + ww[j] * down[j] + wn[j] * row[j + 1] + ws[j] * row[j - 1] + si[j]
        row[j] = new if new > floor else floor


@nb.njit(cache=True)
def gauss_seidel(p, w_e, w_w, w_n, w_s, s, floor, sweeps):
    """``sweeps`` projected Gauss–Seidel sweeps in place (:func:`_relax_row`; as
    :func:`relax` with ω = 1, the new value formed directly as Σ w p_nb + s: 30 % cheaper
    than the SOR form p + ω(Σ w p_nb + s − p), which differs by round-off only)."""
    for _ in range(sweeps):
        for i in range(p.shape[0]):
            _relax_row(p, i, w_e, w_w, w_n, w_s, s, floor)


@nb.njit(cache=True)
def relax_with_residual(p, w_e, w_w, w_n, w_s, s, a_p, fixed, cavitation_pressure, mask,
                        out):
    """One projected sweep and, one row behind it, the mask fixed | (p ≤ p_cav) and the
    flux residual on the unmasked nodes (:func:`_row_residual`) — in one pass over the
    grid. Returns True when any mask entry changed (the coarse operators are rebuilt only
    then — along a warm-started orbit the set rarely moves)."""
    n = p.shape[0]
    changed = False
    for i in range(n):
        _relax_row(p, i, w_e, w_w, w_n, w_s, s, cavitation_pressure)
        if i >= 2:  # rows i − 2, i − 1, i are final: the residual of row i − 1 is
            changed |= _row_residual(p, i - 1, w_e, w_w, w_n, w_s, s, a_p, fixed,
                                     cavitation_pressure, mask, out)
    for i in (n - 1, 0):  # their θ neighbours (periodic) were updated last
        changed |= _row_residual(p, i, w_e, w_w, w_n, w_s, s, a_p, fixed,
                                 cavitation_pressure, mask, out)
    return changed


@nb.njit(cache=True)
def relax_with_change(p, w_e, w_w, w_n, w_s, s, floor, previous):
    """One projected sweep that also returns max|p − previous| / max|p| [-] (0 when
    p ≡ 0) against ``previous`` (the field at the start of the cycle) and sets
    previous := p, in one pass."""
    n, m = p.shape
    largest_change = 0.0
    largest_value = 0.0
    for i in range(n):
        _relax_row(p, i, w_e, w_w, w_n, w_s, s, floor)
        for j in range(m):
            value = p[i, j]
            largest_change = max(largest_change, abs(value - previous[i, j]))
            largest_value = max(largest_value, abs(value))
            previous[i, j] = value
    return largest_change / largest_value if largest_value > 0.0 else 0.0


@nb.njit(cache=True)
def add_projected(coarse, fine, fine_mask, floor):
    """fine := max(fine + bilinear interpolation of ``coarse``, floor) on unmasked nodes."""
    n, m = fine.shape
    for i in range(n):
        for j in range(1, m - 1):
            if not fine_mask[i, j]:
                value = fine[i, j] + interpolated(coarse, i, j)
                fine[i, j] = value if value > floor else floor


@nb.njit(cache=True)
def coarse_operators(mask_fine, coarse_east, coarse_north, symmetric):
    """Masks (every other node of the finer mask) and stencils of the coarse levels."""
    levels = len(coarse_east)
    masks = [coarsen(mask_fine, symmetric)]
    for level in range(1, levels):
        masks.append(coarsen(masks[level - 1], symmetric))
    if levels < CUT_LEVELS:
        stencils = [stencil(coarse_east[k], coarse_north[k], masks[k], symmetric)
                    for k in range(levels)]
    else:
        stencils = [cut_stencil(coarse_east[k], coarse_north[k], masks[k], symmetric,
                                mask_fine, 2 ** (k + 1)) for k in range(levels)]
    return masks, stencils


@nb.njit(cache=True)
def level_arrays(coarse_east):
    """Zeroed work arrays of the coarse levels: corrections, normalised sources and
    residuals (allocated once per solve, reused by every :func:`correction`)."""
    errors = [np.zeros(a.shape) for a in coarse_east]
    sources = [np.zeros(a.shape) for a in coarse_east]
    work = [np.zeros(a.shape) for a in coarse_east]
    return errors, sources, work


@nb.njit(cache=True)
def correction(rhs_fine, masks, stencils, coarse_east, coarse_north, symmetric, coarse_cycles,
               errors, sources, work):
    """Linear cycle for A e = rhs on the coarse levels (lists, fine → coarse; masks and
    stencils of :func:`coarse_operators`, work arrays of :func:`level_arrays`):
    ``coarse_cycles`` visits of every level per visit of its parent (1: V-cycle, 2:
    W-cycle; non-recursive, with visit counters); returns the correction on the first
    coarse level."""
    levels = len(coarse_east)
    restrict(rhs_fine, masks[0], symmetric, stencils[0][4], sources[0])
    errors[0][:] = 0.0
    last = levels - 1
    w_e, w_w, w_n, w_s, a_p = stencils[last]
    omega = coarsest_relaxation(coarse_east[last], coarse_north[last])
    visits = np.zeros(levels, dtype=np.int64)
    k = 0
    while True:
        while k < last:
            _descend(np.int64(k), errors, sources, work, stencils, masks, symmetric)
            k += 1
        relax(errors[last], w_e, w_w, w_n, w_s, sources[last], omega, -np.inf,
              COARSEST_SWEEPS)
        if last == 0:
            return errors[0]
        while k > 0:
            k -= 1
            _ascend(k, errors, sources, stencils, masks)
            visits[k] += 1
            if visits[k] < coarse_cycles:
                break
            visits[k] = 0
            if k == 0:
                return errors[0]
        _descend(np.int64(k), errors, sources, work, stencils, masks, symmetric)
        k += 1


def coarse_levels(n_theta: int, n_z: int, limit: int = 4) -> int:
    """How many coarser grids halve (n_theta, n_z) intervals evenly, keeping ≥ 8 × 2 [-]."""
    count = 0
    while count < limit and n_theta % 2 == 0 and n_z % 2 == 0 and n_theta >= 16 and n_z >= 4:
        n_theta, n_z = n_theta // 2, n_z // 2
        count += 1
    return count


@nb.njit(cache=True)
def multigrid_solve(p, h, source, fixed, radius, d_theta, d_z, cavitation_pressure,
                    tolerance, max_cycles, n_coarse, symmetric):
    """Projected multigrid cycles in place on ``p`` [Pa] (module docstring).

    h : film thickness [m]; source : b of the flux balance [Pa m^4]; fixed : Dirichlet
    nodes (edge rows included) holding their current value; symmetric : arrays hold
    z ≤ 0 of a z-symmetric problem, the mid-plane row before a padding row (masked).
    Returns (cycles, relative error measure [-]: the last cycle's change, or the geometric
    estimate of the remaining error when that stopped the cycles).
    """
    a_east, a_north = conductances(h, radius, d_theta, d_z)
    w_e, w_w, w_n, w_s, a_p = stencil(a_east, a_north, fixed.copy(), symmetric)  # writable, as
    # the coarse masks: one specialisation of the stencil (sweep counts and levels are int64
    # at every call for the same reason: a literal argument compiles a callee once more)
    s = source / a_p
    n, m = p.shape
    for i in range(n):
        for j in range(m):
            if fixed[i, j]:
                s[i, j] = p[i, j]
    coarse_east = []
    coarse_north = []
    coarse_h = h
    for k in range(1, n_coarse + 1):
        step = 2**k
        coarse_h = coarsen(coarse_h, symmetric)
        a_e, a_n = conductances(coarse_h, radius, d_theta * step, d_z * step)
        coarse_east.append(a_e)
        coarse_north.append(a_n)
    change = np.inf
    previous = p.copy()
    flux_residual = np.empty_like(p)
    mask = np.ones(p.shape, dtype=np.bool_)
    coarse_cycles = 2 if n_coarse >= W_CYCLE_LEVELS else 1
    masks, stencils = coarse_operators(mask, coarse_east, coarse_north, symmetric)
    errors, sources, work = level_arrays(coarse_east)
    last_change, last_rate = np.inf, 1.0
    for cycle in range(1, max_cycles + 1):
        gauss_seidel(p, w_e, w_w, w_n, w_s, s, cavitation_pressure, PRE_SWEEPS - 1)
        if n_coarse > 0:
            moved = relax_with_residual(p, w_e, w_w, w_n, w_s, s, a_p, fixed,
                                        cavitation_pressure, mask, flux_residual)
            if moved or cycle == 1:
                masks, stencils = coarse_operators(mask, coarse_east, coarse_north, symmetric)
            add_projected(correction(flux_residual, masks, stencils, coarse_east, coarse_north,
                                     symmetric, coarse_cycles, errors, sources, work),
                          p, mask, cavitation_pressure)
        else:
            gauss_seidel(p, w_e, w_w, w_n, w_s, s, cavitation_pressure, np.int64(1))
        gauss_seidel(p, w_e, w_w, w_n, w_s, s, cavitation_pressure, POST_SWEEPS - 1)
        change = relax_with_change(p, w_e, w_w, w_n, w_s, s, cavitation_pressure, previous)
        if change <= tolerance:
            return cycle, change
        rate = change / last_change
        if rate < ESTIMATE_RATE and last_rate < ESTIMATE_RATE:
            remaining = change * rate / (1.0 - rate)
            if remaining <= tolerance:
                return cycle, remaining
        last_change, last_rate = change, rate
    return max_cycles, change


@nb.njit(cache=True)
def _fold(pressure, h, source, fixed):
    """Rows z ≤ 0 of the four fields plus the padding row of the symmetric layout
    (pressure and source 0, h mirrored, fixed True), in one compiled call."""
    n, m = pressure.shape
    mid = (m - 1) // 2
    p_half = np.empty((n, mid + 2))
    h_half = np.empty((n, mid + 2))
    s_half = np.empty((n, mid + 2))
    f_half = np.empty((n, mid + 2), dtype=np.bool_)
    for i in range(n):
        for j in range(mid + 1):
            p_half[i, j] = pressure[i, j]
            h_half[i, j] = h[i, j]
            s_half[i, j] = source[i, j]
            f_half[i, j] = fixed[i, j]
        p_half[i, mid + 1] = 0.0
        h_half[i, mid + 1] = h[i, mid + 1]
        s_half[i, mid + 1] = 0.0
        f_half[i, mid + 1] = True
    return p_half, h_half, s_half, f_half


@nb.njit(cache=True)
def _unfold(half, pressure):
    """pressure := the z-symmetric field of the half ``half`` (mid-plane row included)."""
    n, m = pressure.shape
    mid = (m - 1) // 2
    for i in range(n):
        for j in range(mid + 1):
            pressure[i, j] = half[i, j]
        for j in range(mid + 1, m):
            pressure[i, j] = half[i, m - 1 - j]


def read_only(mask: np.ndarray) -> np.ndarray:
    """A read-only view of ``mask``: every caller hands :func:`multigrid_solve` the same
    array type, so numba compiles it (and its callees) for one signature only."""
    view = mask.view()
    view.setflags(write=False)
    return view


def solve_on_grid(pressure, h, source, fixed, grid, cavitation_pressure, tolerance,
                  max_cycles, symmetric) -> tuple[int, float]:
    """Projected multigrid on a full (n_θ, n_z + 1) grid, in place on ``pressure`` [Pa];
    with ``symmetric`` only z ≤ 0 is solved (half the work) and mirrored.

    Returns (cycles, last relative change [-]).
    """
    if not symmetric:
        return multigrid_solve(pressure, h, source, read_only(fixed), grid.radius, grid.d_theta,
                               grid.d_z, cavitation_pressure, tolerance, max_cycles,
                               coarse_levels(grid.n_theta, grid.n_z), False)
    half, h_half, source_half, fixed_half = _fold(pressure, h, source, read_only(fixed))
    cycles, change = multigrid_solve(
        half, h_half, source_half, read_only(fixed_half), grid.radius, grid.d_theta, grid.d_z,
        cavitation_pressure, tolerance, max_cycles, coarse_levels(grid.n_theta, grid.n_z // 2),
        True)
    _unfold(half, pressure)
    return cycles, change
