"""Mixed lubrication: any film model plus Greenwood–Tripp asperity contact with boundary
friction, behind the same :class:`conrod.film.base.FilmModel` interface.

The orbit solver's generic path calls ``film.force(state)``; wrapping its film as
``MixedLubricationFilm(film, params, μ_dry)`` makes the film and the asperities share the
load, so that the transition from film to contact is smooth:

.. math:: F = F_{film} + F_a - μ_{dry} |F_a|\\, s\\, \\hat t, \\qquad
          s = \\tanh(V_s / v_{reg}),\\quad V_s = \\mathbf v·\\hat t + (ω_j - ω_b) R,

F_a the radial asperity force of :func:`conrod.contact.asperity.asperity_force`,
t̂ = (−n_y, n_x) the tangent at the line of centres, V_s the sliding speed of the journal
surface over the shell (regularised like the hard-contact friction of the orbit solver).
``solve`` returns the film's own characteristics, with the asperity force and its friction
in ``extra`` (``asperity_force_N``, ``boundary_friction_N``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numba as nb

from conrod.contact.asperity import asperity_force
from conrod.film.base import FilmModel, FilmResult, FilmState
from conrod.film.wrapper import FilmWrapper

SLIDING_REGULARISATION_SPEED = 1.0e-4
"""Sliding speed below which boundary friction is regularised (tanh) [m/s]."""


@nb.njit(cache=True)
def asperity_force_with_friction(
    ex: float, ey: float, vx: float, vy: float, relative_speed: float, clearance: float,
    params: tuple[float, float, float, float], friction_coefficient: float,
) -> tuple[float, float, float, float]:
    """Asperity force plus boundary friction on the journal (F_x, F_y) [N], with the asperity
    normal force |F_a| [N] and the friction force μ|F_a| s [N].

    ex, ey [m], vx, vy [m/s]: centre position/velocity; relative_speed ω_j − ω_b [rad/s];
    clearance c [m]; params as for :func:`asperity_force`; friction_coefficient μ_dry [-].
    """
    fx, fy = asperity_force(ex, ey, clearance, params)
    normal = math.hypot(fx, fy)
    e = math.hypot(ex, ey)
    if normal == 0.0 or e == 0.0:
        return fx, fy, 0.0, 0.0
    tx = -ey / e
    ty = ex / e
    sliding = vx * tx + vy * ty + relative_speed * params[0]
    friction = friction_coefficient * normal * math.tanh(sliding / SLIDING_REGULARISATION_SPEED)
    return fx - friction * tx, fy - friction * ty, normal, friction


@dataclass
class MixedLubricationFilm(FilmWrapper):
    """A film model whose force includes Greenwood–Tripp asperity contact.

    base : FilmModel  The oil-film model (its memory and deformation support are declared
        through :class:`~conrod.film.wrapper.FilmWrapper`).
    asperity_parameters : tuple  (R [m], L [m], σ [m], K E' [Pa]) of
        :func:`conrod.contact.asperity.kernel_parameters`.
    friction_coefficient : float  Boundary (dry) friction coefficient μ_dry [-].
    """

    base: FilmModel
    asperity_parameters: tuple[float, float, float, float]
    friction_coefficient: float = 0.1

    def _asperity(self, state: FilmState) -> tuple[float, float, float, float]:
        return asperity_force_with_friction(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed - state.shell_speed, self.geometry.radial_clearance,
            self.asperity_parameters, self.friction_coefficient,
)

    def adjust_force(self, state: FilmState, fx: float, fy: float) -> tuple[float, float]:
        """Film + asperity + boundary-friction force on the journal (F_x, F_y) [N]."""
        ax, ay, _, _ = self._asperity(state)
        return fx + ax, fy + ay

    def adjust_result(self, state: FilmState, result: FilmResult) -> FilmResult:
        """The base film's result; asperity normal and friction forces [N] in ``extra``."""
        _, _, normal, friction = self._asperity(state)
        result.extra["asperity_force_N"] = normal
        result.extra["boundary_friction_N"] = friction
        return result
