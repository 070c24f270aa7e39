"""Many right-hand sides of one SuperLU factor in one compiled sweep
(:mod:`conrod.numerics.sparse_lu`): the answers of SuperLU's own solve, to round-off, on
symmetric and unsymmetric sparse matrices and any column ordering."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from conrod.numerics.sparse_lu import ManyRightHandSides, banded_solve_rows


def _matrix(n: int, seed: int, symmetric: bool):
    rng = np.random.default_rng(seed)
    a = sp.random(n, n, density=4.0 / n, random_state=rng, format="csc")
    if symmetric:
        a = a + a.T
    return (a + sp.diags(1.0 + np.abs(a).sum(axis=1).A1)).tocsc(), rng


@pytest.mark.parametrize("symmetric, ordering", [(True, "MMD_AT_PLUS_A"), (False, "COLAMD"),
                                                 (False, "NATURAL")])
@pytest.mark.parametrize("seed", [0, 1])
def test_rows_solved_at_once_are_superlus_answers(symmetric, ordering, seed):
    matrix, rng = _matrix(300, seed, symmetric)
    right = rng.standard_normal((37, 300))
    factor = splu(matrix, permc_spec=ordering)
    expected = np.array([factor.solve(row) for row in right])
    solved = ManyRightHandSides(matrix, ordering).solve_rows(right)
    assert solved.shape == right.shape and solved.flags.c_contiguous
    assert np.abs(solved - expected).max() <= 1e-12 * np.abs(expected).max()
    assert np.abs(solved @ matrix.T - right).max() <= 1e-10 * np.abs(right).max()


def test_a_permuted_identity_is_solved_exactly():
    n = 50
    order = np.random.default_rng(3).permutation(n)
    matrix = sp.csc_matrix((np.full(n, 2.0), (np.arange(n), order)), shape=(n, n))
    right = np.arange(2 * n, dtype=float).reshape(2, n)
    solved = ManyRightHandSides(matrix).solve_rows(right)
    assert np.array_equal(solved @ matrix.T.toarray(), right)


def _ring(rows: int, per_row: int, empty: tuple[int, ...], seed: int):
    """The 5-point flux balance (an M-matrix, CSR) of the nodes of a periodic ring of
    ``rows`` grid rows of ``per_row`` nodes, rows in ``empty`` without nodes (a cavitated
    arc), numbered row by row; random conductances, a Dirichlet edge on both sides."""
    rng = np.random.default_rng(seed)
    present = np.ones((rows, per_row), dtype=bool)
    present[list(empty)] = False
    index = -np.ones((rows, per_row), dtype=np.int64)
    index[present] = np.arange(present.sum())
    east = rng.uniform(0.5, 2.0, (rows, per_row))
    north = rng.uniform(0.5, 2.0, (rows, per_row + 1))
    entries: list[tuple[int, int, float]] = []
    for i, j in zip(*np.nonzero(present), strict=True):
        here = index[i, j]
        couplings = [((i + 1) % rows, j, east[i, j]), ((i - 1) % rows, j, east[i - 1, j]),
                     (i, j + 1, north[i, j + 1]), (i, j - 1, north[i, j])]
        entries.append((here, here, sum(c for _, _, c in couplings)))
        for ni, nj, c in couplings:
            if 0 <= nj < per_row and present[ni, nj]:
                entries.append((here, index[ni, nj], -c))
    r, c, v = (np.array(x) for x in zip(*entries, strict=True))
    n = int(present.sum())
    return sp.csr_matrix((v, (r, c)), shape=(n, n)), rng


@pytest.mark.parametrize("empty", [(0,), (11,), (5, 6, 7), ()])
def test_the_banded_solve_of_a_cut_ring_is_superlus_answer(empty):
    """A ring cut by an empty row anywhere (the band renumbered from the cut) is solved as
    SuperLU solves it, to round-off; a ring without a cut is left to SuperLU (None)."""
    matrix, rng = _ring(24, 6, empty, seed=len(empty))
    right = rng.standard_normal((9, matrix.shape[0]))
    solved = banded_solve_rows(matrix.indptr, matrix.indices, matrix.data, right)
    if not empty:
        assert solved is None
        return
    expected = ManyRightHandSides(matrix.tocsc()).solve_rows(right)
    assert solved is not None and solved.shape == right.shape
    assert np.abs(solved - expected).max() <= 1e-12 * np.abs(expected).max()


def test_repeated_entries_add_up_in_the_banded_solve():
    """Entries given twice (a folded column added onto its image) count as their sum."""
    matrix, rng = _ring(16, 4, (3,), seed=5)
    coo = matrix.tocoo()
    doubled = sp.csr_matrix((np.concatenate([coo.data, 0.5 * coo.data, 0.5 * coo.data]),
                             (np.tile(coo.row, 3), np.tile(coo.col, 3))),
                            shape=matrix.shape, copy=False)
    rows = np.repeat(np.arange(matrix.shape[0]), 3 * np.diff(matrix.indptr))
    order = np.argsort(np.concatenate([coo.row, coo.row, coo.row]), kind="stable")
    indptr = np.concatenate([[0], np.cumsum(3 * np.diff(matrix.indptr))])
    data = np.concatenate([coo.data, 0.5 * coo.data, 0.5 * coo.data])[order]
    columns = np.concatenate([coo.col, coo.col, coo.col])[order]
    assert np.array_equal(rows, np.concatenate([coo.row] * 3)[order])
    right = rng.standard_normal((3, matrix.shape[0]))
    solved = banded_solve_rows(indptr, columns, data, right)
    expected = ManyRightHandSides(doubled.tocsc()).solve_rows(right)
    assert solved is not None
    assert np.abs(solved - expected).max() <= 1e-12 * np.abs(expected).max()


def test_a_matrix_without_positive_pivots_is_left_to_superlu():
    """A pivot that is not positive (no M-matrix) ends the banded solve: None."""
    matrix, rng = _ring(12, 3, (0,), seed=7)
    negated = -matrix
    assert banded_solve_rows(negated.indptr, negated.indices, negated.data,
                             rng.standard_normal((2, matrix.shape[0]))) is None
