"""Steady film energy equation averaged across the film thickness, 2-D in (θ, z) on the
film grid: finite volumes with upwinding, solved directly (scipy sparse LU).

For the control volume of node P (:mod:`conrod.film.thermal.flows`), with the cycle-mean
face fluxes Q [m³/s], the volumetric heat capacity ρc_p [J/(m³ K)], the dissipation D_P
[W] and the film-to-wall coefficients H_j, H_s [W/(m² K)] to the journal and the shell:

.. math:: ρc_p\\Big[\\sum_{out} Q_f T_P − \\sum_{in} Q_f T_{nb(f)} + S^-_P T_P − S^+_P T_0\\Big]
          + H_j A_P (T_P − T_j) + H_s A_P (T_P − T_s) = D_P,

each face carrying the temperature of the node it leaves (upwind, so reverse flow and the
cavitated zone are taken as the flux goes), S⁺ = max(O, 0) and S⁻ = max(−O, 0) with O the
net outflow through the faces. Mixing model: oil that enters a control volume from outside
the film (S⁺: the supply at grooves and holes, oil drawn in at an edge, or the oil the
Swift–Stieber cavitation model adds where the film reforms) enters at the supply
temperature T_0 and mixes completely with the recirculating oil that flows into that cell
(at a groove the classical hot-oil carry-over mixing (Q_rec T_rec + Q_s T_0)/(Q_rec + Q_s));
oil that leaves (S⁻: side leakage, oil lost in the cavitated zone) takes the cell's
temperature. Walls: the journal turns past the whole film, so it has one temperature T_j —
adiabatic over the cycle (Σ H_j A (T − T_j) = 0) or given; the shell has one temperature
T_s (a thin steel-backed shell conducting around its circumference), losing
H_h A_tot (T_s − T_h) to the housing at T_h (H_h = 0: adiabatic). The walls with H = 0 take
no heat (their temperature is then reported as the film's mean).

Quasi-steady: the field at one instant of the cycle with the walls held at their
cycle-mean temperatures (the walls' time constants are long against a cycle, the oil's
transit time through the film short, so h ∂T/∂t is dropped). The film's own volume change
A ∂h/∂t then enters the balance as oil of the cell's temperature — squeezed out where the
film closes, taken up where it opens — and only the rest of the net outflow,
O + A ∂h/∂t, is fed from outside at T_0 or lost at T_P: in a full film this is the
advective form q·∇T of the equation, so squeezed oil is never taken for fresh supply oil.
The heat the volume change carries, ρc_p Σ A ∂h/∂t (T_P − T_0), is reported on its own
(``to_volume``: generated = to oil + to journal + to shell + to volume, both counted above
the supply temperature, since Σ(S⁺ − S⁻) = Σ A ∂h/∂t). Where the film is squeezed faster
than oil flows through a cell, the oil stays longer than the transit time and the
quasi-steady field overstates its temperature (docs/thermal.md).

Conservation: summing every row, the face terms cancel, so (convected out − convected in)
+ to journal + to shell = generated, to the round-off of the direct solve.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

from conrod.errors import ConvergenceError
from conrod.film.thermal.flows import FilmFlows


@dataclass(frozen=True)
class ThermalWalls:
    """Heat paths of the film (module docstring).

    film_coefficient : float  Film-to-wall coefficient H on both walls [W/(m² K)] (0:
        adiabatic film).
    housing_coefficient : float  Shell-to-housing coefficient H_h per shell area
        [W/(m² K)] (0: adiabatic shell).
    housing_temperature : float  Housing temperature T_h [°C].
    journal_temperature : float or None  Given journal temperature [°C]; None: adiabatic
        over the cycle.
    shell_temperature : float or None  Given shell temperature [°C] (the housing path is
        then unused); None: from the shell's balance with the film and the housing.
    """

    film_coefficient: float
    housing_coefficient: float
    housing_temperature: float
    journal_temperature: float | None = None
    shell_temperature: float | None = None


@dataclass(frozen=True)
class FilmTemperature:
    """Solution of the film energy equation (units in brackets).

    temperature : ndarray  T(θ, z) on the film grid [°C].
    journal_temperature, shell_temperature : float  Wall temperatures [°C].
    generated : float  Viscous dissipation of the film [W].
    to_oil : float  Heat convected away by the oil (out − in) [W].
    to_journal, to_shell : float  Heat conducted into the journal and the shell [W].
    to_volume : float  Heat the film's own volume change takes, ρc_p Σ A ∂h/∂t (T_P − T_0)
        (< 0: the oil squeezed out gives up heat it held) [W]; 0 for a cycle mean (then
        ``to_oil`` is ρc_p (Σ S⁻ T_P − Σ S⁺ T_0); with a volume change ρc_p Σ S⁻ (T_P − T_0),
        the same sum).
    """

    temperature: np.ndarray
    journal_temperature: float
    shell_temperature: float
    generated: float
    to_oil: float
    to_journal: float
    to_shell: float
    to_volume: float = 0.0

    @property
    def imbalance(self) -> float:
        """generated − (to oil + to journal + to shell + to volume) [W] (round-off)."""
        return self.generated - (self.to_oil + self.to_journal + self.to_shell
                                 + self.to_volume)


def solve_energy(flows: FilmFlows, heat_capacity: float, supply_temperature: float,
                 walls: ThermalWalls, volume_rate: np.ndarray | None = None
                 ) -> FilmTemperature:
    """T(θ, z) [°C] and the wall temperatures of the steady energy equation (module
    docstring) for the cycle-mean ``flows``, ρc_p = ``heat_capacity`` [J/(m³ K)] and the
    supply temperature T_0 [°C]. ``volume_rate``: A ∂h/∂t per control volume [m³/s] of an
    instantaneous (quasi-steady) film, whose volume change carries the cell's own oil
    (module docstring, *Quasi-steady*); None: 0 (a cycle mean). :class:`ConvergenceError`
    when it has no finite answer."""
    n, m = flows.area.shape
    index = np.arange(n * m).reshape(n, m)
    entries: list[tuple] = []
    rhs = _convection(flows, heat_capacity, supply_temperature, index, entries, volume_rate)
    conductance = walls.film_coefficient * flows.area
    extra = _walls(flows, walls, conductance, supply_temperature, index, entries)
    rows, cols, vals = (np.concatenate([np.ravel(e[k]) for e in entries]) for k in range(3))
    size = n * m + 2
    matrix = sp.csc_matrix((vals, (rows, cols)), shape=(size, size))
    solution = spsolve(matrix, np.concatenate([rhs.ravel(), extra]))
    if not np.all(np.isfinite(solution)):
        raise ConvergenceError("film energy equation: no finite temperature (a film region "
                               "without through-flow and without a heat path to the walls)",
                               where="thermal film")
    return _answer(flows, solution, conductance, heat_capacity, supply_temperature,
                   volume_rate)


def _convection(flows: FilmFlows, heat_capacity: float, supply_temperature: float,
                index: np.ndarray, entries: list, volume_rate: np.ndarray | None
                ) -> np.ndarray:
    """Upwind convection entries (row, column, value [W/K]) appended to ``entries``, and the
    right-hand side: dissipation and the heat of the oil fed at T_0 [W]."""
    for flux, neighbour in ((flows.east, np.roll(index, -1, axis=0)),
                            (flows.north[:, :-1], index[:, 1:])):
        own = index[:, : flux.shape[1]]
        forward = heat_capacity * np.maximum(flux, 0.0)
        backward = heat_capacity * np.maximum(-flux, 0.0)
        entries += [(own, own, forward), (neighbour, own, -forward),  # leaves P at T_P
                    (neighbour, neighbour, backward), (own, neighbour, -backward)]
    outflow = _external_outflow(flows, volume_rate)
    entries.append((index, index, heat_capacity * np.maximum(-outflow, 0.0)))
    if volume_rate is not None:  # the film's own volume change at T_P
        entries.append((index, index, heat_capacity * volume_rate))
    return flows.dissipation + heat_capacity * np.maximum(outflow, 0.0) * supply_temperature


def _walls(flows: FilmFlows, walls: ThermalWalls, conductance: np.ndarray,
           supply_temperature: float, index: np.ndarray, entries: list) -> np.ndarray:
    """Film-to-wall entries and the rows of the journal and the shell temperature (the
    last two unknowns) appended to ``entries``; their right-hand sides [W]."""
    journal, shell = index.size, index.size + 1
    total = float(conductance.sum())
    entries += [(index, index, 2.0 * conductance), (index, np.full(index.shape, journal),
                                                    -conductance),
                (index, np.full(index.shape, shell), -conductance)]
    extra = np.array([supply_temperature, supply_temperature])
    if total > 0.0 and walls.journal_temperature is None:  # adiabatic journal: Σ q = 0
        entries += [(np.full(index.shape, journal), index, -conductance),
                    (journal, journal, total)]
        extra[0] = 0.0
    else:
        entries.append((journal, journal, 1.0))
        if walls.journal_temperature is not None:
            extra[0] = walls.journal_temperature
    if total > 0.0 and walls.shell_temperature is not None:  # given shell temperature
        entries.append((shell, shell, 1.0))
        extra[1] = walls.shell_temperature
    elif total > 0.0:
        housing = walls.housing_coefficient * float(flows.area.sum())
        entries += [(np.full(index.shape, shell), index, -conductance),
                    (shell, shell, total + housing)]
        extra[1] = housing * walls.housing_temperature
    else:
        entries.append((shell, shell, 1.0))
    return extra


def _external_outflow(flows: FilmFlows, volume_rate: np.ndarray | None) -> np.ndarray:
    """Net outflow through the faces not made up by the film's own volume change, O + A ∂h/∂t:
    > 0 fed from outside at T_0, < 0 lost at T_P [m³/s]."""
    outflow = flows.net_outflow()
    return outflow if volume_rate is None else outflow + volume_rate


def _answer(flows: FilmFlows, solution: np.ndarray, conductance: np.ndarray,
            heat_capacity: float, supply_temperature: float,
            volume_rate: np.ndarray | None = None) -> FilmTemperature:
    """The temperatures and heat flows of a solution vector [°C, W]."""
    n, m = flows.area.shape
    temperature = solution[: n * m].reshape(n, m)
    t_journal, t_shell = float(solution[-2]), float(solution[-1])
    if not conductance.any():  # no wall heat path: the walls at the film's mean
        t_journal = t_shell = float(np.sum(temperature * flows.area) / flows.area.sum())
    outflow = _external_outflow(flows, volume_rate)
    if volume_rate is None:
        to_oil = heat_capacity * float(np.sum(np.maximum(-outflow, 0.0) * temperature)
                                       - np.sum(np.maximum(outflow, 0.0)) * supply_temperature)
        to_volume = 0.0
    else:  # both above the supply temperature (their sum is the same on any scale)
        rise = temperature - supply_temperature
        to_oil = heat_capacity * float(np.sum(np.maximum(-outflow, 0.0) * rise))
        to_volume = heat_capacity * float(np.sum(volume_rate * rise))
    to_journal = float(np.sum(conductance * (temperature - solution[-2])))
    to_shell = float(np.sum(conductance * (temperature - solution[-1])))
    return FilmTemperature(temperature, t_journal, t_shell, flows.generated_power, to_oil,
                           to_journal, to_shell, to_volume)
