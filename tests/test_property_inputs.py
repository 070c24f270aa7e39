"""Property-based tests over the case-file schema and the input tables (hypothesis).

Every generated input either runs with finite results or fails with conrod's own error:
a CaseError whose every line names the file, a field (``section.key``) or a row, or a
ConvergenceError saying where; through the command line, a case file with one mistake is
refused (exit 2) with exactly one line naming the field, never a traceback (exit 1).
Derandomized: the same cases on every CI run.
"""

from __future__ import annotations

import collections
import re
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from conrod import Case, Simulation
from conrod.errors import CaseError, ConvergenceError
from conrod.io.atomic import first_non_finite
from conrod.loads.engine_loads import compute_engine_loads
from conrod.loads.pressure import read_pressure_trace
from conrod.loads.table_load import load_cycle_from_table
from conrod.mechanism.setup import mechanism_case
from conrod.mechanism.simulation import simulate
from conrod.output.tables import cycle_table, loads_table, summary_items
from conrod.results.plausibility import check_mechanism
from hardening_helpers import (
    DELETE,
    EXAMPLES,
    cheap_engine_run,
    cheap_mechanism,
    cheap_table_run,
    mutated,
    write_case,
)

CASES_PER_RUN = {"run": 300, "loads": 250, "mechanism": 150, "tables": 300,
                 "command line": 40}
"""Generated inputs per CI run (1040 in all)."""

FIELD = re.compile(
    r"^(case file '[^']*': )?("
    r"[a-z_]+(\[\d+\])?(\.[a-z_]+(\[\d+\])?)* = "  # section.key = value
    r"|[a-z_]+(\.[a-z_]+)*(\[\d+\])?(\.[a-z_]+)*: "  # section.key: ... / section: ...
    r"|(load\.table|pressure trace) '[^']*'"  # a table file (and its line)
    r"|case file '[^']*'"  # the file itself (encoding, TOML syntax, missing section)
    r"|run needs|film = |supply_pressure = |cavitation_pressure = "  # film/section rules
    r")")
"""What every line of a CaseError must start with: the file, a field or a table row."""


def _settings(command: str):
    return settings(max_examples=CASES_PER_RUN[command], deadline=None, derandomize=True,
                    database=None, print_blob=True,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large,
                                           HealthCheck.filter_too_much])


def _leaves(data: dict, prefix: tuple = ()) -> list[tuple]:
    paths = []
    for key, value in data.items():
        if isinstance(value, dict):
            paths += _leaves(value, (*prefix, key))
        else:
            paths.append((*prefix, key))
    return paths


NASTY = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**9, 10**9),
    st.booleans(), st.text(max_size=6),
    st.sampled_from(["", "0.02", "1e-3", "short", "reynolds", "exact", "seed", "none"]),
    st.just({}), st.dictionaries(st.sampled_from(["a", "width"]), st.floats(0, 1), max_size=2),
    st.lists(st.floats(0, 1), max_size=2), st.just(DELETE))
"""Values of any type, as a careless or hurried user might write them."""
SCALE = st.sampled_from([0.0, -1.0, 1e-12, 1e-6, 1e-3, 0.1, 0.3, 0.5, 0.7, 0.8, 0.9, 0.99,
                         1.01, 1.1, 1.25, 1.5, 2.0, 3.0, 10.0, 1e3, 1e6, 1e12])
"""Factors that turn a valid number into an extreme but well-typed one."""


@st.composite
def mutations(draw, base: dict, frozen: tuple = ()) -> dict:
    """``base`` with 1–3 leaves replaced by nasty or rescaled values, or an unknown key."""
    case = base
    paths = [p for p in _leaves(base) if not any(p[: len(f)] == f for f in frozen)]
    for _ in range(draw(st.integers(1, 3))):
        path = draw(st.sampled_from(paths))
        old = _get(case, path)
        kind = draw(st.sampled_from(["scale", "scale", "scale", "nasty", "unknown"]))
        if kind == "scale" and isinstance(old, int | float) and not isinstance(old, bool):
            value = type(old)(old * draw(SCALE)) if isinstance(old, float) else int(
                old * draw(SCALE))
            case = mutated(case, path, value)
        elif kind == "unknown":
            case = mutated(case, (*path[:-1], draw(st.sampled_from(["widht", "x", "speed_"]))),
                           1.0)
        else:
            case = mutated(case, path, draw(NASTY))
    return case


def _get(case: dict, path: tuple):
    node = case
    for part in path:
        node = node.get(part) if isinstance(node, dict) else None
    return node


def _assert_names_a_field(error: CaseError) -> None:
    for line in str(error).splitlines():
        assert FIELD.match(line), f"message does not name a field or file: {line!r}"


def _assert_finite(data, what: str) -> None:
    found = first_non_finite(data)
    assert found is None, f"non-finite {what}: {found}"


OUTCOMES: collections.Counter = collections.Counter()
"""(command, outcome) → count, printed at the end of the module (run pytest with -s)."""


@pytest.fixture(scope="module", autouse=True)
def _report_outcomes():
    yield
    print("\ngenerated inputs:", dict(sorted(OUTCOMES.items())))


def _outcome(command: str, action) -> str:
    """'ran', 'case error' or 'not converged'; anything else propagates (a defect)."""
    try:
        action()
    except CaseError as error:
        _assert_names_a_field(error)
        outcome = "case error"
    except ConvergenceError as error:
        assert str(error)
        outcome = "not converged"
    else:
        outcome = "ran"
    OUTCOMES[command, outcome] += 1
    return outcome


# -- conrod run -----------------------------------------------------------------------------
RUN_FROZEN = (("solver", "film"), ("solver", "integrator"), ("solver", "n_theta"),
              ("solver", "n_z"), ("solver", "adaptive_method"), ("title",), ("source",))
"""Kept: these choose a (slower) model, not a value; other tests cover them."""


def _run(data: dict) -> None:
    case = Case.from_dict(data, base_dir=EXAMPLES)
    results = Simulation(case).run()
    _assert_finite({k: np.asarray(v, dtype=float) for k, v in cycle_table(results).items()},
                   "cycle.csv")
    _assert_finite(summary_items(results), "summary.json")


@_settings("run")
@given(st.one_of(mutations(cheap_table_run(), RUN_FROZEN),
                 mutations(cheap_engine_run(), RUN_FROZEN)))
def test_run_is_total(data):
    _outcome("run", lambda: _run(data))


# -- conrod loads ---------------------------------------------------------------------------
def _loads(data: dict) -> None:
    case = Case.from_dict(data, base_dir=EXAMPLES)
    case.require("loads", "engine", "bearing")
    loads = compute_engine_loads(case)
    _assert_finite(loads_table(loads), "loads.csv")
    _assert_finite(loads.summary(), "loads_summary.json")


@_settings("loads")
@given(mutations(cheap_engine_run(), (("solver",), ("title",), ("source",))))
def test_loads_is_total(data):
    _outcome("loads", lambda: _loads(data))


# -- conrod mechanism -----------------------------------------------------------------------
MECHANISM_FROZEN = (("clearance", "cycles"), ("clearance", "tolerance"), ("title",),
                    ("source",), ("clearance", "output_step_deg"))


def _mechanism(data: dict) -> None:
    base = mechanism_case(Case.from_dict(data, base_dir=EXAMPLES))
    results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
    _assert_finite(results.summary(), "summary.json")
    check_mechanism(results, base.mechanism)


@_settings("mechanism")
@given(mutations(cheap_mechanism(), MECHANISM_FROZEN))
def test_mechanism_is_total(data):
    _outcome("mechanism", lambda: _mechanism(data))


# -- load tables and pressure traces --------------------------------------------------------
CELL = st.one_of(st.floats(-1e6, 1e6), st.floats(allow_nan=True, allow_infinity=True),
                 st.integers(-100, 800), st.sampled_from(["", "#N/A", "x", " 1", "1,5", "#"]))
LINE = st.one_of(st.lists(CELL, min_size=1, max_size=4).map(lambda c: ",".join(map(str, c))),
                 st.sampled_from(["# comment", "", "   ", "crank_angle_deg,load_x_N,load_y_N",
                                  "crank_angle_deg,pressure_Pa"]))


@st.composite
def tables(draw) -> bytes:
    """A CSV that starts as a valid load table or trace and is then damaged."""
    header = draw(st.sampled_from(["crank_angle_deg,load_x_N,load_y_N",
                                   "crank_angle_deg,pressure_Pa", "angle,load"]))
    step = draw(st.sampled_from([5.0, 10.0, 30.0, 90.0, 360.0]))
    rows = [f"{a:g}," + ",".join(["1000"] * header.count(",")) for a in np.arange(0, 720, step)]
    lines = [header, *rows]
    for _ in range(draw(st.integers(0, 3))):
        position = draw(st.integers(0, len(lines)))
        if draw(st.booleans()) and lines:
            lines[min(position, len(lines) - 1)] = draw(LINE)
        else:
            lines.insert(position, draw(LINE))
    data = "\n".join(lines).encode()
    if draw(st.integers(0, 9)) == 0:
        position = draw(st.integers(0, len(data)))
        data = data[:position] + draw(st.sampled_from([b"\xb0", b"\xff", b"\x00"])) + data[
            position:]
    return data


@_settings("tables")
@given(tables())
def test_table_readers_are_total(data):
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "table.csv"
        path.write_bytes(data)
        section = Case.from_dict(cheap_table_run(), base_dir=EXAMPLES).load

        def read_load():
            cycle = load_cycle_from_table(section, path)
            assert np.all(np.isfinite(cycle.load_x)) and np.all(np.isfinite(cycle.crank_angle))

        def read_trace():
            angles, pressures = read_pressure_trace(path)
            assert np.all(np.isfinite(angles)) and np.all(pressures > 0.0)

        _outcome("load table", read_load)
        _outcome("pressure trace", read_trace)


# -- the command line: one mistake, one line --------------------------------------------------
CLI_BASES = {"run": (cheap_engine_run, cheap_table_run), "loads": (cheap_engine_run,),
             "mechanism": (cheap_mechanism,)}
CLI_LINE = re.compile(r"^error: (case file '[^']*': )?")
"""The command line's prefix of a CaseError line, before what :data:`FIELD` matches."""


@st.composite
def one_mistake(draw) -> tuple[str, dict]:
    """(command, a shipped example with one leaf rescaled, replaced, deleted or misspelt)."""
    command = draw(st.sampled_from(["run", "run", "loads", "mechanism"]))
    base = draw(st.sampled_from(CLI_BASES[command]))()
    paths = [p for p in _leaves(base) if p[0] not in ("title", "source")]
    path = draw(st.sampled_from(paths))
    old = _get(base, path)
    kind = draw(st.sampled_from(["scale", "nasty", "delete", "misspelt"]))
    if kind == "scale" and isinstance(old, int | float) and not isinstance(old, bool):
        factor = draw(SCALE)
        return command, mutated(base, path, type(old)(old * factor))
    if kind == "misspelt":
        return command, mutated(mutated(base, path, DELETE), (*path[:-1], path[-1] + "x"), old)
    return command, mutated(base, path, DELETE if kind == "delete" else draw(NASTY))


@_settings("command line")
@given(one_mistake())
def test_command_line_refuses_one_mistake_in_one_line(item):
    """Exit 0, 3 or 4, or exit 2 with one line that names the file, field or row."""
    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app

    _register_commands()
    command, data = item
    with tempfile.TemporaryDirectory() as folder:
        case = write_case(Path(folder), data)
        arguments = [command, str(case), "--out", str(Path(folder) / "out")]
        result = CliRunner().invoke(app, arguments + (["--no-figures"] if command == "run"
                                                      else []))
    assert "Traceback" not in result.output, result.output
    assert result.exit_code in (0, 2, 3, 4), (result.exit_code, result.output)
    lines = [line for line in result.stderr.splitlines()
             if line.startswith(("error", "not converged"))]
    OUTCOMES["command line", f"exit {result.exit_code}"] += 1
    if result.exit_code == 2:
        assert len(lines) == 1, lines
        rest = CLI_LINE.sub("", lines[0])
        assert FIELD.match(rest) or FIELD.match(lines[0][len("error: "):]), lines[0]
