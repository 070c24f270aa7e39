"""``[solver]`` section: film model and numerics of the orbit.

Only ``film`` is a fixed key; the rest is documented in ``docs/orbit.md``.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from conrod.cases.base import Section, range_error
from conrod.registry import FilmName, IntegratorName

AdaptiveMethod = Literal["Radau", "BDF", "LSODA"]

LONGEST_CYCLE_DEG = 720.0
"""Longest load cycle (four-stroke) [deg]; budgets assume it."""
MAX_INTEGRATOR_STEPS = 2_000_000
"""Step budget of a run: (cycle / step) × max_cycles of the step the integrator uses
(rk2: step_deg, quasi_static: quasi_static_step_deg, adaptive: at least max_step_deg) [-]."""
MAX_OUTPUT_POINTS = 100_000
"""Most result rows per cycle (cycle / output_step_deg) [-]."""
MAX_GRID_NODES = 300_000
"""Most film grid nodes n_theta × (n_z + 1) [-]."""


class SolverSection(Section):
    """Which film model drives the orbit, and how the orbit is integrated."""

    film: FilmName = Field(default="short", description="Film model [-]")
    integrator: IntegratorName = Field(
        default="auto",
        description="auto (implicit: the orbit with mass), implicit (TR-BDF2, "
        "error-controlled, compiled with the film force; implicit steps of the film content "
        "for the mass-conserving film), "
        "adaptive (SciPy Radau/BDF/LSODA), rk2 ([D0] fixed step) or quasi_static "
        "(massless mobility) [-]",
)
    adaptive_method: AdaptiveMethod = Field(
        default="Radau", description="scipy solve_ivp method of the adaptive integrator [-]"
    )
    max_step_deg: float = Field(
        default=1.0, gt=0.0, le=1.0, description="Largest step of the adaptive integrator [deg]"
)
    step_deg: float | None = Field(
        default=None, gt=0.0, le=5.0,
        description="Fixed step of rk2 [deg]; not given: the largest stable step that "
        "divides output_step_deg (from the film's squeeze damping; 0.01 for a film "
        "without a damping estimate)",
)
    quasi_static_step_deg: float = Field(
        default=0.5, gt=0.0, le=5.0, description="Fixed step of the quasi_static integrator [deg]"
    )
    relative_tolerance: float = Field(
        default=1.0e-6, gt=0.0, le=1.0e-2,
        description="Relative tolerance (adaptive, implicit) [-]"
)
    absolute_tolerance: float = Field(
        default=1.0e-4, gt=0.0, le=1.0,
        description="Absolute tolerance on position/c and velocity/(c ω) (adaptive, "
        "implicit) [-]",
)
    output_step_deg: float = Field(
        default=1.0, gt=0.0, le=10.0, description="Crank-angle spacing of the results [deg]"
)
    massless_start: bool = Field(
        default=False,
        description="Start the implicit orbit with mass from the periodic massless orbit "
        "instead of the concentric position (with the shooting accelerator it saves no "
        "time: docs/orbit.md) [-]",
)
    accelerate_cycles: bool = Field(
        default=True,
        description="Start each cycle at the Anderson extrapolation of the cycle-to-cycle "
        "map instead of where the last cycle ended (fewer cycles to a periodic orbit) [-]",
)
    periodic_accelerator: Literal["shooting", "anderson"] = Field(
        default="shooting",
        description="With accelerate_cycles: shooting (quasi-Newton step on the one-cycle "
        "map at every cycle, each cycle measured by its own closure) or anderson (Anderson "
        "extrapolation while the repeated cycles converge slowly) [-]",
)
    lead_in: float = Field(
        default=0.5, ge=0.0, lt=1.0,
        description="With the shooting accelerator, the orbit with mass on an elastic bore "
        "(the bore solved with the journal's implicit step) starts concentric this share of "
        "a cycle before φ = 0 instead of a whole cycle; then each cycle is measured by its "
        "own closure (0: a whole first cycle) [cycles]",
)
    max_cycles: int = Field(default=8, ge=1, le=200, description="Most cycles to integrate [-]")
    min_cycles: int = Field(default=2, ge=1, le=200, description="Fewest cycles to integrate [-]")
    periodicity_tolerance: float = Field(
        default=1.0e-3, gt=0.0, le=1.0,
        description="Periodic when max |e_k − e_(k−1)|/c at equal angles is below this [-]",
    )
    film_tolerance: float = Field(
        default=1.0e-12, gt=0.0, le=1.0e-3,
        description="Iteration tolerance of grid films in the orbit; tight, because the "
        "Newton iteration of the implicit integrators stalls on a noisier force [-]",
    )
    n_theta: int = Field(
        default=72, ge=8, le=2048, multiple_of=2,
        description="Circumferential grid intervals (= nodes, periodic), even [-]",
    )
    n_z: int = Field(
        default=16, ge=4, le=512, multiple_of=2,
        description="Axial grid intervals (n_z + 1 nodes), even [-]",
    )
    mass_x: float | None = Field(
        default=None, gt=0.0, le=1.0e5,
        description="Moving mass along film x (rod axis for a big end) [kg]",
    )
    mass_y: float | None = Field(
        default=None, gt=0.0, le=1.0e5, description="Moving mass along film y [kg]"
    )
    contact_film_thickness: float = Field(
        default=0.0, ge=0.0, le=1.0e-4,
        description="Film thickness at which hard contact starts (contact circle radius "
        "c − this) [m]",
    )
    thermal_iterations: int = Field(
        default=6, ge=0, le=50,
        description="Most heat-balance iterations (0: viscosity at supply temperature) [-]",
    )
    thermal_tolerance: float = Field(
        default=0.5, gt=0.0, le=50.0, description="Heat-balance convergence on temperature [K]"
    )
    thermal: Literal["heat_balance", "film"] = Field(
        default="heat_balance",
        description="Film temperature: one effective temperature from the global heat "
        "balance, or the film's temperature field T(θ, z) from its energy equation "
        "(docs/thermal.md) [-]",
    )
    thermal_wall_coefficient: float = Field(
        default=2000.0, ge=0.0, le=1.0e7,
        description="thermal = 'film': heat-transfer coefficient film to journal and film "
        "to shell [W/(m^2 K)]",
    )
    thermal_housing_coefficient: float = Field(
        default=0.0, ge=0.0, le=1.0e6,
        description="thermal = 'film': heat-transfer coefficient shell to housing per shell "
        "area; 0: adiabatic shell [W/(m^2 K)]",
    )
    thermal_housing_temperature: float | None = Field(
        default=None, ge=-40.0, le=300.0,
        description="thermal = 'film': housing temperature; None: the supply temperature [°C]",
    )
    thermal_journal_temperature: float | None = Field(
        default=None, ge=-40.0, le=300.0,
        description="thermal = 'film': journal temperature; None: adiabatic journal (no net "
        "heat over the cycle) [°C]",
    )
    thermal_map_angles: list[Annotated[float, Field(ge=0.0, le=720.0)]] | None = Field(
        default=None, max_length=12,
        description="thermal = 'film': crank angles of the quasi-steady temperature maps "
        "(walls held at their cycle-mean temperatures, docs/thermal.md); None: the angles of "
        "the smallest h_min and of the largest p_max; an empty list: no maps [deg]",
    )

    @model_validator(mode="after")
    def _within_budget(self) -> SolverSection:
        """Steps, result rows and grid nodes within the budgets, refused before any run."""
        fixed_steps = {"rk2": "step_deg", "quasi_static": "quasi_static_step_deg"}
        step_name = fixed_steps.get(self.integrator, "max_step_deg")  # error-controlled: bound
        step = getattr(self, step_name)
        if step is None:  # rk2 without step_deg: the largest stable step, chosen per film
            step_name, step = "max_step_deg", self.max_step_deg
        smallest = LONGEST_CYCLE_DEG * self.max_cycles / MAX_INTEGRATOR_STEPS
        if step < smallest:
            raise range_error(
                f"solver.{step_name}", step, f">= {smallest:.3g} with max_cycles = "
                f"{self.max_cycles} (budget {MAX_INTEGRATOR_STEPS} steps per run)", "deg")
        if step_name in fixed_steps.values():
            ratio = self.output_step_deg / step
            if ratio < 1.0 - 1e-9 or abs(ratio - round(ratio)) > 1e-9 * ratio:
                raise range_error(f"solver.{step_name}", step, "a divisor of "
                                  f"solver.output_step_deg = {self.output_step_deg:g} "
                                  "(output_step_deg / k, k = 1, 2, ...)", "deg")
        smallest_output = LONGEST_CYCLE_DEG / MAX_OUTPUT_POINTS
        if self.output_step_deg < smallest_output:
            raise range_error("solver.output_step_deg", self.output_step_deg,
                              f">= {smallest_output:.3g} (budget {MAX_OUTPUT_POINTS} rows "
                              "per cycle)", "deg")
        nodes = self.n_theta * (self.n_z + 1)
        if nodes > MAX_GRID_NODES:
            raise range_error("solver.n_theta x solver.n_z", f"{self.n_theta}x{self.n_z}",
                              f"n_theta * (n_z + 1) <= {MAX_GRID_NODES} nodes", "")
        return self
