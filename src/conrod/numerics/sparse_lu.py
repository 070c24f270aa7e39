"""Many right-hand sides of one sparse LU factor in one compiled pass.

SuperLU (:func:`scipy.sparse.linalg.splu`) factors P_r A P_c = L U. Its ``solve`` takes one
right-hand side at a time quickly, but its blocked solve of a 2-D right-hand side is slower
than a loop, and a loop of a hundred back-substitutions costs a Python call each. Here the
factor's L (unit lower) and U (upper), both compressed by columns, are swept once with all
right-hand sides side by side (the innermost loop runs over the right-hand sides,
contiguous in memory):

.. math:: L\\,y = P_r b, \\qquad U\\,w = y, \\qquad x = P_c\\,w

The same arithmetic as SuperLU's triangular solves up to the order of the sums (round-off).

A matrix whose nodes lie on a ring of grid rows (the film's active set on the periodic θ
grid, numbered row by row) is banded once the ring is cut where no coupling crosses it — a
θ row without an active node, which a cavitated arc gives: :func:`banded_solve_rows`
numbers the nodes from that cut and factors the band without pivoting (an M-matrix, the
flux balance's, needs none; Golub & Van Loan, Matrix Computations, 4th ed., §4.3 banded
systems, §4.1.1 diagonal dominance): on the README's main job's film responses 0.4 ms for
the banded factor and solves against 1.7 ms of SuperLU's factor and compiled sweep.
"""

from __future__ import annotations

import numba as nb
import numpy as np
from scipy.sparse.linalg import splu

BAND_LIMIT = 64
"""Widest band (lower + upper + 1) :func:`banded_solve_rows` factors [-]; a wider one (no
ring cut, a full film) is left to SuperLU."""


def banded_solve_rows(indptr: np.ndarray, indices: np.ndarray, data: np.ndarray,
                      right: np.ndarray) -> np.ndarray | None:
    """X (m, n) with A X[q] = B[q] for the rows of ``right`` B (m, n), A (n × n) given by
    rows (CSR ``indptr``, ``indices``, ``data``; repeated entries add up): numbered from
    the first cut of the ring that no entry crosses, A's band factored without pivoting
    (module docstring). None where no such cut leaves a band of at most
    :data:`BAND_LIMIT` or a pivot is not positive: SuperLU's case."""
    out, ok = _banded_solve_rows(  # one signature: int64 indices, float64 values
        indptr.astype(np.int64, copy=False), indices.astype(np.int64, copy=False),
        data.astype(float, copy=False), np.ascontiguousarray(right, dtype=float), BAND_LIMIT)
    return out if ok else None


@nb.njit(cache=True)
def _ring_cut(indptr, indices, n):
    """First k with no entry (r, c), |r − c| ≤ n/2, spanning k − 1 → k (0 where no entry
    wraps around the ring); −1 where every cut is crossed."""
    crossing = np.zeros(n + 1, dtype=np.int64)
    wraps = False
    for r in range(n):
        for p in range(indptr[r], indptr[r + 1]):
            c = indices[p]
            low, high = min(r, c), max(r, c)
            if high - low > n // 2:
                wraps = True
            else:
                crossing[low + 1] += 1
                crossing[high + 1] -= 1
    if not wraps:
        return 0
    count = crossing[0]
    for k in range(1, n):
        count += crossing[k]
        if count == 0:
            return k
    return -1


@nb.njit(cache=True)
def _banded_solve_rows(indptr, indices, data, right, limit):
    """:func:`banded_solve_rows` (the answer, True) or (empty, False)."""
    m, n = right.shape
    start = _ring_cut(indptr, indices, n)
    if start < 0:
        return np.empty((0, 0)), False
    lower, upper = 0, 0
    for r in range(n):
        new_r = (r - start) % n
        for p in range(indptr[r], indptr[r + 1]):
            offset = (indices[p] - start) % n - new_r
            lower, upper = max(lower, -offset), max(upper, offset)
    if lower + upper + 1 > limit:
        return np.empty((0, 0)), False
    band = np.zeros((n, lower + upper + 1))  # band[i, j − i + lower] = A[i, j]
    for r in range(n):
        new_r = (r - start) % n
        for p in range(indptr[r], indptr[r + 1]):
            band[new_r, (indices[p] - start) % n - new_r + lower] += data[p]
    for k in range(n):  # L U in place, L unit lower
        pivot = band[k, lower]
        if not pivot > 0.0:
            return np.empty((0, 0)), False
        for i in range(k + 1, min(k + lower + 1, n)):
            factor = band[i, k - i + lower] / pivot
            band[i, k - i + lower] = factor
            if factor != 0.0:
                for j in range(k + 1, min(k + upper + 1, n)):
                    band[i, j - i + lower] -= factor * band[k, j - k + lower]
    work = np.empty((n, m))  # the right-hand sides side by side, renumbered
    for i in range(n):
        old = (i + start) % n
        for q in range(m):
            work[i, q] = right[q, old]
    for i in range(n):
        for j in range(max(0, i - lower), i):
            factor = band[i, j - i + lower]
            if factor != 0.0:
                for q in range(m):
                    work[i, q] -= factor * work[j, q]
    for i in range(n - 1, -1, -1):
        for j in range(i + 1, min(i + upper + 1, n)):
            value = band[i, j - i + lower]
            if value != 0.0:
                for q in range(m):
                    work[i, q] -= value * work[j, q]
        diagonal = band[i, lower]
        for q in range(m):
            work[i, q] /= diagonal
    out = np.empty((m, n))
    for i in range(n):
        old = (i + start) % n
        for q in range(m):
            out[q, old] = work[i, q]
    return out, True


class ManyRightHandSides:
    """The LU factor of a square sparse ``matrix`` (SuperLU, ``permc_spec`` its column
    ordering) that solves many right-hand sides at once (:meth:`solve_rows`)."""

    def __init__(self, matrix, permc_spec: str = "COLAMD"):
        factor = splu(matrix, permc_spec=permc_spec)
        lower, upper = factor.L, factor.U
        self.perm_r, self.perm_c = factor.perm_r, factor.perm_c
        self.lower = (lower.indptr, lower.indices, lower.data)
        self.upper = (upper.indptr, upper.indices, upper.data)

    def solve_rows(self, right: np.ndarray) -> np.ndarray:
        """X (m, n) with A X[q] = B[q] for the rows of ``right`` B (m, n) [unit of B / A]."""
        return _solve_rows(*self.lower, *self.upper, self.perm_r, self.perm_c,
                           np.ascontiguousarray(right, dtype=float))


@nb.njit(cache=True)
def _solve_rows(l_indptr, l_indices, l_data, u_indptr, u_indices, u_data, perm_r, perm_c,
                right):
    """X (m, n) of the rows of B = ``right``: L U (P_c^T x) = P_r b for each row, the rows
    side by side in one work array (n, m)."""
    m, n = right.shape
    work = np.empty((n, m))
    for i in range(n):
        row = perm_r[i]
        for q in range(m):
            work[row, q] = right[q, i]
    _triangular_solves(l_indptr, l_indices, l_data, u_indptr, u_indices, u_data, work)
    out = np.empty((m, n))
    for i in range(n):
        row = perm_c[i]
        for q in range(m):
            out[q, i] = work[row, q]
    return out


@nb.njit(cache=True)
def _triangular_solves(l_indptr, l_indices, l_data, u_indptr, u_indices, u_data, x):
    """L Y = X then U W = Y in place on X (n, m), L unit lower and U upper, both compressed
    by columns."""
    n, m = x.shape
    for j in range(n):
        for p in range(l_indptr[j], l_indptr[j + 1]):
            i = l_indices[p]
            if i > j:
                value = l_data[p]
                for c in range(m):
                    x[i, c] -= value * x[j, c]
    for j in range(n - 1, -1, -1):
        diagonal = 0.0
        for p in range(u_indptr[j], u_indptr[j + 1]):
            if u_indices[p] == j:
                diagonal = u_data[p]
        for c in range(m):
            x[j, c] /= diagonal
        for p in range(u_indptr[j], u_indptr[j + 1]):
            i = u_indices[p]
            if i < j:
                value = u_data[p]
                for c in range(m):
                    x[i, c] -= value * x[j, c]
