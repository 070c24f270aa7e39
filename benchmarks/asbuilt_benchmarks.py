"""The big end as built: cost of the assembled bore and the KamAZ-740 example side by side
(rigid / elastic / elastic + assembly / elastic + assembly + warm journal and housing).

Run:  python benchmarks/asbuilt_benchmarks.py [--no-runs]
      (writes benchmarks/asbuilt_benchmarks.md)

Rod: the KamAZ-740 example's built-in housing (examples/kamaz_740_truck_diesel.toml) with
75 kN per bolt and 40 µm crush (the example's commented ``[housing.assembly]``), and for the
last row the journal at 105 °C and the housing at 95 °C (``[housing.thermal]``). Build times
are medians of 3 fresh builds (no cache); the runs are one each, Reynolds film 72 × 16,
the example's own orbit settings, in one process one after the other.
"""

from __future__ import annotations

import os
import platform
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.housing.conduction import Cooling
from conrod.housing.housing import Housing
from conrod.housing.thermal import field_bore
from conrod.io.atomic import write_text
from conrod.simulation.simulation import Simulation

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "kamaz_740_truck_diesel.toml"
OUTPUT = Path(__file__).with_suffix(".md")
ASSEMBLY = {"bolt_preload": 75.0e3, "crush_height": 40.0e-6}
WARM = {"journal_temperature": 105.0, "housing_temperature": 95.0}
"""Mean running temperatures of the warm row: journal and housing a few kelvin either side
of the heat balance's effective film temperature (about 100 °C) [degC]."""


def kamaz(n_theta: int = 72, assembly: dict | None = None, warm: dict | None = None) -> Case:
    data = tomllib.loads(EXAMPLE.read_text())
    data["solver"] = {**data.get("solver", {}), "n_theta": n_theta}
    if assembly is not None:
        data["housing"]["assembly"] = assembly
    if warm is not None:
        data["housing"]["thermal"] = warm
    return Case.from_dict(data, base_dir=EXAMPLE.parent)


def build_rows(n_theta: int) -> list[tuple[str, ...]]:
    plain, assembled = [], []
    for _ in range(3):
        start = time.perf_counter()
        Housing.from_case(kamaz(n_theta), use_cache=False)
        plain.append(time.perf_counter() - start)
        start = time.perf_counter()
        housing = Housing.from_case(kamaz(n_theta, ASSEMBLY), use_cache=False)
        assembled.append(time.perf_counter() - start)
    own = housing.info["assembly_seconds"]
    with tempfile.TemporaryDirectory() as folder:
        Housing.from_case(kamaz(n_theta, ASSEMBLY), cache_dir=folder)
        start = time.perf_counter()
        cached = Housing.from_case(kamaz(n_theta, ASSEMBLY), cache_dir=folder)
        from_cache = time.perf_counter() - start
        assert cached.info["assembly_from_cache"]
    conducting = kamaz(n_theta, warm={"journal_temperature": 105.0,
                                      "shell_temperature_angles": [0.0, 90.0, 180.0, 270.0],
                                      "shell_temperatures": [125.0, 115.0, 118.0, 115.0],
                                      "ambient_temperature": 90.0}).housing.thermal
    structure = housing.structure
    cooling = Cooling(conducting.conductivity, conducting.surface_heat_transfer,
                      conducting.ambient_temperature)
    times = []
    for _ in range(3):
        start = time.perf_counter()
        field_bore(structure, conducting, cooling)
        times.append(time.perf_counter() - start)
    return [(f"housing build, {n_theta} film nodes, without / with the assembly",
             f"{np.median(plain):.2f} / {np.median(assembled):.2f} s", "–",
             f"{housing.info['n_dofs']} unknowns"),
            (f"assembly load case alone, {n_theta} film nodes", f"{own:.2f} s", "≤ 2 s",
             "bolt bands, crush, joint operator and its influence of the film nodes"),
            (f"housing with its assembly from the cache, {n_theta} film nodes",
             f"{from_cache * 1e3:.0f} ms", "–", "two npz files"),
            (f"conducting housing (temperature field + thermal load), {n_theta} film nodes",
             f"{np.median(times):.2f} s", "–", "conduction, its thermal load and one solve")]


def run_row(label: str, case: Case, housing: str | None) -> tuple[str, ...]:
    start = time.perf_counter()
    extra = {} if housing is None else {"housing": housing}
    results = Simulation(case, film="reynolds", n_theta=72, n_z=16, rigid_companion=False,
                         **extra).run()
    seconds = time.perf_counter() - start
    summary = getattr(results, "elastic", results).summary
    temperature = summary.effective_temperature
    info = getattr(results, "info", {}) or {}
    joint = info.get("joint_over_run")
    opens = "–" if joint is None else (
        f"opens at {joint['at_crank_angle_deg']:.0f}° (outer {joint['open_share_of_joint']:.0%})"
        if joint["opens"] else "closed")
    clearance = Simulation(case, film="reynolds", n_theta=72, n_z=16, **extra).geometry()
    return (label, f"{clearance.radial_clearance * 1e6:.1f}", f"{summary.h_min * 1e6:.3f}",
            f"{summary.p_max / 1e6:.1f}", "–" if temperature is None else f"{temperature:.1f}",
            f"{summary.mean_friction_power:.0f}", opens, f"{seconds:.0f}")


def table(header: tuple[str, ...], rows: list[tuple[str, ...]]) -> list[str]:
    return ["| " + " | ".join(header) + " |", "| " + " | ".join("---" for _ in header) + " |",
            *("| " + " | ".join(row) + " |" for row in rows)]


def main() -> None:
    lines = ["# The big end as built (benchmarks/asbuilt_benchmarks.py)", "",
             f"Python {platform.python_version()}, {platform.machine()}, "
             f"{os.cpu_count()} CPUs, load average {os.getloadavg()[0]:.1f} at the start.", "",
             "## Assembly load case (KamAZ-740 rod, 75 kN per bolt, 40 µm crush) and warm bore", ""]
    rows = build_rows(72) + build_rows(144)
    lines += table(("item", "measured", "target", "note"), rows)
    if "--no-runs" not in sys.argv:
        case = kamaz()
        runs = [run_row("rigid bore", case, "rigid"),
                run_row("elastic", case, None),
                run_row("elastic + assembly", kamaz(assembly=ASSEMBLY), None),
                run_row("elastic + assembly + warm (journal 105 °C, housing 95 °C)",
                        kamaz(assembly=ASSEMBLY, warm=WARM), None)]
        lines += ["", "## KamAZ-740 example side by side (Reynolds 72 × 16)", "",
                  *table(("big end", "radial clearance [µm]", "h_min [µm]", "p_max [MPa]",
                          "effective film temperature [°C]", "mean friction power [W]",
                          "bonded joint over the run", "wall time [s]"), runs)]
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
