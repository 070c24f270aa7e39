"""The compiled weighted sums give NumPy's pairwise sums bit for bit
(:mod:`conrod.numerics.pairwise`), on the shapes of the shipped grids and beyond NumPy's
block of 128 values and its 8192-value buffer."""

import numpy as np
import pytest

from conrod.numerics.pairwise import exact_order, weighted_row_sums, weighted_sums

SHAPES = [(1, 1), (5, 1), (10, 3), (37, 9), (73, 9), (145, 17), (217, 33), (3, 300),
          (290, 65), (1000, 37)]


@pytest.mark.parametrize("shape", SHAPES)
def test_weighted_sums_are_numpys_bit_for_bit(shape):
    rng = np.random.default_rng(sum(shape))
    for _ in range(40):  # magnitudes over 14 decades: the order of the sums shows
        p = rng.standard_normal(shape) * 10.0 ** rng.uniform(-5, 9, shape)
        w_x = rng.standard_normal(shape) * 10.0 ** rng.uniform(-8, 0, shape)
        w_y = rng.standard_normal(shape)
        sum_x, sum_y = weighted_sums(p, w_x, w_y)
        assert sum_x == (p * w_x).sum() and sum_y == (p * w_y).sum()
        assert np.array_equal(weighted_row_sums(w_x, p), (w_x * p).sum(axis=1))


def test_a_sum_in_another_order_would_differ():
    """The check above can fail: a plain running sum of the same products differs from
    NumPy's in the last bits on most of these fields."""
    rng = np.random.default_rng(7)
    differ = 0
    for _ in range(40):
        p = rng.standard_normal((145, 17)) * 10.0 ** rng.uniform(-5, 9, (145, 17))
        w = rng.standard_normal((145, 17))
        running = 0.0
        for value in (p * w).ravel():
            running += value
        differ += running != weighted_sums(p, w, w)[0]
    assert differ > 20


def test_exact_order_only_for_c_contiguous_float_arrays_of_one_shape():
    a = np.ones((4, 3))
    assert exact_order(a, a.copy())
    assert not exact_order(a, np.asfortranarray(np.ones((4, 3))))
    assert not exact_order(a, np.ones((4, 3), dtype=np.float32))
    assert not exact_order(a, np.ones((3, 4)))
    assert not exact_order(np.ones((4, 6))[:, ::2], a)


def test_nan_and_infinity_propagate_as_in_numpy():
    p = np.ones((9, 9))
    p[4, 4] = np.nan
    assert np.isnan(weighted_sums(p, p, p)[0]) and np.isnan(weighted_row_sums(p, p)[4])
    p[4, 4] = np.inf
    assert weighted_sums(p, p, p)[0] == np.inf
