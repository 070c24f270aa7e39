"""Compiled kernels of the finite-difference (finite-volume) Reynolds solver.

Discretisation ([D2] ch. 3; frame and signs of :mod:`conrod.film.base`)
---------------------------------------------------------------------------
The Reynolds equation divided by 12μ is a mass balance of the volumetric flux
q = (U h/2 − h³/(12μ) ∂p/∂x, −h³/(12μ) ∂p/∂z), x = Rθ, U = R(ω_j + ω_b):

.. math:: \\nabla\\cdot q + \\partial_t h = 0.

On a vertex-centred grid (θ periodic with ``n_theta`` intervals, z with ``n_z``
intervals and both edges as nodes) each node owns a control volume RΔθ × w_j
(w_j = Δz inside, Δz/2 on an edge row). With face film thicknesses taken as node
averages the balance of node P reads (everything multiplied by 12μ):

.. math:: a_P p_P - a_E p_E - a_W p_W - a_N p_N - a_S p_S = b_P,

a_E = h_e³ w_j /(RΔθ), a_N = h_n³ RΔθ/Δz, b_P = −12μ[(U/2)(h_e − h_w) w_j + ḣ RΔθ w_j].
The scheme is second order and conservative, so boundary flows computed as node
*imbalances* (:func:`node_imbalance`) satisfy the global mass balance to round-off.

Solver: lexicographic SOR with the Swift–Stieber projection p := max(p, p_cav) after
each node update (Christopherson's method as in [D2] ch. 3), deterministic.
"""

from __future__ import annotations

import math

import numba as nb
import numpy as np


@nb.njit(cache=True)
def assemble_coefficients(
    h: np.ndarray, h_rate: np.ndarray, radius: float, d_theta: float, d_z: float,
    omega_sum: float, viscosity: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Face conductances a_E (n_θ, n_nodes_z), a_N (n_θ, n_nodes_z − 1) [m^4] and the
    source b (n_θ, n_nodes_z) [Pa m^4] of the discrete balance (module docstring).

    h : film thickness at the nodes [m]; h_rate : ∂h/∂t at the nodes [m/s].
    """
    n_theta, n_nodes = h.shape
    a_east = np.empty((n_theta, n_nodes))
    a_north = np.empty((n_theta, n_nodes - 1))
    source = np.empty((n_theta, n_nodes))
    surface_speed = radius * omega_sum
    arc = radius * d_theta
    for i in range(n_theta):
        ip = (i + 1) % n_theta
        im = (i - 1) % n_theta
        for j in range(n_nodes):
            width = d_z if 0 < j < n_nodes - 1 else 0.5 * d_z
            h_e = 0.5 * (h[i, j] + h[ip, j])
            h_w = 0.5 * (h[i, j] + h[im, j])
            a_east[i, j] = h_e * h_e * h_e * width / arc
            source[i, j] = -12.0 * viscosity * width * (
                0.5 * surface_speed * (h_e - h_w) + h_rate[i, j] * arc
)
            if j < n_nodes - 1:
                h_n = 0.5 * (h[i, j] + h[i, j + 1])
                a_north[i, j] = h_n * h_n * h_n * arc / d_z
    return a_east, a_north, source


@nb.njit(cache=True)
def sor_solve(
    pressure: np.ndarray, a_east: np.ndarray, a_north: np.ndarray, source: np.ndarray,
    fixed: np.ndarray, cavitation_pressure: float, relaxation: float,
    tolerance: float, max_iterations: int,
) -> tuple[int, float]:
    """Projected SOR sweeps in place on ``pressure`` [Pa] until the largest update
    is below ``tolerance`` × max|p|; nodes with ``fixed`` keep their value.

    Returns (sweeps done, last relative update [-]). Edge rows must be fixed.
    """
    n_theta, n_nodes = pressure.shape
    inverse_diagonal = np.zeros((n_theta, n_nodes))
    for i in range(n_theta):
        im = (i - 1) % n_theta
        for j in range(1, n_nodes - 1):
            diagonal = a_east[i, j] + a_east[im, j] + a_north[i, j] + a_north[i, j - 1]
            inverse_diagonal[i, j] = 1.0 / diagonal
    change = math.inf
    for sweep in range(1, max_iterations + 1):
        largest_update = 0.0
        largest_pressure = 0.0
        for i in range(n_theta):
            ip = (i + 1) % n_theta
            im = (i - 1) % n_theta
            for j in range(1, n_nodes - 1):
                old = pressure[i, j]
                if fixed[i, j]:
                    largest_pressure = max(largest_pressure, abs(old))
                    continue
                gauss_seidel = inverse_diagonal[i, j] * (
                    a_east[i, j] * pressure[ip, j] + a_east[im, j] * pressure[im, j]
                    + a_north[i, j] * pressure[i, j + 1]
                    + a_north[i, j - 1] * pressure[i, j - 1] + source[i, j]
)
                new = old + relaxation * (gauss_seidel - old)
                if new < cavitation_pressure:
                    new = cavitation_pressure
                pressure[i, j] = new
                largest_update = max(largest_update, abs(new - old))
                largest_pressure = max(largest_pressure, abs(new))
        if largest_pressure == 0.0:
            return sweep, 0.0
        change = largest_update / largest_pressure
        if change <= tolerance:
            return sweep, change
    return max_iterations, change


@nb.njit(cache=True, inline="always")
def _net_outflow(pressure, a_east, a_north, source, i, ip, im, j):
    """Oil leaving node (i, j) through its four faces minus its source [Pa m^4]: the
    imbalance of the discrete balance at one node (0 where it is solved)."""
    m = pressure.shape[1]
    p = pressure[i, j]
    value = a_east[i, j] * (p - pressure[ip, j]) + a_east[im, j] * (p - pressure[im, j])
    if j < m - 1:
        value += a_north[i, j] * (p - pressure[i, j + 1])
    if j > 0:
        value += a_north[i, j - 1] * (p - pressure[i, j - 1])
    return value - source[i, j]


@nb.njit(cache=True)
def flow_balance(pressure, a_east, a_north, source, fixed, cavitation_pressure,
                 axial_weights):
    """Sums of :func:`node_imbalance` [Pa m^4] in one pass: (cavitated nodes and the edge
    nodes beside a cavitated node — the oil not conserved; edge nodes that leak — the side
    flow; fixed interior nodes — the supply) and Σ w_j over the cavitated free nodes [m].
    The edges are the first and last rows."""
    n, m = pressure.shape
    lost = 0.0
    leaking = 0.0
    supply = 0.0
    cavitated_width = 0.0
    for i in range(n):
        ip = i + 1 if i + 1 < n else 0
        im = i - 1 if i > 0 else n - 1
        for j in range(m):
            value = _net_outflow(pressure, a_east, a_north, source, i, ip, im, j)
            if j == 0 or j == m - 1:
                inner = 1 if j == 0 else m - 2
                if not fixed[i, inner] and pressure[i, inner] <= cavitation_pressure:
                    lost += value
                else:
                    leaking += value
            elif fixed[i, j]:
                supply += value
            elif pressure[i, j] <= cavitation_pressure:
                lost += value
                cavitated_width += axial_weights[j]
    return lost, leaking, supply, cavitated_width


@nb.njit(cache=True)
def node_imbalance(
    pressure: np.ndarray, a_east: np.ndarray, a_north: np.ndarray, source: np.ndarray,
) -> np.ndarray:
    """12μ × (flow entering the film from outside) at every node [Pa m^4 = 12μ m^3/s].

    Zero at free full-film nodes; at Dirichlet nodes it is the boundary flow (edge rows:
    negative = side leakage; supply regions: positive = supply), at cavitated nodes the
    oil the Swift–Stieber condition does not conserve.
    """
    n_theta, n_nodes = pressure.shape
    imbalance = np.empty((n_theta, n_nodes))
    for i in range(n_theta):
        ip = (i + 1) % n_theta
        im = (i - 1) % n_theta
        for j in range(n_nodes):
            imbalance[i, j] = _net_outflow(pressure, a_east, a_north, source, i, ip, im, j)
    return imbalance


@nb.njit(cache=True)
def prolongate(coarse: np.ndarray) -> np.ndarray:
    """Bilinear interpolation of a field from a grid to the grid with twice the
    intervals in θ (periodic) and z; coarse nodes coincide with every other fine node."""
    n_theta, n_nodes = coarse.shape
    fine = np.empty((2 * n_theta, 2 * n_nodes - 1))
    for i in range(n_theta):
        ip = (i + 1) % n_theta
        for j in range(n_nodes):
            fine[2 * i, 2 * j] = coarse[i, j]
            fine[2 * i + 1, 2 * j] = 0.5 * (coarse[i, j] + coarse[ip, j])
            if j < n_nodes - 1:
                fine[2 * i, 2 * j + 1] = 0.5 * (coarse[i, j] + coarse[i, j + 1])
                fine[2 * i + 1, 2 * j + 1] = 0.25 * (
                    coarse[i, j] + coarse[ip, j] + coarse[i, j + 1] + coarse[ip, j + 1]
)
    return fine


@nb.njit(cache=True)
def film_fraction_swift_stieber(
    pressure: np.ndarray, h: np.ndarray, fixed: np.ndarray, cavitation_pressure: float,
    direction: int,
) -> np.ndarray:
    """Film fraction ϑ [-] implied by Swift–Stieber in the cavitated zone: the striated
    film carries the Couette flux of the rupture point, ϑ = h_rupture / h (≤ 1), walking
    each axial line in the transport ``direction`` (+1 or −1); 1 in the full film."""
    n_theta, n_nodes = pressure.shape
    fraction = np.ones((n_theta, n_nodes))
    for j in range(n_nodes):
        start = -1
        for i in range(n_theta):
            if fixed[i, j] or pressure[i, j] > cavitation_pressure:
                start = i
                break
        if start < 0:
            continue
        h_rupture = h[start, j]
        for step in range(1, n_theta + 1):
            i = (start + direction * step) % n_theta
            if fixed[i, j] or pressure[i, j] > cavitation_pressure:
                h_rupture = h[i, j]
            else:
                fraction[i, j] = min(1.0, h_rupture / h[i, j])
    return fraction


@nb.njit(cache=True)
def coefficient_derivatives(
    h: np.ndarray, dh: np.ndarray, dh_rate: np.ndarray, radius: float, d_theta: float,
    d_z: float, omega_sum: float, viscosity: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Derivatives of a_E [m^4], a_N [m^4] and b [Pa m^4] of :func:`assemble_coefficients`
    along a state direction q, given ∂h/∂q (``dh``) and ∂ḣ/∂q (``dh_rate``) at the nodes
    (per unit of q); same shapes as :func:`assemble_coefficients` returns."""
    n_theta, n_nodes = h.shape
    d_east = np.empty((n_theta, n_nodes))
    d_north = np.empty((n_theta, n_nodes - 1))
    d_source = np.empty((n_theta, n_nodes))
    surface_speed = radius * omega_sum
    arc = radius * d_theta
    for i in range(n_theta):
        ip = (i + 1) % n_theta
        im = (i - 1) % n_theta
        for j in range(n_nodes):
            width = d_z if 0 < j < n_nodes - 1 else 0.5 * d_z
            h_e = 0.5 * (h[i, j] + h[ip, j])
            dh_e = 0.5 * (dh[i, j] + dh[ip, j])
            dh_w = 0.5 * (dh[i, j] + dh[im, j])
            d_east[i, j] = 3.0 * h_e * h_e * dh_e * width / arc
            d_source[i, j] = -12.0 * viscosity * width * (
                0.5 * surface_speed * (dh_e - dh_w) + dh_rate[i, j] * arc
            )
            if j < n_nodes - 1:
                h_n = 0.5 * (h[i, j] + h[i, j + 1])
                dh_n = 0.5 * (dh[i, j] + dh[i, j + 1])
                d_north[i, j] = 3.0 * h_n * h_n * dh_n * arc / d_z
    return d_east, d_north, d_source


@nb.njit(cache=True)
def film_gap(clearance, e_x, e_y, v_x, v_y, cos_theta, sin_theta, n_nodes):
    """Rigid film thickness h = c − e_x cos θ − e_y sin θ [m] and its rate
    ∂h/∂t = −ė_x cos θ − ė_y sin θ [m/s] on the (n_θ, ``n_nodes``) grid, in one pass
    (``cos_theta``, ``sin_theta``: the node values, shape (n_θ,))."""
    n = cos_theta.shape[0]
    h = np.empty((n, n_nodes))
    h_rate = np.empty((n, n_nodes))
    for i in range(n):
        gap = clearance - e_x * cos_theta[i] - e_y * sin_theta[i]
        rate = -v_x * cos_theta[i] - v_y * sin_theta[i]
        for j in range(n_nodes):
            h[i, j] = gap
            h_rate[i, j] = rate
    return h, h_rate


@nb.njit(cache=True)
def mirror_equal(field):
    """True when every row of ``field`` (2-D) reads the same backwards, field[i, k] =
    field[i, m − 1 − k] (NaN equal to nothing, the middle one to itself neither) [-]: stops
    at the first difference."""
    n, m = field.shape
    for i in range(n):
        for k in range((m + 1) // 2):
            if field[i, k] != field[i, m - 1 - k]:
                return False
    return True


@nb.njit(cache=True)
def warm_field(last, previous, step, floor, fixed, fixed_values):
    """Warm-start field max(p + α(p − p_previous), floor) [Pa] (α = ``step``; pass
    ``previous`` = ``last`` and α = 0 for the last field itself) with the Dirichlet
    values on ``fixed`` nodes, as a new array."""
    n, m = last.shape
    out = np.empty((n, m))
    for i in range(n):
        for j in range(m):
            if fixed[i, j]:
                out[i, j] = fixed_values[i, j]
                continue
            value = last[i, j] + step * (last[i, j] - previous[i, j])
            out[i, j] = value if value > floor else floor
    return out


@nb.njit(cache=True)
def force_and_extremes(pressure, w_x, w_y, h):
    """(Σ p w_x, Σ p w_y) [N] (summed per axial column, then over the columns) and the
    first node (C order) of the largest pressure and of the smallest film thickness, in
    one pass: (sum_x, sum_y, i_p, j_p, i_h, j_h)."""
    n, m = pressure.shape
    column_x = np.zeros(m)
    column_y = np.zeros(m)
    i_p = j_p = i_h = j_h = 0
    p_best = pressure[0, 0]
    h_best = h[0, 0]
    for i in range(n):
        for j in range(m):
            value = pressure[i, j]
            column_x[j] += value * w_x[i, j]
            column_y[j] += value * w_y[i, j]
            if value > p_best:
                p_best, i_p, j_p = value, i, j
            if h[i, j] < h_best:
                h_best, i_h, j_h = h[i, j], i, j
    return column_x.sum(), column_y.sum(), i_p, j_p, i_h, j_h
