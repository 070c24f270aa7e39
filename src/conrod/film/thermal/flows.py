"""Volume fluxes and viscous dissipation of a solved film on its finite-volume grid, and
their means over a cycle — what the film's energy equation (:mod:`conrod.film.thermal.energy`)
is driven by.

Each node of the film grid (θ periodic, ``n_z + 1`` axial nodes with both edges) owns a
control volume RΔθ × w_j (w_j = Δz inside, Δz/2 on an edge row). ``east[i, j]`` is the
volume flux [m³/s] through the face between nodes (i, j) and (i + 1, j), positive towards
+θ; ``north[i, j]`` the flux through the face between (i, j) and (i, j + 1), positive
towards +z (the last column, beyond the edge, is 0); ``dissipation[i, j]`` the power
the viscous shear turns into heat in the control volume [W]; ``area`` the control-volume
area [m²]; ``supply`` the grooves and holes [-].
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FilmFlows:
    """Fluxes [m³/s], dissipation [W] and cell areas [m²] on the film grid (module
    docstring); ``supply`` marks the nodes of grooves and holes [-]; ``squeeze_power``
    −Σ p ∂h/∂t A, the power the journal's motion puts into the film [W], and
    ``pumping_power`` Σ p Q over the supply nodes, the power of the feed pressure [W]: in a
    steady or periodic film the dissipation is the friction power plus both."""

    east: np.ndarray
    north: np.ndarray
    dissipation: np.ndarray
    area: np.ndarray
    supply: np.ndarray
    squeeze_power: float = 0.0
    pumping_power: float = 0.0

    def net_outflow(self) -> np.ndarray:
        """Volume leaving each control volume through its faces less what enters [m³/s]:
        0 in a full film, > 0 where oil is fed (supply, reverse flow at an edge), < 0 where
        it leaves the film (the edges) or the cavitation model loses it."""
        east, north = self.east, self.north
        out = east - np.roll(east, 1, axis=0) + north
        out[:, 1:] -= north[:, :-1]
        return out

    @property
    def generated_power(self) -> float:
        """Viscous dissipation of the whole film [W]."""
        return float(self.dissipation.sum())


def mean_flows(samples: list[FilmFlows]) -> FilmFlows:
    """The mean of equally spaced samples over a cycle (the time mean) [m³/s, W]."""
    if not samples:
        raise ValueError("mean_flows: no samples")
    first = samples[0]
    return FilmFlows(
        east=np.mean([s.east for s in samples], axis=0),
        north=np.mean([s.north for s in samples], axis=0),
        dissipation=np.mean([s.dissipation for s in samples], axis=0),
        area=first.area, supply=first.supply,
        squeeze_power=float(np.mean([s.squeeze_power for s in samples])),
        pumping_power=float(np.mean([s.pumping_power for s in samples])))


def shear_dissipation(pressure: np.ndarray, h: np.ndarray, viscosity: np.ndarray,
                      sliding_speed: float, radius: float, d_theta: float,
                      axial_weights: np.ndarray, d_z: float) -> np.ndarray:
    """Viscous dissipation per control volume [W]: A (μ ΔU²/h + h³/(12μ)|∇p|²) at the
    nodes (Couette and Poiseuille shear, their cross term integrating to 0 across the
    film), ∇p by central differences (one-sided on the edges); ΔU = R(ω_j − ω_b) [m/s]."""
    arc = radius * d_theta
    d_x = (np.roll(pressure, -1, axis=0) - np.roll(pressure, 1, axis=0)) / (2.0 * arc)
    d_z_p = np.gradient(pressure, d_z, axis=1)
    density = (viscosity * sliding_speed**2 / h
               + h**3 / (12.0 * viscosity) * (d_x * d_x + d_z_p * d_z_p))
    return density * arc * axial_weights[None, :]
