"""What the engineer sees: exit codes, the headline, the friction split in the heat
balance, command-line hygiene and the Python API."""

from __future__ import annotations

import dataclasses
import json

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod.cli.app import _register_commands, app
from conrod.orbit.heat_balance import effective_temperature
from hardening_helpers import EXAMPLES, cheap_table_run, mutated, write_case


@pytest.fixture(scope="module")
def runner():
    _register_commands()
    return CliRunner()


def _periodic_case() -> dict:
    return mutated(cheap_table_run(), ("solver", "max_cycles"), 12)


def test_non_periodic_orbit_exits_3_and_accept_warnings_exits_0(runner, tmp_path):
    case = write_case(tmp_path, mutated(cheap_table_run(), ("solver", "max_cycles"), 1))
    # one cycle from the concentric start: not periodic
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "a"),
                                 "--no-figures"])
    assert result.exit_code == 3 and "not converged" in result.output
    assert json.loads((tmp_path / "a" / "summary.json").read_text())["converged"] is False
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "b"),
                                 "--no-figures", "--accept-warnings"])
    assert result.exit_code == 0, result.output


def _thin_film_case() -> dict:
    """200 x the Flores load at 100 rpm: the film thins below the roughness and its rigid
    pressure passes the lining hardness (two warnings)."""
    return mutated(mutated(_periodic_case(), ("load", "scale"), 200), ("load", "speed"), 100)


def test_run_with_warnings_exits_4(runner, tmp_path):
    result = runner.invoke(app, ["run", str(write_case(tmp_path, _thin_film_case())),
                                 "--out", str(tmp_path / "o"), "--no-figures"])
    assert result.exit_code == 4, result.output
    assert "finished with 2 warning(s)" in result.output
    assert "below the combined roughness" in result.output
    assert "the hardness of the hardest big-end lining alloys" in result.output
    assert (tmp_path / "o" / "summary.json").exists()  # written all the same


def _contact_cycle(share: float):
    """A real cycle with hard contact carrying ``share`` of the load from 90° to 180°."""
    from conrod import Case, Simulation

    cycle = Simulation(Case.from_dict(_periodic_case(), base_dir=EXAMPLES)).run().cycle
    angle = cycle.crank_angle_deg
    touching = (angle >= 90.0) & (angle <= 180.0)
    load = np.hypot(cycle.load_x, cycle.load_y)
    force = np.where(touching, share * load, 0.0)
    return dataclasses.replace(cycle, in_contact=touching, contact_force=force,
                               friction_force=0.1 * force,
                               sliding_speed=np.where(touching, 2.0, 0.0))


def test_contact_share_and_intervals_are_reported():
    """Independent answer: the share is P_c/|F| as constructed, the interval 90–180°."""
    from conrod.results.summary import contact_intervals, contact_load_share, contact_warnings

    cycle = _contact_cycle(0.68)
    assert contact_load_share(cycle).max() == pytest.approx(0.68, rel=1e-12)
    assert contact_intervals(cycle) == [(90.0, 180.0)]
    (warning,) = contact_warnings(cycle)
    assert "68% of the load" in warning and "90–180°" in warning
    assert contact_warnings(_contact_cycle(0.1)) == []


def test_heat_balance_includes_contact_and_boundary_friction():
    """Independent answer: the heat balance N = ρ c_p Q ΔT with N = film power + the mean of
    μ P_c |V| (here 0.1 P_c x 2 m/s where in contact) + the boundary (asperity) friction."""
    from conrod import Case
    from conrod.simulation.orbit_outputs import heat_balance_temperature

    cycle = _contact_cycle(0.5)
    lubricant = Case.from_dict(_periodic_case(), base_dir=EXAMPLES).lubricant
    contact_power = np.mean(0.1 * cycle.contact_force * 2.0)
    assert contact_power > 0.0
    rho = lubricant.density_at(lubricant.supply_temperature)
    expected = lubricant.supply_temperature + (cycle.friction_power.mean() + contact_power) / (
        rho * lubricant.specific_heat * cycle.side_flow.mean())
    assert heat_balance_temperature(cycle, lubricant) == pytest.approx(expected, rel=1e-12)
    boundary = 12.5  # [W] cycle mean of μ F_a |V| of the asperities
    assert heat_balance_temperature(cycle, lubricant, boundary) == pytest.approx(
        expected + boundary / (rho * lubricant.specific_heat * cycle.side_flow.mean()),
        rel=1e-12)


def test_headline_on_terminal_and_at_the_top_of_summary_json(runner, tmp_path):
    out = tmp_path / "o"
    result = runner.invoke(app, ["run", str(write_case(tmp_path, _periodic_case())),
                                 "--out", str(out), "--no-figures", "--accept-warnings"])
    assert result.exit_code == 0, result.output
    for label in ("model", "film h_min", "contact", "p_max", "friction power", "oil flow",
                  "temperature", "warnings"):
        assert label in result.output
    summary = json.loads((out / "summary.json").read_text())
    assert list(summary)[:5] == ["headline", "conrod_version", "case_hash_sha256",
                                 "converged", "solver_settings"]
    assert len(summary["case_hash_sha256"]) == 64
    assert summary["solver_settings"]["film"] == "short"
    assert "isoviscous" in summary["headline"]["model"]


def test_friction_split_sums_and_heat_balance_uses_it():
    """Independent answer: T_eff = T_s + (N_film + N_contact)/(ρ c_p Q), the global heat
    balance, with the contact power μ P_c |V| integrated from the per-angle columns."""
    from conrod import Case, Simulation

    case = Case.from_dict(_thin_film_case(), base_dir=EXAMPLES)
    results = Simulation(case).run()
    s, cycle = results.summary, results.cycle
    contact = np.mean(np.abs(cycle.friction_force) * np.abs(cycle.sliding_speed))
    assert s.mean_contact_friction_power == pytest.approx(contact, rel=1e-12)
    assert s.mean_total_friction_power == pytest.approx(
        s.mean_friction_power + s.mean_contact_friction_power, rel=1e-12)
    lubricant = case.lubricant
    expected = effective_temperature(
        s.mean_total_friction_power, s.mean_side_flow, lubricant.supply_temperature,
        lubricant.density_at(lubricant.supply_temperature), lubricant.specific_heat)
    assert s.effective_temperature == pytest.approx(expected, rel=1e-9)


def test_help_keeps_units_and_version(runner):
    assert "[rpm]" in runner.invoke(app, ["steady", "--help"]).output
    assert "[deg]" in runner.invoke(app, ["loads", "--help"]).output
    assert "[rpm]" in runner.invoke(app, ["mechanism", "--help"]).output
    root = runner.invoke(app, ["--help"]).output
    assert "Exit codes" in root and "finished with warnings" in root
    from conrod import __version__

    result = runner.invoke(app, ["--version"])
    assert result.exit_code == 0 and result.output.strip() == f"conrod {__version__}"


def test_root_help_lists_each_command_s_whole_summary(runner):
    """`conrod --help` (80 columns) gives each command's first help paragraph whole,
    wrapped, not cut at the terminal's width with "..."."""
    import inspect

    root = " ".join(runner.invoke(app, ["--help"]).output.split())
    for info in app.registered_commands:
        first = (info.help or inspect.getdoc(info.callback)).split("\n\n")[0].split()
        assert " ".join(first[-3:]) in root, first


def test_help_pages_show_units_without_markup_escapes(runner):
    """Every command's help is plain text: a unit in brackets shows as written, not with
    the backslash rich markup needed (`\\[rpm]`)."""
    for info in app.registered_commands:
        page = runner.invoke(app, [info.name, "--help"]).output
        assert "\\" not in page, (info.name, page)


def test_film_choice_is_validated_by_the_command_line(runner, tmp_path):
    result = runner.invoke(app, ["run", str(EXAMPLES / "flores2006_table_load.toml"),
                                 "--out", str(tmp_path / "o"), "--film", "shortt"])
    assert result.exit_code == 2 and "--film" in result.output
    assert not (tmp_path / "o").exists()


def test_with_validates_the_changed_copy():
    from conrod import Case, CaseError

    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml")
    faster = case.with_(engine__speed=3000)
    assert faster.engine.speed == 3000 and case.engine.speed == 2000
    assert faster.content_hash() != case.content_hash()
    with pytest.raises(CaseError, match="engine.speed"):
        case.with_(engine__speed=-5)


def test_run_api_and_dataframe_with_units(tmp_path):
    """conrod.run on a case object; every DataFrame column name ends in its unit and the
    values agree with the fields (angles converted to degrees)."""
    import conrod

    case = conrod.Case.from_dict(_periodic_case(), base_dir=EXAMPLES)
    results = conrod.run(case)
    frame = results.cycle.to_dataframe()
    units = ("_deg", "_m", "_m_s", "_Pa", "_N_m", "_W", "_m3_s", "_N", "_rad_s", "_1")
    assert all(name.endswith(units) for name in frame.columns if name != "in_contact")
    assert np.array_equal(frame["h_min_m"].to_numpy(), results.cycle.h_min)
    assert np.allclose(frame["crank_angle_deg"].to_numpy(), np.degrees(results.cycle.crank_angle))


def test_no_figures_writes_no_png_and_a_rerun_leaves_no_stale_file(runner, tmp_path):
    case = write_case(tmp_path, _periodic_case())
    out = tmp_path / "o"
    first = runner.invoke(app, ["run", str(case), "--out", str(out), "--accept-warnings"])
    assert first.exit_code == 0, first.output
    assert list(out.glob("*.png"))
    (out / "notes.txt").write_text("mine")  # a file of the user's, not of conrod's
    second = runner.invoke(app, ["run", str(case), "--out", str(out), "--no-figures",
                                 "--accept-warnings"])
    assert second.exit_code == 0, second.output
    assert not list(out.rglob("*.png"))  # the previous figures are gone, none written
    manifest = json.loads((out / "manifest.json").read_text())
    listed = {entry["file"] for entry in manifest["tables"]} | {"manifest.json"}
    assert {p.name for p in out.iterdir()} == listed | {"notes.txt"}


@pytest.mark.parametrize("command", ["housing", "stress", "sweep"])
def test_every_command_checks_out_before_computing(runner, tmp_path, command):
    taken = tmp_path / "taken"
    taken.write_text("keep me")
    result = runner.invoke(app, [command, str(EXAMPLES / "passenger_car_diesel_2000rpm.toml"),
                                 "--out", str(taken)])
    assert result.exit_code == 2 and "is an existing file" in result.output
    assert taken.read_text() == "keep me"


@pytest.mark.parametrize("peak_deg", [0.0, 5.0, 180.0, 357.5])
def test_pressure_map_peak_lies_inside_the_plot_away_from_its_edges(peak_deg):
    """A field whose peak sits at ``peak_deg`` (also at the 0°/360° seam) is drawn with the
    peak in the middle of the window: at least 90° from either edge."""
    import conrod.plotting.orbit_plots as orbit_plots
    from conrod import Case, Simulation

    results = Simulation(Case.from_dict(_periodic_case(), base_dir=EXAMPLES)).run()
    theta = np.linspace(0.0, 2.0 * np.pi, 145)
    z = np.linspace(-0.01, 0.01, 9)
    distance = np.angle(np.exp(1j * (theta - np.radians(peak_deg))))
    field = 1e6 * np.exp(-(distance / 0.2) ** 2)[:, None] * np.cos(z / 0.02)[None, :]
    results = dataclasses.replace(results, pressure_at_p_max=field, pressure_grid=(theta, z))
    ax = orbit_plots.plot_pressure_map(results).axes[0]
    mesh = ax.collections[0]
    values = np.asarray(mesh.get_array()).reshape(z.size, -1)
    edges = mesh.get_coordinates()[0, :, 0]
    column = int(np.argmax(values.max(axis=0)))
    x_peak = 0.5 * (edges[column] + edges[column + 1])
    left, right = ax.get_xlim()
    assert min(x_peak - left, right - x_peak) > 90.0
    assert np.isclose(x_peak % 360.0, peak_deg % 360.0, atol=2.6)


def test_run_registers_the_film_thickness_map_and_envelope():
    """Independent answer for the envelope: h = c − |e| at the shell angle facing the
    journal centre, so min over θ and φ of the map equals min over φ of c − |e|."""
    import conrod.output  # noqa: F401  (registers the tables and figures)
    from conrod import Case, Simulation
    from conrod.output.registry import figures

    results = Simulation(Case.from_dict(_periodic_case(), base_dir=EXAMPLES)).run()
    files = {spec.file for spec in figures(results)}
    assert {"film_thickness_map.png", "min_film_envelope.png"} <= files
    h = results.film_thickness
    e = np.hypot(results.cycle.eccentricity_x, results.cycle.eccentricity_y)
    assert h.min() == pytest.approx((results.clearance - e).min(), rel=1e-4)


def test_loads_of_a_load_table_case(runner, tmp_path):
    """A bearing given by its load table gets its load diagram; the summary's peak is the
    largest |F| of the table (independent: read back from loads.csv)."""
    out = tmp_path / "o"
    result = runner.invoke(app, ["loads", str(EXAMPLES / "flores2006_table_load.toml"),
                                 "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert (out / "polar_load_diagram.png").stat().st_size > 1000
    table = np.genfromtxt(out / "loads.csv", delimiter=",", names=True)
    summary = json.loads((out / "loads_summary.json").read_text())
    assert summary["peak_load_N"] == pytest.approx(
        np.hypot(table["load_x_N"], table["load_y_N"]).max(), rel=1e-9)


def _rk2_case() -> dict:
    return mutated(cheap_table_run(), ("solver",), {
        "film": "short", "integrator": "rk2", "step_deg": 1.25, "output_step_deg": 5.0,
        "max_cycles": 12, "min_cycles": 1, "mass_x": 200.0, "mass_y": 200.0})


def test_under_resolved_rk2_orbit_exits_4(runner, tmp_path):
    """Step study: at 1.25° the smallest h_min is 3 % above the 0.625° answer (which moves
    by < 0.01 % at 0.3125°): under-resolved, exit 4; at 0.625° the check passes."""
    case = write_case(tmp_path, _rk2_case())
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "a"),
                                 "--no-figures"])
    assert result.exit_code == 4, result.output
    assert "under-resolved" in result.output
    summary = json.loads((tmp_path / "a" / "summary.json").read_text())
    assert any("under-resolved" in w for w in summary["warnings"])
    result = runner.invoke(app, ["run", str(case), "--out", str(tmp_path / "b"),
                                 "--no-figures", "--step-deg", "0.625"])
    assert result.exit_code == 0, result.output


def test_mass_conserving_without_oil_feed_is_refused_before_computing(runner, tmp_path):
    result = runner.invoke(app, ["run", str(EXAMPLES / "passenger_car_diesel_2000rpm.toml"),
                                 "--out", str(tmp_path / "o"), "--film", "mass_conserving"])
    assert result.exit_code == 2, result.output
    assert "needs an oil feed above the cavitation pressure" in result.output
    assert "bearing.supply_pressure" in result.output
    assert not (tmp_path / "o").exists()


def test_mass_conserving_without_oil_feed_is_refused_by_the_python_api_too():
    from conrod import Case, Simulation
    from conrod.errors import CaseError

    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml")
    with pytest.raises(CaseError, match=r"needs an oil feed .*bearing.supply_pressure = 0 Pa"):
        Simulation(case, film="mass_conserving")
    grooved = Case.from_toml(EXAMPLES / "ruston_hornsby_6vebx_mk3.toml")
    with pytest.raises(CaseError, match="1 groove"):  # a groove, but not fed
        Simulation(grooved, film="mass_conserving")
    Simulation(grooved.with_(bearing__supply_pressure=3e5), film="mass_conserving")


def test_lengths_in_metres_are_keyword_only():
    """A positional 15e-6 could be an eccentricity in metres or a ratio; refused clearly."""
    import dataclasses

    from conrod import BearingGeometry, FilmState

    with pytest.raises(TypeError, match=r"FilmState takes keyword arguments only, got 2 "
                                        r"positional \(eccentricities are in metres"):
        FilmState(15e-6, 0.0, journal_speed=300.0, viscosity=0.01)
    with pytest.raises(TypeError, match=r"BearingGeometry\(diameter=0.05, width=0.025"):
        BearingGeometry(0.05, 0.025, 25e-6)
    state = FilmState(eccentricity_x=15e-6, eccentricity_y=0.0, journal_speed=300.0,
                      viscosity=0.01)
    assert dataclasses.replace(state, viscosity=0.02).viscosity == 0.02  # copies still work
    assert BearingGeometry(diameter=0.05, width=0.025, radial_clearance=25e-6).radius == 0.025


def _rigid_run_with_peak(p_max: float):
    """A plausible 8-point cycle whose film pressure peaks at ``p_max`` [Pa] at 90°."""
    import types

    n = 8
    peaks = np.full(n, 5e7)
    peaks[1] = p_max
    cycle = types.SimpleNamespace(
        crank_angle=np.radians(np.arange(n) * 90.0), eccentricity_ratio=np.full(n, 0.9),
        h_min=np.full(n, 2e-6), p_max=peaks, load_x=np.full(n, 6e4), load_y=np.zeros(n),
        contact_force=np.zeros(n), in_contact=np.zeros(n, dtype=bool))
    case = types.SimpleNamespace(
        contact=types.SimpleNamespace(model="hard", roughness=0.4e-6),
        lubricant=types.SimpleNamespace(max_temperature=200.0))
    summary = types.SimpleNamespace(effective_temperature=120.0)
    return types.SimpleNamespace(cycle=cycle, clearance=25e-6, summary=summary), case


def test_film_pressure_above_lining_hardness_is_flagged():
    """ISO 4383 lining hardness: AlSn20Cu 30-40 HBW, CuPb24Sn4 60-90 HBW (<= 0.9 GPa); the
    bound sits above all of them, so rigid-bore peaks of several hundred MPa pass."""
    from conrod.results import plausibility

    assert plausibility.FILM_PRESSURE_LIMIT > 90 * 9.80665e6  # 90 HBW in Pa
    for usual in (6.5e8, 9.9e8):  # the shipped short-film passenger-car peak is ~650 MPa
        assert plausibility.check_run(*_rigid_run_with_peak(usual)) == []
    warned = plausibility.check_run(*_rigid_run_with_peak(13.8e9))
    assert len(warned) == 1
    assert warned[0].startswith("p_max 1.38e+04 MPa at crank angle 90.0 deg is above 1000 MPa")
    assert "elastic big end" in warned[0] and "h_min" in warned[0]


@pytest.mark.slow
def test_2000rpm_reynolds_case_is_full_film_as_its_source_says():
    """[D0] §3.5: at 2000 rpm 'dry friction does not occur'. With the finite-length film,
    contact as [D4] eq. 4.1.1 defines it (journal on the clearance circle) and the
    Greenwood-Tripp asperity load of the composite roughness, the film carries the load
    (72x16 as shipped: asperities <= 0.41 % of the load; 36x8 here: 0.65 %)."""
    import conrod
    from conrod.contact.asperity import asperity_force_array, kernel_parameters

    shipped = conrod.Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm_reynolds.toml")
    case = shipped.with_(solver__n_theta=36, solver__n_z=8)  # coarse: 15 s instead of ~1 min
    results = conrod.run(case)
    cycle = results.cycle
    assert float(np.max(cycle.contact_force)) == 0.0 and not np.any(cycle.in_contact)
    assert results.summary.warnings == () and results.summary.periodic
    load = np.hypot(cycle.load_x, cycle.load_y)
    fx, fy = asperity_force_array(cycle.eccentricity_x, cycle.eccentricity_y,
                                  results.clearance, kernel_parameters(case))
    assert float(np.max(np.hypot(fx, fy) / load)) < 0.01  # asperities: under 1 % of the load
    assert 0.0 < results.summary.h_min < case.contact.roughness * 3.0  # thin, yet film


def test_rk2_automatic_step_is_checked_against_the_implicit_orbit():
    """Without a fixed step there is no half step: the reference is the error-controlled
    implicit orbit (the table film at 2000 rpm: rk2 4.11 µm, implicit 1.15 µm)."""
    import types

    from conrod.results.summary import step_study_warnings

    coarse, fine = types.SimpleNamespace(h_min=4.11e-6), types.SimpleNamespace(h_min=1.15e-6)
    (warning,) = step_study_warnings(coarse, fine, None)
    assert warning.startswith("under-resolved: h_min 4.11 µm with rk2's automatic step but "
                              "1.15 µm with the error-controlled implicit integrator")
    assert "solver.step_deg" in warning
    assert step_study_warnings(coarse, types.SimpleNamespace(h_min=4.12e-6), None) == []
    assert "at step 0.01 deg but" in step_study_warnings(coarse, fine, 0.01)[0]


@pytest.mark.slow
def test_rk2_automatic_step_beyond_the_budget_is_refused_with_the_fix(runner, tmp_path):
    """The passenger car's film at 2000 rpm asks rk2 for a step below the step budget
    (1e-4 deg, measured along its implicit orbit): refused with exit 2 and the working
    integrators, not a 6-exabyte allocation (exit 1) nor an exit 3 after trial cycles."""
    result = runner.invoke(app, ["run", str(EXAMPLES / "passenger_car_diesel_2000rpm.toml"),
                                 "--integrator", "rk2", "--max-cycles", "4",
                                 "--no-figures", "--no-step-check",
                                 "--out", str(tmp_path / "o")])
    assert result.exit_code == 2, result.output
    assert "solver.integrator = 'rk2': this bearing's film is too stiff" in result.output
    assert "integrator = 'implicit' or 'auto'" in result.output


@pytest.mark.slow
def test_adaptive_step_with_a_non_finite_jacobian_is_a_solver_failure(runner, tmp_path):
    """R&H with the mobility film under the adaptive integrator: the implicit method's LU
    met a non-finite Jacobian (was exit 1, an internal error); now the next method is
    tried and the run ends as a solver failure naming the crank angle (exit 3)."""
    result = runner.invoke(app, ["run", str(EXAMPLES / "ruston_hornsby_6vebx_mk3.toml"),
                                 "--film", "mobility", "--integrator", "adaptive", "--grid",
                                 "24x8", "--max-cycles", "4", "--no-figures", "--no-step-check",
                                 "--out", str(tmp_path / "o")])
    assert result.exit_code == 3, result.output
    assert "at crank angle" in result.output
