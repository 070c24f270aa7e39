"""Exact response of the mass-conserving film's content step to the bore deformation.

On its converged cavitation set the implicit content step (Ausas, Jai & Buscaglia 2009;
:func:`conrod.film.mass_conserving.kernel.elrod_adams_step`) is, per free cell P,

.. math:: R_P = a_P p̃_P − Σ a_{nb} p̃_{nb} + C_e ϑ_e − C_w ϑ_w + K_P ϑ_P − S_P = 0

with one unknown per cell: p̃_P on the full cells (p̃ > 0, ϑ = 1) and ϑ_P on the cells at
the cavitation pressure (p̃ = 0, 0 < ϑ ≤ 1); ϑ at a face is taken upwind. A bore
displacement u_r raises h on row r at every axial node, which changes the conductances
a = h_f³ Δz/Δx (Δx/Δz), the Couette coefficients C = 6μU h_f Δz and the capacity
K = κ 12μΔxΔz h/Δt (κ = 1 backward Euler, 3/2 BDF2); S (the content at the start of the
step) does not move. For a fixed set,

.. math:: ∂R/∂x\\;∂x/∂u_r = −∂R/∂u_r

is one sparse LU and n back-substitutions, and the nodal forces f_j = Σ_k W_jk p(θ_j, z_k)
follow linearly. A displacement u_jk of a single film node (a housing that deforms along the
width; ``nodal`` w per node, flattened row-major) moves h at that node alone: its faces by
half of a row's move, its own capacity by κ ϑ; summed over k it is the row's response.
Unlike the Reynolds response (:mod:`conrod.film.reynolds.response`), the
film fraction of the broken-film cells and its transport are in it, which is what makes
the coupled Newton iteration converge in a few steps.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import scipy.sparse as sp

from conrod.film.mass_conserving.results import axial_weights
from conrod.film.step_system import FilmResponse
from conrod.numerics.sparse_lu import ManyRightHandSides


def content_step_response(film: Any, state, solved, nodal: np.ndarray,
                          rate_step: float) -> FilmResponse:
    """∂f/∂u (n × n) [N/m] and ∂F/∂u (2 × n) [N/m] of the content step of ``film`` at its
    converged shifted pressure p̃ [Pa] and film fraction ϑ [-] (``solved``, the memory after
    the step) on the (deformed) end state ``state``; the content capacity is
    K/h = κ 12μΔxΔz/Δt = 12μΔxΔz/``rate_step`` [Pa m] (κ = 1 backward Euler, 3/2 BDF2);
    ``nodal`` W (n, n_z + 1) [m²]. The journal velocity enters the step only through its
    position, so the velocity blocks are zero."""
    dx, dz = film.spacing()
    viscous = 12.0 * state.viscosity * dx * dz / rate_step
    per_node = nodal.ndim == 1
    d_pressure = pressure_by_bore(film.fields(state), solved.pressure, solved.fraction,
                                  viscous, per_node)
    if per_node:
        nodal_response = (d_pressure.reshape(d_pressure.shape[0], -1) * nodal[None, :]).T
    else:
        nodal_response = np.einsum("rjk,jk->jr", d_pressure, nodal)
    theta, _ = film.grid()
    trig = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    force = force_by_bore(d_pressure, axial_weights(solved.pressure.shape[1], dz),
                          trig[:, 0], trig[:, 1], film.geometry.radius)
    return FilmResponse(nodal_response, np.zeros((nodal_response.shape[0], 2)), force,
                        np.zeros((2, 2)))


def force_by_bore(d_pressure: np.ndarray, line_weights: np.ndarray,
                  cos_theta: np.ndarray, sin_theta: np.ndarray, radius: float) -> np.ndarray:
    """∂F/∂u (2 × n) [N/m] of the film force F = −R Δθ Σ_i (cos θ_i, sin θ_i) Σ_k w_k p_ik
    from ∂p/∂u (n, n_θ, n_z + 1) [Pa/m]; ``line_weights`` w_k the axial quadrature [m]."""
    line = d_pressure @ line_weights  # (n_bore, n_θ)
    factor = -radius * 2.0 * np.pi / cos_theta.size
    return factor * np.stack([line @ cos_theta, line @ sin_theta])


def pressure_by_bore(fields, pressure: np.ndarray, fraction: np.ndarray,
                     capacity_per_thickness: float, per_node: bool = False) -> np.ndarray:
    """∂p/∂u_r (n, n_θ, n_z + 1) [Pa/m] of the content step on its converged cavitation
    set (module docstring); zero on the cells at the cavitation pressure. u_r moves a whole
    film row r (n = n_θ), or with ``per_node`` the single film node r = j (n_z + 1) + k
    (n = n_θ (n_z + 1))."""
    forward = bool(fields.couette_east[0, fields.h.shape[1] // 2] >= 0.0)
    free = fields.free
    full = free & (pressure > 0.0)
    partial = free & ~full & (fraction > 0.0)
    unknown = full | partial
    index = -np.ones(pressure.shape, dtype=np.int64)
    index[unknown] = np.arange(int(unknown.sum()))
    matrix = _unknown_matrix(fields, full, partial, index, capacity_per_thickness, forward)
    derivatives = _node_derivatives if per_node else _bore_derivatives
    rows = derivatives(fields, pressure, fraction, capacity_per_thickness, forward)
    right = -rows[:, unknown]  # (n_bore, n_unknown)
    n_bore = rows.shape[0]
    d_pressure = np.zeros((n_bore,) + pressure.shape)
    if right.shape[1] == 0:
        return d_pressure
    solved = ManyRightHandSides(matrix.tocsc()).solve_rows(right).T  # all columns at once
    full_of_unknown = full[unknown]
    nodes = np.nonzero(unknown)
    d_pressure[:, nodes[0][full_of_unknown], nodes[1][full_of_unknown]] = (
        solved[full_of_unknown].T)
    return d_pressure


def _unknown_matrix(fields, full, partial, index, kappa: float, forward: bool):
    """∂R/∂x on the unknowns (p̃ on full cells, ϑ on partial ones), sparse."""
    a_e, a_n = fields.a_east, fields.a_north
    a_w = np.roll(a_e, 1, axis=0)
    a_s = np.zeros_like(a_n)
    a_s[:, 1:] = a_n[:, :-1]
    rows, cols, values = [], [], []

    def add(mask, target, value):
        ok = mask & (target >= 0)
        rows.append(index[ok])
        cols.append(target[ok])
        values.append(value[ok])

    here = index
    # pressure columns: the rows of every unknown cell that sees a full cell's p̃
    add(full, here, a_e + a_w + a_n + a_s)
    unknown = full | partial
    full_index = np.where(full, index, -1)
    add(unknown, np.roll(full_index, -1, axis=0), -a_e)
    add(unknown, np.roll(full_index, 1, axis=0), -a_w)
    shifted = np.full_like(index, -1)
    shifted[:, :-1] = full_index[:, 1:]
    add(unknown, shifted, -a_n)
    shifted = np.full_like(index, -1)
    shifted[:, 1:] = full_index[:, :-1]
    add(unknown, shifted, -a_s)
    # film-fraction columns: own capacity and Couette outflow, the downstream inflow
    capacity = kappa * fields.h
    couette = fields.couette_east
    if forward:
        add(partial, here, couette + capacity)
        partial_index = np.where(partial, index, -1)
        add(unknown, np.roll(partial_index, 1, axis=0), -np.roll(couette, 1, axis=0))
    else:
        add(partial, here, capacity - np.roll(couette, 1, axis=0))
        partial_index = np.where(partial, index, -1)
        add(unknown, np.roll(partial_index, -1, axis=0), couette)
    size = int(unknown.sum())
    return sp.coo_matrix((np.concatenate(values), (np.concatenate(rows),
                                                   np.concatenate(cols))),
                         shape=(size, size))


def _bore_derivatives(fields, pressure, fraction, kappa: float, forward: bool) -> np.ndarray:
    """∂R/∂u_r (n, n_θ, n_z + 1) at fixed unknowns: u_r moves h on row r at every z."""
    h = fields.h
    n, m = h.shape
    h_east = 0.5 * (h + np.roll(h, -1, axis=0))
    h_north = h.copy()
    h_north[:, :-1] = 0.5 * (h[:, :-1] + h[:, 1:])
    # per unit u_r: h_e of the faces (r − 1, r) and (r, r + 1) moves by 1/2, h_n of row r by 1
    da_east = 1.5 * fields.a_east / h_east       # ∂a_e/∂h of either node of the face
    dc_east = 0.5 * fields.couette_east / h_east
    da_north = 3.0 * fields.a_north / h_north     # both nodes of a north face in one row
    result = np.zeros((n, n, m))
    p = pressure
    up = fraction if forward else np.roll(fraction, -1, axis=0)
    rows = np.arange(n)
    # east face between i and i + 1 changes with u_i and u_{i+1}: it enters R_i (+) and
    # R_{i+1} (as its west face)
    flow_east = da_east * (p - np.roll(p, -1, axis=0)) + dc_east * up
    for owner in (rows, (rows + 1) % n):  # the face of row i moves with u_i and u_{i+1}
        result[owner, rows, :] += flow_east
        result[owner, (rows + 1) % n, :] -= flow_east
    # north faces of row i move with u_i: a_n (p_P − p_N) into R_P, minus into R_N
    flow_north = np.zeros((n, m))
    flow_north[:, :-1] = da_north[:, :-1] * (p[:, :-1] - p[:, 1:])
    result[rows, rows, :] += flow_north
    result[rows, rows, 1:] -= flow_north[:, :-1]
    result[rows, rows, :] += kappa * fraction
    free = fields.free
    return np.where(free[None, :, :], result, 0.0)


def _node_derivatives(fields, pressure, fraction, kappa: float, forward: bool) -> np.ndarray:
    """∂R/∂u_jk (n_θ (n_z + 1), n_θ, n_z + 1) at fixed unknowns: u_jk moves h at the film
    node (j, k) alone, each of its faces by half (:func:`_bore_derivatives` per node)."""
    h = fields.h
    n, m = h.shape
    h_east = 0.5 * (h + np.roll(h, -1, axis=0))
    h_north = h.copy()
    h_north[:, :-1] = 0.5 * (h[:, :-1] + h[:, 1:])
    da_east = 1.5 * fields.a_east / h_east       # ∂a_e/∂h of either node of the face
    dc_east = 0.5 * fields.couette_east / h_east
    da_north = 1.5 * fields.a_north / h_north     # ∂a_n/∂h of either node of the face
    p = pressure
    up = fraction if forward else np.roll(fraction, -1, axis=0)
    result = np.zeros((n * m, n, m))
    j, k = np.divmod(np.arange(n * m), m)
    # east face (i, i + 1) at level k: the nodes (i, k) and (i + 1, k) move it; it enters
    # R_i (+) and R_{i+1} (−)
    flow_east = (da_east * (p - np.roll(p, -1, axis=0)) + dc_east * up)
    for owner_row in (j, (j - 1) % n):  # the node's own east face, and its west face
        face = flow_east[owner_row, k]
        np.add.at(result, (np.arange(n * m), owner_row, k), face)
        np.add.at(result, (np.arange(n * m), (owner_row + 1) % n, k), -face)
    # north face (k, k + 1) of row j: the nodes (j, k) and (j, k + 1) move it
    flow_north = np.zeros((n, m))
    flow_north[:, :-1] = da_north[:, :-1] * (p[:, :-1] - p[:, 1:])
    for owner_level, valid in ((k, k < m - 1), (k - 1, k > 0)):
        node = np.flatnonzero(valid)
        face = flow_north[j[node], owner_level[node]]
        np.add.at(result, (node, j[node], owner_level[node]), face)
        np.add.at(result, (node, j[node], owner_level[node] + 1), -face)
    result[np.arange(n * m), j, k] += kappa * fraction[j, k]
    free = fields.free
    return np.where(free[None, :, :], result, 0.0)
