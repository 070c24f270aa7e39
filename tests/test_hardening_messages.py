"""Messages say what is wrong in the user's terms: a table or mobility film past its
eccentricity range says so (not an extrapolated p_max of -1e26 Pa); a misspelt key is one
line with its "did you mean", not that line plus the required field it misspells."""

from __future__ import annotations

import subprocess
import sys

import pytest
from typer.testing import CliRunner

from conrod import Case
from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError, ConvergenceError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.short.film import ShortBearingFilm
from conrod.film.table.film import TabulatedFilm
from hardening_helpers import FLORES_TABLE, example_dict, mutated, write_case

_register_commands()


@pytest.mark.parametrize("args, named, page", [
    (("run", "{case}", "--film", "foo"), "'--film'", "conrod run"),
    (("run", "{case}", "--bogus"), "--bogus", "conrod run"),
    (("runn", "{case}"), "'runn'", "conrod"), (("run",), "'case_file'", "conrod run"),
    (("loads", "{case}", "--grid"), "--grid", "conrod loads"),
    (("run", "{case}", "--grid"), "--grid", "conrod run")])
def test_a_mistake_on_the_command_line_is_one_line(tmp_path, args, named, page):
    """The console command: an unknown option or command, a value not among the choices, a
    missing argument or option value: one line on stderr naming it and the help page to read
    (not click's usage, hint and message), exit 2, nothing on stdout."""
    case = write_case(tmp_path, example_dict("flores2006_table_load"))
    done = subprocess.run(
        [sys.executable, "-c", "from conrod.cli.app import main; main()",
         *(arg.format(case=case) for arg in args)],
        capture_output=True, text=True, timeout=120, check=False)
    lines = done.stderr.strip().splitlines()
    assert done.returncode == 2 and done.stdout == "", (done.returncode, done.stdout)
    assert len(lines) == 1 and lines[0].startswith("error: ") and named in lines[0], lines
    assert lines[0].endswith(f"(see {page} --help)"), lines


@pytest.mark.parametrize("film", ["table", "mobility"])
def test_a_table_film_past_its_range_says_so(tmp_path, film):
    """The Flores bearing with a 40 times thinner oil: the load presses the journal past
    the table's last node (ε = 0.995), where its values are extrapolated. Where the
    extrapolated film is not physical the orbit stops there (exit 3, naming the range);
    where it is, the run says the values are extrapolated (a warning, exit 4) — never a
    silent answer."""
    case = example_dict("flores2006_table_load")
    case["load"]["table"] = str(FLORES_TABLE)
    case["lubricant"]["viscosity"] = 0.0001
    path = write_case(tmp_path, case)
    result = CliRunner().invoke(app, ["run", str(path), "--film", film, "--grid", "36x8",
                                      "--out", str(tmp_path / "out"), "--no-figures"])
    assert result.exit_code in (3, 4), result.output
    if result.exit_code == 3:
        last = result.output.strip().splitlines()[-1]
        assert last.startswith("not converged: journal eccentricity ratio ")
        assert "is beyond the table's eccentricity range (<= 0.995), where" in last
        assert not (tmp_path / "out").exists()
    else:
        warning = next(line for line in result.output.splitlines()
                       if "past the film table's last node (0.995)" in line)
        assert warning.startswith("warning: journal eccentricity ratio up to 0.99")
        assert "values there are extrapolated, not tabulated" in warning


def test_a_table_film_on_the_shell_says_so_instead_of_dividing_by_zero():
    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6)
    film = TabulatedFilm(ShortBearingFilm(geometry), n_eps=5, n_direction=8, use_cache=False)
    state = FilmState(eccentricity_x=25e-6, eccentricity_y=0.0, velocity_x=1e-3,
                      journal_speed=200.0, viscosity=0.01)
    with pytest.raises(ConvergenceError, match=r"^journal eccentricity ratio 1 \(h_min = 0 m\) "
                       r"is beyond the table's eccentricity range \(<= 0.995\), where the "
                       "journal touches the shell"):
        film.solve(state)


@pytest.mark.parametrize(("section", "wrong", "right"), [
    ("load", "sped", "speed"), ("bearing", "widht", "width"),
    ("lubricant", "viscosty", "viscosity")])
def test_a_misspelt_required_key_is_one_line_with_did_you_mean(tmp_path, section, wrong,
                                                               right):
    case = example_dict("flores2006_table_load")
    case["load"]["table"] = str(FLORES_TABLE)
    value = case[section].pop(right)
    path = write_case(tmp_path, mutated(case, (section, wrong), value))
    with pytest.raises(CaseError) as caught:
        Case.from_toml(path)
    [line] = str(caught.value).splitlines()
    assert f"{section}.{wrong}: unknown key '{wrong}'; did you mean '{right}'?" in line
