"""The film's temperature field over a cycle (``[solver] thermal = "film"``): the converged
cycle-mean temperature T(θ, z), the wall temperatures and the heat flows
(:mod:`conrod.film.thermal.energy`, docs/thermal.md)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class FilmWarmBore:
    """The bore warm from the film's temperatures (``[housing.thermal]`` without given
    temperatures, docs/thermal.md): what the last orbit ran on.

    journal_temperature : float  The energy solution's journal temperature [°C].
    angles : ndarray  Shell angles of ``shell_side_temperature`` [rad].
    shell_side_temperature : ndarray  Shell-side (housing bore) temperature T_b(θ) [°C].
    housing_temperature : float  Mean temperature of the housing (the conduction field's
        mean over the big end; the shell-side mean for a free ring) [°C].
    clearance_change : float  Δc of the radial clearance, warm − cold [m].
    out_of_round : float or None  Peak-to-valley of the bore's thermal profile h₀(θ) [m];
        None where the film's bore carries none (a rigid bore).
    profile : ndarray or None  The thermal profile h₀(θ) at ``angles`` (the corrected
        thermal bore displacement less its mean, outward +) [m]; None on a rigid bore.
    """

    journal_temperature: float
    angles: np.ndarray
    shell_side_temperature: np.ndarray
    housing_temperature: float
    clearance_change: float
    out_of_round: float | None
    profile: np.ndarray | None = None

    def summary_items(self) -> dict:
        """summary.json items (units in the names)."""
        return {"warm_bore_journal_temperature_C": self.journal_temperature,
                "warm_bore_shell_side_temperature_C": [
                    float(self.shell_side_temperature.min()),
                    float(self.shell_side_temperature.max())],
                "warm_bore_housing_temperature_C": self.housing_temperature,
                "warm_bore_clearance_change_um": self.clearance_change * 1e6,
                "warm_bore_out_of_round_um": None if self.out_of_round is None
                else self.out_of_round * 1e6}


@dataclass(frozen=True)
class ThermalFilmResults:
    """Converged film temperature of a run (units in brackets).

    temperature : ndarray  Cycle-mean film temperature T(θ, z) on the film grid [°C].
    theta, z : ndarray  Grid nodes: shell angle θ [rad], axial position z [m].
    journal_temperature, shell_temperature : float  Wall temperatures [°C].
    housing_temperature, supply_temperature : float  [°C].
    generated : float  Cycle-mean viscous dissipation of the film [W].
    to_oil, to_journal, to_shell : float  Cycle-mean heat convected by the oil (out − in)
        and conducted into the journal and the shell [W]; they sum to ``generated``.
    friction_power : float  Cycle-mean friction power of the film (torque × speed) [W].
    squeeze_power, pumping_power : float  Cycle-mean power the journal's motion (−F·v) and
        the feed pressure (p Q) put into the film [W]: ``generated`` is friction + squeeze +
        pumping power to the discretisation error of the grid.
    iterations : int  Orbit–energy iterations done [-].
    change : float  Largest temperature change of the last iteration [K].
    tolerance : float  ``[solver] thermal_tolerance`` [K].
    max_valid_temperature : float  Highest temperature of the oil data [°C].
    warm_bore : FilmWarmBore or None  The bore warm from these temperatures (None: not
        film-driven).
    """

    temperature: np.ndarray
    theta: np.ndarray
    z: np.ndarray
    journal_temperature: float
    shell_temperature: float
    housing_temperature: float
    supply_temperature: float
    generated: float
    to_oil: float
    to_journal: float
    to_shell: float
    friction_power: float
    squeeze_power: float
    pumping_power: float
    iterations: int
    change: float
    tolerance: float
    max_valid_temperature: float
    warm_bore: FilmWarmBore | None = None

    @property
    def converged(self) -> bool:
        """True when the last iteration changed T by at most the tolerance [-]."""
        return self.change <= self.tolerance

    @property
    def hottest(self) -> tuple[float, float, float]:
        """(largest film temperature [°C], its shell angle θ [rad], axial position z [m])."""
        i, j = np.unravel_index(int(np.argmax(self.temperature)), self.temperature.shape)
        return float(self.temperature[i, j]), float(self.theta[i]), float(self.z[j])

    @property
    def mean_temperature(self) -> float:
        """Mean film temperature over the film area (trapezoidal in z) [°C]."""
        weights = np.ones(self.z.size)
        weights[[0, -1]] = 0.5
        return float(np.sum(self.temperature * weights) / (weights.sum() * self.theta.size))

    def warnings(self) -> list[str]:
        """Not converged, or hotter than the oil data (each one line)."""
        out = []
        if not self.converged:
            out.append(f"thermal film not converged: the film temperature changed by "
                       f"{self.change:.3g} K in the last of {self.iterations} iterations "
                       f"(> solver.thermal_tolerance = {self.tolerance:g} K; raise "
                       "solver.thermal_iterations)")
        hottest = self.hottest[0]
        if hottest > self.max_valid_temperature:
            out.append(f"film temperature up to {hottest:.1f} °C: above the oil data "
                       f"(lubricant.max_temperature = {self.max_valid_temperature:g} °C)")
        return out

    def headline_text(self) -> str:
        """The headline's temperature line."""
        t, theta, z = self.hottest
        text = (f"film max {t:.1f} °C at θ = {math.degrees(theta):.0f}°, z = {z * 1e3:.1f} mm; "
                f"journal {self.journal_temperature:.1f} °C, shell "
                f"{self.shell_temperature:.1f} °C (thermal film)")
        warm = self.warm_bore
        if warm is None:
            return text
        shape = ("" if warm.out_of_round is None else
                 f", thermal out-of-round {warm.out_of_round * 1e6:.2f} µm")
        return (f"{text}; bore warm from the film: clearance {warm.clearance_change * 1e6:+.2f} "
                f"µm{shape}, housing {warm.housing_temperature:.1f} °C")

    def summary_items(self) -> dict:
        """summary.json items (units in the names)."""
        t, theta, z = self.hottest
        return {"thermal_film": {
            "max_film_temperature_C": t, "max_film_temperature_theta_deg": math.degrees(theta),
            "max_film_temperature_z_mm": z * 1e3,
            "mean_film_temperature_C": self.mean_temperature,
            "journal_temperature_C": self.journal_temperature,
            "shell_temperature_C": self.shell_temperature,
            "housing_temperature_C": self.housing_temperature,
            "generated_power_W": self.generated, "heat_to_oil_W": self.to_oil,
            "heat_to_journal_W": self.to_journal, "heat_to_shell_W": self.to_shell,
            "friction_power_W": self.friction_power, "squeeze_power_W": self.squeeze_power,
            "pumping_power_W": self.pumping_power, "iterations": self.iterations,
            "last_change_K": self.change, "converged": self.converged,
            **({} if self.warm_bore is None else self.warm_bore.summary_items())}}

    def table(self) -> dict[str, np.ndarray]:
        """thermal_film.csv columns: the temperature at every grid node."""
        theta, z = np.meshgrid(np.degrees(self.theta), self.z * 1e3, indexing="ij")
        return {"theta_deg": theta.ravel(), "z_mm": z.ravel(),
                "temperature_C": self.temperature.ravel()}
