"""Quasi-steady film temperature maps at chosen crank angles of a thermal film run
(``[solver] thermal_map_angles``, docs/thermal.md, *Temperature maps at chosen angles*): the
film temperature T(θ, z) of the film at that instant, with the journal and the shell held
at their cycle-mean temperatures, and the heat flows of that instant."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class ThermalMapsResults:
    """Film temperature maps at chosen crank angles (units in brackets; k maps).

    requested_deg : ndarray  Crank angles asked for [deg] (k,).
    crank_angle_deg : ndarray  Crank angle of the output row each map is solved at (the row
        nearest the asked angle) [deg] (k,).
    temperature : ndarray  T(θ, z) per map [°C] (k, n_θ, n_z + 1).
    theta, z : ndarray  Grid nodes: shell angle θ [rad], axial position z [m].
    journal_temperature, shell_temperature : float  The walls, held at their cycle-mean
        temperatures [°C].
    generated : ndarray  Viscous dissipation of the film at each map's instant [W] (k,).
    to_oil, to_journal, to_shell : ndarray  Heat convected by the oil (out − in) and
        conducted into the journal and the shell at each instant [W] (k,).
    to_volume : ndarray  Heat the film's own volume change takes at each instant,
        ρc_p Σ A ∂h/∂t (T − T_0) (< 0: squeezed-out oil gives up heat it held) [W] (k,);
        with the three above it sums to ``generated`` (oil and volume counted above the
        supply temperature).
    friction_power : ndarray  Friction power of the film at each map's row [W] (k,).
    squeeze_share : ndarray  Share of the film area squeezed out faster than oil flows in
        (there the quasi-steady temperature is too high) [-] (k,).
    """

    requested_deg: np.ndarray
    crank_angle_deg: np.ndarray
    temperature: np.ndarray
    theta: np.ndarray
    z: np.ndarray
    journal_temperature: float
    shell_temperature: float
    generated: np.ndarray
    to_oil: np.ndarray
    to_journal: np.ndarray
    to_shell: np.ndarray
    to_volume: np.ndarray
    friction_power: np.ndarray
    squeeze_share: np.ndarray

    def hottest(self, k: int) -> tuple[float, float, float]:
        """(largest film temperature of map ``k`` [°C], its shell angle θ [rad], axial
        position z [m])."""
        field = self.temperature[k]
        i, j = np.unravel_index(int(np.argmax(field)), field.shape)
        return float(field[i, j]), float(self.theta[i]), float(self.z[j])

    def imbalance(self, k: int) -> float:
        """generated − (to oil + to journal + to shell) of map ``k`` [W] (round-off)."""
        return float(self.generated[k] - (self.to_oil[k] + self.to_journal[k]
                                          + self.to_shell[k] + self.to_volume[k]))

    def summary_items(self) -> list[dict]:
        """summary.json 'thermal_film' 'maps': one item per map (units in the names); the
        heat to the oil includes what the film's volume change takes (given on its own), so
        that oil + journal + shell is the generated power."""
        items = []
        for k in range(self.requested_deg.size):
            t, theta, z = self.hottest(k)
            items.append({
                "requested_crank_angle_deg": float(self.requested_deg[k]),
                "crank_angle_deg": float(self.crank_angle_deg[k]),
                "max_film_temperature_C": t,
                "max_film_temperature_theta_deg": math.degrees(theta),
                "max_film_temperature_z_mm": z * 1e3,
                "generated_power_W": float(self.generated[k]),
                "heat_to_oil_W": float(self.to_oil[k] + self.to_volume[k]),
                "heat_to_oil_by_volume_change_W": float(self.to_volume[k]),
                "heat_to_journal_W": float(self.to_journal[k]),
                "heat_to_shell_W": float(self.to_shell[k]),
                "friction_power_W": float(self.friction_power[k]),
                "squeeze_dominated_area_share": float(self.squeeze_share[k])})
        return items

    def table(self) -> dict[str, np.ndarray]:
        """thermal_maps.csv columns, long: one row per map and grid node."""
        k, n, m = self.temperature.shape
        angle = np.repeat(self.crank_angle_deg, n * m)
        theta, z = np.meshgrid(np.degrees(self.theta), self.z * 1e3, indexing="ij")
        return {"crank_angle_deg": angle, "theta_deg": np.tile(theta.ravel(), k),
                "z_mm": np.tile(z.ravel(), k), "temperature_C": self.temperature.ravel()}
