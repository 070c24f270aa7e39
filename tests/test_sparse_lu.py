"""Many right-hand sides of one SuperLU factor in one compiled sweep
(:mod:`conrod.numerics.sparse_lu`): the answers of SuperLU's own solve, to round-off, on
symmetric and unsymmetric sparse matrices and any column ordering."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import splu

from conrod.numerics.sparse_lu import ManyRightHandSides


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
