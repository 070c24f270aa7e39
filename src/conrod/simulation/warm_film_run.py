"""The bore warm from the thermal film (TEHD): ``[solver] thermal = "film"`` with a
``[housing.thermal]`` that gives no temperatures (docs/thermal.md, *Thermal distortion from
the film*).

Each thermal iteration takes the temperatures of the warm bore from the energy solution:

* the journal at the solution's journal temperature T_j;
* the housing bore (shell side) at T_b(θ) = (H T̄(θ) + H_h T_h)/(H + H_h): the local series
  balance of the film's axial-mean temperature T̄(θ) through the film-to-shell coefficient
  H and the shell-to-housing coefficient H_h towards T_h (``thermal_housing_temperature``).
  Its mean over θ is the shell temperature T_s of the energy solution exactly (the same
  balance summed); the shell there conducts round its circumference, here not at all, so
  T_b(θ) is the largest variation the film's heat can give the bore (the housing's own
  conduction then smooths it, :mod:`conrod.housing.conduction`). H = 0: T_b = T_s.
  A finite-element housing conducts from T_b(θ) at the film nodes to the crankcase
  (``ambient_temperature``, default T_h); a housing without one grows as a free ring at
  the mean, T_s.

Journal and bore temperatures are under-relaxed with the film's, and the clearance c + Δc
and the thermal bore profile h₀(θ) are rebuilt before the next orbit from a case whose
``[housing.thermal]`` holds them as given temperatures (the given-temperature path of
:mod:`conrod.housing.as_built` with the same numbers; the FE thermal solve cached per
temperature field by the housing's cache). The iteration stops when the film's temperature
and these temperatures change by at most ``thermal_tolerance``.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.orbit.heat_balance import RELAXATION
from conrod.results.thermal import FilmWarmBore

FE_MODELS = ("builtin", "mesh")
"""Housing models that conduct from the shell-side temperature T_b(θ) [-]."""


def film_driven(sim: Any) -> bool:
    """True when ``sim``'s warm bore takes its temperatures from the thermal film [-]."""
    section = sim.case.housing.thermal
    return sim.solver.thermal == "film" and section is not None and section.from_film


def bore_temperatures(answer: Any, area: np.ndarray, walls: Any) -> tuple[float, np.ndarray]:
    """(T_j, T_b(θ_j) at the film's θ nodes) [°C] of an energy solution ``answer`` with the
    cell areas ``area`` [m²] and the heat paths ``walls`` (module docstring)."""
    film = (answer.temperature * area).sum(axis=1) / area.sum(axis=1)
    h, h_h = walls.film_coefficient, walls.housing_coefficient
    if h <= 0.0:
        return answer.journal_temperature, np.full(film.shape, answer.shell_temperature)
    return answer.journal_temperature, (h * film + h_h * walls.housing_temperature) / (h + h_h)


@dataclass
class WarmFilmBore:
    """The film-driven warm bore of one thermal iteration loop (module docstring)."""

    sim: Any
    journal: float
    shell: np.ndarray
    ambient: float
    current: Any = None

    @classmethod
    def start(cls, sim: Any, walls: Any) -> WarmFilmBore:
        """At the supply temperature everywhere (the bore of the first orbit)."""
        supply = float(sim.case.lubricant.supply_temperature)
        bore = cls(sim, supply, np.full(sim.solver.n_theta, supply),
                   float(walls.housing_temperature))
        bore.current = bore.simulation()
        return bore

    def update(self, answer: Any, area: np.ndarray, walls: Any) -> None:
        """Relax towards the temperatures of ``answer`` and rebuild the simulation."""
        journal, shell = bore_temperatures(answer, area, walls)
        self.journal += RELAXATION * (journal - self.journal)
        self.shell = self.shell + RELAXATION * (shell - self.shell)
        self.current = self.simulation()

    def target_change(self, answer: Any, area: np.ndarray, walls: Any) -> float:
        """Largest change [K] of the temperatures of ``answer`` from the current ones."""
        journal, shell = bore_temperatures(answer, area, walls)
        return max(abs(journal - self.journal), float(np.max(np.abs(shell - self.shell))))

    def section(self) -> Any:
        """``[housing.thermal]`` with the current temperatures as given ones."""
        section = self.sim.case.housing.thermal
        if self.sim.case.housing.model not in FE_MODELS:  # a free ring at the mean
            return section.at_temperatures(self.journal, [0.0], [float(self.shell.mean())],
                                           self.ambient)
        angles = [360.0 * j / self.shell.size for j in range(self.shell.size)]  # film nodes
        return section.at_temperatures(self.journal, angles,
                                       [float(t) for t in self.shell], self.ambient)

    def simulation(self) -> Any:
        """The simulation of the case with these temperatures given (same loads,
        integrator, solver; rigid when ``sim`` is), of ``sim``'s own type."""
        sim = self.sim
        housing = sim.case.housing.model_copy(update={"thermal": self.section()})
        case = sim.case.model_copy(update={"housing": housing, "solver": sim.solver})
        return type(sim)(case, loads=sim.load_cycle(), integrator=sim.integrator(),
                          housing="rigid" if sim.housing() is None else None,
                          rigid_companion=False)

    def results(self) -> FilmWarmBore:
        """What the last orbit's bore was built from and is (:class:`FilmWarmBore`)."""
        current, cold = self.current, self.sim.case.bearing.radial_clearance
        change = current.geometry().radial_clearance - cold
        housing = current.housing()
        if housing is not None and housing.warm is not None:
            profile = housing.warm.profile(housing.projector)
            mean = housing.warm.housing_temperature
        else:
            profile, mean = None, _rigid_housing_temperature(current)
        return FilmWarmBore(self.journal, 2.0 * np.pi * np.arange(self.shell.size)
                            / self.shell.size, self.shell.copy(), float(mean), float(change),
                            None if profile is None else float(np.ptp(profile)), profile)


def _rigid_housing_temperature(sim: Any) -> float:
    """Mean housing temperature behind a rigid bore [°C]: the FE conduction field's mean
    for a conducting housing, else the free ring's uniform temperature."""
    section = sim.case.housing.thermal
    if section.conducting:
        from conrod.housing.housing import Housing

        return float(Housing.from_case(sim.case.model_copy(
            update={"solver": sim.solver})).warm.housing_temperature)
    return float(section.housing_temperature)
