"""Building blocks of the projected multigrid of :mod:`conrod.film.reynolds.multigrid`
(compiled): face conductances and normalised 5-point stencils of the finite-volume
Reynolds balance (:mod:`conrod.film.reynolds.kernel`), (projected) Gauss–Seidel/SOR
relaxation, flux residuals, and the grid transfers — restriction (transpose of bilinear
prolongation), bilinear prolongation, every-other-node coarsening — with θ periodic and the
optional mid-plane symmetric layout (z ≤ 0 plus one padding row).
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np


@nb.njit(cache=True)
def conductances(h: np.ndarray, radius: float, d_theta: float, d_z: float):
    """Face conductances a_E, a_N [m^4] of the scheme in :mod:`reynolds_kernel`
    (a_N padded to the node shape, last column 0)."""
    n, m = h.shape
    a_east = np.zeros((n, m))
    a_north = np.zeros((n, m))
    arc = radius * d_theta
    for i in range(n):
        ip = i + 1 if i + 1 < n else 0
        for j in range(m):
            width = d_z if 0 < j < m - 1 else 0.5 * d_z
            h_e = 0.5 * (h[i, j] + h[ip, j])
            a_east[i, j] = h_e * h_e * h_e * width / arc
            if j < m - 1:
                h_n = 0.5 * (h[i, j] + h[i, j + 1])
                a_north[i, j] = h_n * h_n * h_n * arc / d_z
    return a_east, a_north


@nb.njit(cache=True)
def stencil(a_east: np.ndarray, a_north: np.ndarray, mask: np.ndarray, symmetric: bool):
    """Normalised weights w_E, w_W, w_N, w_S = a/a_P and a_P; zero weights and a_P = 1
    on masked nodes and on the first and last rows (their value never changes).

    ``symmetric``: the row before last is the mid-plane of a z-symmetric problem and the
    last row is padding; the mirror node p(z) = p(−z) folds a_N into a_S there."""
    n, m = a_east.shape
    w_e = np.zeros((n, m))
    w_w = np.zeros((n, m))
    w_n = np.zeros((n, m))
    w_s = np.zeros((n, m))
    a_p = np.ones((n, m))
    for i in range(n):
        im = i - 1 if i > 0 else n - 1
        for j in range(1, m - 1):
            if mask[i, j]:
                continue
            total = a_east[i, j] + a_east[im, j] + a_north[i, j] + a_north[i, j - 1]
            a_p[i, j] = total
            inverse = 1.0 / total  # one division per node (they dominate the set-up)
            w_e[i, j] = a_east[i, j] * inverse
            w_w[i, j] = a_east[im, j] * inverse
            w_n[i, j] = a_north[i, j] * inverse
            w_s[i, j] = a_north[i, j - 1] * inverse
            if symmetric and j == m - 2:
                a_p[i, j] = total + a_north[i, j - 1] - a_north[i, j]
                w_e[i, j] = a_east[i, j] / a_p[i, j]
                w_w[i, j] = a_east[im, j] / a_p[i, j]
                w_s[i, j] = 2.0 * a_north[i, j - 1] / a_p[i, j]
                w_n[i, j] = 0.0
    return w_e, w_w, w_n, w_s, a_p


@nb.njit(cache=True, inline="always")
def _first_masked(finest, i, j, di, dj, step):
    """Fine cells [-] from finest node (i, j) along (di, dj) to the first masked finest
    node, at most ``step`` (θ periodic)."""
    n = finest.shape[0]
    for t in range(1, step):
        if finest[(i + t * di) % n, j + t * dj]:
            return t
    return step


@nb.njit(cache=True)
def cut_stencil(a_east, a_north, mask, symmetric, finest, step):
    """:func:`stencil` of a coarse level whose nodes are every ``step``-th node of the
    finest grid, with the free boundary where the finest mask puts it: a face towards a
    masked coarse neighbour whose grid line meets a masked finest node t < ``step`` cells
    away ends there (zero correction at distance t, Shortley–Weller), its conductance ×
    step/t. Sampled masks alone put that boundary up to a coarse cell off."""
    w_e, w_w, w_n, w_s, a_p = stencil(a_east, a_north, mask, symmetric)
    n, m = a_east.shape
    for i in range(n):
        im = i - 1 if i > 0 else n - 1
        for j in range(1, m - 1):
            if mask[i, j]:
                continue
            fi, fj = step * i, step * j
            ip = i + 1 if i + 1 < n else 0
            mid = symmetric and j == m - 2
            t_e = _first_masked(finest, fi, fj, 1, 0, step) if mask[ip, j] else step
            t_w = _first_masked(finest, fi, fj, -1, 0, step) if mask[im, j] else step
            t_s = _first_masked(finest, fi, fj, 0, -1, step) if mask[i, j - 1] else step
            t_n = t_s if mid else (_first_masked(finest, fi, fj, 0, 1, step)
                                   if mask[i, j + 1] else step)
            if t_e == step and t_w == step and t_s == step and t_n == step:
                continue
            a_e = a_east[i, j] * step / t_e
            a_w = a_east[im, j] * step / t_w
            a_s = a_north[i, j - 1] * step / t_s
            a_n = a_s if mid else a_north[i, j] * step / t_n
            a_p[i, j] = a_e + a_w + a_n + a_s
            w_e[i, j] = a_e / a_p[i, j] if t_e == step else 0.0
            w_w[i, j] = a_w / a_p[i, j] if t_w == step else 0.0
            w_s[i, j] = (2.0 if mid else 1.0) * a_s / a_p[i, j] if t_s == step else 0.0
            w_n[i, j] = a_n / a_p[i, j] if t_n == step and not mid else 0.0
    return w_e, w_w, w_n, w_s, a_p


@nb.njit(cache=True)
def relax(p, w_e, w_w, w_n, w_s, s, omega, floor, sweeps):
    """``sweeps`` lexicographic (projected) SOR sweeps in place:
    p := max(p + ω(Σ w p_nb + s − p), floor). Returns the largest update of the last sweep."""
    n, m = p.shape
    largest = 0.0
    for _ in range(sweeps):
        largest = 0.0
        for i in range(n):
            ip = i + 1 if i + 1 < n else 0
            im = i - 1 if i > 0 else n - 1
            row, up, down = p[i], p[ip], p[im]
            we, ww, wn, ws, si = w_e[i], w_w[i], w_n[i], w_s[i], s[i]
            for j in range(1, m - 1):
                old = row[j]
                target = we[j] * up[j] + ww[j] * down[j] + wn[j] * row[j + 1] + ws[j] * row[j - 1]
                new = old + omega * (target + si[j] - old)
                if new < floor:
                    new = floor
                row[j] = new
                change = abs(new - old)
                if change > largest:
                    largest = change
    return largest


@nb.njit(cache=True)
def residual(p, w_e, w_w, w_n, w_s, s, a_p, mask, out=None):
    """Flux residual a_P(Σ w p_nb + s − p) [Pa m^4]; zero on masked nodes and edges
    (written into ``out`` when given, to avoid allocating in the cycle loop)."""
    n, m = p.shape
    if out is None:
        out = np.empty((n, m))
    for i in range(n):
        ip = i + 1 if i + 1 < n else 0
        im = i - 1 if i > 0 else n - 1
        out[i, 0] = 0.0
        out[i, m - 1] = 0.0
        for j in range(1, m - 1):
            if mask[i, j]:
                out[i, j] = 0.0
                continue
            target = (w_e[i, j] * p[ip, j] + w_w[i, j] * p[im, j]
                      + w_n[i, j] * p[i, j + 1] + w_s[i, j] * p[i, j - 1])
            out[i, j] = a_p[i, j] * (target + s[i, j] - p[i, j])
    return out


@nb.njit(cache=True)
def restrict(fine: np.ndarray, coarse_mask: np.ndarray, symmetric: bool,
             a_p: np.ndarray, out: np.ndarray) -> None:
    """out := (transpose of bilinear prolongation of ``fine``) / a_P — weighted sums of
    fine balances (1, ½, ¼) on the grid of ``coarse_mask``, normalised by the coarse
    diagonal a_P [m^4] (the source form of :func:`relax`), 0 on masked nodes and edges; a
    symmetric problem mirrors the row above the mid-plane."""
    n, m = fine.shape
    nc, mc = coarse_mask.shape
    for ic in range(nc):
        out[ic, 0] = 0.0
        out[ic, mc - 1] = 0.0
        for jc in range(1, mc - 1):
            if coarse_mask[ic, jc]:
                out[ic, jc] = 0.0
                continue
            total = 0.0
            for di in range(-1, 2):
                i = (2 * ic + di) % n
                for dj in range(-1, 2):
                    j = 2 * jc + dj
                    if symmetric and j == m - 1:
                        j = 2 * jc - 1
                    total += (1.0 - 0.5 * abs(di)) * (1.0 - 0.5 * abs(dj)) * fine[i, j]
            out[ic, jc] = total / a_p[ic, jc]


@nb.njit(cache=True, inline="always")
def interpolated(coarse: np.ndarray, i: int, j: int) -> float:
    """Bilinear interpolation of ``coarse`` (θ periodic) at fine node (i, j)."""
    nc = coarse.shape[0]
    i0 = i // 2
    i1 = (i0 + 1) % nc if i % 2 else i0
    j0 = j // 2
    j1 = j0 + 1 if j % 2 else j0
    return 0.25 * (coarse[i0, j0] + coarse[i1, j0] + coarse[i0, j1] + coarse[i1, j1])


@nb.njit(cache=True)
def add_prolongated(coarse: np.ndarray, fine: np.ndarray, fine_mask: np.ndarray) -> None:
    """fine += bilinear interpolation of ``coarse`` (θ periodic) on unmasked nodes."""
    n, m = fine.shape
    for i in range(n):
        for j in range(1, m - 1):
            if not fine_mask[i, j]:
                fine[i, j] += interpolated(coarse, i, j)


@nb.njit(cache=True)
def coarsen(field: np.ndarray, symmetric: bool) -> np.ndarray:
    """Values at the nodes of the next coarser grid (every other node); a symmetric
    layout keeps its padding row last."""
    if not symmetric:
        return field[::2, ::2].copy()
    n, m = field.shape
    columns = m // 2  # nodes 0, 2, … below the padding row m − 1
    out = np.empty(((n + 1) // 2, columns + 1), dtype=field.dtype)
    for i in range(out.shape[0]):  # element loops: no array-slice assignment to compile
        for j in range(columns):
            out[i, j] = field[2 * i, 2 * j]
        out[i, columns] = field[2 * i, m - 1]
    return out


@nb.njit(cache=True, inline="always")
def copy_into(target: np.ndarray, source: np.ndarray) -> None:
    """target := source for two arrays of one 2-D shape (an element loop: numba compiles
    the checks of an array-slice assignment, ``target[:] = source``, once per process)."""
    for i in range(target.shape[0]):
        for j in range(target.shape[1]):
            target[i, j] = source[i, j]


@nb.njit(cache=True)
def coarsest_relaxation(a_east: np.ndarray, a_north: np.ndarray) -> float:
    """SOR factor for the coarsest grid from the mean conductances (Young) [-]."""
    n, m = a_east.shape
    east = np.mean(a_east[:, 1:-1])
    north = np.mean(a_north[:, : m - 1])
    rho = (east + north * math.cos(math.pi / (m - 1))) / (east + north)
    return 2.0 / (1.0 + math.sqrt(1.0 - rho * rho))
