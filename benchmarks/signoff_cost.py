"""What the sign-off costs: the per-cell indicators (one more film solve per output angle,
with its pressure field, unless it reads the solves of the cycle's characteristics: a rigid
orbit without film memory) against the orbit, and the size of ``fields.nc`` (``conrod run
--fields``) at 1° against the issue's 50 MB for a 72 × 16 run.

Run:  python benchmarks/signoff_cost.py   → benchmarks/signoff_cost.md

Each case runs its orbit once in this process (BLAS on one thread, as ``conrod run``
does), then the sign-off is timed on the converged orbit three times (the best kept), the
fields written at 1° and 5°; the netCDF-4 file (h5netcdf, zlib 4) is compared with the
same fields as an uncompressed netCDF-3 file (scipy), the other engine xarray offers.
"""

from __future__ import annotations

import os

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

from conrod import Case, Simulation  # noqa: E402
from conrod.output.fields_file import fields_bytes, fields_dataset  # noqa: E402
from conrod.simulation.fields import sign_off  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
CASES = (
    ("passenger car, Reynolds + asperities", "passenger_car_diesel_2000rpm_reynolds.toml",
     {"n_theta": 72, "n_z": 16}),
    ("KamAZ-740, Reynolds on the rigid bore (compiled orbit)", "kamaz_740_truck_diesel.toml",
     {"n_theta": 144, "n_z": 16, "housing": "rigid", "film": "reynolds"}),
    ("KamAZ-740 solid big end, elastic Reynolds (3-D compliance)",
     "kamaz_740_solid_big_end.toml", {"n_theta": 36, "n_z": 8}),
    ("passenger car fed, mass-conserving (massless orbit)", "passenger_car_diesel_2000rpm.toml",
     {"n_theta": 72, "n_z": 16, "film": "mass_conserving", "integrator": "quasi_static",
      "contact_film_thickness": 0.0, "thermal_iterations": 0}),
)


def _case(name: str, settings: dict) -> tuple[Case, dict]:
    case = Case.from_toml(ROOT / "examples" / name)
    if settings.get("film") == "mass_conserving":
        case = case.with_(bearing__supply_pressure=0.3e6, bearing__grooves=[{"width": 0.002}])
    return case, settings


def measure(label: str, name: str, settings: dict) -> dict:
    case, overrides = _case(name, settings)
    simulation = Simulation(case, rigid_companion=False, **overrides)
    start = time.perf_counter()
    results, thermal = simulation.run_orbit()  # on the elastic bore where the case has one
    orbit = time.perf_counter() - start
    memory = thermal.orbit.last.film_memory
    best, best_rows = float("inf"), float("inf")
    for _ in range(3):
        start = time.perf_counter()
        signoff = sign_off(thermal.problem, results.cycle, memory, results.summary, {}, 1.0)
        best = min(best, time.perf_counter() - start)
        start = time.perf_counter()  # reading the characteristics' solves where it can
        sign_off(thermal.problem, results.cycle, memory, results.summary, {}, 1.0,
                 thermal.rows)
        best_rows = min(best_rows, time.perf_counter() - start)
    fields = signoff.fields
    size_1 = len(fields_bytes(fields))
    size_5 = len(fields_bytes(fields.every(5.0)))
    with tempfile.TemporaryDirectory() as folder:
        classic = Path(folder) / "classic.nc"
        fields_dataset(fields).to_netcdf(classic, engine="scipy")
        size_classic = classic.stat().st_size
    return {"case": label, "grid": f"{overrides['n_theta']}x{overrides['n_z']}",
            "rows": fields.crank_angle.size, "fields": ", ".join(fields.values),
            "orbit_s": orbit, "signoff_s": best, "signoff_rows_s": best_rows,
            "nc_1deg_MB": size_1 / 1e6,
            "nc_5deg_MB": size_5 / 1e6, "netcdf3_1deg_MB": size_classic / 1e6}


def main() -> None:
    rows = [measure(*case) for case in CASES]
    lines = ["# Sign-off cost and fields.nc size", "",
             f"`python benchmarks/signoff_cost.py`, {time.strftime('%Y-%m-%d')}, this 2-core "
             "machine shared with other jobs (times are wall times of one process).", "",
             "| case | grid | output rows | fields | orbit + characteristics [s] | "
             "sign-off (indicators, erosion, fields), solving the film again [s] | ratio | "
             "sign-off as runs do it (reading the characteristics' solves where it can) [s] | "
             "fields.nc at 1° [MB] | at 5° [MB] | netCDF-3 at 1° (scipy, uncompressed) [MB] |",
             "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |"]
    for r in rows:
        lines.append(f"| {r['case']} | {r['grid']} | {r['rows']} | {r['fields']} | "
                     f"{r['orbit_s']:.1f} | {r['signoff_s']:.2f} | "
                     f"{r['signoff_s'] / r['orbit_s']:.2f} | {r['signoff_rows_s']:.2f} | "
                     f"{r['nc_1deg_MB']:.2f} | "
                     f"{r['nc_5deg_MB']:.2f} | {r['netcdf3_1deg_MB']:.1f} |")
    text = "\n".join(lines) + "\n"
    (ROOT / "benchmarks" / "signoff_cost.md").write_text(text, encoding="utf-8")
    sys.stdout.write(text)


if __name__ == "__main__":
    main()
