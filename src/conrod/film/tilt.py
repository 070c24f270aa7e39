"""The axial dimension of a grid film: journal tilt, the profile, moments and where h_min sits.

Tilt (misalignment). The journal axis at axial position z (from mid-width) passes through
(e_x + z γ_y, e_y − z γ_x): γ_x, γ_y [rad] are right-handed rotations of the journal about
the film's x and y axes (docs/conventions.md). Its film thickness and rate are

.. math:: h = c − (e_x + zγ_y)\\cos θ − (e_y − zγ_x)\\sin θ + h_0 + δ,
          \\qquad ∂h/∂t = −(\\dot e_x + z\\dotγ_y)\\cos θ − (\\dot e_y − z\\dotγ_x)\\sin θ,

so the tilt adds z(γ_x sin θ − γ_y cos θ) to h and z(γ̇_x sin θ − γ̇_y cos θ) to its rate
(:func:`tilt_fields`). The pressure's moment on the journal about the bearing centre is the
generalised force of the tilt angles,

.. math:: M_x = ∫∫ p\\, z \\sin θ\\, dA = Σ p\\, ∂h/∂γ_x\\, A,\\qquad
          M_y = −∫∫ p\\, z \\cos θ\\, dA = Σ p\\, ∂h/∂γ_y\\, A

(as F = Σ p ∂h/∂e A is the force), with the film's own area weights (:func:`moment_weights`,
M = −Σ p w as F = −Σ p w). A centred journal tilted about any axis therefore feels a moment
that opposes the tilt and no net force (the film at −z mirrors the one at +z turned by π).
"""

from __future__ import annotations

import numpy as np

from conrod.film.base import FilmState
from conrod.film.characteristics import FilmGrid, minimum_film_at


def tilt_fields(state: FilmState, cos_theta: np.ndarray, sin_theta: np.ndarray,
                z: np.ndarray) -> tuple[np.ndarray | None, np.ndarray | None]:
    """(film-thickness change [m], its rate [m/s]) of the tilt of ``state`` on the nodes
    (cos θ, sin θ) (n,) × z (m,), each None when zero (module docstring)."""
    gap = rate = None
    if state.tilt_x or state.tilt_y:
        gap = np.multiply.outer(state.tilt_x * sin_theta - state.tilt_y * cos_theta, z)
    if state.tilt_rate_x or state.tilt_rate_y:
        rate = np.multiply.outer(state.tilt_rate_x * sin_theta
                                 - state.tilt_rate_y * cos_theta, z)
    return gap, rate


def axial_gap(profile: np.ndarray | None, tilt: np.ndarray | None) -> np.ndarray | None:
    """The profile h₀ plus the tilt's change of h [m] (None when both are None)."""
    if tilt is None:
        return profile
    return tilt if profile is None else profile + tilt


def moment_weights(cos_theta: np.ndarray, sin_theta: np.ndarray, z: np.ndarray,
                   area: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(w_Mx, w_My) with M = −Σ p w [m³]: w_Mx = −z sin θ A, w_My = z cos θ A
    (``area`` the nodes' control areas (n, m) [m²])."""
    return (-np.multiply.outer(sin_theta, z) * area, np.multiply.outer(cos_theta, z) * area)


def thickness_directions(cos_theta: np.ndarray, sin_theta: np.ndarray,
                         z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(∂h/∂γ_x, ∂h/∂γ_y) = (z sin θ, −z cos θ) on the nodes [m/rad]."""
    return np.multiply.outer(sin_theta, z), -np.multiply.outer(cos_theta, z)


def pressure_moments(pressure: np.ndarray, weights: tuple[np.ndarray, np.ndarray]
                     ) -> tuple[float, float]:
    """(M_x, M_y) [N m] of a pressure field [Pa] with :func:`moment_weights`."""
    w_x, w_y = weights
    return -float(np.sum(pressure * w_x)), -float(np.sum(pressure * w_y))


def axial_minimum(h: np.ndarray, column: int, grid: FilmGrid, tolerance: float,
                  refine: bool = True) -> tuple[float, float]:
    """(axial position of h_min [m], smallest h on the two edges [m]) of a film thickness
    field h (n, m) [m] whose smallest value lies in θ column ``column``: the middle of the
    axial nodes of that column within ``tolerance`` [m] of its minimum (0 for a film
    uniform along the width); the edge value refined in θ by the parabola of
    :func:`conrod.film.characteristics.minimum_film_at` when ``refine``, as the film's
    h_min is (nodal otherwise)."""
    values = h[column]
    near = np.flatnonzero(values <= values.min() + tolerance)
    position = 0.5 * (grid.z[near[0]] + grid.z[near[-1]])
    edges = (0, h.shape[1] - 1)
    edge = (min(minimum_film_at(h, grid, int(np.argmin(h[:, j])), j)[0] for j in edges)
            if refine else min(float(h[:, j].min()) for j in edges))
    return float(position), float(edge)


def axial_summary(h: np.ndarray, column: int, grid: FilmGrid, clearance: float,
                  pressure: np.ndarray, weights: tuple[np.ndarray, np.ndarray],
                  refine: bool = True) -> dict:
    """FilmResult fields of the axial dimension: moments [N m], h_min axial position [m],
    edge h_min [m] (tolerance 1e-9 c; ``refine`` as :func:`axial_minimum`)."""
    moment_x, moment_y = pressure_moments(pressure, weights)
    position, edge = axial_minimum(h, column, grid, 1e-9 * clearance, refine)
    return {"moment_x": moment_x, "moment_y": moment_y, "min_film_axial_position": position,
            "edge_min_film_thickness": edge}
