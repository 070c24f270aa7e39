"""A steady thermal plain journal bearing in ROSS (ross-rotordynamics, ``PlainJournal``,
its thermo-hydro-dynamic model) and in conrod's thermal film at a constant load.

Run:  pip install -e ".[bench]"; python benchmarks/ross_thd_comparison.py
      (writes benchmarks/ross_thd_comparison.md; a few minutes)

The bearing: D = 80 mm, L = 30 mm, c = 50 µm, 2600 rpm, one full-length axial groove at
θ = 0 held at ambient pressure (ROSS: one 360° pad, whose ends are held at 0), the load
towards θ = 270° (−y) on the journal, oil with the Vogel law μ = a exp(b/(T + c)) in both
codes (ROSS's own law, μ = a T^b fitted through two points, replaced by the same Vogel law
through a subclass), ρ = 860 kg/m³, c_p = 2000 J/(kg K), supply at 90 °C, adiabatic walls
in both (ROSS's model has no wall heat path; conrod: ``thermal_wall_coefficient = 0``).

Two comparisons per load: isoviscous (μ at 90 °C in both: the hydrodynamic models alone,
and the energy equations on nearly the same flows) and thermal (μ(T) of the film's
temperature field). conrod: ``[load]`` table constant over a 360° cycle, Reynolds film,
periodic orbit settled to 1e-6 (a steady journal), the thermal film's energy equation of the
cycle-mean flows — at a constant load the steady solution. ROSS: its equilibrium search
(Nelder–Mead on the force residual, its own tolerance), its THD iteration (1 % on T). The
two mix differently at the groove (ROSS: a given fraction of supply oil with the pad's mean
outlet temperature; conrod: by the flows at the groove nodes), so ROSS is given conrod's
temperature of the oil leaving the groove as its inlet temperature (groove factor 1,
reference temperature = that temperature): both films start from the same oil. Last, the
energy equations alone: conrod's equation with the oil its cavitated zone gains taken at the
cell's temperature (ROSS's advective form) against ROSS with that variant's inlet.
"""

from __future__ import annotations

import math
import os
import platform
import time
import warnings
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.film.thermal.energy import ThermalWalls, solve_energy
from conrod.io.atomic import write_text
from conrod.simulation.simulation import Simulation
from conrod.simulation.thermal_film_run import cycle_flows

OUTPUT = Path(__file__).with_suffix(".md")
RADIUS, WIDTH, CLEARANCE = 0.040, 0.030, 50.0e-6  # [m]
SPEED_RPM = 2600.0
OMEGA = SPEED_RPM * math.pi / 30.0  # [rad/s]
VOGEL = (5.0e-5, 900.0, 95.0)  # a [Pa s], b [°C], c [°C]
DENSITY, SPECIFIC_HEAT, CONDUCTIVITY = 860.0, 2000.0, 0.13  # [kg/m³, J/(kg K), W/(m K)]
SUPPLY = 90.0  # [°C]
LOADS = (1000.0, 2000.0, 3000.0)  # [N]
GRID = {"conrod": (72, 16), "ross": (36, 8)}  # (n_θ, n_z) intervals / cells
GROOVE_WIDTH = 2.0e-3  # [m] conrod's groove (ROSS: a line)


def vogel(temperature):
    """μ(T) [Pa s] of the Vogel law of both codes, T [°C]."""
    a, b, c = VOGEL
    return a * np.exp(b / (np.asarray(temperature, float) + c))


# ------------------------------------------------------------------------ conrod
def conrod_case(folder: Path, load: float, thermal: bool, grid: tuple[int, int]) -> Case:
    rows = [f"{a},0.0,{-load}" for a in np.arange(0.0, 361.0, 10.0)]
    (folder / "load.csv").write_text("crank_angle_deg,load_x_N,load_y_N\n" + "\n".join(rows))
    a, b, c = VOGEL
    n_theta, n_z = grid
    solver = {"film": "reynolds", "n_theta": n_theta, "n_z": n_z, "output_step_deg": 10.0,
              "periodicity_tolerance": 1e-6, "max_cycles": 40, "relative_tolerance": 1e-9,
              "absolute_tolerance": 1e-7, "thermal": "film", "thermal_wall_coefficient": 0.0,
              "thermal_housing_coefficient": 0.0, "thermal_tolerance": 0.05,
              "thermal_iterations": 40 if thermal else 0}
    data = {"title": f"ROSS comparison, {load:g} N",
            "bearing": {"diameter": 2 * RADIUS, "width": WIDTH, "radial_clearance": CLEARANCE,
                        "axial_grooves": [{"angle": 0.0, "width": GROOVE_WIDTH}]},
            "lubricant": {"vogel_a": a, "vogel_b": b, "vogel_c": c, "density": DENSITY,
                          "specific_heat": SPECIFIC_HEAT, "supply_temperature": SUPPLY},
            "load": {"table": "load.csv", "speed": SPEED_RPM, "cycle_deg": 360},
            "solver": solver}
    return Case.from_dict(data, base_dir=folder)


def conrod_point(folder: Path, load: float, thermal: bool, grid: tuple[int, int]) -> dict:
    """The steady point of conrod (module docstring) and the temperature of the oil that
    leaves its groove into the land (flow-weighted over z) [°C]."""
    from conrod.simulation.thermal_film_run import thermal_film_orbit

    start = time.perf_counter()
    orbit = thermal_film_orbit(Simulation(conrod_case(folder, load, thermal, grid)))
    wall = time.perf_counter() - start
    cycle, film = orbit.cycle, orbit.film
    e_x, e_y = float(cycle.eccentricity_x[0]), float(cycle.eccentricity_y[0])
    flows = cycle_flows(orbit.problem, orbit.cycle)
    fed = np.maximum(flows.net_outflow(), 0.0)
    row = groove_exit_row(flows.supply)
    leaving = np.maximum(flows.east[row], 0.0)
    return {"eps": math.hypot(e_x, e_y) / CLEARANCE,
            "position_deg": math.degrees(math.atan2(e_y, e_x)) % 360.0,
            "h_min_um": float(cycle.h_min.mean()) * 1e6,
            "p_max_MPa": float(cycle.p_max.mean()) / 1e6, "t_max_C": film.hottest[0],
            "t_mean_C": film.mean_temperature, "friction_W": float(cycle.friction_power.mean()),
            "inlet_C": float(np.sum(leaving * film.temperature[row]) / np.sum(leaving)),
            "fed_groove": float(np.sum(fed[flows.supply])) * 6e4,
            "fed_elsewhere": float(np.sum(fed[~flows.supply])) * 6e4,
            "land_inflow": float(np.sum(leaving)) * 6e4,
            "eps_spread": float(np.ptp(np.hypot(cycle.eccentricity_x, cycle.eccentricity_y))
                                / CLEARANCE),
            "thermal_converged": film.converged, "wall_s": wall,
            "advective": advective_variant(flows, row, simulation_capacity(folder, load))}


def simulation_capacity(folder: Path, load: float) -> float:
    """ρ c_p of the case at the supply temperature [J/(m³ K)]."""
    lubricant = conrod_case(folder, load, False, GRID["ross"]).lubricant
    return lubricant.density_at(SUPPLY) * lubricant.specific_heat


def advective_variant(flows, row: int, heat_capacity: float) -> dict:
    """What-if of conrod's energy equation on the same flows, adiabatic: the oil the
    Swift–Stieber film gains outside the groove (where the full-film Couette flux of the
    cavitated zone grows) taken at the cell's own temperature instead of the supply
    temperature — the advective form ROSS solves. Entered as a volume change of minus that
    gain (:func:`conrod.film.thermal.energy.solve_energy`): only the groove feeds oil at
    T_0. Largest and mean temperature, temperature leaving the groove [°C]."""
    gain = np.where(flows.supply, 0.0, np.maximum(flows.net_outflow(), 0.0))
    answer = solve_energy(flows, heat_capacity, SUPPLY, ThermalWalls(0.0, 0.0, SUPPLY),
                          volume_rate=-gain)
    leaving = np.maximum(flows.east[row], 0.0)
    weights = np.ones(answer.temperature.shape[1])
    weights[[0, -1]] = 0.5
    mean = float(np.sum(answer.temperature * weights) / (weights.sum()
                                                          * answer.temperature.shape[0]))
    return {"t_max_C": float(answer.temperature.max()), "t_mean_C": mean,
            "inlet_C": float(np.sum(leaving * answer.temperature[row]) / np.sum(leaving))}


def groove_exit_row(supply: np.ndarray) -> int:
    """The last θ row of the groove in the direction of rotation (+θ): the row whose east
    face lets the mixed oil into the land."""
    rows = supply.any(axis=1)
    exits = np.flatnonzero(rows & ~np.roll(rows, -1))
    return int(exits[0])


# ------------------------------------------------------------------------ ROSS
def ross_point(load: float, thermal: bool, inlet: float, guess) -> dict:
    """The ROSS point (module docstring): the oil entering the pad at ``inlet`` [°C] (its
    reference temperature with a groove factor 1: all of it at that temperature), the Vogel
    law (or its value at the supply temperature: isoviscous)."""
    from ross.bearings.plain_journal import PlainJournal

    law = vogel if thermal else (lambda t: vogel(SUPPLY) * np.ones_like(np.asarray(t, float)))

    class VogelJournal(PlainJournal):
        """ROSS's plain journal with conrod's viscosity law."""

        @property
        def interpolate(self):
            return law

        @interpolate.setter
        def interpolate(self, value):  # ROSS's own fit, not used
            pass

    lubricant = {"temperature1": 313.15, "temperature2": 373.15,
                 "liquid_viscosity1": float(vogel(40.0)),
                 "liquid_viscosity2": float(vogel(100.0)), "liquid_density": DENSITY,
                 "liquid_specific_heat": SPECIFIC_HEAT,
                 "liquid_thermal_conductivity": CONDUCTIVITY}
    n_theta, n_z = GRID["ross"]
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        bearing = VogelJournal(
            n=0, axial_length=WIDTH, journal_radius=RADIUS, radial_clearance=CLEARANCE,
            elements_circumferential=n_theta, elements_axial=n_z, n_pad=1,
            pad_arc_length=360, preload=0, geometry="circular",
            reference_temperature=inlet, frequency=[OMEGA], fxs_load=0.0, fys_load=-load,
            lubricant=lubricant, groove_factor=[1.0], initial_guess=list(guess),
            method="perturbation", operating_type="flooded")
        wall = time.perf_counter() - start
        eps, attitude = (float(v) for v in bearing.equilibrium_pos)
        force_x, force_y = bearing._forces(bearing.equilibrium_pos, OMEGA)  # its fields there
    return {"eps": eps, "position_deg": math.degrees(attitude) % 360.0,
            "h_min_um": (1.0 - eps) * CLEARANCE * 1e6,
            "p_max_MPa": float(bearing.Pdim_last.max()) / 1e6,
            "t_max_C": float(bearing.Tdim_last.max()),
            "t_mean_C": float(bearing.Tdim_last.mean()),
            "friction_W": ross_friction(bearing), "residual_N": math.hypot(force_x,
                                                                           force_y - load),
            "wall_s": wall}


def ross_friction(bearing) -> float:
    """Friction power of ROSS's solved film [W]: Couette shear μU/h on the journal and the
    Poiseuille share (h/2) ∂p/∂x, integrated over the film, times U = ωR (ROSS reports no
    friction; computed here from its fields the way conrod's full-film convention does)."""
    n_theta, n_z = GRID["ross"]
    theta = np.asarray(bearing.theta_range[0])
    e_x, e_y = bearing.X * CLEARANCE, bearing.Y * CLEARANCE
    h = CLEARANCE - e_x * np.cos(theta) - e_y * np.sin(theta)
    pressure = bearing.Pdim_last[:, :, 0]  # (n_z, n_θ)
    viscosity = bearing.interpolate(bearing.Tdim_last[:, :, 0])
    speed = OMEGA * RADIUS
    d_x = RADIUS * (theta[1] - theta[0])
    gradient = (np.roll(pressure, -1, axis=1) - np.roll(pressure, 1, axis=1)) / (2 * d_x)
    shear = viscosity * speed / h[None, :] + 0.5 * h[None, :] * gradient
    area = d_x * WIDTH / n_z
    return float(np.sum(shear) * area * speed)


# ------------------------------------------------------------------------ table
QUANTITIES = (("ε [-]", "eps", "{:.4f}"), ("journal position [deg]", "position_deg", "{:.1f}"),
              ("h_min [µm]", "h_min_um", "{:.2f}"), ("p_max [MPa]", "p_max_MPa", "{:.2f}"),
              ("T_max [°C]", "t_max_C", "{:.1f}"), ("T_mean [°C]", "t_mean_C", "{:.1f}"),
              ("friction power [W]", "friction_W", "{:.1f}"))


def rows_of(load: float, label: str, mine: dict, fine: dict, theirs: dict) -> list[str]:
    out = []
    for name, key, fmt in QUANTITIES:
        a, b = mine[key], theirs[key]
        if key in ("t_max_C", "t_mean_C"):
            diff = f"{a - b:+.1f} K"
        elif key == "position_deg":
            diff = f"{a - b:+.1f}°"
        else:
            diff = f"{a / b - 1:+.1%}"
        out.append(f"| {load:g} | {label} | {name} | {fmt.format(a)} | {fmt.format(fine[key])} "
                   f"| {fmt.format(b)} | {diff} |")
    return out


def main() -> None:
    import tempfile

    coarse, fine = GRID["ross"], GRID["conrod"]
    lines = ["# A steady thermal plain journal bearing: conrod against ROSS", "",
             f"`python benchmarks/ross_thd_comparison.py` on {platform.processor() or 'cpu'}, "
             f"{os.cpu_count()} cores (shared), Python {platform.python_version()}, ROSS "
             f"{ross_version()}; the bearing and both models in the script's docstring. "
             f"conrod Reynolds {coarse[0]} × {coarse[1]} and {fine[0]} × {fine[1]} intervals, "
             f"ROSS {coarse[0]} × {coarse[1]} cells (ROSS at 72 × 16 takes 155 s a point).", "",
             f"| load [N] | viscosity | quantity | conrod {coarse[0]}×{coarse[1]} | conrod "
             f"{fine[0]}×{fine[1]} | ROSS {coarse[0]}×{coarse[1]} | conrod {coarse[0]}×"
             f"{coarse[1]} vs ROSS |", "| --- | --- | --- | --- | --- | --- | --- |"]
    notes, advective = [], []
    for load in LOADS:
        for thermal in (False, True):
            mine = conrod_point(Path(tempfile.mkdtemp()), load, thermal, coarse)
            finer = conrod_point(Path(tempfile.mkdtemp()), load, thermal, fine)
            guess = (mine["eps"], math.radians(mine["position_deg"]) - 2 * math.pi)
            label = "μ(T) thermal" if thermal else "isoviscous (90 °C)"
            try:
                theirs = ross_point(load, thermal, mine["inlet_C"], guess)
            except ZeroDivisionError:  # its equilibrium search reached ε = 1
                notes.append(f"| {load:g} | {label} | ROSS failed (division by zero in its "
                             "energy equation: its equilibrium search reached ε = 1) |")
                continue
            lines += rows_of(load, label, mine, finer, theirs)
            if not thermal:
                variant = mine["advective"]
                alike = ross_point(load, False, variant["inlet_C"], guess)
                advective.append(
                    f"| {load:g} | {variant['inlet_C']:.1f} | {variant['t_max_C']:.1f} | "
                    f"{alike['t_max_C']:.1f} | {variant['t_max_C'] - alike['t_max_C']:+.1f} K "
                    f"| {variant['t_mean_C']:.1f} | {alike['t_mean_C']:.1f} | "
                    f"{variant['t_mean_C'] - alike['t_mean_C']:+.1f} K |")
            notes.append(
                f"| {load:g} | {label} | {mine['inlet_C']:.2f} | {mine['land_inflow']:.3f} | "
                f"{mine['fed_groove']:.3f} / {mine['fed_elsewhere']:.3f} | "
                f"{mine['eps_spread']:.1e} | {mine['thermal_converged'] if thermal else '–'} | "
                f"{theirs['residual_N']:.2g} | {mine['wall_s']:.1f} | {theirs['wall_s']:.1f} |")
            print("\n".join(lines[-7:]), notes[-1], sep="\n", flush=True)
    lines += ["", "| load [N] | viscosity | inlet temperature (conrod, given to ROSS) [°C] | "
              "flow into the land [l/min] | conrod's supply oil fed at T_0: groove / "
              "cavitated zone [l/min] | conrod ε spread over the cycle [-] | conrod "
              "thermal converged | ROSS force residual [N] | conrod wall [s] | ROSS wall [s] |",
              "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"] + notes
    lines += ["", "Isoviscous, the energy equations alone: conrod's equation on its own "
              f"{coarse[0]} × {coarse[1]} flows with the oil its cavitated zone gains taken at "
              "the cell's temperature (only the groove feeds supply oil — ROSS's advective "
              "form), ROSS with that variant's groove exit temperature as its inlet.", "",
              "| load [N] | inlet [°C] | T_max conrod variant [°C] | T_max ROSS [°C] | "
              "difference | T_mean conrod variant [°C] | T_mean ROSS [°C] | difference |",
              "| --- | --- | --- | --- | --- | --- | --- | --- |"] + advective
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


def ross_version() -> str:
    from importlib.metadata import version

    return version("ross-rotordynamics")


if __name__ == "__main__":
    main()
