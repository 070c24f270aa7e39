"""Clearance-mechanism benchmarks: run and sweep times, accuracy vs tolerance, and
the in-house compiled integrator against SciPy's stiff/non-stiff solvers on the same RHS.

Run:  python benchmarks/mechanism_benchmarks.py   (writes benchmarks/mechanism_benchmarks.md)

Case: ``examples/kulayev_worn_rod_bearings.toml`` (3000 rpm, load 0.5, 3 cycles).
Times are wall-clock on whatever machine runs this (numba compiled and cached first).
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import replace
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from conrod.cases.case import Case
from conrod.io.atomic import write_text
from conrod.mechanism import integrator as rk
from conrod.mechanism.kernel import mechanism_rhs
from conrod.mechanism.model import seed_initial_state
from conrod.mechanism.setup import mechanism_case
from conrod.mechanism.simulation import error_scale, simulate
from conrod.sweep.mechanism import run_sweep

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "kulayev_worn_rod_bearings.toml"
OUTPUT = Path(__file__).with_suffix(".md")


def timed(function, repeat: int = 3):
    """(best wall time [s], last result) over ``repeat`` calls."""
    best, result = math.inf, None
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        best = min(best, time.perf_counter() - start)
    return best, result


def run_table(base) -> list[str]:
    lines = ["| tolerance | steps (rejected) | time [s] | energy residual (rel.) | "
             "v_max big / small [m/s] | impacts/cycle |", "| --- | --- | --- | --- | --- | --- |"]
    for tolerance in (1e-3, 1e-4, 1e-5, 1e-6):
        settings = replace(base.settings, tolerance=tolerance)
        seconds, results = timed(lambda s=settings: simulate(
            base.mechanism, base.scaled_gas_table(), s))
        summary = results.summary()
        lines.append(
            f"| {tolerance:g} | {results.steps} ({results.rejected_steps}) | {seconds:.2f} | "
            f"{summary['energy_residual_relative']:.2e} | "
            f"{summary['max_impact_velocity_big_end_m_s']:.4f} / "
            f"{summary['max_impact_velocity_small_end_m_s']:.4f} | "
            f"{summary['impacts_per_cycle']:g} |")
    return lines


def solver_table(base) -> list[str]:
    """First 90° of the example: in-house DOPRI5 vs solve_ivp on the same numba RHS."""
    mechanism, table = base.mechanism, base.scaled_gas_table()
    p = mechanism.parameters()
    y0 = seed_initial_state(mechanism, float(table[0]))
    end = math.radians(90.0)
    scale = error_scale(mechanism, 1e-6)
    seconds, ours = timed(lambda: rk.integrate(
        y0, 0.0, end, p, table, scale, 1e-5, math.radians(0.25), True, np.array([end]),
        np.array([3e-7, 1e-7]), 10**8, 1000))
    reference = solve_ivp(lambda a, y: mechanism_rhs(a, y, p, table), (0.0, end), y0,
                          method="DOP853", rtol=1e-12, atol=1e-15, max_step=5e-5)
    lines = ["| solver | settings | time [s] | RHS calls | piston error vs DOP853 1e-12 [m] |",
             "| --- | --- | --- | --- | --- |",
             f"| conrod DOPRI5 (numba) | tolerance 1e-6 | {seconds:.3f} | {7 * ours[3]} | "
             f"{abs(ours[0][0, 6] - reference.y[6, -1]):.1e} |"]
    atol = np.abs(scale[:8]).min()
    for method in ("RK45", "LSODA", "Radau"):
        start = time.perf_counter()
        solution = solve_ivp(lambda a, y: mechanism_rhs(a, y, p, table), (0.0, end), y0,
                             method=method, rtol=1e-9, atol=atol, max_step=math.radians(0.25))
        seconds = time.perf_counter() - start
        error = abs(solution.y[6, -1] - reference.y[6, -1])
        lines.append(f"| scipy {method} | rtol 1e-9, atol {atol:.0e} | {seconds:.2f} | "
                     f"{solution.nfev} | {error:.1e} |")
    return lines


def sweep_lines(base) -> list[str]:
    speeds, loads = np.linspace(1000, 3000, 9), np.linspace(0.5, 1.0, 3)
    lines = ["| cycles | runs | wall time [s] | most informative regime |",
             "| --- | --- | --- | --- |"]
    for cycles in (2, 3):
        run = replace(base, settings=replace(base.settings, cycles=cycles))
        seconds, sweep = timed(lambda r=run: run_sweep(r, speeds, loads), repeat=1)
        best = sweep.best()
        lines.append(f"| {cycles} | {speeds.size * loads.size} | {seconds:.1f} | "
                     f"{best['speed_rpm']:g} rpm, load {best['load_scale']:g}, "
                     f"Δv = {best['impact_velocity_excess_m_s']:.3f} m/s |")
    return lines


def main() -> None:
    base = mechanism_case(Case.from_toml(EXAMPLE))
    simulate(base.mechanism, base.scaled_gas_table(), base.settings)  # compile / load cache
    text = ["# Clearance-mechanism benchmarks", "",
            f"Python {sys.version.split()[0]}; case `{EXAMPLE.name}`; "
            "regenerate with `python benchmarks/mechanism_benchmarks.py`.", "",
            "## One run (3 cycles) vs tolerance", "", *run_table(base), "",
            "## Integrators on the first 90° (same compiled right-hand side)", "",
            *solver_table(base), "",
            "## Sweep speed 1000:3000:9 × load 0.5:1.0:3", "", *sweep_lines(base), ""]
    write_text(OUTPUT, "\n".join(text))
    print("\n".join(text))


if __name__ == "__main__":
    main()
