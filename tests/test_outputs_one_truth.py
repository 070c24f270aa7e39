"""One truth in every output: the headline, summary.json and cycle.csv give the same h_min
angle and contact intervals; contact outputs only where there is contact; the friction split
sums and the heat balance takes all of it; one naming for cycle.csv and to_dataframe();
units everywhere (conrod steady); the case recorded in the result folder; a rerun renews its
report; the default --out and a folder of folders say why; unit slips refused with the value
meant; the mechanism's regime criterion finite and monotone."""

from __future__ import annotations

import json
import re
import tomllib

import numpy as np
import pandas as pd
import pytest
from typer.testing import CliRunner

from conrod import Case, Simulation
from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError
from hardening_helpers import EXAMPLES, cheap_table_run, mutated, write_case


@pytest.fixture(scope="module")
def runner():
    _register_commands()
    return CliRunner()


def _periodic() -> dict:
    return mutated(cheap_table_run(), ("solver", "max_cycles"), 12)


def _thin_film() -> dict:
    """200 x the Flores load at 100 rpm: the film thins below the roughness (exit 4)."""
    return mutated(mutated(_periodic(), ("load", "scale"), 200), ("load", "speed"), 100)


@pytest.mark.slow
def test_headline_summary_and_cycle_csv_give_one_h_min_angle_and_contact_interval(
        runner, tmp_path):
    """The 1000 rpm example touches the shell around combustion: the film h_min (outside
    contact), its angle and the contact interval read the same in the headline,
    summary.json and cycle.csv (before: 61° vs 22°, 19–60° vs 18.05–58.33°)."""
    out = tmp_path / "pc1000"
    result = runner.invoke(app, ["run", str(EXAMPLES / "passenger_car_diesel_1000rpm.toml"),
                                 "--out", str(out), "--no-figures"])
    assert result.exit_code == 4, result.output
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    cycle = pd.read_csv(out / "cycle.csv")
    free = cycle[cycle["in_contact"] == 0]
    row = free["h_min_m"].idxmin()
    assert summary["film_h_min_m"] == pytest.approx(free["h_min_m"][row], rel=1e-9)
    angle = summary["film_h_min_crank_angle_deg"]
    assert angle == pytest.approx(free["crank_angle_deg"][row])
    touching = cycle["crank_angle_deg"][cycle["in_contact"] == 1]
    ((start, end),) = summary["contact_intervals_deg"]
    assert (start, end) == pytest.approx((touching.min(), touching.max()))
    lines = summary["headline"]
    assert lines["film h_min"].startswith(f"{summary['film_h_min_m'] * 1e6:.3f} µm at "
                                          f"{angle:.0f}°")
    assert lines["contact"].startswith(f"{start:.0f}–{end:.0f}°")
    assert lines["status"] == "exit code 4 (finished with warnings)"
    assert summary["exit_code"] == 4
    for label in ("film h_min", "contact", "status"):
        assert lines[label] in result.output


def test_contact_outputs_only_where_there_is_contact(tmp_path):
    """A run without contact writes no contact or wear table or figure and gives the
    bearing's nominal specific load W_max/(B·D); a run with contact writes them."""
    import conrod.output  # noqa: F401
    from conrod.output.registry import figures, tables

    case = Case.from_dict(_periodic(), base_dir=EXAMPLES)
    quiet = Simulation(case).run()
    files = {s.file for s in tables(quiet)} | {s.file for s in figures(quiet)}
    assert not {name for name in files if "wear" in name or "contact" in name}
    items = quiet.contact.summary_items()
    load = np.hypot(quiet.cycle.load_x, quiet.cycle.load_y).max()
    assert items["nominal_specific_load_Pa"] == pytest.approx(
        load / (case.bearing.width * case.bearing.diameter))
    touching = Simulation(case.with_(contact__model="hard", solver__contact_film_thickness=
                                     2.0e-6, load__scale=200.0, load__speed=100.0)).run()
    assert touching.contact.has_contact
    files = {s.file for s in tables(touching)} | {s.file for s in figures(touching)}
    assert {"wear_journal.csv", "wear_shell.csv", "contact_cycle.png"} <= files


def test_friction_split_sums_and_the_heat_balance_takes_boundary_friction():
    """Under Greenwood–Tripp contact (the 1000 rpm example with asperity contact instead of
    the hard wall, h/σ = 2.4) the asperities' boundary friction μ F_a |V| is in the total
    and in the heat balance (independent answer from the cycle and the contact analysis:
    T = T_s + (N_film + N_contact + N_boundary)/(ρ c_p Q)); h/σ < 3 is stated."""
    from conrod.orbit.heat_balance import effective_temperature
    from conrod.results.summary import headline

    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_1000rpm.toml").with_(
        contact__model="greenwood_tripp", solver__contact_film_thickness=0.0,
        solver__integrator="quasi_static")
    results = Simulation(case).run()
    s, cycle, contact = results.summary, results.cycle, results.contact
    boundary = np.mean(case.contact.dry_friction_coefficient * contact.asperity_force
                       * np.abs(cycle.sliding_speed))
    assert boundary > 0.0
    assert s.mean_boundary_friction_power == pytest.approx(boundary, rel=1e-12)
    assert s.mean_total_friction_power == pytest.approx(
        s.mean_friction_power + s.mean_contact_friction_power + boundary, rel=1e-12)
    lubricant = case.lubricant
    expected = effective_temperature(
        s.mean_total_friction_power, s.mean_side_flow, lubricant.supply_temperature,
        lubricant.density_at(lubricant.supply_temperature), lubricant.specific_heat)
    assert s.effective_temperature == pytest.approx(expected, rel=1e-9)
    lines = headline(results)
    assert f"boundary (asperities) {boundary:.1f} W" in lines["friction power"]
    assert 1.0 < s.film_thickness_ratio < 3.0
    assert f"h/σ = {s.film_thickness_ratio:.2g} < 3: mixed lubrication" in lines["film h_min"]
    assert not any("h/σ" in warning for warning in s.warnings)


def test_film_below_the_roughness_is_warned():
    """h/σ < 1 outside hard contact is a warning under either contact model (the same
    cycle with its film thinned to 0.8 σ at one angle)."""
    import dataclasses

    from conrod.results.plausibility import check_run

    for model in ("hard", "greenwood_tripp"):
        case = Case.from_dict(mutated(_periodic(), ("contact", "model"), model),
                              base_dir=EXAMPLES)
        results = Simulation(case).run()
        h_min = results.cycle.h_min.copy()
        h_min[100] = 0.8 * case.contact.roughness
        thin = dataclasses.replace(results, cycle=dataclasses.replace(results.cycle,
                                                                      h_min=h_min))
        (warning,) = [w for w in check_run(thin, case) if "h/σ" in w]
        assert "below the combined roughness" in warning and "h/σ = 0.8 < 1" in warning
        assert ("greenwood_tripp" in warning) == (model == "hard")


def test_cycle_csv_and_dataframe_name_the_same_columns(tmp_path):
    import conrod.output  # noqa: F401
    from conrod.output.registry import write_results

    results = Simulation(Case.from_dict(_periodic(), base_dir=EXAMPLES)).run()
    write_results(results, tmp_path / "o", figures=False)
    csv = pd.read_csv(tmp_path / "o" / "cycle.csv")
    frame = results.cycle.to_dataframe()
    assert list(frame.columns) == list(csv.columns)[:len(frame.columns)]
    for name in frame.columns:
        np.testing.assert_allclose(csv[name], np.asarray(frame[name], dtype=float),
                                   rtol=1e-8, atol=1e-300)  # cycle.csv: 9 digits


def test_steady_prints_every_number_with_its_unit(runner):
    result = runner.invoke(app, ["steady", "--load", "10000", "--speed-rpm", "3000",
                                 "--viscosity", "0.01", "--diameter", "0.05", "--width",
                                 "0.05", "--radial-clearance", "5e-5", "--grid", "36x8"])
    assert result.exit_code == 0, result.output
    values = [line.split() for line in result.output.splitlines()]
    numbers = [v for v in values if re.fullmatch(r"[-+0-9.e]+", v[1])]
    assert numbers and all(re.fullmatch(r"\[.+\]", " ".join(v[2:])) for v in numbers), numbers
    lines = dict((v[0], " ".join(v[1:])) for v in values)
    assert lines["min_film_thickness"].endswith("[m]")
    assert lines["max_pressure"].endswith("[Pa]")
    data = json.loads(runner.invoke(app, ["steady", "--load", "10000", "--speed-rpm", "3000",
                                          "--viscosity", "0.01", "--diameter", "0.05",
                                          "--width", "0.05", "--radial-clearance", "5e-5",
                                          "--grid", "36x8", "--json"]).output)
    assert data["units"]["min_film_thickness"] == "m" and data["units"]["K_xx"] == "N/m"


def test_result_folder_records_its_case_and_report_needs_no_case(runner, tmp_path):
    """The case file (as written, comments and all), its load table and the values the
    command line set are in the folder; conrod report DIR lists the inputs with their sources
    without --case and prints no path of this machine."""
    case = write_case(tmp_path, _periodic(), name="flores.toml")
    out = tmp_path / "run"
    result = runner.invoke(app, ["run", str(case), "--out", str(out), "--max-cycles", "9",
                                 "--no-figures"])
    assert result.exit_code == 0, result.output
    manifest = json.loads((out / "manifest.json").read_text(encoding="utf-8"))
    record = manifest["case"]
    assert (out / "case.toml").read_bytes() == case.read_bytes()
    assert record["set"] == {"solver.max_cycles": 9}
    table = out / record["tables"]["load.table"]
    assert table.read_bytes() == (EXAMPLES / "data" / "flores2006_load.csv").read_bytes()
    files = {entry["file"] for entry in manifest["tables"]}
    assert {"case.toml", table.name} <= files and set(manifest["files"]) >= files
    from conrod.output.folder import recorded_case

    again = recorded_case(out)
    assert again.solver.max_cycles == 9 and again.load.scale == Case.from_toml(case).load.scale
    report = runner.invoke(app, ["report", str(out)])
    assert report.exit_code == 0, report.output
    html = (out / "report.html").read_text(encoding="utf-8")
    assert "<h2>Case inputs</h2>" in html and "set for this run (command line)" in html
    assert str(tmp_path) not in html and "/tmp" not in html


def test_rerun_renews_the_report_and_default_out_says_why(runner, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    case = write_case(tmp_path, _periodic(), name="flores.toml")
    first = runner.invoke(app, ["run", str(case), "--no-figures"])
    assert first.exit_code == 0, first.output
    out = tmp_path / "results" / "flores"  # the default: results/<case name>
    assert (out / "summary.json").is_file()
    assert runner.invoke(app, ["report", str(out)]).exit_code == 0
    old = (out / "report.html").read_text(encoding="utf-8")
    again = runner.invoke(app, ["run", str(case), "--no-figures", "--max-cycles", "9"])
    assert again.exit_code == 0, again.output
    assert "rewritten for this result" in again.output
    new = (out / "report.html").read_text(encoding="utf-8")
    assert new != old and "solver.max_cycles = 9" in new
    refused = runner.invoke(app, ["run", str(case), "--out", "results", "--no-figures"])
    assert refused.exit_code == 2
    message = " ".join(refused.output.split())
    assert "holds other result folders (flores)" in message and "a folder of its own" in message


@pytest.mark.parametrize(("change", "meant"), [
    ({"lubricant__viscosity": 6.5}, "did you mean 0.0065 Pa s = 6.5 mPa s?"),
    ({"lubricant__viscosity": 12.0}, "did you mean 0.012 Pa s = 12 mPa s?"),
    ({"bearing__radial_clearance": 0.04}, "did you mean 4e-05 m = 0.04 mm?"),
    ({"bearing__radial_clearance": 40.0}, "did you mean 4e-05 m = 40 µm?"),
    ({"bearing__radial_clearance": 0.005}, "did you mean 5e-06 m = 0.005 mm?"),
    ({"engine__speed": 209.4395}, "did you mean 2000 rpm = 209.4 rad/s?"),
    ({"bearing__diameter": 85.0}, "did you mean 0.085 m = 85 mm?"),
    ({"engine__bore": 81.0}, "did you mean 0.081 m = 81 mm?"),
])
def test_unit_slips_are_refused_with_the_value_meant(change, meant):
    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml")
    with pytest.raises(CaseError) as error:
        case.with_(**change)
    key = next(iter(change)).replace("__", ".")
    assert str(error.value).startswith(f"{key} = ") and meant in str(error.value)


def test_plausible_values_are_not_taken_for_unit_slips():
    case = Case.from_toml(EXAMPLES / "passenger_car_diesel_2000rpm.toml")
    case.with_(lubricant__viscosity=0.15)  # a thick oil at 90 °C: within 10 x SAE 60
    case.with_(lubricant__viscosity=3.0, lubricant__supply_temperature=-20.0)  # cold start
    case.with_(engine__speed=600.0)  # idle: 1.9 m/s mean piston speed
    data = tomllib.loads((EXAMPLES / "ruston_hornsby_6vebx_mk3.toml").read_text())
    assert data["load"]["speed"] == 600  # a load-table speed has no stroke to judge by


def test_regime_criterion_is_finite_and_monotone_where_a_joint_does_not_knock():
    """Δv = v_worn − v_other: finite with a silent small end (the old ratio gave 173 from
    a 1 mm/s floor), increasing in the worn joint's impact velocity, decreasing in the
    other's, and the regime names the joint that drives it."""
    from conrod.mechanism.regimes import SweepResults

    worn = np.array([0.05, 0.10, 0.20, 0.10, 0.10])
    other = np.array([0.00, 0.00, 0.00, 0.05, 0.30])
    sweep = SweepResults(np.array([1000.0, 2000.0, 3000.0, 2000.0, 2000.0]),
                         np.array([1.0] * 5), np.vstack([worn, other]),
                         np.vstack([worn, other]) / 2, np.ones((2, 5)), 0)
    assert np.all(np.isfinite(sweep.excess))
    np.testing.assert_allclose(sweep.excess, worn - other)
    assert sweep.excess[2] > sweep.excess[1] > sweep.excess[0]  # worn joint louder
    assert sweep.excess[1] > sweep.excess[3] > sweep.excess[4]  # other joint louder
    best = sweep.best()
    assert best["speed_rpm"] == 3000.0 and best["driven_by"] == "big_end"
    assert best["small_end_silent"] and "small end silent" in best["in_words"]
    assert "impact_velocity_excess_m_s" in sweep.columns()
    loud = SweepResults(np.array([1000.0]), np.array([1.0]), np.array([[0.05], [0.2]]),
                        np.array([[0.05], [0.2]]), np.ones((2, 1)), 0)
    assert loud.best()["driven_by"] == "small_end" and loud.best()[
        "impact_velocity_excess_m_s"] == pytest.approx(-0.15)


def test_a_p_max_peak_over_one_output_step_is_not_printed_without_its_doubt():
    """A p_max standing tens of percent above both neighbouring output angles (the trace
    669 → 786 → 564 MPa) is printed with that doubt; a smooth peak is not."""
    import dataclasses

    from conrod.results.summary import headline, peak_step_jump

    results = Simulation(Case.from_dict(_periodic(), base_dir=EXAMPLES)).run()
    assert peak_step_jump(results.cycle) < 0.1
    assert "neighbouring" not in headline(results)["p_max"]
    p_max = results.cycle.p_max.copy()
    i = int(np.argmax(p_max))
    p_max[i] = 1.4 * max(p_max[i - 1], p_max[i + 1])
    spiky = dataclasses.replace(results, cycle=dataclasses.replace(results.cycle,
                                                                   p_max=p_max))
    assert peak_step_jump(spiky.cycle) == pytest.approx(0.4)
    assert "stands 40% above both neighbouring output angles" in headline(spiky)["p_max"]


def test_housing_and_stress_folders_get_their_own_page(runner, tmp_path):
    """Not an empty run page: the housing summary and figures; for the rod stresses which
    pressure loads the rod (here the shipped file's short film: a rigid bore's, said so)
    and the maxima in MPa; both with the case inputs and their sources."""
    kamaz = EXAMPLES / "kamaz_740_truck_diesel.toml"
    assert runner.invoke(app, ["housing", str(kamaz), "--out", str(tmp_path / "h")]
                         ).exit_code == 0
    assert runner.invoke(app, ["stress", str(kamaz), "--out", str(tmp_path / "s"),
                               "--angles", "360"]).exit_code == 0
    for folder, headings in (("h", ["Housing summary", "Case inputs", "Figures"]),
                             ("s", ["Which pressure loads the rod", "Rod stress summary",
                                    "Case inputs", "Figures"])):
        result = runner.invoke(app, ["report", str(tmp_path / folder)])
        assert result.exit_code == 0, result.output
        html = (tmp_path / folder / "report.html").read_text(encoding="utf-8")
        found = re.findall(r"<h2>(.*?)</h2>", html)
        assert all(heading in found for heading in headings), found
        assert "Headline" not in found and html.count("<img ") >= 2
        assert "estimated dimensions" in html or "ESTIMATE" in html  # sources of the case
    page = (tmp_path / "s" / "report.html").read_text(encoding="utf-8")
    assert "rigid-bore run (short film)" in page and "max von Mises [MPa]" in page
