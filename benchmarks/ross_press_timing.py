"""ROSS 3.1 side of the film benchmark (runs in ROSS's own Python ≥ 3.13 environment).

Usage (called by film_benchmarks.py):  python ross_press_timing.py N_THETA N_Z REPEATS

Prints one JSON line: the median and all CPU times [s] of ROSS's finite-element pressure
solve (``ross.bearings.fluid_film.pressure.press``, banded LU with the Reynolds cavitation
clamp in back substitution) at the converged fixed journal position, and the film load [N].

Bearing: D = 50 mm, L = 25 mm, c = 25 µm, μ = 0.02 Pa s (isoviscous), 200 rad/s, journal
held at ε = 0.6 (``equilibrium_type="match_eccentricity"``), cavitation at 0 Pa gauge,
ambient 0 Pa at both edges. ROSS's mesh: N_THETA × N_Z film elements.

The bore is one land of 2π − 1e-5 rad, not 2π: for a land of exactly 360° ROSS 3.1 sets the
circumferential conductance k_x to zero (``press_assemble_all_jit``, ``if is_360: k_x =
0.0``), i.e. it solves the short-bearing (Ocvirk) equation — parabolic in z, 3192 N here
against the Ocvirk closed form 3182 N. A land 1e-5 rad short of the circle keeps the full
Reynolds operator; its one edge (p = 0, at θ = 0 of ROSS's frame) lies inside the
cavitated zone (θ ≈ 270°–90° for this journal position), so the problem is the 360°
Swift–Stieber film that conrod solves.
"""

from __future__ import annotations

import json
import math
import sys
import time
import warnings

import numpy as np

LAND_ARC = 2.0 * math.pi - 1.0e-5
"""Arc of the one land [rad]: just short of 2π (see the module docstring)."""


def main() -> None:
    n_theta, n_z, repeats = (int(arg) for arg in sys.argv[1:4])
    warnings.simplefilter("ignore")
    from ross.bearings.fluid_film import pressure
    from ross.bearings.plain_journal import PlainJournal

    original = pressure.press
    times: list[float] = []

    def timed_press(*args, **kwargs):
        start = time.process_time()
        out = original(*args, **kwargs)
        times.append(time.process_time() - start)
        return out

    pressure.press = timed_press
    viscosity = 0.02
    lubricant = {
        "liquid_viscosity1": viscosity, "temperature1": 313.15,
        "liquid_viscosity2": viscosity, "temperature2": 373.15,
        "liquid_density": 860.0, "liquid_specific_heat": 1950.0,
        "liquid_thermal_conductivity": 0.13, "vapour_viscosity": 9e-6,
        "vapour_density": 0.029, "vapour_specific_heat": 1000.0,
        "vapour_thermal_conductivity": 0.026, "saturation_pressure": 1e5,
        "surface_tension": 0.04, "molecular_weight": 500.0,
    }
    eps, angle = 0.6, -0.5 * math.pi
    loads = []
    for repeat in range(repeats + 1):  # the first one compiles ROSS's kernels
        if repeat == 1:
            times.clear()
        bearing = PlainJournal(
            n=0, pad_axial_length=0.025, journal_diameter=0.05, radial_clearance=2.5e-5,
            n_pads=1, pad_arc=LAND_ARC, oil_supply_temperature=313.15, speed=[200.0],
            fys_load=-1000.0, lubricant=lubricant,
            initial_position=(eps * math.cos(angle), eps * math.sin(angle)),
            oil_flow_v=1e-2, thermal_type=None, equilibrium_type="match_eccentricity",
            total_ex_film=n_theta, total_ez_film=n_z, cavitation_pressure=0.0,
        )
        loads.append(_load(bearing))
    print(json.dumps({"grid": [n_theta, n_z], "median": float(np.median(times)),
                      "times": times, "load": loads[-1]}))


def _load(bearing) -> float:
    """|F| [N]: ROSS's own film force (``fx_hydro``, ``fy_hydro`` of its outputs)."""
    outputs = bearing._results.outputs[0]
    return float(math.hypot(outputs["fx_hydro"][0], outputs["fy_hydro"][0]))


if __name__ == "__main__":
    main()
