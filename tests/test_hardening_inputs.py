"""Regression tests for bad input found by fuzzing: each defect ends in one CaseError line
naming the file, the field or row, the value and the allowed range — before any computation."""

from __future__ import annotations

import re
import time

import numpy as np
import pytest

from conrod import Case, Simulation
from conrod.errors import CaseError, ConvergenceError
from conrod.loads.pressure import read_pressure_trace
from conrod.loads.table_load import read_load_columns
from conrod.mechanism.setup import mechanism_case
from hardening_helpers import (
    DELETE,
    FLORES_TABLE,
    cheap_engine_run,
    cheap_mechanism,
    cheap_table_run,
    example_dict,
    mutated,
    write_case,
)


def _error(case: dict) -> str:
    with pytest.raises(CaseError) as info:
        Case.from_dict(case)
    message = str(info.value)
    assert "Traceback" not in message and "Value error" not in message
    return message


# -- encoding -------------------------------------------------------------------------------
def test_case_file_with_a_latin1_degree_sign_names_byte_position_and_line(tmp_path):
    path = write_case(tmp_path, cheap_table_run())
    text = path.read_bytes().replace(b"\n[bearing]", b"\n# supply at 80 \xb0C\n[bearing]", 1)
    path.write_bytes(text)
    position = text.index(b"\xb0")
    line = text[:position].count(b"\n") + 1
    with pytest.raises(CaseError) as info:
        Case.from_toml(path)
    message = str(info.value)
    assert str(path) in message and "not UTF-8" in message and "0xb0" in message
    assert f"byte position {position}" in message and f"line {line}" in message


@pytest.mark.parametrize("reader, what", [(read_load_columns, "load.table"),
                                          (read_pressure_trace, "pressure trace")])
def test_tables_with_a_stray_byte_name_the_byte(tmp_path, reader, what):
    path = tmp_path / "table.csv"
    path.write_bytes(b"# comment \xff\ncrank_angle_deg,load_x_N,load_y_N\n")
    with pytest.raises(CaseError, match=rf"{what} .*not UTF-8 text: byte 0xff at byte "
                                        r"position 10 \(line 1, column 11\)"):
        reader(path)


def test_utf8_with_byte_order_mark_is_accepted(tmp_path):
    path = write_case(tmp_path, cheap_table_run())
    path.write_bytes(b"\xef\xbb\xbf" + path.read_bytes())
    assert Case.from_toml(path).load is not None


# -- strict types ---------------------------------------------------------------------------
@pytest.mark.parametrize("value", [True, "0.02", {"a": 1}, [0.02]])
def test_bearing_width_must_be_a_number(value):
    message = _error(mutated(cheap_table_run(), ("bearing", "width"), value))
    assert message.startswith(f"bearing.width = {value!r}: a number is required")
    assert "(allowed: >= 0.001 and <= 5 m)" in message


def test_integer_fields_refuse_floats_and_booleans():
    message = _error(mutated(cheap_table_run(), ("solver", "max_cycles"), True))
    assert "solver.max_cycles = True: a whole number is required" in message


@pytest.mark.parametrize("key", ["title", "source"])
def test_empty_text_is_refused(key):
    assert _error(mutated(cheap_table_run(), (key,), "")) == f"{key} = '': must not be empty"


def test_inline_table_where_text_belongs_names_key_and_file(tmp_path):
    path = write_case(tmp_path, mutated(cheap_table_run(), ("title",), DELETE))
    path.write_text('title = { text = "x" }\n' + path.read_text(encoding="utf-8"))
    with pytest.raises(CaseError) as info:
        Case.from_toml(path)
    assert str(info.value) == (f"case file {str(path)!r}: title = {{'text': 'x'}}: "
                               "text in quotes is required")


@pytest.mark.parametrize("value", [float("nan"), float("inf")])
def test_nan_and_infinity_are_refused(value):
    message = _error(mutated(cheap_engine_run(), ("engine", "speed"), value))
    assert "engine.speed" in message and "finite number" in message


# -- cross-field rules and budgets -----------------------------------------------------------
def test_contact_film_thickness_at_the_clearance_is_refused():
    case = mutated(cheap_table_run(), ("solver", "contact_film_thickness"), 35.56e-6)
    assert _error(case) == ("solver.contact_film_thickness = 3.556e-05: out of range "
                            "(allowed: >= 0 and < bearing.radial_clearance = 3.556e-05 m)")


def test_a_tiny_quasi_static_step_fails_at_validation_not_allocation():
    case = mutated(cheap_table_run(), ("solver", "quasi_static_step_deg"), 1e-9)
    start = time.perf_counter()
    message = _error(case)
    assert time.perf_counter() - start < 1.0
    # 720 deg x 2 cycles / 2e6 steps = 7.2e-4 deg: the budget, stated in the message
    assert message.startswith("solver.quasi_static_step_deg = 1e-09: out of range "
                              "(allowed: >= 0.00072 with max_cycles = 2")


@pytest.mark.parametrize(("make", "path", "allowed"), [
    (cheap_engine_run, ("engine", "speed"), "(allowed: >= 1 and <= 30000 rpm)"),
    (cheap_mechanism, ("engine", "speed"), "(allowed: >= 1 and <= 30000 rpm)"),
    (cheap_table_run, ("load", "speed"), "(allowed: >= 0.1 and <= 30000 rpm)"),
    (cheap_table_run, ("bearing", "width"), "(allowed: >= 0.001 and <= 5 m)"),
    (cheap_engine_run, ("bearing", "diameter"), "(allowed: >= 0.001 and <= 5 m)"),
    (cheap_table_run, ("bearing", "radial_clearance"), "(allowed: >= 1e-06 and <= 0.01 m)"),
])
def test_vanishing_sizes_and_speeds_are_refused_with_their_physical_range(make, path, allowed):
    """1e-300 passed '> 0' and divided by zero deep inside (an internal error)."""
    message = _error(mutated(make(), path, 1e-300))
    assert message.startswith(f"{'.'.join(path)} = 1e-300: ") and message.endswith(allowed)
    assert len(message.splitlines()) == 1


def test_clearance_equal_to_the_journal_radius_is_refused():
    case = mutated(cheap_table_run(), ("bearing", "radial_clearance"), 0.0635 / 2)
    assert "bearing.radial_clearance = 0.03175" in _error(case)
    case = mutated(cheap_table_run(), ("bearing", "radial_clearance"), 0.002)
    assert "<= 0.05 x journal radius = 0.0015875 m" in _error(case)


def test_full_groove_wider_than_the_bearing_is_refused():
    case = mutated(cheap_table_run(), ("bearing", "grooves"), [{"width": 0.03}])
    assert _error(case) == ("bearing.grooves[0].width = 0.03: out of range "
                            "(allowed: > 0 and < bearing.width = 0.0254 m)")


def test_groove_reaching_past_the_edge_is_refused():
    case = mutated(cheap_table_run(), ("bearing", "grooves"),
                   [{"width": 0.01, "axial_position": 0.01}])
    assert "bearing.grooves[0].axial_position = 0.01" in _error(case)


def test_vogel_law_overflowing_in_the_documented_range_is_refused():
    lubricant = {"vogel_a": 1e-4, "vogel_b": 1.0e5, "vogel_c": 95.0,
                 "supply_temperature": 90.0}
    message = _error(mutated(cheap_table_run(), ("lubricant",), lubricant))
    # mu(90 °C) = 1e-4 exp(1e5/185) overflows; allowed b <= ln(10/1e-4) * 185 = 2129.8
    assert message.startswith("lubricant.vogel_b = 100000.0: out of range (allowed: > 0 and "
                              "<= 2130")


def test_joint_clearance_above_a_tenth_of_the_diameter_is_refused():
    case = mutated(cheap_mechanism(), ("clearance", "big_end", "clearance_max"), 0.006)
    assert "clearance.big_end.clearance_max = 0.006: must not exceed 0.1 x diameter" in (
        _error(case))


def test_mechanism_output_rows_within_budget():
    case = mutated(cheap_mechanism(), ("clearance", "output_step_deg"), 1e-5)
    assert "clearance.output_step_deg = 1e-05" in _error(case)


def test_slow_table_speed_ends_within_the_budget_instead_of_hanging():
    """The R&H table load at 0.5 rpm (a 240 s cycle, nearly a pure squeeze film): the
    adaptive orbit either finds the periodic orbit (its methods give way to one another
    within the film-evaluation budget: Radau, BDF, LSODA) or stops at the budget naming
    the crank angle — it never grinds on. Measured: periodic after 3 cycles in 37 s on a
    loaded 2-core machine."""
    case = example_dict("ruston_hornsby_6vebx_mk3")
    case["load"]["table"] = str(FLORES_TABLE.parent / "ruston_hornsby_6vebx_mk3_load.csv")
    case["load"]["speed"] = 0.5
    start = time.perf_counter()
    try:
        results = Simulation(Case.from_dict(case)).run()
    except ConvergenceError as error:
        assert re.search("budget of .* film evaluations per cycle .* at crank angle",
                         str(error)), error
    else:
        summary = results.summary
        assert summary.periodic and summary.h_min > 0.0 and np.isfinite(summary.p_max)
    assert time.perf_counter() - start < 180.0


# -- tables ---------------------------------------------------------------------------------
def test_comment_only_table_names_the_file(tmp_path):
    path = tmp_path / "load.csv"
    path.write_text("# only a comment\n# another\n")
    with pytest.raises(CaseError) as info:
        read_load_columns(path)
    assert str(info.value) == (f"load.table {str(path)!r}: no header and no data rows (the "
                               "file holds only comments or blank lines)")


def test_na_row_is_an_error_not_a_comment(tmp_path):
    rows = ["crank_angle_deg,load_x_N,load_y_N"] + [f"{a},1000,0" for a in range(0, 720, 90)]
    rows.insert(3, "#N/A,#N/A,#N/A")
    path = tmp_path / "load.csv"
    path.write_text("\n".join(rows) + "\n")
    with pytest.raises(CaseError, match=r"line 4: '#N/A' is a spreadsheet error value"):
        read_load_columns(path)


def test_non_numeric_cell_names_line_and_column(tmp_path):
    path = tmp_path / "load.csv"
    rows = ["crank_angle_deg,load_x_N,load_y_N"] + [f"{a},1000,0" for a in range(0, 720, 90)]
    rows[2] = "90,1 kN,0"
    path.write_text("\n".join(rows) + "\n")
    with pytest.raises(CaseError, match=r"line 3: load_x_N = '1 kN' is not a number"):
        read_load_columns(path)


def test_fixed_step_must_divide_the_output_step():
    case = mutated(cheap_table_run(), ("solver", "quasi_static_step_deg"), 2.0)
    assert _error(case) == ("solver.quasi_static_step_deg = 2.0: out of range (allowed: a "
                            "divisor of solver.output_step_deg = 5 (output_step_deg / k, "
                            "k = 1, 2, ...) deg)")


def test_mechanism_case_from_toml_names_the_file(tmp_path):
    path = write_case(tmp_path, mutated(cheap_mechanism(), ("engine", "speed"), "3000"))
    with pytest.raises(CaseError) as info:
        mechanism_case(Case.from_toml(path))
    assert str(info.value).startswith(f"case file {str(path)!r}: engine.speed = '3000'")


# -- command-line options ---------------------------------------------------------------------
STEADY = ["steady", "--load", "1e4", "--speed-rpm", "3000", "--viscosity", "0.01",
          "--diameter", "0.05", "--width", "0.05"]


@pytest.mark.parametrize("args, expected", [
    (["steady", "--length-to-diameter", "1", "--eccentricity", "0.5", "--grid", "4096x4096"],
     "error: grid = '4096x4096': out of range (allowed: NTHETA * (NZ + 1) <= 300000 nodes)"),
    ([*STEADY, "--radial-clearance", "0.05"],
     "error: radial_clearance = 0.05: out of range (allowed: <= 0.05 x diameter/2 = "
     "0.00125 m)"),
    ([*STEADY[:2], "inf", *STEADY[3:], "--radial-clearance", "5e-5"],
     "error: load = inf: out of range (allowed: finite, > 0)"),
    (["loads", str(FLORES_TABLE.parents[1] / "kamaz_740_truck_diesel.toml"), "--out",
      "unused", "--step", "1e-6"],
     "error: --step = 1e-06: out of range (allowed: >= 0.0072 (budget 100000 rows per cycle) "
     "and <= 10 deg, dividing 720)"),
    (["mechanism", str(FLORES_TABLE.parents[1] / "kulayev_worn_rod_bearings.toml"), "--out",
      "unused", "--sweep", "speed=1e-300:3000:3"],
     "error: --sweep speed = 1e-300: out of range (allowed: >= 1 and <= 30000 rpm)"),
    (["run", str(FLORES_TABLE.parents[1] / "flores2006_table_load.toml"), "--out", "unused",
      "--grid", "2048x512", "--film", "reynolds"],
     "error: solver.n_theta x solver.n_z = '2048x512': out of range (allowed: n_theta * "
     "(n_z + 1) <= 300000 nodes)"),
])
def test_command_line_options_are_checked(tmp_path, monkeypatch, args, expected):
    from typer.testing import CliRunner

    from conrod.cli.app import _register_commands, app

    _register_commands()
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, args)
    assert result.exit_code == 2
    assert result.output.strip() == expected
