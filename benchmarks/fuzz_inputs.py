"""Fuzz campaign over the command line: mutated case files and input tables through
``conrod run``, ``conrod loads`` and ``conrod mechanism`` (seeded, reproducible).

    python benchmarks/fuzz_inputs.py [N]      # → benchmarks/fuzz_inputs.md

Each input is a shipped example with 1–3 mutations (a value of the wrong type, an extreme
or rescaled number, a deleted or misspelt key, a stray non-UTF-8 byte, a damaged load
table). Commands run in-process (typer's CliRunner) into a fresh folder. Classified:
exit 0 with finite CSV/JSON, exit 2 with every stderr line naming a file/field/row,
exit 3, any other ending (a traceback), more than HANG_S seconds (a hang), non-finite
numbers written.
"""

from __future__ import annotations

import json
import math
import random
import re
import shutil
import sys
import tempfile
import time
import tomllib
from collections import Counter
from pathlib import Path

import numpy as np
from typer.testing import CliRunner

REPO = Path(__file__).resolve().parents[1]
EXAMPLES = REPO / "examples"
HANG_S = 60.0
COMMANDS = {"run": ["flores2006_table_load", "passenger_car_diesel_2000rpm",
                    "passenger_car_diesel_1000rpm", "ruston_hornsby_6vebx_mk3",
                    "kamaz_740_truck_diesel"],
            "loads": ["passenger_car_diesel_2000rpm", "kamaz_740_truck_diesel"],
            "mechanism": ["kulayev_worn_rod_bearings"]}
FIELD = re.compile(r"^(error|not converged): (case file '[^']*': )?([a-z_]+(\[\d+\])?"
                   r"(\.[a-z_]+(\[\d+\])?)*( = |: )|(load\.table|pressure trace|case file) '"
                   r"|--out '|run needs|film = |supply_pressure = |cavitation_pressure = )")
NASTY = [True, False, "0.02", "", "abc", {}, {"a": 1}, [1.0], 0, -1, 1e300, -1e-300,
         float("nan"), float("inf"), 10**12]
SCALES = [0.0, -1.0, 1e-9, 1e-3, 0.5, 0.9, 1.1, 2.0, 10.0, 1e3, 1e9]


def leaves(data: dict, prefix: tuple = ()) -> list[tuple]:
    out = []
    for key, value in data.items():
        out += leaves(value, (*prefix, key)) if isinstance(value, dict) else [(*prefix, key)]
    return out


def toml_value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return "nan" if math.isnan(value) else ("inf" if value == math.inf else (
            "-inf" if value == -math.inf else repr(value)))
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{k} = {toml_value(v)}" for k, v in value.items()) + " }"
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    return str(value)


def to_toml(data: dict, prefix: str = "") -> str:
    lines = [f"{k} = {toml_value(v)}" for k, v in data.items()
             if not isinstance(v, dict) and not (isinstance(v, list) and v and
                                                 isinstance(v[0], dict))]
    text = "\n".join(lines) + "\n"
    for key, value in data.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict):
            text += f"\n[{name}]\n" + to_toml(value, f"{name}.")
        elif isinstance(value, list) and value and isinstance(value[0], dict):
            text += "".join(f"\n[[{name}]]\n" + to_toml(v, f"{name}.") for v in value)
    return text


def mutate(rng: random.Random, data: dict) -> tuple[dict, list[str]]:
    notes = []
    for _ in range(rng.choice([1, 1, 2, 3])):
        path = rng.choice(leaves(data))
        node = data
        for part in path[:-1]:
            node = node[part]
        old = node[path[-1]]
        kind = rng.choice(["scale", "scale", "scale", "nasty", "delete", "unknown"])
        if kind == "scale" and isinstance(old, int | float) and not isinstance(old, bool):
            node[path[-1]] = type(old)(old * rng.choice(SCALES))
        elif kind == "delete":
            del node[path[-1]]
        elif kind == "unknown":
            node[path[-1] + rng.choice(["_", "s", "x"])] = old
        else:
            node[path[-1]] = rng.choice(NASTY)
        notes.append(f"{kind} {'.'.join(path)}")
    return data, notes


def damage_table(rng: random.Random, path: Path) -> str:
    lines = path.read_text(encoding="utf-8").splitlines()
    kind = rng.choice(["na", "comment only", "text", "byte", "drop rows", "nan"])
    data_rows = [i for i, line in enumerate(lines) if line and line[0].isdigit()]
    if kind == "na":
        lines[rng.choice(data_rows)] = "#N/A,#N/A,#N/A"
    elif kind == "comment only":
        lines = [f"# {line}" for line in lines]
    elif kind == "text":
        i = rng.choice(data_rows)
        lines[i] = lines[i].replace(",", ",x", 1)
    elif kind == "drop rows":
        lines = lines[: data_rows[0] + 2]
    elif kind == "nan":
        i = rng.choice(data_rows)
        lines[i] = lines[i].split(",")[0] + ",nan" + "," * (lines[i].count(",") - 1)
    text = "\n".join(lines) + "\n"
    if kind == "byte":
        path.write_bytes(b"# 90 \xb0C\n" + text.encode())
    else:
        path.write_text(text, encoding="utf-8")
    return f"table {kind}"


def finite_outputs(folder: Path) -> bool:
    for path in folder.glob("*.csv"):
        for line in path.read_text().splitlines()[1:]:
            if re.search(r"(?i)\b(nan|inf)\b", line):
                return False
    for path in folder.glob("*.json"):
        text = path.read_text()
        if re.search(r"\b(NaN|Infinity)\b", text):
            return False
    return True


def one_input(rng: random.Random, runner, app, work: Path, index: int) -> dict:
    command = rng.choice(["run"] * 5 + ["loads"] * 3 + ["mechanism"] * 3)
    example = rng.choice(COMMANDS[command])
    folder = work / f"in{index}"
    shutil.copytree(EXAMPLES / "data", folder / "data")
    with open(EXAMPLES / f"{example}.toml", "rb") as handle:
        data = tomllib.load(handle)
    if command == "run":  # keep valid runs short: at most 3 cycles
        data.setdefault("solver", {})["max_cycles"] = min(
            data.get("solver", {}).get("max_cycles", 8), 3)
    notes = []
    roll = rng.random()
    if roll < 0.1 and "load" in data:
        notes.append(damage_table(rng, folder / data["load"]["table"]))
    else:
        data, notes = mutate(rng, data)
    case = folder / "case.toml"
    text = to_toml(data).encode()
    if roll > 0.95:
        at = rng.randrange(len(text))
        text = text[:at] + b"\n# \xb0\n" + text[at:]
        notes.append("stray byte")
    case.write_bytes(text)
    out = folder / "out"
    arguments = [command, str(case), "--out", str(out)]
    if command == "run":
        arguments.append("--no-figures")
    start = time.perf_counter()
    result = runner.invoke(app, arguments)
    seconds = time.perf_counter() - start
    shutil.rmtree(folder / "data")
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    errors = [line for line in lines if line.startswith(("error", "not converged"))]
    if seconds > HANG_S:
        outcome = "hang"
    elif result.exception is not None and not isinstance(result.exception, SystemExit):
        outcome = "traceback"
    elif result.exit_code == 0:
        outcome = "ran" if finite_outputs(out) else "non-finite output"
    elif result.exit_code == 2:
        outcome = "exit 2 naming a field" if errors and all(
            FIELD.match(line) for line in errors) else "exit 2 without the field"
    elif result.exit_code == 3:
        outcome = "exit 3 (not converged)"
    else:
        outcome = f"exit {result.exit_code}"
    if outcome in ("exit 2 naming a field", "exit 3 (not converged)") and out.exists():
        outcome = "partial output"
    shutil.rmtree(folder, ignore_errors=True)
    return {"command": command, "example": example, "notes": notes, "outcome": outcome,
            "seconds": seconds, "message": errors[:1]}


def main(count: int) -> None:
    from conrod.cli.app import _register_commands, app

    _register_commands()
    runner = CliRunner()
    rng = random.Random(20261122)
    records = []
    with tempfile.TemporaryDirectory() as folder:
        for index in range(count):
            records.append(one_input(rng, runner, app, Path(folder), index))
            if (index + 1) % 50 == 0:
                print(index + 1, Counter(r["outcome"] for r in records), flush=True)
    write_report(records)


def write_report(records: list[dict]) -> None:
    outcomes = Counter(r["outcome"] for r in records)
    by_command = Counter((r["command"], r["outcome"]) for r in records)
    seconds = np.array([r["seconds"] for r in records])
    lines = ["# Fuzz campaign over the command line", "",
             f"`python benchmarks/fuzz_inputs.py {len(records)}` (seed 20261122; mutated "
             "shipped examples, in-process CLI).", "",
             "| Outcome | Inputs |", "| --- | ---: |"]
    lines += [f"| {name} | {n} |" for name, n in sorted(outcomes.items())]
    lines += ["", "| Command | Outcome | Inputs |", "| --- | --- | ---: |"]
    lines += [f"| {c} | {o} | {n} |" for (c, o), n in sorted(by_command.items())]
    lines += ["", f"Slowest input {seconds.max():.1f} s, median {np.median(seconds):.2f} s.", ""]
    bad = [r for r in records if r["outcome"] not in ("ran", "exit 2 naming a field",
                                                      "exit 3 (not converged)")]
    if bad:
        lines += ["## Inputs not ending cleanly", ""]
        lines += [f"- {r['command']} {r['example']} {r['notes']}: {r['outcome']} "
                  f"{r['message']}" for r in bad]
    (REPO / "benchmarks" / "fuzz_inputs.md").write_text("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 1100)
