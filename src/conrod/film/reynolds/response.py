"""The Reynolds film's answer by its pressure alone, and the exact response of that answer
to the film thickness (:class:`~conrod.film.capabilities.HasPressureEvaluation`,
:class:`~conrod.film.capabilities.HasThicknessResponse`).

On its converged active set A (free nodes with p > p_cav) the Swift–Stieber pressure solves
a linear system K_AA(h) p_A = b(h, ḣ) (:mod:`conrod.film.linearised`). A displacement u_j of
film row j changes h by u_j at every axial node of the row (a 2-D housing deforms alike at
every z) and, when the rate is in the squeeze term, ḣ by u_j/τ_r; a displacement u_jk of
one film node (a housing that deforms along the width) changes h and ḣ at that node alone;
a journal velocity v changes ḣ by −(v_x cos θ + v_y sin θ). With a viscosity field μ(θ, z)
the conductances are those of h_μ = h (μ_r/μ)^{1/3}
(:mod:`conrod.film.reynolds.viscosity_field`), which a direction moves by (h_μ/h) ∂h/∂q
while the source moves with ∂h/∂q; one direction at a time. For a fixed active set each
direction q costs one back-substitution with the same sparse LU factor, all directions in
one compiled sweep (:mod:`conrod.numerics.sparse_lu`):

.. math:: K_{AA}\\,∂p_A/∂q = −\\big(∂K/∂q\\,p − ∂b/∂q\\big)_A

and the nodal loads — per row f_j = Σ_k W_jk p(θ_j, z_k) (``nodal`` W of shape
(n_θ, n_z + 1)), per node f_jk = w_jk p(θ_j, z_k) (``nodal`` w flattened row-major, shape
(n_θ (n_z + 1),)) — and the film force F = −(w_x, w_y)·p follow linearly. The per-row
response is the sum over k of the per-node one. This is the derivative of the discrete
film wherever the active set does not
switch under an infinitesimal move, which makes a Newton iteration of the film with a
deforming bore converge in a few steps (semismooth Newton where it switches).

Where the film is the same in both halves of its width (gap, rate, active set and pressure
mirror-symmetric about the mid-plane: a bore deformed alike over the width, no tilt), the
directions of whole film rows and of the journal velocity are symmetric too, and so are
their ∂p_A/∂q: they are solved on the active nodes with z ≤ 0, with the couplings to the
mirrored nodes folded onto their images (K_H = K_{H,A} E, E the expansion from the half to
all active nodes), one LU of half the size.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

import numpy as np
from scipy.linalg import lu_factor, lu_solve
from scipy.sparse import csr_matrix

from conrod.film.base import FilmResult
from conrod.film.linearised import active_matrix
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds import viscosity_field as vf
from conrod.film.reynolds.memory import ReynoldsMemory
from conrod.film.reynolds.response_kernel import (
    active_rows,
    bore_node_imbalance,
    bore_row_imbalance,
    row_directions,
    row_load_response,
)
from conrod.film.step_system import FilmResponse
from conrod.film.tilt import thickness_directions
from conrod.numerics.pairwise import exact_order, weighted_sums
from conrod.numerics.sparse_lu import ManyRightHandSides, banded_solve_rows


def thickness_response(film: Any, state, pressure: np.ndarray, nodal: np.ndarray,
                       rate_step: float | None,
                       tilt: tuple[float, float] | None = None) -> FilmResponse:
    """∂f/∂u, ∂f/∂v, ∂F/∂u, ∂F/∂v of the isoviscous Reynolds ``film`` (with its viscosity
    field μ(θ, z), if any: :func:`_imbalance`) at the converged
    ``pressure`` [Pa] of the (deformed) ``state``; ``nodal`` W (n_θ, n_z + 1) [m²] for
    displacements of whole film rows, or w (n_θ (n_z + 1),) [m²] for displacements of single
    film nodes (row-major); ``rate_step`` τ_r [s] of the rate in the squeeze term (None: no
    rate term).

    ``tilt`` = (τ [s], ℓ [m]) of a journal whose tilt is solved: two more velocity columns,
    those of the edge velocities v = ℓγ̇ of an implicit step (γ = (γ_r + τ ℓγ̇)/ℓ, so h moves
    by τ z(sin θ, −cos θ)/ℓ and its rate by z(sin θ, −cos θ)/ℓ per unit v), and the
    moments' rows (``moment_by_bore``, ``moment_by_velocity``, :mod:`conrod.film.tilt`)."""
    problem = film.discrete_problem(state)
    grid = film.film_grid
    omega_sum = state.journal_speed + state.shell_speed
    conduction = problem.conduction  # a viscosity field: the conductances of h_μ
    if conduction is None:
        a_east, a_north, _ = kernel.assemble_coefficients(
            problem.h, problem.h_rate, grid.radius, grid.d_theta, grid.d_z, omega_sum,
            state.viscosity)
    else:
        a_east, a_north = vf.field_conductances(conduction, grid)
    active = ~problem.fixed & (pressure > problem.cavitation)
    if not active.any():  # no film pressure (e.g. concentric, at rest): the full-film branch
        active = ~problem.fixed
    n_theta, n_nodes = pressure.shape
    shape = (n_theta, n_nodes)
    rate = 0.0 if rate_step is None else 1.0 / rate_step
    nodes = np.nonzero(active)  # row by row, the numbering of active_matrix's
    half = (_mirror_half(active, nodes, pressure, problem)
            if MIRROR_HALF and tilt is None and nodal.ndim == 2 else None)
    solved_nodes = nodes if half is None else (nodes[0][half[0]], nodes[1][half[0]])
    index = -np.ones(shape, dtype=np.int64)  # each solved node's place among them
    index[solved_nodes] = np.arange(solved_nodes[0].size)
    if conduction is None:
        right = (_node_directions if nodal.ndim == 1 else _row_directions)(
            pressure, problem.h, rate, grid, omega_sum, state.viscosity, index)
    else:
        right = _field_directions(pressure, problem, rate, grid, omega_sum,
                                  state.viscosity, nodal.ndim == 1, index)
    directions = _velocity_directions(film, shape, tilt)
    n_bore = right.shape[0]
    right = np.concatenate([right] + [-_imbalance(pressure, problem.h, dh, dh_rate, grid,
                                                   omega_sum, state.viscosity,
                                                   conduction)[solved_nodes][None]
                                      for dh, dh_rate in directions])
    w_x, w_y = film.force_weights
    if half is None:
        solved = _solve((a_east, a_north, active), right, many=nodal.ndim == 1)
        force = -np.stack([solved @ w_x[nodes], solved @ w_y[nodes]])
        nodal_response = _nodal_response(solved, nodal, nodes, shape)
    else:  # one half of the width (module docstring); its answer stays on the half
        keep, representative = half
        solved = _solve_half((a_east, a_north, active), keep, representative, right)
        force = -np.stack([solved @ _fold(w_x[nodes], representative, keep.size),
                           solved @ _fold(w_y[nodes], representative, keep.size)])
        nodal_response = _nodal_response(solved, nodal, nodes, shape, representative)
    response = FilmResponse(*_split(nodal_response, n_bore), force[:, :n_bore],
                            force[:, n_bore:])
    if tilt is None:
        return response
    m_x, m_y = film.moment_weights
    moment = -np.stack([solved @ m_x[nodes], solved @ m_y[nodes]])
    return replace(response, moment_by_bore=moment[:, :n_bore],
                   moment_by_velocity=moment[:, n_bore:])


MIRROR_HALF = True
"""Solve the directions of whole film rows on one half of the width where the film is
mirror-symmetric about the mid-plane (module docstring) [-]."""


def _mirror_half(active: np.ndarray, nodes, pressure: np.ndarray, problem
                 ) -> tuple[np.ndarray, np.ndarray] | None:
    """(the active nodes with z ≤ 0 (their places among the active nodes), each active
    node's place among those: itself or its mirror image) where the film — active set,
    pressure, gap, its rate and conductances — is the same in both halves of the width, an
    odd number of axial nodes; else None."""
    n_nodes = active.shape[1]
    if n_nodes % 2 == 0 or not all(vf.mirror_symmetric(field) for field in (
            active, pressure, problem.h, problem.h_rate, problem.conduction, problem.fixed)):
        return None
    rows_i, rows_j = nodes
    mirrored = np.minimum(rows_j, n_nodes - 1 - rows_j)
    keep = np.nonzero(rows_j <= (n_nodes - 1) // 2)[0]
    place = -np.ones(active.shape, dtype=np.int64)
    place[rows_i[keep], rows_j[keep]] = np.arange(keep.size)
    return keep, place[rows_i, mirrored]


def _folded(matrix, keep: np.ndarray, representative: np.ndarray):
    """K_H = K_{H,A} E of :func:`_mirror_half` (CSC): the rows ``keep`` of the active
    matrix with each column added onto its representative's."""
    rows = matrix.tocsr()[keep]
    return csr_matrix((rows.data, representative[rows.indices], rows.indptr),
                      shape=(keep.size, keep.size)).tocsc()


def _solve_half(balance, keep: np.ndarray, representative: np.ndarray,
                right: np.ndarray) -> np.ndarray:
    """∂p_H/∂q (n_q, n_H) of K_H ∂p_H/∂q = −r_q (:func:`_folded`) for the rows of ``right``,
    ``balance`` = (a^E, a^N, active): by the band of the ring cut at a θ row without active
    nodes (:func:`~conrod.numerics.sparse_lu.banded_solve_rows` on the rows of
    :func:`~conrod.film.reynolds.response_kernel.active_rows`), else by SuperLU."""
    solved = banded_solve_rows(*active_rows(*balance, True), right)
    if solved is None:
        matrix, _ = active_matrix(*balance)
        solved = ManyRightHandSides(_folded(matrix, keep, representative)).solve_rows(right)
    return solved


def _fold(weights: np.ndarray, representative: np.ndarray, size: int) -> np.ndarray:
    """E^T w: the weights of the active nodes added onto their representatives [-]."""
    return np.bincount(representative, weights=weights, minlength=size)


def _solve(balance, right: np.ndarray, many: bool) -> np.ndarray:
    """∂p_A/∂q (n_q, n_A) [Pa per unit q] of K_AA ∂p_A/∂q = −r_q for the rows of ``right``
    (−r_q, (n_q, n_A)), ``balance`` = (a^E, a^N, active); ``many``: directions of single
    film nodes."""
    if many and right.shape[0] > right.shape[1]:
        # more directions than active nodes (a node per film node): one dense LU and one
        # blocked solve, 3x faster than as many sparse back-substitutions
        matrix, _ = active_matrix(*balance)
        return lu_solve(lu_factor(matrix.toarray()), right.T).T
    solved = banded_solve_rows(*active_rows(*balance, False), right)
    if solved is None:
        matrix, _ = active_matrix(*balance)
        solved = ManyRightHandSides(matrix, "MMD_AT_PLUS_A").solve_rows(right)  # symmetric
    return solved


def _nodal_response(solved: np.ndarray, nodal: np.ndarray, nodes, shape,
                    representative: np.ndarray | None = None) -> np.ndarray:
    """∂f/∂q (n_f, n_q) of the nodal loads: per film row (``nodal`` W (n_θ, n_z + 1)) or
    per film node (w flattened row-major) [N per unit q]; ``representative``: ``solved`` is
    on the half of :func:`_mirror_half` (per film row only)."""
    if nodal.ndim == 1:
        flat = np.ravel_multi_index(nodes, shape)
        out = np.zeros((nodal.size, solved.shape[0]))
        out[flat] = (solved * nodal[flat]).T
        return out
    columns = np.arange(nodes[0].size) if representative is None else representative
    return row_load_response(solved, nodal[nodes], nodes[0], columns, shape[0])


def _split(nodal_response: np.ndarray, n_bore: int) -> tuple[np.ndarray, np.ndarray]:
    return nodal_response[:, :n_bore], nodal_response[:, n_bore:]


def _velocity_directions(film: Any, shape: tuple[int, int], tilt: tuple[float, float] | None
                         ) -> list[tuple[np.ndarray, np.ndarray]]:
    """(∂h/∂v, ∂ḣ/∂v) of the velocity columns (thickness_response)."""
    zero = np.zeros(shape)
    out = [(zero, -np.ascontiguousarray(np.broadcast_to(trig[:, None], shape)))
           for trig in film.node_directions]
    if tilt is not None:
        tau, lever = tilt
        cos_theta, sin_theta = film.node_directions
        for field in thickness_directions(cos_theta, sin_theta, film.film_grid.z):
            out.append((tau * field / lever, field / lever))
    return out


def _row_directions(pressure, h, rate, grid, omega_sum, viscosity, index) -> np.ndarray:
    """−∂r_A/∂u_j (n_θ, n_A) of whole film rows at the active nodes (``index``: a node's
    place among them, −1 where not active) [Pa m^3]."""
    return row_directions(bore_row_imbalance(pressure, h, rate, grid.radius, grid.d_theta,
                                             grid.d_z, omega_sum, viscosity), index)


def _node_directions(pressure, h, rate, grid, omega_sum, viscosity, index) -> np.ndarray:
    """−∂r_A/∂u_jk (n_θ (n_z + 1), n_A) of single film nodes, row-major, at the active nodes
    (``index`` as in :func:`_row_directions`) [Pa m^3]."""
    n_theta, n_nodes = pressure.shape
    n_bore = pressure.size
    stencil = bore_node_imbalance(pressure, h, rate, grid.radius, grid.d_theta, grid.d_z,
                                  omega_sum, viscosity)
    imbalance = np.zeros((n_bore, n_theta, n_nodes))
    node = np.arange(n_bore)
    j, k = np.divmod(node, n_nodes)
    np.add.at(imbalance, (node, j, k), stencil[j, k, 0])
    np.add.at(imbalance, (node, (j - 1) % n_theta, k), stencil[j, k, 1])
    np.add.at(imbalance, (node, (j + 1) % n_theta, k), stencil[j, k, 2])
    low, high = k > 0, k < n_nodes - 1
    np.add.at(imbalance, (node[low], j[low], k[low] - 1), stencil[j[low], k[low], 3])
    np.add.at(imbalance, (node[high], j[high], k[high] + 1), stencil[j[high], k[high], 4])
    active = index >= 0
    return -imbalance[:, active]


def _imbalance(pressure, h, dh, dh_rate, grid, omega_sum, viscosity,
               conduction: np.ndarray | None = None) -> np.ndarray:
    """∂r/∂q [Pa m^3] of a direction with ∂h/∂q = ``dh`` [-], ∂ḣ/∂q = ``dh_rate`` [1/s];
    with a viscosity field (``conduction`` h_μ = h (μ_r/μ)^{1/3} [m]) the conductances move
    with ∂h_μ/∂q = (h_μ/h) ∂h/∂q, the source with ∂h/∂q
    (:mod:`conrod.film.reynolds.viscosity_field`)."""
    dh, dh_rate = np.ascontiguousarray(dh), np.ascontiguousarray(dh_rate)
    d_east, d_north, d_source = kernel.coefficient_derivatives(
        h, dh, dh_rate, grid.radius, grid.d_theta, grid.d_z, omega_sum, viscosity)
    if conduction is not None:
        d_east, d_north, _ = kernel.coefficient_derivatives(
            conduction, np.ascontiguousarray(dh * (conduction / h)), dh_rate, grid.radius,
            grid.d_theta, grid.d_z, omega_sum, viscosity)
    return kernel.node_imbalance(pressure, d_east, d_north, d_source)


def _field_directions(pressure, problem, rate, grid, omega_sum, viscosity,
                      per_node: bool, index) -> np.ndarray:
    """−∂r_A/∂u [Pa m^3] at the active nodes (``index`` as in :func:`_row_directions`) of
    whole film rows (or, ``per_node``, single film nodes, row-major) on a film with a
    viscosity field, one direction at a time (:func:`_imbalance`)."""
    shape = pressure.shape
    count = shape[0] * shape[1] if per_node else shape[0]
    active = index >= 0
    right = np.zeros((count, int(active.sum())))
    for q in range(count):
        dh = np.zeros(shape)
        if per_node:
            dh[divmod(q, shape[1])] = 1.0
        else:
            dh[q, :] = 1.0
        right[q] = -_imbalance(pressure, problem.h, dh, rate * dh, grid, omega_sum,
                               viscosity, problem.conduction)[active]
    return right


@dataclass(frozen=True)
class PressureEvaluation:
    """One Reynolds pressure solve on a (deformed) state; the other characteristics
    (friction, flows) are computed once, for the accepted answer (:meth:`finish`).

    film : ReynoldsFilm  The film that solved it.
    state : FilmState  The (deformed, rated) state.  problem : the film's discrete problem.
    pressure : ndarray  Converged p(θ, z) [Pa].  info : dict  Solver diagnostics.
    contact_pressure : ndarray or None  Greenwood–Tripp asperity pressure p_a(h) on the
        deformed film [Pa] (:mod:`conrod.ehd.asperity`); None without mixed lubrication.
    contact_slope : ndarray or None  dp_a/dh there [Pa/m].
    """

    film: Any
    state: Any
    problem: Any
    pressure: np.ndarray
    info: dict
    contact_pressure: np.ndarray | None = None
    contact_slope: np.ndarray | None = None

    @property
    def load_pressure(self) -> np.ndarray:
        """Film plus asperity pressure, the load on bore and journal [Pa]."""
        if self.contact_pressure is None:
            return self.pressure
        return self.pressure + self.contact_pressure

    def force(self) -> np.ndarray:
        """Film force on the journal, asperity force included (F_x, F_y) [N]."""
        return self.resultant(self.load_pressure)

    def contact_force(self) -> np.ndarray:
        """Asperity force on the journal (A_x, A_y) [N]; zero without mixed lubrication."""
        if self.contact_pressure is None:
            return np.zeros(2)
        return self.resultant(self.contact_pressure)

    def resultant(self, pressure: np.ndarray) -> np.ndarray:
        """Force of ``pressure`` [Pa] on the journal, −Σ p (w_x, w_y) (2,) [N]."""
        w_x, w_y = self.film.force_weights
        if exact_order(pressure, w_x, w_y):  # the same sums in one compiled call
            return -np.array(weighted_sums(pressure, w_x, w_y))
        return -np.array([(pressure * w_x).sum(), (pressure * w_y).sum()])

    def min_film_thickness(self) -> float:
        """Smallest nodal film thickness [m]."""
        return self.problem.min_film_thickness()

    def finish(self) -> tuple[FilmResult, ReynoldsMemory]:
        """All characteristics, pressure included, and the film memory after the solve; with
        asperity contact its force is in the journal force and its size in
        ``extra['asperity_force_N']`` [N]."""
        result = self.film.characteristics(self.problem, self.pressure, self.pressure,
                                           self.state, self.info)
        result.pressure = self.pressure
        if self.contact_pressure is not None:  # the journal force holds the asperity force
            contact = self.contact_force()
            result.force_x += float(contact[0])
            result.force_y += float(contact[1])
            result.extra["asperity_force_N"] = float(np.hypot(*contact))
        return result, ReynoldsMemory(self.pressure)

    def memory(self) -> ReynoldsMemory:
        """The film memory after the solve (its warm start), without the characteristics."""
        return ReynoldsMemory(self.pressure)


def answered_evaluation(film: Any, state, memory: ReynoldsMemory) -> PressureEvaluation:
    """The evaluation of ``state`` by the isoviscous Reynolds ``film`` whose converged
    pressure is ``memory``'s (the answer of the implicit step that solved it at this very
    state): its characteristics are that answer's, not those of one more solve within the
    solver's tolerance of it (no sweeps)."""
    return PressureEvaluation(film, state, film.discrete_problem(state), memory.pressure,
                              {"sweeps": 0.0, "relative_update": 0.0, "warm_start": 1.0,
                               "multigrid": float(film.method == "multigrid")})


def evaluate_pressure(film: Any, state, memory: ReynoldsMemory | None,
                      accuracy: float | None = None) -> PressureEvaluation:
    """Pressure of the isoviscous Reynolds ``film`` at ``state`` warm-started from
    ``memory`` (None: a cold start), to the relative ``accuracy`` where looser than the
    film's tolerance (None: the tolerance)."""
    problem = film.discrete_problem(state)
    pressure, info = film.solve_pressure(problem, state, memory or film.initial_memory(),
                                         accuracy)
    return PressureEvaluation(film, state, problem, pressure, info)
