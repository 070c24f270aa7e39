"""``[solver]`` section: film model and numerics of the orbit.

Only ``film`` is a fixed key; the rest is documented in ``docs/orbit.md``.
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from conrod.cases.base import Section
from conrod.registry import FilmName, IntegratorName

AdaptiveMethod = Literal["Radau", "BDF", "LSODA"]


class SolverSection(Section):
    """Which film model drives the orbit, and how the orbit is integrated."""

    film: FilmName = Field(default="short", description="Film model [-]")
    integrator: IntegratorName = Field(
        default="auto",
        description="auto (per film: implicit, or quasi_static for the mass-conserving "
        "film), implicit (TR-BDF2, error-controlled, compiled with the film force), "
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
        default=True,
        description="Start the implicit orbit with mass from the periodic massless orbit "
        "(fewer cycles); false: from the concentric position [-]",
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
        "implicit integrator differentiates the film force with ~1e-8 steps [-]",
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
