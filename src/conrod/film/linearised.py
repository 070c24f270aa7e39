"""Film sensitivities: linearised stiffness and damping of a journal-bearing film.

For small motions about a state (e, ė) the film force on the journal is

.. math:: F(e + Δe, ė + Δė) ≈ F − K Δe − C Δė,
          \\qquad K_{ij} = −∂F_i/∂e_j,\\; C_{ij} = −∂F_i/∂\\dot e_j,

the eight rotordynamic coefficients of Lund [1] (K in N/m, C in N s/m).

Finite-difference Reynolds film (:func:`linearise_reynolds`)
------------------------------------------------------------
The converged Swift–Stieber pressure solves a linear system on its *active set*
A = {free nodes with p > p_cav}: K_AA(e) p_A = b(e, ė) + (terms of the Dirichlet and
cavitated nodes, whose pressures do not depend on the state). For a fixed active set the
derivative along a state direction q is one more linear solve with the same matrix,

.. math:: K_{AA}\\,∂p_A/∂q = −(∂K/∂q\\,p − ∂b/∂q)_A ,

(the squeeze source is linear in ė, so ∂/∂ė needs no approximation at all). K_AA is
symmetric, so the force derivatives need only two *adjoint* solves,

.. math:: K_{AA} λ_x = w_x,\\; K_{AA} λ_y = w_y, \\qquad ∂F_i/∂q = λ_i · (∂K/∂q\\,p − ∂b/∂q)_A,

with w the force quadrature weights (F_i = −Σ w_i p). ``method="adjoint"`` (default)
solves them with the film's own multigrid (cavitated nodes held at 0, no projection,
tolerance 1e-12, the mid-plane symmetry when the film uses it); ``method="direct"``
solves the four right-hand sides with one sparse LU (SciPy's SuperLU) instead. The result is the
exact derivative of the discrete force wherever the active set does not change under an
infinitesimal move (everywhere except on switching surfaces of measure zero); the
derivative of the coefficient arrays is analytic
(:func:`conrod.film.reynolds.kernel.coefficient_derivatives`). Dirichlet regions (edges,
grooves, holes, an inlet line) are held where they are.

Tilt (the 4 × 4 set). With the journal's tilt angles γ_x, γ_y (:mod:`conrod.film.tilt`) the
coordinates are q = (e_x, e_y, γ_x, γ_y) and the generalised forces Q = (F_x, F_y, M_x, M_y)
(M the moments of the pressure about the bearing centre, the generalised forces of γ):

.. math:: K_{ij} = −∂Q_i/∂q_j,\\qquad C_{ij} = −∂Q_i/∂\\dot q_j \\quad (i, j = 1…4),

in N/m, N/rad (forces by tilt), N m/m (moments by displacement) and N m/rad. ∂h/∂γ_x = z sin θ,
∂h/∂γ_y = −z cos θ; the moments' adjoints use the moment weights. ``tilt=True`` (what
:meth:`ReynoldsFilm.sensitivities` asks) adds them as ``full_stiffness``, ``full_damping`` and
``moment``; the 2 × 2 blocks ``stiffness``, ``damping`` are the same numbers either way.
Without journal speed the damping set is symmetric (the squeeze film dissipates
Σ C q̇ q̇): a check that forces and moments share one convention.

Any other film model (:func:`linearise_by_differences`): central differences of
``film.force`` (with ``tilt=True`` of ``film.solve``'s forces and moments) with steps of
1e-6 c and 1e-6 c(|ω_j + ω_b| + 1 rad/s), the tilt steps divided by L/2.

Load frame and dimensionless form (:meth:`FilmLinearisation.in_load_frame`): x along the
load W = −F, y 90° ahead of it in the direction of rotation (Lund's convention [1]);
K̄ = K c/W, C̄ = C c ω/W with ω = |ω_j + ω_b| [2].

[1] J.W. Lund, "Review of the concept of dynamic coefficients for fluid film journal
    bearings", J. Tribol. 109 (1987) 37–41.
[2] J.W. Lund, K.K. Thomsen, "A calculation method and data for the dynamic coefficients
    of oil-lubricated journal bearings", ASME Topics in Fluid Film Bearing and Rotor
    Bearing System Design and Optimization (1978) 1–28.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
from scipy.sparse import csr_matrix
from scipy.sparse.linalg import splu

from conrod.errors import CaseError
from conrod.film.base import FilmState
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds.response_kernel import active_rows
from conrod.film.tilt import thickness_directions

STATE_KEYS = ("eccentricity_x", "eccentricity_y", "velocity_x", "velocity_y")


@dataclass(frozen=True)
class FilmLinearisation:
    """Film force and its linearisation about one state.

    force : (2,) ndarray  Film force on the journal (F_x, F_y) [N].
    stiffness : (2, 2) ndarray  K_ij = −∂F_i/∂e_j [N/m].
    damping : (2, 2) ndarray  C_ij = −∂F_i/∂ė_j [N s/m].
    speed : float  |ω_j + ω_b| used by :meth:`dimensionless` [rad/s].
    clearance : float  Radial clearance c [m].
    frame : str  'film' (x, y of :mod:`conrod.film.base`) or 'load' (x along W = −F).
    moment : (2,) ndarray or None  Moments of the pressure (M_x, M_y) [N m] (tilt set).
    full_stiffness : (4, 4) ndarray or None  K_ij = −∂Q_i/∂q_j, q = (e_x, e_y, γ_x, γ_y),
        Q = (F_x, F_y, M_x, M_y) [N/m, N/rad, N m/m, N m/rad] (module docstring).
    full_damping : (4, 4) ndarray or None  C_ij = −∂Q_i/∂q̇_j [N s/m, N s/rad, N m s/m,
        N m s/rad].
    """

    force: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    speed: float
    clearance: float
    frame: str = "film"
    moment: np.ndarray | None = None
    full_stiffness: np.ndarray | None = None
    full_damping: np.ndarray | None = None

    @property
    def force_jacobian(self) -> tuple[np.ndarray, np.ndarray]:
        """(∂F/∂e [N/m], ∂F/∂ė [N s/m]) for an implicit integrator's Jacobian."""
        return -self.stiffness, -self.damping

    @property
    def load(self) -> float:
        """|F| = W at equilibrium [N]."""
        return float(math.hypot(*self.force))

    def in_load_frame(self) -> FilmLinearisation:
        """The same coefficients with x along the load W = −F and y 90° ahead of it in
        the direction of rotation (Lund's convention)."""
        if self.load == 0.0:
            raise CaseError("film force = 0 N: out of range (allowed: > 0 N) for the load frame")
        x_axis = -np.asarray(self.force) / self.load
        y_axis = np.array([-x_axis[1], x_axis[0]])
        rotation = np.column_stack((x_axis, y_axis))
        turned = replace(self, force=rotation.T @ self.force,
                         stiffness=rotation.T @ self.stiffness @ rotation,
                         damping=rotation.T @ self.damping @ rotation, frame="load")
        if self.full_stiffness is None:
            return turned
        both = np.kron(np.eye(2), rotation)  # the tilt vector turns like the displacement
        return replace(turned, moment=rotation.T @ self.moment,
                       full_stiffness=both.T @ self.full_stiffness @ both,
                       full_damping=both.T @ self.full_damping @ both)

    def dimensionless(self) -> tuple[np.ndarray, np.ndarray]:
        """(K̄ = K c/W, C̄ = C c ω/W) [-] in this object's frame."""
        scale = self.clearance / self.load
        return self.stiffness * scale, self.damping * scale * self.speed

    def as_dict(self, tilt: bool = False) -> dict[str, float]:
        """Flat dictionary K_xx … C_yy [N/m, N s/m] and K_bar_xx … C_bar_yy [-]; with
        ``tilt`` (and the 4 × 4 set) also M_x, M_y [N m] and the entries involving a tilt,
        K_xgx … C_gygy (x, y, gx = γ_x, gy = γ_y; units in the module docstring)."""
        stiffness_bar, damping_bar = self.dimensionless()
        values: dict[str, float] = {}
        for name, matrix in (("K", self.stiffness), ("C", self.damping),
                             ("K_bar", stiffness_bar), ("C_bar", damping_bar)):
            for (i, a) in enumerate("xy"):
                for (j, b) in enumerate("xy"):
                    values[f"{name}_{a}{b}"] = float(matrix[i, j])
        if tilt and self.full_stiffness is not None:
            values.update(_tilt_items(self))
        return values


_TILT_NAMES = ("x", "y", "gx", "gy")
"""Coordinate names of the tilt set in :meth:`FilmLinearisation.as_dict`."""


def _tilt_items(lin: FilmLinearisation) -> dict[str, float]:
    """M_x, M_y [N m] and the 4 × 4 K_ab, C_ab with a, b in x, y, gx (γ_x), gy (γ_y), the
    entries that involve a tilt (units in the module docstring)."""
    values = {"M_x": float(lin.moment[0]), "M_y": float(lin.moment[1])}
    for name, matrix in (("K", lin.full_stiffness), ("C", lin.full_damping)):
        for i, a in enumerate(_TILT_NAMES):
            for j, b in enumerate(_TILT_NAMES):
                if i >= 2 or j >= 2:
                    values[f"{name}_{a}{b}"] = float(matrix[i, j])
    return values


def _directions(film, state: FilmState, tilt: bool = False
                ) -> list[tuple[np.ndarray, np.ndarray]]:
    """(∂h/∂q, ∂ḣ/∂q) at the nodes for q = e_x, e_y, ė_x, ė_y [-] (with ``tilt`` then
    γ_x, γ_y, γ̇_x, γ̇_y [m/rad])."""
    shape = (film.n_theta, film.n_z + 1)
    cos_theta, sin_theta = film.node_directions
    cos = np.broadcast_to(cos_theta[:, None], shape)
    sin = np.broadcast_to(sin_theta[:, None], shape)
    zero = np.zeros(shape)
    out = [(-cos, zero), (-sin, zero), (zero, -cos), (zero, -sin)]
    if tilt:
        by_x, by_y = thickness_directions(cos_theta, sin_theta, film.film_grid.z)
        out += [(by_x, zero), (by_y, zero), (zero, by_x), (zero, by_y)]
    return out


def active_matrix(a_east: np.ndarray, a_north: np.ndarray, active: np.ndarray):
    """Sparse K_AA (CSC) of the flux balance restricted to the active nodes, and their index
    (rows, columns), the nodes numbered row by row: the rows of
    :func:`conrod.film.reynolds.response_kernel.active_rows`, the one place the stencil is
    written."""
    indptr, indices, data = active_rows(a_east, a_north, active, False)
    size = indptr.size - 1
    matrix = csr_matrix((data, indices, indptr), shape=(size, size)).tocsc()
    return matrix, np.nonzero(active)


ADJOINT_TOLERANCE = 1.0e-12
"""Multigrid tolerance of the adjoint solves (relative change per cycle) [-]."""


def linearise_reynolds(film, state: FilmState, method: str = "adjoint",
                       memory=None, tilt: bool = False,
                       adjoint_tolerance: float = ADJOINT_TOLERANCE,
                       idle_full_film: bool = False) -> FilmLinearisation:
    """Exact derivatives of a :class:`~conrod.film.reynolds.film.ReynoldsFilm` force (with
    ``tilt`` also of its moments, and by the tilt angles and rates) on the converged active
    set (module docstring): one film solve (warm-started from the film ``memory`` when
    given), then two (tilt: four) adjoint multigrid solves (``method="adjoint"``) or one
    sparse LU (``"direct"``). ``idle_full_film``: a film without pressure (a journal at
    rest) is linearised on the full-film branch (all free nodes), the derivative of the
    pressure that any motion starts; else its derivatives are zero."""
    if method not in ("adjoint", "direct"):
        raise CaseError(f"method = {method!r}: allowed 'adjoint' or 'direct'")
    problem = film.discrete_problem(state)
    if memory is None:
        memory = film.initial_memory()
    pressure, _ = film.solve_pressure(problem, state, memory)
    grid = film.film_grid
    omega_sum = state.journal_speed + state.shell_speed
    a_east, a_north, _ = kernel.assemble_coefficients(
        problem.h, problem.h_rate, grid.radius, grid.d_theta, grid.d_z, omega_sum,
        state.viscosity)
    active = ~problem.fixed & (pressure > film.geometry.cavitation_pressure)
    if idle_full_film and not active.any():
        active = ~problem.fixed
    weights = film.force_weights + (film.moment_weights if tilt else ())
    force = np.array([-np.sum(pressure * w) for w in weights])
    directions = _directions(film, state, tilt)
    jacobian = np.zeros((len(weights), len(directions)))
    if active.any():
        d_residuals = np.empty((len(directions),) + pressure.shape)
        for column, (dh, dh_rate) in enumerate(directions):
            d_east, d_north, d_source = kernel.coefficient_derivatives(
                problem.h, np.ascontiguousarray(dh), np.ascontiguousarray(dh_rate),
                grid.radius, grid.d_theta, grid.d_z, omega_sum, state.viscosity)
            d_residuals[column] = kernel.node_imbalance(pressure, d_east, d_north, d_source)
        if method == "direct":
            matrix, nodes = active_matrix(a_east, a_north, active)
            d_pressure = splu(matrix).solve(-d_residuals[:, nodes[0], nodes[1]].T)
            for row, w in enumerate(weights):
                jacobian[row] = -w[nodes] @ d_pressure
        else:
            symmetric = film.symmetric and state.deformation is None and not state.tilted
            for row, w in enumerate(weights):
                adjoint = _adjoint(film, problem.h, w, ~active, symmetric and row < 2,
                                   adjoint_tolerance)
                jacobian[row, :4] = np.tensordot(d_residuals[:4], adjoint * active, axes=2)
                if tilt:
                    jacobian[row, 4:] = np.tensordot(d_residuals[4:], adjoint * active,
                                                     axes=2)
    return _linearisation(force, jacobian, abs(omega_sum), film.geometry.radial_clearance)


def tilt_jacobian(film, state: FilmState, memory, tolerance: float | None = None,
                  tilt: bool = True) -> tuple[np.ndarray, np.ndarray, object]:
    """(Q (4,) [N, N m], ∂Q/∂(e, γ, ė, γ̇) (4 × 8), memory) of a Reynolds film at ``state``
    (``tilt`` False: (F (2,), ∂F/∂(e, ė) (2 × 4), memory)); adjoints to ``tolerance``."""
    if film.pressure_viscosity is not None or film.viscosity_field is not None or \
            state.viscosity_field is not None:  # μ(p) or a viscosity field: differences
        lin = linearise_by_differences(film, state, tilt=tilt)
    else:
        lin = linearise_reynolds(film, state, memory=memory, tilt=tilt,
                                 adjoint_tolerance=tolerance or ADJOINT_TOLERANCE,
                                 idle_full_film=True)
    if not tilt:
        return lin.force, np.hstack([-lin.stiffness, -lin.damping]), memory
    return (np.concatenate([lin.force, lin.moment]),
            np.hstack([-lin.full_stiffness, -lin.full_damping]), memory)


def _linearisation(generalised: np.ndarray, jacobian: np.ndarray, speed: float,
                   clearance: float) -> FilmLinearisation:
    """The linearisation of a force (2,) or force and moments (4,) [N, N m] with the
    Jacobian ∂Q/∂(q, q̇), columns (e, ė) or (e, ė, γ, γ̇)."""
    lin = FilmLinearisation(force=generalised[:2], stiffness=-jacobian[:2, :2],
                            damping=-jacobian[:2, 2:4], speed=speed, clearance=clearance)
    if generalised.size == 2:
        return lin
    by_position = np.hstack([jacobian[:, :2], jacobian[:, 4:6]])
    by_rate = np.hstack([jacobian[:, 2:4], jacobian[:, 6:8]])
    return replace(lin, moment=generalised[2:], full_stiffness=-by_position,
                   full_damping=-by_rate)


def _adjoint(film, h: np.ndarray, weights: np.ndarray, masked: np.ndarray,
              symmetric: bool, tolerance: float = ADJOINT_TOLERANCE) -> np.ndarray:
    """λ with K_AA λ = weights on the active nodes, λ = 0 on ``masked`` ones [m^-2]
    (multigrid to the relative change ``tolerance``)."""
    from conrod.errors import ConvergenceError
    from conrod.film.reynolds import multigrid as multigrid

    adjoint = np.zeros(h.shape)
    source = np.where(masked, 0.0, weights)
    cycles, change = multigrid.solve_on_grid(
        adjoint, h, source, masked, film.film_grid, -np.inf, tolerance,
        film.max_iterations, symmetric)
    if not change <= tolerance:
        raise ConvergenceError(f"adjoint multigrid after {cycles} cycles",
                               where="film sensitivities", residual=change)
    return adjoint


TILT_KEYS = ("tilt_x", "tilt_y", "tilt_rate_x", "tilt_rate_y")


def linearise_by_differences(film, state: FilmState, relative_step: float = 1.0e-6,
                             tilt: bool = False) -> FilmLinearisation:
    """Central differences of ``film.force`` (any film model) [N/m, N s/m]; with ``tilt``
    of the forces and moments of ``film.solve`` by (e, ė, γ, γ̇) (module docstring)."""
    c = film.geometry.radial_clearance
    omega_sum = state.journal_speed + state.shell_speed
    steps = (relative_step * c,) * 2 + (relative_step * c * (abs(omega_sum) + 1.0),) * 2
    keys = STATE_KEYS
    if tilt:
        lever = 0.5 * film.geometry.width
        steps = steps + tuple(step / lever for step in steps)
        keys = keys + TILT_KEYS

    def generalised(at: FilmState) -> np.ndarray:
        if not tilt:
            return np.array(film.force(at))
        result = film.solve(at)
        return np.array([result.force_x, result.force_y, result.moment_x, result.moment_y])

    jacobian = np.zeros((4 if tilt else 2, len(keys)))
    for column, (key, step) in enumerate(zip(keys, steps, strict=True)):
        value = getattr(state, key)
        plus = generalised(replace(state, **{key: value + step}))
        minus = generalised(replace(state, **{key: value - step}))
        jacobian[:, column] = (plus - minus) / (2.0 * step)
    return _linearisation(generalised(state), jacobian, abs(omega_sum), c)


def linearise(film, state: FilmState, tilt: bool = False) -> FilmLinearisation:
    """Stiffness and damping of any film model: its own
    (:class:`~conrod.film.capabilities.HasSensitivities`, e.g. the active-set solve of the
    isoviscous Reynolds film; the 4 × 4 tilt set with it), central differences of the force
    otherwise (with ``tilt`` of the forces and moments)."""
    from conrod.film.capabilities import HasSensitivities

    if isinstance(film, HasSensitivities):
        return film.sensitivities(state)
    return linearise_by_differences(film, state, tilt=tilt)
