"""Cycles to a periodic orbit on every shipped example, by cycle-start strategy.

Run from the repository root:  python benchmarks/periodic_benchmarks.py [EXAMPLE_STEM ...]
[--elastic] (``--elastic``: the examples on an elastic Reynolds bore, see SAME_AS)
Writes benchmarks/periodic_benchmarks.md (rows of the examples measured replace those of
an earlier run). For each example the orbit at the supply viscosity (no heat balance) is
made periodic from the concentric start with the case's own integrator and film by

* ``plain``: cycles repeated from where the last one ended (``accelerate_cycles`` and
  ``massless_start`` off);
* ``main``: the default settings before the shooting accelerator (massless start and
  Anderson extrapolation, ``periodic_accelerator = "anderson"``);
* ``shooting``: ``periodic_accelerator = "shooting"`` from the massless start (the
  default until the massless start was turned off) and from the concentric one
  (``massless_start`` off: the default now).

Each column gives the cycles integrated with mass (massless cycles of the massless start
in brackets; on an elastic bore the shooting's half-cycle lead-in counts 0.5,
``[solver] lead_in``), the periodicity error of the accepted cycle [-] and the wall time [s] (numba
compilation excluded: a warm-up cycle runs first). The last column: max |Δe|/c between the
accepted cycle of ``shooting`` and of ``plain`` at equal output angles [-] (the
periodicity tolerance is 1e-3). Grids coarsened where named (to keep runs short on a
shared 2-core machine).
"""

from __future__ import annotations

import contextlib
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "benchmarks" / "periodic_benchmarks.md"

EXAMPLES = {
    # stem: [solver] overrides (coarsened grids), note
    "flores2006_table_load": ({}, ""),
    "passenger_car_diesel_1000rpm": ({}, ""),
    "passenger_car_diesel_2000rpm": ({}, ""),
    "passenger_car_diesel_2000rpm_5w30_piezoviscous": ({}, ""),
    "ruston_hornsby_6vebx_mk3": ({}, ""),
    "passenger_car_diesel_2000rpm_reynolds": ({"n_theta": 36, "n_z": 8}, "36×8"),
    "passenger_car_diesel_2000rpm_crank_fed": ({"n_theta": 36, "n_z": 8}, "36×8"),
    "kamaz_740_truck_diesel": ({}, ""),
    "kamaz_740_truck_diesel_tilt": ({"n_theta": 36, "n_z": 8}, "36×8"),
    "kamaz_740_solid_big_end": ({"n_theta": 36, "n_z": 8}, "36×8 (EHD)"),
}
STRATEGIES = {
    "plain": {"accelerate_cycles": False, "massless_start": False},
    "main": {"periodic_accelerator": "anderson", "massless_start": True},
    "shooting": {"periodic_accelerator": "shooting", "massless_start": True},
    "shooting, concentric start": {"periodic_accelerator": "shooting", "massless_start": False},
}
MAX_CYCLES = 16


def measure(stem: str, overrides: dict, strategy: dict) -> dict:
    """Cycles, error, wall time and the accepted cycle of one run."""
    from conrod import Case, Simulation
    from conrod.orbit import periodic as periodic_module

    case = Case.from_toml(ROOT / "examples" / f"{stem}.toml")
    sim = Simulation(case, max_cycles=MAX_CYCLES, **overrides, **strategy)
    problem = sim.problem()
    massless: list[int] = []
    original = periodic_module._massless_start

    def counted(problem, settings):
        orbit = periodic_module.periodic_orbit(problem, settings, integrator="quasi_static")
        massless.append(orbit.cycles)
        return orbit.last.end_state

    periodic_module._massless_start = counted
    try:
        sim_warm = Simulation(case, max_cycles=1, min_cycles=1, **overrides)
        periodic_module.integrate_cycle(sim_warm.problem(), _start(), sim_warm.solver,
                                        sim_warm.integrator())
        if strategy.get("massless_start", False):
            with contextlib.suppress(Exception):  # the massless start's integrator too
                periodic_module.integrate_cycle(sim_warm.problem(), _start(), sim_warm.solver,
                                                "quasi_static")
        massless.clear()
        start = time.perf_counter()
        orbit = periodic_module.periodic_orbit(problem, sim.solver, integrator=sim.integrator())
        wall = time.perf_counter() - start
    finally:
        periodic_module._massless_start = original
    return {"cycles": orbit.cycles_run, "massless": sum(massless), "error": orbit.periodicity_error,
            "periodic": orbit.periodic, "wall": wall, "history": orbit.history,
            "x": orbit.last.x, "y": orbit.last.y, "c": problem.clearance}


def _start():
    from conrod.orbit.problem import initial_state

    return initial_state()


def _cell(run: dict) -> str:
    if "same" in run:
        return f"as {run['same']} (same run)"
    mark = "" if run["periodic"] else " (not periodic)"
    extra = f" (+{run['massless']})" if run["massless"] else ""
    return f"{run['cycles']:g}{extra}{mark}, {run['error']:.1e}, {run['wall']:.3g} s"


SAME_AS = {"main": "plain", "shooting, concentric start": "shooting"}
"""With ``--elastic``: on an elastic Reynolds bore main accelerates nothing (plain) and
no massless start is made (shooting from the concentric start): those columns are
not run again."""


def main(stems: list[str]) -> None:
    rows = _existing()
    elastic = "--elastic" in stems
    stems = [s for s in stems if s != "--elastic"]
    for stem in stems or list(EXAMPLES):
        overrides, note = EXAMPLES[stem]
        runs = {}
        for name, strategy in STRATEGIES.items():
            if elastic and name in SAME_AS:
                runs[name] = {**runs[SAME_AS[name]], "same": SAME_AS[name]}
                continue
            try:
                runs[name] = measure(stem, overrides, strategy)
            except Exception as error:  # noqa: BLE001 - a failing example is a row, not a stop
                runs[name] = {"failed": f"{type(error).__name__}: {str(error)[:80]}"}
            print(stem, name, {k: v for k, v in runs[name].items()
                               if k not in ("x", "y")}, flush=True)
        rows[stem] = _row(stem, note, runs)
        _write(rows)


def _row(stem: str, note: str, runs: dict) -> str:
    cells = [runs[n].get("failed") or _cell(runs[n]) for n in STRATEGIES]
    a, b = runs.get("shooting", {}), runs.get("plain", {})
    diff = "–"
    if "x" in a and "x" in b:
        diff = f"{float(np.max(np.hypot(a['x'] - b['x'], a['y'] - b['y'])) / a['c']):.1e}"
    return f"| {stem} | {note or 'as shipped'} | " + " | ".join(cells) + f" | {diff} |"


def _existing() -> dict:
    rows = {}
    if OUT.exists():
        for line in OUT.read_text().splitlines():
            parts = line.split("|")
            if len(parts) > 2 and parts[1].strip() in EXAMPLES:
                rows[parts[1].strip()] = line
    return rows


def _write(rows: dict) -> None:
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    lines = [
        "# Cycles to a periodic orbit on the shipped examples",
        "",
        f"Machine: {platform.processor() or platform.machine()}, {os.cpu_count()} cores "
        f"(shared; load {load:.1f} when written), Python {platform.python_version()}. "
        "`python benchmarks/periodic_benchmarks.py`. Orbit at the supply viscosity, "
        "no heat balance; each cell: cycles with mass (+ massless cycles of the massless "
        "start), periodicity error of the accepted cycle [-], wall time (warm). "
        "Last column: max |Δe|/c between the accepted cycles of shooting and plain.",
        "",
        "| example | grid | plain (repeat) | main (massless start + Anderson) | "
        "shooting (massless start) | shooting, concentric start (default) | "
        "Δ shooting vs plain |",
        "|---|---|---|---|---|---|---|",
    ]
    lines += [rows[s] for s in EXAMPLES if s in rows]
    OUT.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(sys.argv[1:])
