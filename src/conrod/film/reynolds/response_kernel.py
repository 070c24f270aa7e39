"""Compiled kernel of :mod:`conrod.film.reynolds.response`: the change of the discrete flow
balance of :mod:`conrod.film.reynolds.kernel` per unit bore displacement at one row.

A bore displacement u_j raises h by u_j on the whole row j (and ḣ by ``rate`` u_j). In the
balance of node (i, k)

.. math:: r_{ik} = a^E_{ik}(p_{ik} − p_{i+1,k}) + a^E_{i−1,k}(p_{ik} − p_{i−1,k})
          + a^N_{ik}(p_{ik} − p_{i,k+1}) + a^N_{i,k−1}(p_{ik} − p_{i,k−1}) − b_{ik}

with a^E = h_e³ w/(RΔθ), a^N = h_n³ RΔθ/Δz and b = −12μ w (U/2 (h_e − h_w) + ḣ RΔθ),
only the faces touching row j change: ∂a^E_{j−1} = ∂a^E_j = 3h_e²w/(2RΔθ),
∂a^N_j = 3h_n² RΔθ/Δz, the wedge sources of the neighbours ∂b_{j∓1} = ∓3μwU, and
∂b_j = −12μw RΔθ ∂ḣ/∂u (the rate). So ∂r/∂u_j lives on rows j − 1, j, j + 1.
"""

from __future__ import annotations

import numba as nb
import numpy as np


@nb.njit(cache=True)
def bore_row_imbalance(pressure: np.ndarray, h: np.ndarray, rate: float, radius: float,
                       d_theta: float, d_z: float, omega_sum: float,
                       viscosity: float) -> np.ndarray:
    """D (n_θ, 3, n_z + 1): D[j, s, k] = ∂r[(j − 1 + s) mod n_θ, k]/∂u_j [Pa m^3]
    (``rate`` = ∂ḣ/∂u [1/s], 0 without the deformation rate)."""
    n_theta, n_nodes = h.shape
    arc = radius * d_theta
    surface_speed = radius * omega_sum
    out = np.zeros((n_theta, 3, n_nodes))
    for j in range(n_theta):
        jm = (j - 1) % n_theta
        jp = (j + 1) % n_theta
        for k in range(n_nodes):
            width = d_z if 0 < k < n_nodes - 1 else 0.5 * d_z
            h_west = 0.5 * (h[jm, k] + h[j, k])      # face j−1 | j
            h_east = 0.5 * (h[j, k] + h[jp, k])      # face j | j+1
            d_west = 1.5 * h_west * h_west * width / arc
            d_east = 1.5 * h_east * h_east * width / arc
            wedge = 6.0 * viscosity * width * surface_speed * 0.5
            # row j − 1: its east face changes, its wedge source b gains −12μw U/2 × ½
            out[j, 0, k] = d_west * (pressure[jm, k] - pressure[j, k]) + wedge
            # row j + 1: its west face changes, its wedge source gains +12μw U/2 × ½
            out[j, 2, k] = d_east * (pressure[jp, k] - pressure[j, k]) - wedge
            # row j: both faces, the axial faces, the rate in the source
            value = (d_east * (pressure[j, k] - pressure[jp, k])
                     + d_west * (pressure[j, k] - pressure[jm, k]))
            if k < n_nodes - 1:
                h_n = 0.5 * (h[j, k] + h[j, k + 1])
                value += 3.0 * h_n * h_n * arc / d_z * (pressure[j, k] - pressure[j, k + 1])
            if k > 0:
                h_s = 0.5 * (h[j, k] + h[j, k - 1])
                value += 3.0 * h_s * h_s * arc / d_z * (pressure[j, k] - pressure[j, k - 1])
            out[j, 1, k] = value + 12.0 * viscosity * width * rate * arc
    return out


@nb.njit(cache=True)
def bore_node_imbalance(pressure: np.ndarray, h: np.ndarray, rate: float, radius: float,
                        d_theta: float, d_z: float, omega_sum: float,
                        viscosity: float) -> np.ndarray:
    """E (n_θ, n_z + 1, 5): E[j, k, s] = ∂r[node s of the stencil]/∂u_jk [Pa m^3] for a
    displacement u_jk of the single film node (j, k) (h and, with ``rate`` = ∂ḣ/∂u [1/s],
    ḣ raised there alone); the stencil s = 0 the node itself, 1 the node j − 1, 2 the node
    j + 1 (both periodic), 3 the node k − 1, 4 the node k + 1 (zero beyond the edges).

    A face conductance depends on the mean of its two nodes, so u_jk moves each of the
    four faces of (j, k) by half of a row's move: ∂a^E = 3h_e² w/(2RΔθ), ∂a^N = 3h_n²
    RΔθ/(2Δz); the wedge sources of j ∓ 1 change by ∓3μwU as for a row, the node's own
    source by the rate. Summed over k, E gives the row response of
    :func:`bore_row_imbalance`."""
    n_theta, n_nodes = h.shape
    arc = radius * d_theta
    surface_speed = radius * omega_sum
    out = np.zeros((n_theta, n_nodes, 5))
    for j in range(n_theta):
        jm = (j - 1) % n_theta
        jp = (j + 1) % n_theta
        for k in range(n_nodes):
            width = d_z if 0 < k < n_nodes - 1 else 0.5 * d_z
            h_west = 0.5 * (h[jm, k] + h[j, k])
            h_east = 0.5 * (h[j, k] + h[jp, k])
            d_west = 1.5 * h_west * h_west * width / arc
            d_east = 1.5 * h_east * h_east * width / arc
            wedge = 6.0 * viscosity * width * surface_speed * 0.5
            out[j, k, 1] = d_west * (pressure[jm, k] - pressure[j, k]) + wedge
            out[j, k, 2] = d_east * (pressure[jp, k] - pressure[j, k]) - wedge
            value = (d_east * (pressure[j, k] - pressure[jp, k])
                     + d_west * (pressure[j, k] - pressure[jm, k]))
            if k < n_nodes - 1:
                h_n = 0.5 * (h[j, k] + h[j, k + 1])
                d_north = 1.5 * h_n * h_n * arc / d_z
                value += d_north * (pressure[j, k] - pressure[j, k + 1])
                out[j, k, 4] = d_north * (pressure[j, k + 1] - pressure[j, k])
            if k > 0:
                h_s = 0.5 * (h[j, k] + h[j, k - 1])
                d_south = 1.5 * h_s * h_s * arc / d_z
                value += d_south * (pressure[j, k] - pressure[j, k - 1])
                out[j, k, 3] = d_south * (pressure[j, k - 1] - pressure[j, k])
            out[j, k, 0] = value + 12.0 * viscosity * width * rate * arc
    return out


@nb.njit(cache=True)
def active_rows(a_east: np.ndarray, a_north: np.ndarray, active: np.ndarray, half: bool):
    """K_AA of the flow balance on the ``active`` nodes by rows (CSR ``indptr``,
    ``indices``, ``data``), the nodes numbered row by row: the diagonal
    a^E_ij + a^E_(i−1)j + a^N_ij + a^N_i(j−1), a neighbour's coupling −(the conductance of
    the face between them) (also :func:`conrod.film.linearised.active_matrix`'s); with
    ``half`` the rows of the nodes with z ≤ 0 and each column on its node's mirror image
    there (K_H of :mod:`conrod.film.reynolds.response`: a column and its image listed apart,
    to be added up) [m^3/(Pa s)]."""
    n_theta, n_nodes = active.shape
    limit = (n_nodes - 1) // 2 if half else n_nodes - 1
    place = -np.ones((n_theta, n_nodes), dtype=np.int64)
    count = 0
    for i in range(n_theta):
        for j in range(limit + 1):
            if active[i, j]:
                place[i, j] = count
                count += 1
    indptr = np.zeros(count + 1, dtype=np.int64)
    indices = np.empty(5 * count, dtype=np.int64)
    data = np.empty(5 * count)
    at = 0
    for i in range(n_theta):
        west, east = (i - 1) % n_theta, (i + 1) % n_theta
        for j in range(limit + 1):
            row = place[i, j]
            if row < 0:
                continue
            indices[at] = row
            data[at] = (a_east[i, j] + a_east[west, j] + a_north[i, j] + a_north[i, j - 1])
            at += 1
            for ni, nj, conductance in ((east, j, a_east[i, j]), (west, j, a_east[west, j]),
                                        (i, j + 1, a_north[i, j]), (i, j - 1, a_north[i, j - 1])):
                if nj < 0 or nj >= n_nodes or not active[ni, nj]:
                    continue
                image = min(nj, n_nodes - 1 - nj) if half else nj
                indices[at] = place[ni, image]
                data[at] = -conductance
                at += 1
            indptr[row + 1] = at
    return indptr, indices[:at], data[:at]


@nb.njit(cache=True)
def row_directions(rows: np.ndarray, index: np.ndarray) -> np.ndarray:
    """−∂r/∂u_j (n_θ, n_solved) at the solved nodes from D of :func:`bore_row_imbalance`
    (``index``: a node's place among the solved nodes, −1 elsewhere) [Pa m^3]: row j
    holds −D[j, s, k] at the place of node ((j − 1 + s) mod n_θ, k)."""
    n_theta, _, n_nodes = rows.shape
    right = np.zeros((n_theta, index.max() + 1))
    for shift in range(3):
        for j in range(n_theta):
            row = (j - 1 + shift) % n_theta
            for k in range(n_nodes):
                place = index[row, k]
                if place >= 0:
                    right[j, place] = -rows[j, shift, k]
    return right


@nb.njit(cache=True)
def row_load_response(solved: np.ndarray, weights: np.ndarray, node_rows: np.ndarray,
                      columns: np.ndarray, n_rows: int) -> np.ndarray:
    """∂f/∂q (n_rows, n_q) of the row loads f_j = Σ W p over the solved nodes: active node a
    (row ``node_rows[a]``, ascending) adds ``weights[a]`` × the column ``columns[a]`` of
    ``solved`` (n_q, n_solved) [N per unit q]. Each row's entries are taken by column, two
    on one column (a node and its mirror image) added first, then w ∂p/∂q summed from zero
    in that order: SciPy's sparse rows (duplicates summed, indices sorted) times a dense
    matrix, the same operations, without building the sparse matrix."""
    n_q = solved.shape[0]
    out = np.zeros((n_rows, n_q))
    count = weights.size
    first = 0
    while first < count:
        row = node_rows[first]
        last = first
        while last < count and node_rows[last] == row:
            last += 1
        order = np.argsort(columns[first:last], kind="mergesort")
        k = 0
        while k < order.size:
            column = columns[first + order[k]]
            weight = weights[first + order[k]]
            k += 1
            while k < order.size and columns[first + order[k]] == column:
                weight += weights[first + order[k]]
                k += 1
            for q in range(n_q):
                out[row, q] += weight * solved[q, column]
        first = last
    return out
