"""Elastic-housing benchmarks: build of the compliance matrix [C], load from the cache, one
deformation update, and peak memory of the built-in rod.

Run:  python benchmarks/housing_benchmarks.py   (writes benchmarks/housing_benchmarks.md)

Rod: the KamAZ-740 example's built-in housing (examples/kamaz_740_truck_diesel.toml);
film grid n_θ = 144 unless stated. Times are medians (build: of 3; cache: of 10; update: of
20 000 calls). Peak memory is the resident-set maximum of a fresh Python process that
builds the housing (imports included).
"""

from __future__ import annotations

import os
import platform
import subprocess
import sys
import tempfile
import time
import tomllib
from pathlib import Path

import numpy as np

from conrod.cases.case import Case
from conrod.housing.housing import Housing
from conrod.io.atomic import write_text

EXAMPLE = Path(__file__).resolve().parents[1] / "examples" / "kamaz_740_truck_diesel.toml"
OUTPUT = Path(__file__).with_suffix(".md")


def kamaz(n_theta: int = 144, per_node: int = 1) -> Case:
    data = tomllib.loads(EXAMPLE.read_text())
    data["solver"] = {"n_theta": n_theta}
    data["housing"]["bore_nodes_per_film_node"] = per_node
    return Case.from_dict(data, base_dir=EXAMPLE.parent)


def median_time(action, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return float(np.median(times))


def build_row(n_theta: int, per_node: int = 1) -> tuple[str, ...]:
    case = kamaz(n_theta, per_node)
    housings = []
    seconds = median_time(lambda: housings.append(Housing.from_case(case, use_cache=False)), 3)
    info = housings[-1].info
    return (f"[C] build, {n_theta} film nodes, {n_theta * per_node} bore nodes",
            f"{seconds * 1e3:.0f} ms", "≤ 2 s" if n_theta == 144 and per_node == 1 else "–",
            f"{info['n_elements']} P2 triangles, {info['n_dofs']} unknowns")


def cache_row(cache_dir: str) -> tuple[str, ...]:
    case = kamaz()
    Housing.from_case(case, cache_dir=cache_dir)
    seconds = median_time(lambda: Housing.from_case(case, cache_dir=cache_dir), 10)
    return ("[C] from the cache, 144 film nodes", f"{seconds * 1e3:.1f} ms", "≤ 50 ms",
            "hash of the inputs + np.load + projector")


def update_rows(cache_dir: str) -> list[tuple[str, ...]]:
    housing = Housing.from_case(kamaz(), cache_dir=cache_dir)
    forces = np.random.default_rng(0).uniform(0.0, 1e3, len(housing.angles))
    coefficients = housing.inertia_coefficients(0.3)
    n = 20000
    start = time.perf_counter()
    for k in range(n):
        housing.deformation(forces, 0.001 * k)
    full = (time.perf_counter() - start) / n
    start = time.perf_counter()
    for _ in range(n):
        housing.deformation_from(forces, coefficients)
    products = (time.perf_counter() - start) / n
    return [("deformation update P(C f + U c(φ)), 144 nodes", f"{full * 1e6:.1f} µs", "≤ 20 µs",
             "inertia coefficients at φ + two matrix-vector products"),
            ("  of which the matrix-vector products", f"{products * 1e6:.1f} µs", "–", "")]


MEMORY_SCRIPT = """
import resource, sys
sys.path.insert(0, {bench!r})
from housing_benchmarks import kamaz
from conrod.housing.housing import Housing
Housing.from_case(kamaz({n}, {per}), use_cache=False)
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
"""


def memory_row(n_theta: int, per_node: int) -> tuple[str, ...]:
    script = MEMORY_SCRIPT.format(bench=str(Path(__file__).parent), n=n_theta, per=per_node)
    output = subprocess.run([sys.executable, "-c", script], check=True, capture_output=True,
                            text=True).stdout
    megabytes = int(output.split()[-1]) / 1024
    return (f"peak memory, {n_theta} film nodes × {per_node} bore nodes each",
            f"{megabytes:.0f} MB", "≤ 500 MB" if per_node == 4 else "–",
            "finest default mesh" if per_node == 4 else "default mesh")


def main() -> None:
    load = os.getloadavg()[0]
    with tempfile.TemporaryDirectory() as cache_dir:
        rows = [build_row(144), build_row(144, 2), build_row(288), cache_row(cache_dir),
                *update_rows(cache_dir), memory_row(144, 1), memory_row(144, 4)]
    lines = ["# Housing benchmarks", "",
             f"Machine: {platform.system().lower()}, {os.cpu_count()} cores, Python "
             f"{platform.python_version()}, load average {load:.1f} at the "
             "start; KamAZ-740 built-in rod (examples/kamaz_740_truck_diesel.toml).", "",
             "| item | measured | target | note |", "| --- | ---: | ---: | --- |"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    write_text(OUTPUT, "\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
