"""Greenwood–Tripp asperity contact on the deformed bore (mixed lubrication on an elastic
big end).

On a rigid shell the asperity pressure p_a(h) = K E' F_{5/2}(h/σ) (Greenwood & Tripp 1970,
:mod:`conrod.contact.asperity`) is integrated over h = c − e cos(θ − ψ). On the deforming
bore the gap is the deformed film thickness the elastic film already has at every film node,
h(θ, z) = h_rigid + P(C f + U c(φ)), so the contact circle is no longer rigid: the asperity
pressure is taken node by node on that h. It acts like the film pressure:

* on the bore nodes through the same transfer, a_j = Σ_k W_jk p_a(h_jk) per film row, or
  a_jk = w_jk p_a(h_jk) per film node of a housing over the width
  (:func:`conrod.ehd.bore_system.bore_force_weights`), added to the film's nodal forces in
  the deformation G = u − λP(C (f + a) + U c(φ));
* on the journal as A = −Σ p_a (w_x, w_y) with the film's force weights, added to the film
  force.

Its derivative is local: a bore displacement u_j moves h by +1 at every axial node of row
j, so ∂a_j/∂u_i = δ_ij Σ_k W_jk p_a'(h_jk) (diagonal) and ∂A/∂u_j = −Σ_k p_a'(h_jk)
(w_x, w_y)_jk (per film node: w_jk p_a'(h_jk) and −p_a'(h_jk) (w_x, w_y)_jk), with
p_a' = (K E'/σ) F_{5/2}'(h/σ) the exact slope of the tabulated F_{5/2}
(log-linear between table points). The journal moves h as a bore displacement −cos θ_j
(−sin θ_j) does, so the journal columns of an implicit step follow from these bore columns
(:mod:`conrod.ehd.bore_system`); the asperity pressure does not depend on the velocity.

Where it is decided: an elastic film built with asperity parameters and the exact film
response carries the asperity force itself (:meth:`ElasticFilm.carries_asperity`); the
orbit then adds no rigid asperity force (:attr:`conrod.orbit.problem.OrbitProblem.rigid_asperity`).

[1] J.A. Greenwood, J.H. Tripp, "The contact of two nominally flat rough surfaces",
    Proc. IMechE 185 (1970) 625–633.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numba as nb
import numpy as np

from conrod.contact.asperity import F52_STEP, F52_X_MAX, F52_X_MIN, LOG_F52, f52
from conrod.ehd.bore_system import bore_loads


@nb.njit(cache=True)
def f52_slope(x: float) -> float:
    """dF_{5/2}/dx of the gap ratio x = h/σ [-]: the exact slope of
    :func:`conrod.contact.asperity.f52` (its table and asymptotic series) (compiled)."""
    if x >= F52_X_MAX:
        return 0.0
    if x <= F52_X_MIN:
        inv = 1.0 / x
        inv2 = inv * inv
        series = 1.0 + inv2 * (1.875 + inv2 * (-0.1171875 - 0.0732421875 * inv2))
        d_series = inv2 * inv * (-3.75 + inv2 * (0.46875 + 0.439453125 * inv2))
        return -2.5 * (-x) ** 1.5 * series + (-x) ** 2.5 * d_series
    position = (x - F52_X_MIN) / F52_STEP
    index = min(int(position), LOG_F52.size - 2)
    return f52(x) * (LOG_F52[index + 1] - LOG_F52[index]) / F52_STEP


@nb.njit(cache=True)
def asperity_field(h: np.ndarray, roughness: float, scale: float
                   ) -> tuple[np.ndarray, np.ndarray]:
    """(p_a [Pa], dp_a/dh [Pa/m]) at every node of the film thickness h [m] (2-D),
    roughness σ [m], pressure scale K E' [Pa] (compiled)."""
    pressure = np.zeros(h.shape)
    slope = np.zeros(h.shape)
    for i in range(h.shape[0]):
        for k in range(h.shape[1]):
            x = h[i, k] / roughness
            if x < F52_X_MAX:
                pressure[i, k] = scale * f52(x)
                slope[i, k] = scale * f52_slope(x) / roughness
    return pressure, slope


OPEN_GAP_SHARE = 1e-3
"""Film thickness, as a share of the radial clearance, that the contact circle on the
deformed bore keeps open (:func:`open_radius`) [-]."""


def deformed_min_gap(angles: np.ndarray, clearance: float, deformation: np.ndarray,
                     position) -> float:
    """min_j (c − x cos θ_j − y sin θ_j + u_j) [m]: h_min on the deformed bore for the
    journal at ``position`` (x, y) [m], bore-node angles θ [rad] (the film rows of a plane
    housing, which deforms alike at every z; every film node of one over the width),
    corrected displacement u [m]; ≤ 0 where the film is closed."""
    gap = (clearance - position[0] * np.cos(angles) - position[1] * np.sin(angles)
           + deformation)
    return float(np.min(gap))


def open_radius(angles: np.ndarray, clearance: float, deformation: np.ndarray, x: float,
                y: float) -> float:
    """Largest |e| [m] along the direction of (x, y) [m] at which the deformed film keeps
    h ≥ :data:`OPEN_GAP_SHARE` c at every bore node: the contact circle is no longer
    rigid, min over cos(θ_j − ψ) > 0 of (c + u_j − h_c)/cos(θ_j − ψ)."""
    e = float(np.hypot(x, y))
    if e <= 0.0:
        return clearance
    cosine = (x * np.cos(angles) + y * np.sin(angles)) / e
    facing = cosine > 1e-12
    room = clearance * (1.0 - OPEN_GAP_SHARE) + deformation[facing]
    return float(max(np.min(room / cosine[facing]), 0.0))


@dataclass(frozen=True)
class DeformedAsperity:
    """Asperity contact on the film nodes of an elastic film.

    roughness : float  Combined RMS roughness σ [m].
    scale : float  K E' [Pa] (:class:`conrod.contact.asperity.AsperityParameters`).
    nodal : ndarray  W (n_θ, n_z + 1) per film row, or w (n_θ (n_z + 1),) per film node:
        bore-node load per nodal pressure [m²]
        (:func:`conrod.ehd.bore_system.bore_force_weights`).
    force_weights : tuple  (w_x, w_y) of the film: journal force −Σ p w [m²].
    """

    roughness: float
    scale: float
    nodal: np.ndarray
    force_weights: tuple[np.ndarray, np.ndarray]

    @classmethod
    def from_parameters(cls, params: tuple[float, float, float, float], nodal: np.ndarray,
                        force_weights) -> DeformedAsperity:
        """From the kernel tuple (R [m], L [m], σ [m], K E' [Pa]) of
        :func:`conrod.contact.asperity.kernel_parameters` (R and L are the film's grid's)."""
        return cls(float(params[2]), float(params[3]), nodal, force_weights)

    def attach(self, evaluation):
        """The pressure evaluation with p_a and dp_a/dh on its deformed h."""
        pressure, slope = asperity_field(np.ascontiguousarray(evaluation.problem.h),
                                         self.roughness, self.scale)
        return dataclasses.replace(evaluation, contact_pressure=pressure,
                                   contact_slope=slope)

    def force(self, pressure: np.ndarray) -> np.ndarray:
        """Asperity force on the journal (A_x, A_y) [N] of p_a [Pa]."""
        w_x, w_y = self.force_weights
        return -np.array([np.sum(pressure * w_x), np.sum(pressure * w_y)])

    def nodal_forces(self, pressure: np.ndarray) -> np.ndarray:
        """Asperity load on the bore nodes a_j [N] of p_a [Pa]."""
        return bore_loads(self.nodal, pressure)

    def add_response(self, response, slope: np.ndarray):
        """The film response plus the asperity terms (module docstring) at dp_a/dh
        [Pa/m]."""
        n = self.nodal.shape[0]
        w_x, w_y = self.force_weights
        nodal_by_bore = response.nodal_by_bore.copy()
        nodal_by_bore[np.arange(n), np.arange(n)] += bore_loads(self.nodal, slope)
        if self.nodal.ndim == 1:  # per film node
            force_by_bore = response.force_by_bore - np.stack(
                [(slope * w_x).ravel(), (slope * w_y).ravel()])
        else:
            force_by_bore = response.force_by_bore - np.stack(
                [np.sum(slope * w_x, axis=1), np.sum(slope * w_y, axis=1)])
        return dataclasses.replace(response, nodal_by_bore=nodal_by_bore,
                                   force_by_bore=force_by_bore)
