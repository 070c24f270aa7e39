"""Cost and answers of the thermal film (``[solver] thermal = "film"``, docs/thermal.md)
against the global heat balance, on the KamAZ-740-like big end.

Run:  python benchmarks/thermal_benchmarks.py   (writes benchmarks/thermal_benchmarks.md)

Runs, one each, in one process, Reynolds film 72 × 16, rigid bore, after a coarse warm-up
run of each mode (so that numba compiling is not timed):

* the thermal example (examples/kamaz_740_truck_diesel_thermal.toml: SAE 30 with its
  Walther law, 3 bar through a shell feed hole) with ``thermal = "heat_balance"`` and with
  ``thermal = "film"`` — the cost ratio (target ≤ 2×) and what the temperature field
  changes;
* the KamAZ example itself (examples/kamaz_740_truck_diesel.toml, constant viscosity, no
  feed) on a rigid bore with the thermal film: the README's side-by-side row (the
  viscosity does not depend on temperature there, so h_min and p_max are those of the
  rigid row; the film adds the temperature field).
"""

from __future__ import annotations

import os
import platform
import time
import tomllib
from pathlib import Path

from conrod.cases.case import Case
from conrod.io.atomic import write_text
from conrod.simulation.simulation import Simulation

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"
OUTPUT = Path(__file__).with_suffix(".md")


def case(name: str, **solver) -> Case:
    data = tomllib.loads((EXAMPLES / name).read_text())
    data["solver"] = {**data.get("solver", {}), **solver}
    return Case.from_dict(data, base_dir=EXAMPLES)


def timed(sim: Simulation):
    wall, cpu = time.perf_counter(), time.process_time()
    results = sim.run()
    return results, time.perf_counter() - wall, time.process_time() - cpu


def row(label: str, results, wall: float, cpu: float) -> tuple[str, ...]:
    s = results.summary
    thermal = results.thermal_film
    if thermal is None:
        hottest, walls, heat = f"{s.effective_temperature:.1f} (effective)", "–", "–"
    else:
        t, theta, z = thermal.hottest
        hottest = f"{t:.1f} at {theta * 57.29577951308232:.0f}°, {z * 1e3:.1f} mm"
        walls = f"{thermal.journal_temperature:.1f} / {thermal.shell_temperature:.1f}"
        heat = (f"{thermal.generated:.0f} = {thermal.to_oil:.0f} + {thermal.to_journal:.0f} "
                f"+ {thermal.to_shell:.0f}")
    return (label, f"{s.h_min * 1e6:.3f}", f"{s.p_max / 1e6:.1f}", hottest, walls,
            f"{s.mean_friction_power:.0f}", heat, f"{s.cycles}", f"{wall:.1f} / {cpu:.1f}")


def main() -> None:
    grid = {"n_theta": 72, "n_z": 16}
    thermal = "kamaz_740_truck_diesel_thermal.toml"
    for mode in ("heat_balance", "film"):  # warm-up: compile every kernel
        Simulation(case(thermal, n_theta=24, n_z=8, thermal=mode)).run()
    runs = []
    for mode in ("heat_balance", "film"):
        runs.append((f"thermal example, thermal = {mode!r}",
                     *timed(Simulation(case(thermal, **grid, thermal=mode)))))
    plain = "kamaz_740_truck_diesel.toml"
    for mode in ("heat_balance", "film"):
        runs.append((f"KamAZ example, rigid bore, thermal = {mode!r}",
                     *timed(Simulation(case(plain, **grid, thermal=mode), film="reynolds",
                                       housing="rigid"))))
    ratio = runs[1][2] / runs[0][2]
    cpu_ratio = runs[1][3] / runs[0][3]
    header = ("run", "h_min [µm]", "p_max [MPa]", "film max temperature [°C] (where)",
              "journal / shell [°C]", "friction power [W]",
              "heat [W] = oil + journal + shell", "cycles", "wall / CPU [s]")
    lines = ["# Thermal film: cost and answers", "",
             f"`python benchmarks/thermal_benchmarks.py` on {platform.processor() or 'cpu'}, "
             f"{os.cpu_count()} cores (shared), Python {platform.python_version()}; "
             "Reynolds 72 × 16, rigid bore, one run each after a coarse warm-up of each mode.",
             "", "| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    lines += ["| " + " | ".join(row(*r)) + " |" for r in runs]
    lines += ["", f"Cost of the thermal film on the thermal example: **{ratio:.2f}× wall, "
              f"{cpu_ratio:.2f}× CPU** of the heat-balance run (target ≤ 2×)."]
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
