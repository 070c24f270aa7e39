"""Running-in (optional): evolve the shell profile with its wear over many cycles, feeding
the worn profile back into the film thickness as the additive field δ(θ, z) of
:class:`conrod.film.base.FilmState`.

The cycles are lumped into ``stages``: each stage runs the periodic orbit with the current
worn profile, takes the shell wear per cycle from :func:`analyse_contact`, and advances the
profile by that wear × the stage's number of cycles (explicit Euler in the number of
cycles — wear changes slowly compared with one cycle, which is what makes lumping valid).
Journal wear is not fed back: the journal turns, so its wear is not fixed in the film frame
and mostly enlarges the clearance uniformly.

The stages are run by :func:`conrod.simulation.running_in.run_in`; each orbit by
``simulate(case, profile)``, where ``profile(theta, z)`` returns δ [m] on any film grid
(θ [rad], z [m]). The default hands :class:`conrod.simulation.simulation.Simulation` the
case's film wrapped in :class:`WornShellFilm`, which adds δ on the film's grid to every
film state. Only film models that declare
:class:`~conrod.film.capabilities.SupportsDeformation` feel the wear (``reynolds``,
``mass_conserving``); the others (closed-form ``short``, tables) are refused. Limits: the
hard-contact circle of the orbit solver and the Greenwood–Tripp kernel keep the round shell
(the wear only opens the film).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from conrod.contact.wear import worn_profile_deformation
from conrod.errors import CaseError
from conrod.film.capabilities import SupportsDeformation
from conrod.film.wrapper import FilmWrapper

Profile = Callable[[np.ndarray, np.ndarray], np.ndarray]
"""Worn-shell film-thickness field δ(θ [rad], z [m]) -> array (len θ, len z) [m]."""


@dataclass
class RunInResults:
    """History of a running-in computation.

    element_angle : ndarray  Shell element centre angles [rad].
    cycles : list  Cycles completed at the start of each stage [-].
    friction_work : list  Friction work per cycle at each stage [J].
    max_contact_force : list  Largest contact force at each stage [N].
    shell_wear : ndarray  Accumulated shell wear depth per element at the end [m].
    stage_summaries : list  ``summary_items()`` of each stage's contact analysis.
    """

    element_angle: np.ndarray
    cycles: list[float] = field(default_factory=list)
    friction_work: list[float] = field(default_factory=list)
    max_contact_force: list[float] = field(default_factory=list)
    shell_wear: np.ndarray | None = None
    stage_summaries: list[dict[str, Any]] = field(default_factory=list)


def profile_from_wear(element_angle: np.ndarray, shell_wear: np.ndarray) -> Profile:
    """δ(θ, z) of a shell worn by ``shell_wear`` [m] per element (centres ``element_angle``)."""
    angles, depth = np.array(element_angle, dtype=float), np.array(shell_wear, dtype=float)

    def profile(theta: np.ndarray, z: np.ndarray) -> np.ndarray:
        return worn_profile_deformation(theta, z, angles, depth)

    return profile


@dataclass
class WornShellFilm(FilmWrapper):
    """A film model whose every state carries the worn-shell field δ(θ, z) [m].

    base : FilmModel  Film model honouring ``FilmState.deformation``
        (:class:`~conrod.film.capabilities.SupportsDeformation`); others are refused.
    profile : Profile  δ(θ [rad], z [m]) [m], evaluated once on ``base.grid()``.
    """

    base: Any
    profile: Profile

    def __post_init__(self) -> None:
        if not isinstance(self.base, SupportsDeformation):
            raise CaseError(
                f"solver.film = {self.base.name!r}: running-in needs a film model that uses "
                "the worn shell profile (allowed: a film honouring a deformation field, "
                "'reynolds' or 'mass_conserving')"
)
        film: Any = self.base
        theta, z = film.grid()
        self._deformation = np.ascontiguousarray(self.profile(theta, z), dtype=float)

    def adjust_state(self, state):
        """The state with the worn-shell field δ(θ, z) [m] added to its own deformation."""
        own = state.deformation
        worn = self._deformation if own is None else own + self._deformation
        return replace(state, deformation=worn)
