"""Fingerprints of what ``conrod run`` writes, to show that a refactoring changed nothing
(or by how much it changed round-off).

Run:  python benchmarks/result_digests.py record before.json
      python benchmarks/result_digests.py compare before.json [--relative 1e-9]

Every shipped orbit example as shipped, and every film × integrator pair on two of them
(the rigid passenger-car case, and the Ruston & Hornsby case on its elastic housing), plus
the Ruston & Hornsby case fed at 3 bar through its groove (so that the mass-conserving film
runs) on its elastic housing and on a rigid bore, each at coarse settings
(``--grid 24x8 --max-cycles 3 --no-figures --no-step-check``) in its own process. ``record``
stores per run the exit code, the SHA-256 of every CSV and of ``summary.json`` without its
wall times, and the headline numbers (h_min, p_max, friction power, flows) at full
precision; ``compare`` reruns and reports, per run, "identical" (every digest equal), the
largest relative difference of the headline numbers, or what else changed.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ("passenger_car_diesel_2000rpm", "passenger_car_diesel_1000rpm",
            "passenger_car_diesel_2000rpm_5w30_piezoviscous", "kamaz_740_truck_diesel",
            "ruston_hornsby_6vebx_mk3", "flores2006_table_load",
            "passenger_car_diesel_2000rpm_reynolds")
FILMS = ("short", "reynolds", "mass_conserving", "mobility", "table")
INTEGRATORS = ("auto", "adaptive", "implicit", "rk2", "quasi_static")
COARSE = ("--grid", "24x8", "--max-cycles", "3", "--no-figures", "--no-step-check")
HEADLINE = ("h_min_m", "p_max_Pa", "mean_total_friction_power_W", "mean_side_flow_m3_s",
            "mean_supply_flow_m3_s")


VARIANTS = {
    "ruston_hornsby_6vebx_mk3@fed": ("ruston_hornsby_6vebx_mk3", (
        ("supply_pressure = 0.0 ", "supply_pressure = 3.0e5 "),)),
    "ruston_hornsby_6vebx_mk3@fed-rigid": ("ruston_hornsby_6vebx_mk3", (
        ("supply_pressure = 0.0 ", "supply_pressure = 3.0e5 "),
        ('model = "builtin"', 'model = "rigid"'))),
}
"""Case variants: name → (shipped example, text replacements in its case file)."""


def runs() -> list[tuple[str, tuple[str, ...]]]:
    """(name, extra arguments) of every run."""
    out = [(example, ()) for example in EXAMPLES]
    out.append(("kamaz_740_truck_diesel+reynolds-ehd", ("--film", "reynolds")))
    for example in ("passenger_car_diesel_2000rpm", "ruston_hornsby_6vebx_mk3"):
        for film in FILMS:
            for integrator in INTEGRATORS:
                out.append((f"{example}+{film}+{integrator}",
                            ("--film", film, "--integrator", integrator)))
    for variant in VARIANTS:
        for film in ("reynolds", "mass_conserving"):
            for integrator in INTEGRATORS:
                out.append((f"{variant}+{film}+{integrator}",
                            ("--film", film, "--integrator", integrator)))
    return out


def case_file(name: str, scratch: Path) -> Path:
    """The case file of run ``name``: a shipped example, or a variant written to
    ``scratch`` with its relative table paths made absolute."""
    key = name.split("+")[0]
    if key not in VARIANTS:
        return ROOT / "examples" / f"{key}.toml"
    example, replacements = VARIANTS[key]
    text = (ROOT / "examples" / f"{example}.toml").read_text(encoding="utf-8")
    for old, new in replacements:
        assert old in text, f"{example}: {old!r} not found"
        text = text.replace(old, new)
    text = text.replace('"data/', f'"{(ROOT / "examples" / "data").as_posix()}/')
    path = scratch / f"{key.replace('@', '_')}.toml"
    path.write_text(text, encoding="utf-8")
    return path


def scrub_wall_times(value):
    """summary.json without its wall times (the only field that differs between runs)."""
    if isinstance(value, dict):
        return {k: scrub_wall_times(v) for k, v in value.items() if "wall_time" not in k}
    if isinstance(value, list):
        return [scrub_wall_times(v) for v in value]
    return value


def _numbers(summary, prefix: str = "") -> dict:
    """The headline numbers anywhere in ``summary`` (elastic and rigid parts alike)."""
    found = {}
    if isinstance(summary, dict):
        for name, value in summary.items():
            if name in HEADLINE and isinstance(value, (int, float)):
                found[prefix + name] = value
            elif isinstance(value, dict):
                found.update(_numbers(value, f"{prefix}{name}."))
    return found


def fingerprint(name: str, extra: tuple[str, ...], scratch: Path) -> dict:
    """Exit code, digests and headline numbers of one run."""
    out = scratch / name
    command = [sys.executable, "-c", "from conrod.cli.app import main; main()", "run",
               str(case_file(name, scratch)), *extra, *COARSE, "--out", str(out)]
    if not name.endswith("-ehd"):
        command.append("--no-rigid")
    done = subprocess.run(command, capture_output=True, text=True, timeout=1800,
                          env=os.environ | {"COLUMNS": "200"})
    record = {"code": done.returncode, "digests": {}, "numbers": {}}
    if not out.exists():
        record["stderr"] = done.stderr.strip().splitlines()[-1:] if done.stderr else []
        return record
    for path in sorted(out.iterdir()):
        if path.suffix == ".csv":
            record["digests"][path.name] = hashlib.sha256(path.read_bytes()).hexdigest()
        elif path.name == "summary.json":
            summary = scrub_wall_times(json.loads(path.read_text(encoding="utf-8")))
            text = json.dumps(summary, sort_keys=True).encode()
            record["digests"][path.name] = hashlib.sha256(text).hexdigest()
            record["numbers"] = _numbers(summary)
    return record


def record_all(workers: int, match: str = "") -> dict:
    with tempfile.TemporaryDirectory() as tmp, ThreadPoolExecutor(workers) as pool:
        futures = {name: pool.submit(fingerprint, name, extra, Path(tmp))
                   for name, extra in runs() if match in name}
        return {name: future.result() for name, future in futures.items()}


def compare(before: dict, after: dict, relative: float) -> list[str]:
    lines = []
    for name, old in before.items():
        new = after.get(name)
        if new is None:
            lines.append(f"{name}: missing")
            continue
        if old["digests"] == new["digests"] and old["code"] == new["code"]:
            lines.append(f"{name}: identical (exit {old['code']})")
            continue
        worst = 0.0
        for key, value in old["numbers"].items():
            other = new["numbers"].get(key)
            if other is None:
                worst = float("inf")
                continue
            worst = max(worst, abs(other - value) / max(abs(value), 1e-300))
        verdict = "within" if worst <= relative else "BEYOND"
        lines.append(f"{name}: exit {old['code']} -> {new['code']}, digests differ, largest "
                     f"relative headline change {worst:.3g} ({verdict} {relative:g})")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=("record", "compare"))
    parser.add_argument("path", type=Path)
    parser.add_argument("--relative", type=float, default=1e-9)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--match", default="", help="only the runs whose name contains this")
    args = parser.parse_args()
    fingerprints = record_all(args.workers, args.match)
    if args.mode == "record":
        old = (json.loads(args.path.read_text(encoding="utf-8"))
               if args.match and args.path.exists() else {})
        args.path.write_text(json.dumps({**old, **fingerprints}, indent=1, sort_keys=True),
                             encoding="utf-8")
        print(f"{len(fingerprints)} runs recorded in {args.path}")
        return
    before = {name: record for name, record in
              json.loads(args.path.read_text(encoding="utf-8")).items() if args.match in name}
    for line in compare(before, fingerprints, args.relative):
        print(line)


if __name__ == "__main__":
    main()
