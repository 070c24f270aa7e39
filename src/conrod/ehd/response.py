"""Exact response of a Reynolds film to the bore deformation and the journal velocity.

On its converged active set A (free nodes with p > p_cav) the Swift–Stieber pressure solves
a linear system K_AA(h) p_A = b(h, ḣ) (:mod:`conrod.film.linearised`). A bore displacement
u_j at film node j changes h by u_j at every axial node of row j (a 2-D housing deforms
alike at every z) and, when the bore's rate is in the squeeze term, ḣ by u_j/Δt; a journal
velocity v changes ḣ by −(v_x cos θ + v_y sin θ). For a fixed active set each direction q
costs one back-substitution with the same sparse LU factor:

.. math:: K_{AA}\\,∂p_A/∂q = −\\big(∂K/∂q\\,p − ∂b/∂q\\big)_A

and the nodal forces f_j = R Δθ_j ∫ p(θ_j, z) dz and the film force F = −(w_x, w_y)·p
follow linearly. This is the derivative of the discrete film wherever the active set does
not switch under an infinitesimal move, which makes the coupled Newton iteration of
:mod:`conrod.ehd.newton` converge in a few steps (semismooth Newton where it switches).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.sparse.linalg import splu

from conrod.ehd.response_kernel import bore_row_imbalance
from conrod.film import reynolds_kernel as kernel
from conrod.film.base import FilmResult
from conrod.film.linearised import _active_matrix
from conrod.film.reynolds import ReynoldsFilm, ReynoldsMemory


@dataclass(frozen=True)
class FilmResponse:
    """Derivatives of the film at one state.

    nodal_by_bore : ndarray  ∂f/∂u (n × n) [N/m].
    nodal_by_velocity : ndarray  ∂f/∂v (n × 2) [N s/m].
    force_by_bore : ndarray  ∂F/∂u (2 × n) [N/m].
    force_by_velocity : ndarray  ∂F/∂v (2 × 2) [N s/m].
    """

    nodal_by_bore: np.ndarray
    nodal_by_velocity: np.ndarray
    force_by_bore: np.ndarray
    force_by_velocity: np.ndarray


def has_exact_response(film) -> bool:
    """True for an isoviscous :class:`~conrod.film.reynolds.ReynoldsFilm` (a pressure-
    dependent viscosity maps the solved field nonlinearly to the pressure) [-]."""
    return isinstance(film, ReynoldsFilm) and film.pressure_viscosity is None


def nodal_force_weights(film, angles: np.ndarray, radius: float) -> np.ndarray:
    """W (n, n_z + 1) with f_j = Σ_k W_jk p(θ_j, z_k): R Δθ_j times the trapezoidal
    weights in z (as :func:`conrod.housing.transfer.nodal_forces`) [m²]."""
    from conrod.housing.transfer import arc_weights

    _, z = film.grid()
    widths = np.zeros(len(z))
    gaps = np.diff(z)
    widths[:-1] += 0.5 * gaps
    widths[1:] += 0.5 * gaps
    return (radius * arc_weights(angles))[:, None] * widths[None, :]


def film_response(film: ReynoldsFilm, state, pressure: np.ndarray, nodal: np.ndarray,
                  rate_step: float | None) -> FilmResponse:
    """∂f/∂u, ∂f/∂v, ∂F/∂u, ∂F/∂v at the converged ``pressure`` [Pa] of the deformed
    ``state``; ``nodal`` from :func:`nodal_force_weights`; ``rate_step`` Δt [s] of the
    deformation rate in the squeeze term (None: no rate term)."""
    problem = film._problem(state)
    grid = film.film_grid
    omega_sum = state.journal_speed + state.shell_speed
    a_east, a_north, _ = kernel.assemble_coefficients(
        problem.h, problem.h_rate, grid.radius, grid.d_theta, grid.d_z, omega_sum,
        state.viscosity)
    active = ~problem.fixed & (pressure > problem.cavitation)
    if not active.any():  # no film pressure (e.g. concentric, at rest): the full-film branch
        active = ~problem.fixed
    n_theta, n_nodes = pressure.shape
    shape = (n_theta, n_nodes)
    n_bore = nodal.shape[0]
    rate = 0.0 if rate_step is None else 1.0 / rate_step
    rows = bore_row_imbalance(pressure, problem.h, rate, grid.radius, grid.d_theta,
                              grid.d_z, omega_sum, state.viscosity)
    imbalance = np.zeros((n_bore + 2,) + shape)
    bore = np.arange(n_bore)
    for shift in range(3):
        imbalance[bore, (bore - 1 + shift) % n_theta, :] = rows[:, shift, :]
    zero = np.zeros(shape)
    for k, trig in enumerate((film._cos, film._sin)):
        dh_rate = -np.ascontiguousarray(np.broadcast_to(trig, shape))
        imbalance[n_bore + k] = _imbalance(pressure, problem.h, zero, dh_rate, grid,
                                           omega_sum, state.viscosity)
    d_pressure = np.zeros((n_bore + 2,) + shape)
    matrix, nodes = _active_matrix(a_east, a_north, active)
    factor = splu(matrix, permc_spec="MMD_AT_PLUS_A")  # K_AA is symmetric
    right = -imbalance[:, nodes[0], nodes[1]]
    for q in range(n_bore + 2):  # one column at a time: SuperLU's blocked solve is ~20x slower
        d_pressure[q, nodes[0], nodes[1]] = factor.solve(np.ascontiguousarray(right[q]))
    w_x, w_y = film._force_weights
    force = -np.stack([np.einsum("qik,ik->q", d_pressure, w_x),
                       np.einsum("qik,ik->q", d_pressure, w_y)])
    nodal_response = np.einsum("qjk,jk->jq", d_pressure, nodal)
    return FilmResponse(nodal_response[:, :n_bore], nodal_response[:, n_bore:],
                        force[:, :n_bore], force[:, n_bore:])


def _imbalance(pressure, h, dh, dh_rate, grid, omega_sum, viscosity) -> np.ndarray:
    d_east, d_north, d_source = kernel.coefficient_derivatives(
        h, np.ascontiguousarray(dh), np.ascontiguousarray(dh_rate), grid.radius,
        grid.d_theta, grid.d_z, omega_sum, viscosity)
    return kernel.node_imbalance(pressure, d_east, d_north, d_source)


@dataclass(frozen=True)
class PressureEvaluation:
    """One Reynolds pressure solve on a deformed state; the other characteristics (friction,
    flows) are computed once, for the accepted answer (:meth:`finish`).

    state : FilmState  The deformed (rated) state.  problem : the film's discrete problem.
    pressure : ndarray  Converged p(θ, z) [Pa].  info : dict  Solver diagnostics.
    contact_pressure : ndarray or None  Greenwood–Tripp asperity pressure p_a(h) on the
        deformed film [Pa] (:mod:`conrod.ehd.asperity`); None without mixed lubrication.
    contact_slope : ndarray or None  dp_a/dh there [Pa/m].
    """

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

    def force(self, film: ReynoldsFilm) -> np.ndarray:
        """Film force on the journal, asperity force included (F_x, F_y) [N]."""
        return _resultant(film, self.load_pressure)

    def contact_force(self, film: ReynoldsFilm) -> np.ndarray:
        """Asperity force on the journal (A_x, A_y) [N]; zero without mixed lubrication."""
        if self.contact_pressure is None:
            return np.zeros(2)
        return _resultant(film, self.contact_pressure)

    def min_film_thickness(self) -> float:
        """Smallest nodal film thickness [m]."""
        return float(self.problem.h.min())

    def finish(self, film: ReynoldsFilm) -> tuple[FilmResult, ReynoldsMemory]:
        """All characteristics, pressure included, and the film memory after the solve; with
        asperity contact its force is in the journal force and its size in
        ``extra['asperity_force_N']`` [N]."""
        result = film._characteristics(self.problem, self.pressure, self.pressure, self.state,
                                       self.info)
        result.pressure = self.pressure
        if self.contact_pressure is not None:  # the journal force holds the asperity force
            contact = self.contact_force(film)
            result.force_x += float(contact[0])
            result.force_y += float(contact[1])
            result.extra["asperity_force_N"] = float(np.hypot(*contact))
        return result, ReynoldsMemory(self.pressure)

    def memory(self) -> ReynoldsMemory:
        """The film memory after the solve (its warm start), without the characteristics."""
        return ReynoldsMemory(self.pressure)


def _resultant(film: ReynoldsFilm, pressure: np.ndarray) -> np.ndarray:
    """Force of ``pressure`` [Pa] on the journal, −Σ p (w_x, w_y) (2,) [N]."""
    w_x, w_y = film._force_weights
    return -np.array([np.sum(pressure * w_x), np.sum(pressure * w_y)])


def evaluate_pressure(film: ReynoldsFilm, state, memory: ReynoldsMemory | None
                      ) -> PressureEvaluation:
    """Pressure of the isoviscous ``film`` at ``state`` warm-started from ``memory``."""
    problem = film._problem(state)
    pressure, info = film._solve_pressure(problem, state, memory or film.initial_memory())
    return PressureEvaluation(state, problem, pressure, info)
