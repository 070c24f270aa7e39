"""Many right-hand sides of one sparse LU factor in one compiled pass.

SuperLU (:func:`scipy.sparse.linalg.splu`) factors P_r A P_c = L U. Its ``solve`` takes one
right-hand side at a time quickly, but its blocked solve of a 2-D right-hand side is slower
than a loop, and a loop of a hundred back-substitutions costs a Python call each. Here the
factor's L (unit lower) and U (upper), both compressed by columns, are swept once with all
right-hand sides side by side (the innermost loop runs over the right-hand sides,
contiguous in memory):

.. math:: L\\,y = P_r b, \\qquad U\\,w = y, \\qquad x = P_c\\,w

The same arithmetic as SuperLU's triangular solves up to the order of the sums (round-off).
"""

from __future__ import annotations

import numba as nb
import numpy as np
from scipy.sparse.linalg import splu


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
