"""Compiled kernels of the mass-conserving (JFO, Elrod–Adams p–θ) film.

Finite-volume form (one cell per grid node, θ periodic, z with Dirichlet edges)
--------------------------------------------------------------------------------
With the film fraction ϑ ∈ [0, 1] (ϑ = 1 where the film is full) and the flux
``q = −h³/(12μ) ∇p + (U/2) h ϑ e_x``, U = R(ω_j + ω_b), mass conservation
∂(ϑh)/∂t + ∇·q = 0 integrated over the cell of node P and multiplied by 12μ reads

.. math:: a_P p_P − Σ_{nb} a_{nb} p_{nb} + C_e ϑ_e − C_w ϑ_w
          + 12μ\\,Δx Δz\\,(ϑ_P \\dot h_P + h_P \\dot ϑ_P) = 0,

a_E = h_e³ Δz/Δx, a_N = h_n³ Δx/Δz, a_P = Σ a_nb, C_e = 6μ U h_e Δz, with ϑ at a face
taken upwind (first order, as Elrod & Adams; second order wherever ϑ = 1) [1, 2].
Complementarity (JFO): p > p_cav ⇒ ϑ = 1;  ϑ < 1 ⇒ p = p_cav.

The kernels work on the shifted pressure p̃ = p − p_cav ≥ 0 (the operator has zero row
sums, so the shift changes nothing else).

[1] H.G. Elrod, "A cavitation algorithm", J. Lubr. Technol. 103 (1981) 350–354.
[2] R.F. Ausas, M. Jai, G.C. Buscaglia, "A mass-conserving algorithm for dynamical
    lubrication problems with cavitation", J. Tribol. 131 (2009) 031702.
"""

from __future__ import annotations

import numba as nb
import numpy as np


@nb.njit(cache=True)
def projected_sor(
    pressure: np.ndarray, free: np.ndarray, a_east: np.ndarray, a_north: np.ndarray,
    source: np.ndarray, offset: float, omega: float, tolerance: float, max_iterations: int,
) -> tuple[int, float]:
    """Projected SOR for a_P p̃_P − Σ a_nb p̃_nb + source_P = 0 with p̃ ≥ 0 (in place).

    pressure : (n, m) shifted pressure p̃ [Pa]; nodes where ``free`` is False are fixed.
    a_east, a_north : face conductances between (i, i+1) and (j, j+1) [m³].
    source : right-hand side per node [m³/s · Pa s] (convection + squeeze, scaled by 12μ).
    offset : p̃ of zero gauge pressure, −p_cav [Pa] (sets the relative change measure).
    Returns (sweeps, last relative max change [-]).
    """
    n, m = pressure.shape
    relative = 1.0
    for sweep in range(max_iterations):
        change = 0.0
        scale = 0.0
        for i in range(n):
            iw = i - 1 if i > 0 else n - 1
            ie = i + 1 if i < n - 1 else 0
            for j in range(1, m - 1):
                if not free[i, j]:
                    continue
                aw = a_east[iw, j]
                ae = a_east[i, j]
                a_s = a_north[i, j - 1]
                an = a_north[i, j]
                target = (
                    aw * pressure[iw, j] + ae * pressure[ie, j]
                    + a_s * pressure[i, j - 1] + an * pressure[i, j + 1] - source[i, j]
) / (aw + ae + a_s + an)
                old = pressure[i, j]
                new = old + omega * (target - old)
                if new < 0.0:
                    new = 0.0
                pressure[i, j] = new
                change = max(change, abs(new - old))
                scale = max(scale, abs(new - offset))
        relative = change / scale if scale > 0.0 else change
        if relative <= tolerance:
            return sweep + 1, relative
    return max_iterations, relative


@nb.njit(cache=True)
def elrod_adams_steady(
    pressure: np.ndarray, fraction: np.ndarray, free: np.ndarray,
    a_east: np.ndarray, a_north: np.ndarray, couette_east: np.ndarray, squeeze: np.ndarray,
    omega: float, tolerance: float, max_iterations: int,
) -> tuple[int, float]:
    """Steady JFO by the Elrod–Adams / Ausas Gauss–Seidel sweep (in place) [2].

    At a full node (ϑ = 1) p̃ is relaxed from the cell balance; if it would drop below 0,
    p̃ = 0 and ϑ is solved from the same balance instead, clamped to [0, 1].
    couette_east : C_e = 6μ U h_e Δz [m³/s · Pa s];  squeeze : 12μ Δx Δz ∂h/∂t [same].
    Returns (sweeps, last relative max change of p̃ and ϑ [-]).
    """
    # the step's sweep with the squeeze term in place of the capacity and no stored content
    return elrod_adams_step(pressure, fraction, free, a_east, a_north, couette_east, squeeze,
                            np.zeros_like(squeeze), omega, tolerance, max_iterations)


@nb.njit(cache=True)
def elrod_adams_step(
    pressure: np.ndarray, fraction: np.ndarray, free: np.ndarray,
    a_east: np.ndarray, a_north: np.ndarray, couette_east: np.ndarray, capacity: np.ndarray,
    known: np.ndarray, omega: float, tolerance: float, max_iterations: int,
) -> tuple[int, float]:
    """One implicit (backward Euler) time step of the JFO film by the Ausas sweep (in place).

    Discrete balance per free cell, all × 12μ (module docstring, ∂(ϑh)/∂t by backward
    Euler over the step Δt with h, a, C at the end of the step):

    .. math:: a_P p̃_P − Σ a_{nb} p̃_{nb} + C_e ϑ_e − C_w ϑ_w + K_P ϑ_P − S_P = 0,

    K_P = 12μΔxΔz h_P/Δt (``capacity``) and S_P = 12μΔxΔz ϑ_P^n h_P^n/Δt (``known``, the
    content at the start of the step) [Pa m³]. At a full node p̃ is relaxed; if it would drop
    below 0, p̃ = 0 and ϑ is solved from the same balance, clamped to [0, 1] [2]. Unlike
    the instantaneous problem, a solution exists for any journal velocity: content squeezed
    into a shrinking gap fills the cell and raises the pressure.
    Returns (sweeps, last relative max change of p̃ and ϑ [-]).
    """
    n, m = pressure.shape
    relative = 1.0
    forward = couette_east[0, m // 2] >= 0.0
    for sweep in range(max_iterations):
        change_p = 0.0
        change_f = 0.0
        scale = 0.0
        for i in range(n):
            iw = i - 1 if i > 0 else n - 1
            ie = i + 1 if i < n - 1 else 0
            for j in range(1, m - 1):
                if not free[i, j]:
                    continue
                aw = a_east[iw, j]
                ae = a_east[i, j]
                a_s = a_north[i, j - 1]
                an = a_north[i, j]
                neighbours = (aw * pressure[iw, j] + ae * pressure[ie, j]
                              + a_s * pressure[i, j - 1] + an * pressure[i, j + 1])
                if forward:
                    own = couette_east[i, j] + capacity[i, j]
                    rest = -couette_east[iw, j] * fraction[iw, j] - known[i, j]
                else:
                    own = capacity[i, j] - couette_east[iw, j]
                    rest = couette_east[i, j] * fraction[ie, j] - known[i, j]
                old_p = pressure[i, j]
                old_f = fraction[i, j]
                new_p = 0.0
                new_f = 1.0
                if old_f >= 1.0:
                    target = (neighbours - rest - own) / (aw + ae + a_s + an)
                    new_p = old_p + omega * (target - old_p)
                if new_p <= 0.0:
                    new_p = 0.0
                    new_f = (neighbours - rest) / own if own > 0.0 else 1.0
                    new_f = min(max(new_f, 0.0), 1.0)
                pressure[i, j] = new_p
                fraction[i, j] = new_f
                change_p = max(change_p, abs(new_p - old_p))
                change_f = max(change_f, abs(new_f - old_f))
                scale = max(scale, new_p)
        relative = max(change_p / scale if scale > 0.0 else change_p, change_f)
        if relative <= tolerance:
            return sweep + 1, relative
    return max_iterations, relative


@nb.njit(cache=True)
def _held(fraction: np.ndarray, i: int, j: int, held: bool) -> float:
    """ϑ of ``fraction`` at (i, j) clipped to [0, 1], 1 on a Dirichlet node (``held``
    False) or for an empty (0, 0) ``fraction`` (a full film) [-]."""
    if not held or fraction.shape[0] == 0:
        return 1.0
    value = fraction[i, j]
    if value < 0.0:
        return 0.0
    if value > 1.0:
        return 1.0
    return value


@nb.njit(cache=True)
def content_step_sweep(
    edge: np.ndarray, supply: np.ndarray, fixed_pressure: np.ndarray, h: np.ndarray,
    squeeze: np.ndarray, a_east: np.ndarray, a_north: np.ndarray, couette_east: np.ndarray,
    cell: float, offset: float, full: float, fraction_n: np.ndarray, thickness_n: np.ndarray,
    fraction_before: np.ndarray, thickness_before: np.ndarray, start_fraction: np.ndarray,
    start_pressure: np.ndarray, omega: float, tolerance: float, max_iterations: int,
) -> tuple[int, float, np.ndarray, np.ndarray]:
    """The implicit content step of :mod:`conrod.film.mass_conserving.step` in one call: its
    content S and capacity K (backward Euler, or BDF2 when ``thickness_before`` is given),
    the start of the sweep, and :func:`elrod_adams_step`. Node by node the same arithmetic
    as the array expressions it replaces (bit for bit).

    cell : 12μΔxΔz/Δt [Pa s];  offset : p̃ of zero gauge pressure, −p_cav [Pa];
    full : film fraction above which a node counts as full [-].
    fraction_n, thickness_n : ϑ^n and h^n of the step's start [-, m]; an empty (0, 0)
        thickness: h^n = h − Δt ∂h/∂t (the content is ϑ(cell h − squeeze)).
    fraction_before, thickness_before : ϑ and h one step earlier, or empty: backward Euler.
    start_fraction, start_pressure : the sweep's start (an earlier trial of the same step,
        or the step's start); an empty pressure starts from ``offset``.
    Returns (sweeps, relative change [-], p̃ [Pa], ϑ [-]).
    """
    n, m = h.shape
    bdf2 = thickness_before.shape[0] > 0
    capacity = np.empty((n, m))
    known = np.empty((n, m))
    fraction = np.empty((n, m))
    pressure = np.empty((n, m))
    solved = ~(edge | supply)
    for i in range(n):
        for j in range(m):
            free = solved[i, j]
            held = _held(fraction_n, i, j, free)
            if thickness_n.shape[0] > 0:
                content = cell * held * thickness_n[i, j]
            else:
                content = held * (cell * h[i, j] - squeeze[i, j])
            if bdf2:
                capacity[i, j] = 1.5 * cell * h[i, j]
                before = cell * _held(fraction_before, i, j, free) * thickness_before[i, j]
                known[i, j] = 2.0 * content - 0.5 * before
            else:
                capacity[i, j] = cell * h[i, j]
                known[i, j] = content
            start = _held(start_fraction, i, j, free)
            fraction[i, j] = start
            if not free:
                pressure[i, j] = fixed_pressure[i, j]
            elif start < full:
                pressure[i, j] = 0.0
            elif start_pressure.shape[0] > 0:
                pressure[i, j] = start_pressure[i, j]
            else:
                pressure[i, j] = offset
    sweeps, change = elrod_adams_step(pressure, fraction, solved, a_east, a_north,
                                      couette_east, capacity, known, omega, tolerance,
                                      max_iterations)
    return sweeps, change, pressure, fraction


@nb.njit(cache=True)
def cell_balance(
    pressure: np.ndarray, fraction: np.ndarray, free: np.ndarray, edge: np.ndarray,
    a_east: np.ndarray, a_north: np.ndarray, couette_east: np.ndarray, squeeze: np.ndarray,
) -> tuple[np.ndarray, float, float]:
    """Cell imbalance of the balance above on the free cells, and the oil entering them
    from edge nodes and from supply (other Dirichlet) nodes, all × 12μ [Pa m³].

    The imbalance is 0 on pressurised cells (to solver tolerance) and −12μΔxΔz h ∂ϑ/∂t on
    cells at p_cav; interior faces cancel, so Σ imbalance = Σ 12μΔxΔz ϑ ∂h/∂t − inflows,
    i.e. 12μ d(content)/dt = inflows to round-off (and solver tolerance).
    """
    n, m = pressure.shape
    forward = couette_east[0, m // 2] >= 0.0
    imbalance = np.zeros((n, m))
    from_edges = 0.0
    from_supply = 0.0
    for i in range(n):
        iw = i - 1 if i > 0 else n - 1
        ie = i + 1 if i < n - 1 else 0
        for j in range(1, m - 1):
            if not free[i, j]:
                continue
            up_e = fraction[i, j] if forward else fraction[ie, j]
            up_w = fraction[iw, j] if forward else fraction[i, j]
            flux_e = couette_east[i, j] * up_e - a_east[i, j] * (pressure[ie, j] - pressure[i, j])
            flux_w = couette_east[iw, j] * up_w - a_east[iw, j] * (pressure[i, j] - pressure[iw, j])
            flux_n = -a_north[i, j] * (pressure[i, j + 1] - pressure[i, j])
            flux_s = -a_north[i, j - 1] * (pressure[i, j] - pressure[i, j - 1])
            imbalance[i, j] = flux_e - flux_w + flux_n - flux_s + squeeze[i, j] * fraction[i, j]
            for inflow, ii, jj in ((flux_w, iw, j), (-flux_e, ie, j),
                                   (flux_s, i, j - 1), (-flux_n, i, j + 1)):
                if free[ii, jj]:
                    continue
                if edge[ii, jj]:
                    from_edges += inflow
                else:
                    from_supply += inflow
    return imbalance, from_edges, from_supply


@nb.njit(cache=True)
def assemble(
    cos_theta: np.ndarray, sin_theta: np.ndarray, n_nodes_z: int, clearance: float,
    ex: float, ey: float, vx: float, vy: float, deformation: np.ndarray,
    d_x: float, d_z: float, viscosity: float, surface_speed: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """h, a_E, a_N, C_e and 12μΔxΔz ∂h/∂t on the grid (module docstring; SI units).

    ``deformation`` is an (n, m) field [m] added to h, or an empty (0, 0) array.
    """
    n = cos_theta.size
    m = n_nodes_z
    h = np.empty((n, m))
    for i in range(n):
        rigid = clearance - ex * cos_theta[i] - ey * sin_theta[i]
        for j in range(m):
            h[i, j] = rigid + (deformation[i, j] if deformation.shape[0] > 0 else 0.0)
    a_east = np.empty((n, m))
    a_north = np.empty((n, m))
    couette = np.empty((n, m))
    squeeze = np.empty((n, m))
    c_e = 6.0 * viscosity * surface_speed * d_z
    c_s = 12.0 * viscosity * d_x * d_z
    for i in range(n):
        ie = i + 1 if i < n - 1 else 0
        rate = -vx * cos_theta[i] - vy * sin_theta[i]
        for j in range(m):
            h_e = 0.5 * (h[i, j] + h[ie, j])
            a_east[i, j] = h_e * h_e * h_e * d_z / d_x
            couette[i, j] = c_e * h_e
            squeeze[i, j] = c_s * rate
            h_n = 0.5 * (h[i, j] + h[i, j + 1]) if j < m - 1 else h[i, j]
            a_north[i, j] = h_n * h_n * h_n * d_x / d_z
    return h, a_east, a_north, couette, squeeze
