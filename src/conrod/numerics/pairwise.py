"""Weighted sums of a film field in one compiled call, bit for bit NumPy's.

NumPy sums a contiguous run of n float64 values pairwise (``numpy/_core/src/umath/
loops_utils.h.src``, ``pairwise_sum``): fewer than 8 values one after the other from 0;
up to 128 in eight running sums over the blocks of eight, combined as
((r₀ + r₁) + (r₂ + r₃)) + ((r₄ + r₅) + (r₆ + r₇)), the remainder added after; more split
at n/2 rounded down to a multiple of 8 and the halves summed alike. A full reduction of a
C-contiguous array runs over its values in memory order, a reduction along the last axis
over each row; the reduction starts from 0.0. The functions here follow that order on the
products w·p formed one by one (each rounded as NumPy's product array holds it), so
``weighted_sum(p, w)`` is ``(p * w).sum()`` and ``weighted_row_sums(w, p)`` is
``(w * p).sum(axis=1)`` to the last bit (``tests/test_pairwise.py``) — without the product
array and the two dispatches, 13 → 4 µs for the force of a film solve of the README job.
Both arrays must be C-contiguous and of one shape (:func:`exact_order`); elsewhere the
callers keep NumPy's expression.
"""

from __future__ import annotations

import numba as nb
import numpy as np

FLOAT = np.dtype(np.float64)
"""The one element type summed here [-]."""
BLOCK = 128
"""NumPy's ``PW_BLOCKSIZE``: the longest run summed in eight running sums [-]."""


def exact_order(*arrays: np.ndarray) -> bool:
    """True when the arrays are C-contiguous float64 arrays of one shape, where the
    compiled sums here give NumPy's bits [-]."""
    shape = arrays[0].shape
    for array in arrays:  # a loop, not all(...): its generator cost more than the sums saved
        if array.dtype != FLOAT or not array.flags.c_contiguous or array.shape != shape:
            return False
    return True


@nb.njit(cache=True)
def _block(p: np.ndarray, w: np.ndarray, start: int, count: int) -> float:
    """NumPy's sum of p[i]·w[i] over a run of at most :data:`BLOCK` values from ``start``."""
    if count < 8:
        total = 0.0
        for i in range(start, start + count):
            total += p[i] * w[i]
        return total
    r0 = p[start] * w[start]
    r1 = p[start + 1] * w[start + 1]
    r2 = p[start + 2] * w[start + 2]
    r3 = p[start + 3] * w[start + 3]
    r4 = p[start + 4] * w[start + 4]
    r5 = p[start + 5] * w[start + 5]
    r6 = p[start + 6] * w[start + 6]
    r7 = p[start + 7] * w[start + 7]
    i = start + 8
    stop = start + count - count % 8
    while i < stop:
        r0 += p[i] * w[i]
        r1 += p[i + 1] * w[i + 1]
        r2 += p[i + 2] * w[i + 2]
        r3 += p[i + 3] * w[i + 3]
        r4 += p[i + 4] * w[i + 4]
        r5 += p[i + 5] * w[i + 5]
        r6 += p[i + 6] * w[i + 6]
        r7 += p[i + 7] * w[i + 7]
        i += 8
    total = ((r0 + r1) + (r2 + r3)) + ((r4 + r5) + (r6 + r7))
    while i < start + count:
        total += p[i] * w[i]
        i += 1
    return total


@nb.njit(cache=True)
def _pairwise(p: np.ndarray, w: np.ndarray, start: int, count: int) -> float:
    """NumPy's pairwise sum of p[i]·w[i] over i = start … start + count − 1 (1-D views):
    its recursion (left half + right half) walked with a stack of runs and one of partial
    sums, as numba's disk cache does not hold a recursive function."""
    if count <= BLOCK:
        return _block(p, w, start, count)
    runs = np.empty((64, 3), dtype=np.int64)  # start, count, halves begun (0, 1, 2)
    sums = np.empty(64)
    runs[0, 0], runs[0, 1], runs[0, 2] = start, count, 0
    top, held = 0, 0
    while top >= 0:
        first, size, begun = runs[top, 0], runs[top, 1], runs[top, 2]
        if size <= BLOCK:
            sums[held] = _block(p, w, first, size)
            held += 1
            top -= 1
            continue
        half = size // 2
        half -= half % 8
        if begun == 2:  # both halves summed: left + right
            sums[held - 2] = sums[held - 2] + sums[held - 1]
            held -= 1
            top -= 1
            continue
        runs[top, 2] = begun + 1
        top += 1
        if begun == 0:
            runs[top, 0], runs[top, 1] = first, half
        else:
            runs[top, 0], runs[top, 1] = first + half, size - half
        runs[top, 2] = 0
    return sums[0]


@nb.njit(cache=True)
def weighted_sums(p: np.ndarray, w_x: np.ndarray, w_y: np.ndarray) -> tuple[float, float]:
    """((p w_x).sum(), (p w_y).sum()) of three C-contiguous 2-D arrays of one shape,
    NumPy's bits."""
    flat = p.ravel()
    return (0.0 + _pairwise(flat, w_x.ravel(), 0, flat.size),
            0.0 + _pairwise(flat, w_y.ravel(), 0, flat.size))


@nb.njit(cache=True)
def weighted_row_sums(w: np.ndarray, p: np.ndarray) -> np.ndarray:
    """(w p).sum(axis=1) of two C-contiguous 2-D arrays of one shape, NumPy's bits."""
    n, m = p.shape
    out = np.empty(n)
    for i in range(n):
        out[i] = 0.0 + _pairwise(p[i], w[i], 0, m)
    return out
