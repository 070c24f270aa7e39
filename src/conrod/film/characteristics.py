"""Film characteristics from a pressure field on a (θ, z) grid — shared by grid models.

Frame and signs as in :mod:`conrod.film.base`. Integrals use the periodic rectangle
rule in θ and the trapezoid rule in z (both second order, the θ rule spectrally
accurate for smooth periodic integrands).

Friction conventions (label every number with the one used)
-----------------------------------------------------------
Shear stress of the film on the journal and on the shell (x = Rθ, sliding ΔU = R(ω_j − ω_b)):

.. math:: τ_j = -ϑ μ ΔU/h - (h/2) ∂p/∂x, \\qquad τ_b = ϑ μ ΔU/h - (h/2) ∂p/∂x

* ``"full_film"``: ϑ = 1 everywhere — Couette shear over the full 360° as in
  Raimondi & Boyd [1], so (R/c)f = 2π²S/√(1−ε²) + ε sin φ/2 for the rigid bearing.
* ``"film_fraction"``: ϑ = film fraction (< 1 in the cavitated zone), the physical
  answer of a mass-conserving model [2].

The pressure term is integrated by parts, −∫h ∂p/∂θ dθ = ∫p ∂h/∂θ dθ (periodic).

[1] A.A. Raimondi, J. Boyd, "A solution for the finite journal bearing and its
    application to analysis and design", ASLE Trans. 1 (1958) 159–209.
[2] B.J. Hamrock, Fundamentals of Fluid Film Lubrication, 2nd ed. (2004), ch. 8–10.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numba as nb
import numpy as np


def _read_only(array: np.ndarray) -> np.ndarray:
    array.flags.writeable = False
    return array


@dataclass(frozen=True)
class FilmGrid:
    """Vertex-centred (θ, z) grid: θ periodic, z from −L/2 to L/2 with edge nodes.

    radius : float  Journal radius R [m].
    width : float  Film width L [m].
    n_theta : int  Circumferential intervals = nodes [-].
    n_z : int  Axial intervals; there are n_z + 1 axial nodes [-].
    """

    radius: float
    width: float
    n_theta: int
    n_z: int

    @cached_property
    def theta(self) -> np.ndarray:
        """Circumferential nodes θ_i = iΔθ [rad] (read-only, cached)."""
        return _read_only(np.arange(self.n_theta) * self.d_theta)

    @cached_property
    def z(self) -> np.ndarray:
        """Axial nodes [m] (read-only, cached)."""
        return _read_only(np.linspace(-0.5 * self.width, 0.5 * self.width, self.n_z + 1))

    @property
    def d_theta(self) -> float:
        """Circumferential spacing Δθ [rad]."""
        return 2.0 * math.pi / self.n_theta

    @property
    def d_z(self) -> float:
        """Axial spacing Δz [m]."""
        return self.width / self.n_z

    @cached_property
    def axial_weights(self) -> np.ndarray:
        """Trapezoid weights of the axial nodes [m]."""
        weights = np.full(self.n_z + 1, self.d_z)
        weights[[0, -1]] *= 0.5
        return _read_only(weights)

    @cached_property
    def area_weights(self) -> np.ndarray:
        """Area of each node's control volume R Δθ w_j, shape (n_θ, n_z + 1) [m^2]."""
        row = self.radius * self.d_theta * self.axial_weights
        return _read_only(np.broadcast_to(row, (self.n_theta, self.n_z + 1)).copy())

    def integrate(self, field: np.ndarray) -> float:
        """∫∫ field R dθ dz over the film [field unit × m^2]."""
        return float(np.sum(field.sum(axis=0) * self.axial_weights) * self.radius * self.d_theta)


def force_weights(grid: FilmGrid) -> tuple[np.ndarray, np.ndarray]:
    """Quadrature weights (w_x, w_y) with F = −(Σ p w_x, Σ p w_y) [m^2]."""
    area = grid.area_weights
    return np.cos(grid.theta)[:, None] * area, np.sin(grid.theta)[:, None] * area


def pressure_force(pressure: np.ndarray, grid: FilmGrid,
                   weights: tuple[np.ndarray, np.ndarray] | None = None) -> tuple[float, float]:
    """Film force on the journal F = −∫∫ p (cos θ, sin θ) R dθ dz [N]
    (``weights`` from :func:`force_weights` to save recomputing them)."""
    w_x, w_y = weights if weights is not None else force_weights(grid)
    return -float(np.sum(pressure * w_x)), -float(np.sum(pressure * w_y))


def theta_derivative(field: np.ndarray, grid: FilmGrid) -> np.ndarray:
    """Periodic central difference ∂/∂θ along axis 0 [field unit / rad]."""
    return (np.roll(field, -1, axis=0) - np.roll(field, 1, axis=0)) / (2.0 * grid.d_theta)


def friction_torques(
    pressure: np.ndarray, h: np.ndarray, grid: FilmGrid, journal_speed: float,
    shell_speed: float, viscosity: float | np.ndarray, film_fraction: np.ndarray | None = None,
) -> tuple[float, float]:
    """Shear moments of the film on the journal and on the shell [N m].

    M_j = R ∫∫ τ_j dA, M_b = R ∫∫ τ_b dA (module docstring); ``film_fraction`` None
    means the full-film (Raimondi–Boyd) convention; ``viscosity`` [Pa s] a number or a
    field of the grid's shape (pressure-dependent viscosity).
    """
    sliding = grid.radius * (journal_speed - shell_speed)
    if np.ndim(viscosity) == 0:  # compiled, one pass, no temporaries
        fraction = np.ones((1, 1)) if film_fraction is None else film_fraction
        couette_sum, poiseuille_sum = _shear_sums(pressure, h, fraction, grid.axial_weights,
                                                  float(viscosity) * sliding, grid.d_theta)
        scale = grid.radius * grid.d_theta
        couette = grid.radius * scale * couette_sum
        poiseuille = 0.5 * scale * poiseuille_sum
        return -couette + poiseuille, couette + poiseuille
    couette_stress = viscosity * sliding / h
    if film_fraction is not None:
        couette_stress = couette_stress * film_fraction
    couette = grid.radius * grid.integrate(couette_stress)
    poiseuille = 0.5 * grid.integrate(pressure * theta_derivative(h, grid))
    return -couette + poiseuille, couette + poiseuille


@nb.njit(cache=True)
def _shear_sums(pressure, h, fraction, axial_weights, stress_numerator, d_theta):
    """Σ w_j ϑ μΔU/h [N/m^2 · m] and Σ w_j p ∂h/∂θ [Pa m · m] over the nodes (ϑ ≡ 1 when
    ``fraction`` is 1 × 1); the rectangle × trapezoid rule of :meth:`FilmGrid.integrate`
    without the factor R Δθ."""
    n, m = h.shape
    full = fraction.shape[0] == 1
    couette = 0.0
    poiseuille = 0.0
    half_inverse_step = 0.5 / d_theta  # a product, not a second division per node
    for i in range(n):
        ip = i + 1 if i + 1 < n else 0
        im = i - 1 if i > 0 else n - 1
        for j in range(m):
            stress = stress_numerator / h[i, j]
            if not full:
                stress *= fraction[i, j]
            couette += axial_weights[j] * stress
            slope = (h[ip, j] - h[im, j]) * half_inverse_step
            poiseuille += axial_weights[j] * pressure[i, j] * slope
    return couette, poiseuille


def peak_pressure(pressure: np.ndarray, grid: FilmGrid) -> tuple[float, float]:
    """Largest pressure [Pa] and its θ [rad], refined by a parabola through the
    largest node and its circumferential neighbours."""
    i, j = np.unravel_index(int(np.argmax(pressure)), pressure.shape)
    return peak_pressure_at(pressure, grid, int(i), int(j))


def peak_pressure_at(pressure: np.ndarray, grid: FilmGrid, i: int, j: int) -> tuple[float, float]:
    """:func:`peak_pressure` [Pa, rad] refined around the known largest node (i, j)."""
    p_minus = pressure[(i - 1) % grid.n_theta, j]
    p_zero = pressure[i, j]
    p_plus = pressure[(i + 1) % grid.n_theta, j]
    curvature = p_minus - 2.0 * p_zero + p_plus
    shift = 0.0 if curvature >= 0.0 else 0.5 * (p_minus - p_plus) / curvature
    peak = p_zero - 0.25 * (p_minus - p_plus) * shift
    angle = (grid.theta[i] + shift * grid.d_theta) % (2.0 * math.pi)
    return float(peak), float(angle)


def minimum_film(h: np.ndarray, grid: FilmGrid) -> tuple[float, float]:
    """Smallest film thickness [m] and its θ [rad] (parabolic refinement in θ)."""
    i, j = np.unravel_index(int(np.argmin(h)), h.shape)
    return minimum_film_at(h, grid, int(i), int(j))


def minimum_film_at(h: np.ndarray, grid: FilmGrid, i: int, j: int) -> tuple[float, float]:
    """:func:`minimum_film` [m, rad] refined around the known smallest node (i, j)."""
    h_minus = h[(i - 1) % grid.n_theta, j]
    h_zero = h[i, j]
    h_plus = h[(i + 1) % grid.n_theta, j]
    curvature = h_minus - 2.0 * h_zero + h_plus
    shift = 0.0 if curvature <= 0.0 else 0.5 * (h_minus - h_plus) / curvature
    smallest = h_zero - 0.25 * (h_minus - h_plus) * shift
    angle = (grid.theta[i] + shift * grid.d_theta) % (2.0 * math.pi)
    return float(smallest), float(angle)


def cavitated_fraction(
    pressure: np.ndarray, free: np.ndarray, cavitation_pressure: float, grid: FilmGrid
) -> float:
    """Area share of free nodes held at the cavitation pressure [-]."""
    cavitated = free & (pressure <= cavitation_pressure)
    return grid.integrate(cavitated.astype(float)) / (2.0 * math.pi * grid.radius * grid.width)


def circumferential_flow(
    pressure: np.ndarray, h: np.ndarray, grid: FilmGrid, index: int, direction: int,
    surface_speed_sum: float, viscosity: float,
) -> float:
    """Volumetric flow through the axial line θ_index in the ``direction`` (±1) of
    increasing/decreasing θ [m^3/s]: ∫ (U h/2 − h³/(12μR) ∂p/∂θ) dz, with ∂p/∂θ
    one-sided (second order) on the ``direction`` side; U = R(ω_j + ω_b) [m/s]."""
    n = grid.n_theta
    p0 = pressure[index]
    p1 = pressure[(index + direction) % n]
    p2 = pressure[(index + 2 * direction) % n]
    gradient = direction * (-3.0 * p0 + 4.0 * p1 - p2) / (2.0 * grid.d_theta)
    h0 = h[index]
    flux = 0.5 * surface_speed_sum * h0 - h0**3 * gradient / (12.0 * viscosity * grid.radius)
    return float(direction * np.sum(flux * grid.axial_weights))
