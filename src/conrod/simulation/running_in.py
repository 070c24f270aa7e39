"""Running-in (optional): the shell worn in over many cycles, lumped into stages of periodic
orbits whose shell wear per cycle advances the worn profile (physics and result type in
:mod:`conrod.contact.running_in`)."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from conrod.contact.running_in import Profile, RunInResults, WornShellFilm, profile_from_wear
from conrod.errors import CaseError
from conrod.simulation.simulation import Simulation, default_film


def _default_simulate(case, profile: Profile):
    return Simulation(case, film=WornShellFilm(default_film(case), profile)).run().contact


def run_in(
    case, cycles: float, stages: int = 5,
    simulate: Callable[[Any, Profile], Any] | None = None,
) -> RunInResults:
    """Wear the shell in over ``cycles`` engine cycles in ``stages`` orbit runs.

    case : Case with ``[contact]``; cycles : total number of cycles [-] (> 0);
    stages : number of orbit runs (≥ 1); simulate : ``(case, profile) -> ContactResults``.
    """
    if not cycles > 0.0:
        raise CaseError(f"run_in cycles = {cycles!r}: out of range (allowed: > 0)")
    if stages < 1:
        raise CaseError(f"run_in stages = {stages!r}: out of range (allowed: >= 1)")
    if simulate is None:
        simulate = _default_simulate
    elements = case.contact.surface_elements
    angles = (np.arange(elements) + 0.5) * 2.0 * np.pi / elements
    wear = np.zeros(elements)
    history = RunInResults(element_angle=angles)
    per_stage = cycles / stages
    for stage in range(stages):
        contact = simulate(case, profile_from_wear(angles, wear))
        history.cycles.append(stage * per_stage)
        history.friction_work.append(contact.work.total)
        history.max_contact_force.append(contact.max_contact_force)
        history.stage_summaries.append(contact.summary_items())
        wear = wear + per_stage * contact.wear.shell_wear
    history.shell_wear = wear
    return history
