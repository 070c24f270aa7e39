"""Cost and answers of the thermal film (``[solver] thermal = "film"``, docs/thermal.md)
against the global heat balance, on the KamAZ-740-like big end.

Run:  python benchmarks/thermal_benchmarks.py   (writes benchmarks/thermal_benchmarks.md)
      python benchmarks/thermal_benchmarks.py --elastic
                                                (writes benchmarks/thermal_benchmarks_elastic.md)

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

``--elastic``: the same on the elastic rod of ``[housing]`` (Reynolds 72 × 16, no rigid
companion run), after a coarse warm-up:

* examples/kamaz_740_truck_diesel_tehd.toml without its ``[housing.assembly]`` and
  ``[housing.thermal]``, ``thermal = "heat_balance"`` and ``"film"``: the cost of the thermal
  film on the elastic bore (target ≤ 2×);
* the TEHD example as shipped: assembled, the bore warm from the film's temperatures;
* the KamAZ example (constant viscosity) elastic with the thermal film, and elastic +
  assembly (75 kN, 40 µm) + the bore warm from the film: the README's side-by-side rows.
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
    write_table(OUTPUT, "# Thermal film: cost and answers", "",
                "Reynolds 72 × 16, rigid bore, one run each after a coarse warm-up of each mode.",
                header, [row(*r) for r in runs],
                f"Cost of the thermal film on the thermal example: **{ratio:.2f}× wall, "
                f"{cpu_ratio:.2f}× CPU** of the heat-balance run (target ≤ 2×).")


def write_table(path, title: str, option: str, setting: str, header, rows, cost: str) -> None:
    """The benchmark's markdown page (title, machine line, table, cost line), written and
    printed."""
    lines = [title, "",
             f"`python benchmarks/thermal_benchmarks.py{option}` on "
             f"{platform.processor() or 'cpu'}, {os.cpu_count()} cores (shared), Python "
             f"{platform.python_version()}; {setting}",
             "", "| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    lines += ["", cost]
    write_text(path, "\n".join(lines) + "\n")
    print("\n".join(lines))


def elastic_case(name: str, drop: tuple[str, ...] = (), housing: dict | None = None,
                 **solver) -> Case:
    data = tomllib.loads((EXAMPLES / name).read_text())
    data["solver"] = {**data.get("solver", {}), "film": "reynolds", **solver}
    for key in drop:
        data["housing"].pop(key, None)
    data["housing"].update(housing or {})
    return Case.from_dict(data, base_dir=EXAMPLES)


def elastic_row(label: str, results, wall: float, cpu: float) -> tuple[str, ...]:
    elastic = results.elastic
    warm = elastic.thermal_film.warm_bore if elastic.thermal_film is not None else None
    bore = ("–" if warm is None else f"{warm.clearance_change * 1e6:+.2f} / "
            f"{warm.out_of_round * 1e6:.2f} ({warm.journal_temperature:.1f}, "
            f"{warm.shell_side_temperature.min():.1f}–{warm.shell_side_temperature.max():.1f},"
            f" {warm.housing_temperature:.1f})")
    thermal = elastic.thermal_film
    iterations = "–" if thermal is None else f"{thermal.iterations}"
    joint = (results.info or {}).get("joint_over_run")
    joint = "–" if joint is None else ("opens" if joint["opens"] else "closed")
    return (*row(label, elastic, wall, cpu)[:-2], f"{elastic.clearance * 1e6:.2f}", bore,
            joint, iterations, f"{elastic.summary.cycles}", f"{wall:.1f} / {cpu:.1f}")


def main_elastic() -> None:
    grid = {"n_theta": 72, "n_z": 16}
    tehd = "kamaz_740_truck_diesel_tehd.toml"
    plain = "kamaz_740_truck_diesel.toml"
    bare = ("assembly", "thermal")
    for mode in ("heat_balance", "film"):  # warm-up: compile every kernel
        Simulation(elastic_case(tehd, bare, n_theta=36, n_z=8, thermal=mode),
                   rigid_companion=False).run()
    runs = [(f"TEHD example elastic, no assembly, thermal = {mode!r}",
             *timed(Simulation(elastic_case(tehd, bare, **grid, thermal=mode),
                               rigid_companion=False))) for mode in ("heat_balance", "film")]
    runs.append(("TEHD example as shipped: elastic + assembly + thermal film (TEHD)",
                 *timed(Simulation(elastic_case(tehd, **grid), rigid_companion=False))))
    runs.append(("KamAZ example, elastic, thermal film",
                 *timed(Simulation(elastic_case(plain, **grid, thermal="film"),
                                   rigid_companion=False))))
    assembled = {"assembly": {"bolt_preload": 75.0e3, "crush_height": 40.0e-6},
                 "thermal": {}}
    runs.append(("KamAZ example, elastic + assembly + thermal film (TEHD)",
                 *timed(Simulation(elastic_case(plain, housing=assembled, **grid,
                                                thermal="film"), rigid_companion=False))))
    ratio, cpu_ratio = runs[1][2] / runs[0][2], runs[1][3] / runs[0][3]
    header = ("run", "h_min [µm]", "p_max [MPa]", "film max temperature [°C] (where)",
              "journal / shell [°C]", "friction power [W]",
              "heat [W] = oil + journal + shell", "warm clearance [µm]",
              "bore from the film: Δc / thermal out-of-round [µm] (T_j, T_b range, housing "
              "mean [°C])", "joint over the run", "thermal iterations", "cycles",
              "wall / CPU [s]")
    write_table(OUTPUT.with_name("thermal_benchmarks_elastic.md"),
                "# Thermal film on the elastic bore (TEHD): cost and answers", " --elastic",
                "Reynolds 72 × 16 on the built-in elastic rod, no rigid companion run, one run "
                "each after a coarse warm-up of each mode.", header,
                [elastic_row(*r) for r in runs],
                f"Cost of the thermal film on the elastic bore (TEHD example without assembly "
                f"and warm bore): **{ratio:.2f}× wall, {cpu_ratio:.2f}× CPU** of the elastic "
                "heat-balance run (target ≤ 2×).")


if __name__ == "__main__":
    import sys

    main_elastic() if "--elastic" in sys.argv[1:] else main()
