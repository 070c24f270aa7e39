"""Sign-off of real runs: the maps' extremes are cycle.csv's per-angle numbers, the margins
the headline's, the netCDF fields round-trip exactly, the report shows margins and maps in
a real browser."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

import conrod
import conrod.output  # noqa: F401  (registers the tables and figures)
from conrod import Case, Simulation
from conrod.cli.app import _register_commands, app
from conrod.cli.options import optional_fields_stride
from conrod.film.characteristics import minimum_film_at, peak_pressure_at
from conrod.output.fields_file import fields_dataset
from conrod.output.registry import write_results
from conrod.report import write_report
from conrod.results.summary import headline
from hardening_helpers import EXAMPLES, cheap_table_run, write_case
from test_report import assert_not_blank, browse

LIMITS = {"min_film_thickness": 0.6e-6, "max_pressure": 700e6, "pressure_range": 300e6,
          "asperity_pressure": 5e6, "max_temperature": 150.0}
"""Limits the passenger car's finite film crosses (MOFT, Δp) and keeps (the others)."""


@pytest.fixture(scope="module")
def reynolds_run():
    """The passenger car with the finite-length film and asperity contact at 36 x 8, its
    fields kept at every output angle (1°)."""
    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm_reynolds.toml")
    case = case.with_(limits=LIMITS)
    return Simulation(case, n_theta=36, n_z=8, fields=1.0).run()


def _refined_rows(values: np.ndarray, theta: np.ndarray, largest: bool):
    """Each row's extreme node refined as the film refines its p_max / h_min [-]."""
    from types import SimpleNamespace

    grid = SimpleNamespace(n_theta=theta.size, theta=theta, d_theta=2 * math.pi / theta.size)
    refine = peak_pressure_at if largest else minimum_film_at
    out = []
    for row in values:
        j, k = np.unravel_index(int(row.argmax() if largest else row.argmin()), row.shape)
        out.append(refine(row, grid, int(j), int(k))[0])
    return np.array(out)


def test_map_extremes_are_the_per_angle_numbers_of_cycle_csv(reynolds_run):
    """Every row of the pressure and film-thickness fields refined at its extreme node is
    that row's p_max and h_min of cycle.csv, to the last bit; the maps' worst values are the
    cycle's extremes at their crank angles, on the shell and on the journal."""
    cycle, signoff = reynolds_run.cycle, reynolds_run.signoff
    fields = signoff.fields
    assert fields.crank_angle.size == cycle.crank_angle.size  # the stride 1° = output step
    np.testing.assert_array_equal(_refined_rows(fields["pressure"], fields.theta, True),
                                  cycle.p_max)
    np.testing.assert_allclose(_refined_rows(fields["film_thickness"], fields.theta, False),
                               cycle.h_min, rtol=1e-12)
    for frame in ("shell", "journal"):
        p_map = signoff.indicators.get("max_pressure", frame)
        assert p_map.worst_value == cycle.p_max.max()
        assert p_map.worst_crank_angle == cycle.crank_angle[cycle.p_max.argmax()]
        h_map = signoff.indicators.get("min_film_thickness", frame)
        assert h_map.worst_value == pytest.approx(cycle.h_min.min(), rel=1e-12)
        assert h_map.worst_crank_angle == cycle.crank_angle[cycle.h_min.argmin()]
        np.testing.assert_array_equal(p_map.values.max(), fields["pressure"].max())
    # the journal map's MOFT sits where cycle.csv puts h_min on the journal
    row = int(cycle.h_min.argmin())
    journal = signoff.indicators.get("min_film_thickness", "journal")
    assert journal.worst_theta == pytest.approx(cycle.h_min_angle_journal[row] % (2 * math.pi),
                                                abs=1e-12)
    asperity = signoff.indicators.get("max_asperity_pressure")
    assert 0.0 < asperity.worst_value < 1e9  # mixed lubrication: h/σ ≈ 1.3 at h_min
    erosion = signoff.indicators.erosion
    assert erosion is not None and erosion.long_name.startswith("proxy")


def test_margins_are_the_numbers_the_headline_prints(reynolds_run):
    """MOFT and POFP margins carry summary.film_h_min and summary.p_max; each margin's
    text is a headline line; a crossed limit is a warning and the run exits 4."""
    summary, signoff = reynolds_run.summary, reynolds_run.signoff
    rows = {m.name: m for m in signoff.margins}
    assert rows["min_film_thickness"].value == summary.film_h_min
    assert rows["min_film_thickness"].crank_angle == summary.film_h_min_crank_angle
    assert rows["max_pressure"].value == summary.p_max
    assert rows["max_temperature"].value == summary.effective_temperature
    lines = headline(reynolds_run)
    for m in signoff.margins:
        assert lines[f"margin {m.name}"] == m.text()
    shown_p = lines["p_max"].split(" at ")[0]  # '507.43 MPa'
    assert lines["margin max_pressure"].startswith(shown_p + " vs limit")
    shown_h = lines["film h_min"].split(" at ")[0]  # '0.487 µm'
    assert lines["margin min_film_thickness"].startswith(shown_h + " vs limit")
    shown_t = lines["temperature"].split(" effective")[0]  # '108.1 °C'
    assert lines["margin max_temperature"].startswith(shown_t + " vs limit")
    crossed = {m.name for m in signoff.margins if m.crossed}
    assert crossed == {"min_film_thickness", "pressure_range"}
    assert sum("limit crossed" in w for w in summary.warnings) == 2
    assert summary.exit_code == 4


@pytest.fixture(scope="module")
def run_folder(reynolds_run, tmp_path_factory):
    out = tmp_path_factory.mktemp("signoff_run")
    write_results(reynolds_run, out, figures=True)
    return out


def test_fields_netcdf_round_trip_is_exact(reynolds_run, run_folder):
    """fields.nc read back by conrod.open_fields is the written Dataset (values, dims,
    units, long names), bit for bit the fields the run computed."""
    written = fields_dataset(reynolds_run.signoff.fields)
    read = conrod.open_fields(run_folder)
    xr.testing.assert_identical(read, written)
    for name, values in reynolds_run.signoff.fields.values.items():
        np.testing.assert_array_equal(read[name].values, values)
        assert read[name].dims == ("crank_angle", "theta", "z")
        assert read[name].attrs["units"] and read[name].attrs["long_name"]
    assert set(read.data_vars) >= {"pressure", "film_thickness", "asperity_pressure",
                                   "journal_rotation"}
    assert read.attrs["Conventions"].startswith("CF-")
    size = (run_folder / "fields.nc").stat().st_size
    assert size < 0.5 * sum(v.nbytes for v in reynolds_run.signoff.fields.values.values())


def test_summary_json_and_margins_csv_hold_the_same_numbers(reynolds_run, run_folder):
    summary = json.loads((run_folder / "summary.json").read_text(encoding="utf-8"))
    margins = summary["signoff"]["margins"]
    assert margins["max_pressure"]["value_Pa"] == reynolds_run.summary.p_max
    assert margins["min_film_thickness"]["value_m"] == reynolds_run.summary.film_h_min
    assert margins["pressure_range"]["crossed"] is True
    text = (run_folder / "margins.csv").read_text(encoding="utf-8").splitlines()
    assert text[0].startswith("limit,unit,value,limit_value,margin") and len(text) == 6
    assert (run_folder / "indicator_maps.csv").is_file()


def test_report_shows_the_margins_and_maps_in_a_browser(run_folder, tmp_path):
    (html_file,) = write_report(run_folder, tmp_path / "run.html")
    html = html_file.read_text(encoding="utf-8")
    assert "<h2>Sign-off: margins and per-cell indicators</h2>" in html
    assert html.index("Sign-off") < html.index("Cycle summary")  # right after the headline
    assert "CROSSED" in html and "pressure range Δp (lining fatigue)" in html
    for title in ("Per-cell indicators on the shell", "Per-cell indicators on the journal",
                  "Cavitation-erosion indicator"):
        assert title in html
    pixels, images, broken, dom = browse(html_file, tmp_path)
    assert broken == 0 and images == html.count("<img ")
    assert "margins" in dom and "CROSSED" in dom
    assert_not_blank(pixels)


def test_fields_are_the_rows_the_characteristics_solved(monkeypatch):
    """A rigid Reynolds run solves the film once per output angle: the sign-off reads the
    pressure fields of the characteristics' solves (no film solve of its own), and they
    are the fields that solving every row again gives, bit for bit."""
    from conrod.orbit.memory import FilmSession
    from conrod.simulation.fields import cycle_fields

    case = cheap_table_run()
    case["solver"].update(film="reynolds", n_theta=36, n_z=8)
    results, thermal = Simulation(Case.from_dict(case)).run_orbit()
    cycle, memory = results.cycle, thermal.orbit.last.film_memory
    assert len(thermal.rows) == len(cycle.crank_angle) and memory is None
    again = cycle_fields(thermal.problem, cycle, memory)  # every row solved again
    solves = []
    solve = FilmSession.solve

    def counted(self, *args, **kwargs):
        solves.append(1)
        return solve(self, *args, **kwargs)

    monkeypatch.setattr(FilmSession, "solve", counted)
    kept = cycle_fields(thermal.problem, cycle, memory, thermal.rows)
    assert solves == []
    assert sorted(kept.values) == sorted(again.values)
    for name, values in again.values.items():
        assert np.array_equal(kept.values[name], values), name
    for name, (values, angles) in again.row_extremes.items():
        assert np.array_equal(kept.row_extremes[name][0], values)
        assert np.array_equal(kept.row_extremes[name][1], angles)
    assert Simulation(Case.from_dict(case), signoff=False).run_orbit()[1].rows is None


def test_mass_conserving_film_gives_the_reformation_intensity():
    """The fed passenger car with the mass-conserving film (massless orbit, 36 x 8): its
    fields hold the film fraction, the erosion map is the reformation intensity, and the
    pressure map's worst value is the cycle's p_max."""
    data = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml").model_dump(
        exclude_none=True)
    data["bearing"].update(supply_pressure=0.3e6, grooves=[{"width": 0.002}])
    data["solver"].update(film="mass_conserving", n_theta=36, n_z=8, integrator="quasi_static",
                          contact_film_thickness=0.0, thermal_iterations=0)
    results = Simulation(Case.from_dict(data, base_dir=EXAMPLES), fields=5.0).run()
    fields, indicators = results.signoff.fields, results.signoff.indicators
    assert "film_fraction" in fields and fields["film_fraction"].min() < 0.5
    assert np.degrees(np.diff(fields.crank_angle)).min() >= 5.0 - 1e-9
    assert indicators.erosion.long_name.startswith("reformation intensity")
    assert indicators.erosion.worst_value > 0.0
    assert indicators.get("max_pressure").worst_value == results.cycle.p_max.max()


def test_bare_fields_option_takes_the_default_stride(tmp_path):
    """``--fields`` alone keeps every 1°; with a value, that stride; a run writes fields.nc
    that open_fields reads (the Flores table load, short film: a second)."""
    assert optional_fields_stride(["run", "c.toml", "--fields"])[-1] == "1"
    assert optional_fields_stride(["run", "c.toml", "--fields", "--out", "x"])[3] == "1"
    assert optional_fields_stride(["run", "c.toml", "--fields", "5"]) == [
        "run", "c.toml", "--fields", "5"]
    data = cheap_table_run()
    data["solver"]["max_cycles"] = 12  # to its periodic orbit: exit 4 from the limit alone
    data["limits"] = {"max_pressure": 1e6}  # the Flores bearing peaks near 6 MPa: crossed
    case = write_case(tmp_path, data)
    _register_commands()
    result = CliRunner().invoke(app, ["run", str(case), "--out", str(tmp_path / "out"),
                                      "--fields", "10", "--no-figures"])
    assert result.exit_code == 4, result.output
    assert "margin max_pressure" in result.output and "CROSSED" in result.output
    read = conrod.open_fields(tmp_path / "out")
    np.testing.assert_allclose(np.diff(read["crank_angle"].values), 10.0)
    assert set(read.data_vars) == {"pressure", "film_thickness", "journal_rotation"}


def test_elastic_film_declares_its_deformation_and_film_fraction():
    """The elastic mass-conserving film declares the bore deformation δ(θ, z) and its inner
    film's film fraction (HasFilmFields); the film thickness built with that δ is the gap
    the film solved: its smallest node is the film's h_min of the step."""
    from conrod.ehd.film import ElasticSettings
    from conrod.ehd.mass_conserving_ehd import ElasticMassConservingFilm
    from conrod.film.base import FilmState
    from conrod.film.capabilities import HasFilmFields
    from conrod.film.mass_conserving.film import MassConservingFilm
    from conrod.simulation.fields import film_thickness_field
    from elastic_helpers import winkler_housing

    data = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml").model_dump(
        exclude_none=True)
    data["bearing"].update(supply_pressure=0.3e6, grooves=[{"width": 0.002}])
    geometry = Case.from_dict(data, base_dir=EXAMPLES).bearing.geometry()
    base = MassConservingFilm(geometry, n_theta=36, n_z=8, tolerance=1e-10)
    film = ElasticMassConservingFilm(base, winkler_housing(geometry, 36, 1e-13), 209.0,
                                     ElasticSettings(rigid_start=0.0, ramp=0.0))
    assert isinstance(film, HasFilmFields) and not isinstance(base, HasFilmFields)
    c = geometry.radial_clearance
    state = FilmState(eccentricity_x=0.8 * c, eccentricity_y=0.1 * c, velocity_x=2e-3,
                      velocity_y=-1e-3, journal_speed=209.0, shell_speed=0.0, viscosity=0.01)
    _, _, after = film.content_step(state, film.initial_memory(), 1e-4)
    result = film.accepted_result(state, after)
    fields = film.film_fields(state, after)
    theta, z = film.grid()
    deformation = fields["deformation"].values
    assert deformation.shape == (36, 9) and deformation.max() > 0.0
    assert fields["deformation"].units == "m"
    fraction = fields["film_fraction"].values
    assert fraction.shape == (36, 9) and 0.0 <= fraction.min() < 1.0 == fraction.max()
    h = film_thickness_field(geometry, state, np.asarray(theta), np.asarray(z), deformation)
    assert h.min() == pytest.approx(result.min_film_thickness, rel=1e-12)


class _HotFilm:
    """The Flores bearing's short film, declaring a film temperature field as a thermal
    film would (HasFilmFields): T = 90 °C + 20 °C x e_x/c on the shell, a known history."""

    def __init__(self, base):
        self.base = base
        self.name, self.geometry = base.name, base.geometry

    def solve(self, state, *, with_pressure=False):
        return self.base.solve(state, with_pressure=with_pressure)

    def force(self, state):
        return self.base.force(state)

    def grid(self):
        return self.base.grid()

    def initial_history(self):
        return None

    def film_fields(self, state, memory):
        from conrod.film.capabilities import FilmField

        theta, z = self.grid()
        ratio = state.eccentricity_x / self.geometry.radial_clearance
        values = np.full((len(theta), len(z)), 90.0 + 20.0 * ratio)
        return {"temperature": FilmField(values, "degC", "film temperature")}


def test_a_declared_temperature_field_plugs_into_fields_maps_and_margins(tmp_path):
    """A film that declares 'temperature' gets it in the fields file, a max_temperature map
    (largest over the cycle = 90 + 20 max e_x/c) and the temperature margin read from that
    map instead of the heat balance; crossing it is a warning."""
    from conrod.film.short.film import ShortBearingFilm

    data = cheap_table_run()
    data["solver"]["max_cycles"] = 12
    data["limits"] = {"max_temperature": 100.0}  # the journal reaches e_x = 0.71 c: 104 °C
    case = Case.from_dict(data, base_dir=EXAMPLES)
    film = _HotFilm(ShortBearingFilm(case.bearing.geometry()))
    results = Simulation(case, film=film, fields=5.0).run()
    signoff = results.signoff
    expected = 90.0 + 20.0 * results.cycle.eccentricity_x.max() / results.clearance
    item = signoff.indicators.get("max_temperature")
    assert item.worst_value == pytest.approx(expected, rel=1e-12)
    (margin,) = signoff.margins
    assert margin.value == item.worst_value and "max_temperature map" in margin.source
    assert expected > 100.0 and margin.crossed
    assert any("film temperature" in w for w in results.summary.warnings)
    write_results(results, tmp_path, figures=False)
    read = conrod.open_fields(tmp_path)
    assert read["temperature"].attrs["units"] == "degC"
    np.testing.assert_array_equal(read["temperature"].values,
                                  signoff.fields["temperature"])


def test_a_bad_fields_stride_is_one_line_exit_2(tmp_path):
    case = write_case(tmp_path, cheap_table_run())
    _register_commands()
    result = CliRunner().invoke(app, ["run", str(case), "--out", str(tmp_path / "out"),
                                      "--fields", "0"])
    assert result.exit_code == 2
    assert "--fields (Simulation fields) = 0.0: out of range" in result.output
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())
