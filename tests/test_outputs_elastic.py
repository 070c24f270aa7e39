"""Every figure and table of an elastic run shows the deformed gap; the orbit figure draws
the widened contact circle and says why; the von Mises figures draw what the run computed;
the headline and the comparison give the firing stroke and the bore displacement split;
``conrod stress`` loads the rod with the pressure of the run it is given and says which.

One massless elastic run of the KamAZ-740 rod (36 × 8 grid, 4° output) feeds them all.
"""

from __future__ import annotations

import json
import tomllib

import numpy as np
import pytest
from typer.testing import CliRunner

import conrod.output  # noqa: F401  (registers the tables and figures)
from conrod import Simulation
from conrod.cli.app import _register_commands, app
from conrod.output.registry import figures, write_results
from conrod.results.case_record import toml_text
from conrod.results.ehd import firing_stroke
from conrod.results.summary import headline
from elastic_helpers import kamaz_case

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def elastic():
    case = kamaz_case(n_theta=36, n_z=8, film="reynolds", integrator="quasi_static",
                      quasi_static_step_deg=2.0, output_step_deg=4.0)
    return Simulation(case).run()


@pytest.fixture(scope="module")
def folder(elastic, tmp_path_factory):
    out = tmp_path_factory.mktemp("elastic")
    write_results(elastic, out, figures=False)
    return out


def _figure(results, name):
    (spec,) = [s for s in figures(results) if s.file == name]
    return spec.build()


def test_film_figures_draw_the_deformed_gap_never_negative(elastic):
    """The rigid-bore gap of this run goes far below zero (the journal passes the rigid
    clearance circle); the deformed gap the figures draw stays positive and its minimum over
    the shell is the run's h_min at every angle, to the grid's resolution: the film refines
    its h_min by a parabola through the bore nodes, the map interpolates u linearly between
    them, which differ by O(c Δθ²) (measured 0.29 µm at Δθ = 10°, bound c (Δθ/2)² = 0.38)."""
    cycle, c = elastic.cycle, elastic.clearance
    rigid_gap = c - np.hypot(cycle.eccentricity_x, cycle.eccentricity_y)
    assert rigid_gap.min() < -5e-6  # what the figures drew before: about -16 um
    gap = elastic.film_thickness
    assert gap.shape == (len(cycle), 361) and gap.min() > 0.0
    spacing = 2.0 * np.pi / len(elastic.bore_angles)
    np.testing.assert_allclose(gap.min(axis=1), cycle.h_min, rtol=0.0,
                               atol=c * (0.5 * spacing) ** 2)
    envelope = elastic.elastic.film_envelope()[1]
    assert envelope.min() == pytest.approx(gap.min())
    mesh = _figure(elastic, "film_thickness_map.png").axes[0].collections[0]
    assert np.asarray(mesh.get_array()).min() > 0.0
    line = _figure(elastic, "min_film_envelope.png").axes[0].lines[0]
    np.testing.assert_allclose(line.get_ydata(), envelope * 1e6)


def test_orbit_draws_the_widened_contact_circle_and_says_why(elastic):
    c, h_c = elastic.clearance, elastic.elastic.contact_threshold or 0.0
    assert elastic.contact_radius == pytest.approx(2.0 * c - h_c)
    fig = _figure(elastic, "orbit.png")
    ax = fig.axes[0]
    labels = [text.get_text() for text in ax.get_legend().get_texts()]
    (label,) = [t for t in labels if t.startswith("contact circle")]
    assert "2c − h_c" in label and "deformed film stops the journal" in label
    radius = max(float(np.max(np.hypot(*line.get_data()))) for line in ax.lines
                 if line.get_label() == label)
    assert radius == pytest.approx(elastic.contact_radius * 1e6, rel=1e-3)
    assert "deforming bore" in ax.get_title()
    e = np.hypot(elastic.cycle.eccentricity_x, elastic.cycle.eccentricity_y)
    assert e.max() > c and ax.get_xlim()[1] > 1e6 * e.max()  # the journal is on the figure


def test_von_mises_figures_draw_what_the_run_computed(elastic, monkeypatch):
    """No finite-element solve in plotting: the figures draw ``results.stresses``."""
    assert set(elastic.stresses) >= {"pressure", "cosine"}

    def refuse(*args, **kwargs):
        raise AssertionError("plotting must not solve the rod")

    monkeypatch.setattr(type(elastic.housing), "stresses", refuse)
    for scheme, name in (("pressure", "von_mises_film_pressure.png"),
                         ("cosine", "von_mises_cosine_load.png")):
        fig = _figure(elastic, name)
        collection = fig.axes[0].collections[0]
        assert np.asarray(collection.get_array()).max() == pytest.approx(
            elastic.stresses[scheme].maximum / 1e6, rel=1e-9)


def test_firing_stroke_and_bore_displacement_in_headline_and_comparison(elastic, folder):
    """Independent answer: the extremes over |φ| <= 90° taken from the two cycles here."""
    def extremes(cycle):
        window = np.abs((cycle.crank_angle_deg + 360.0) % 720.0 - 360.0) <= 90.0
        film = window & ~cycle.in_contact
        return cycle.h_min[film].min() * 1e6, cycle.p_max[window].max() / 1e6

    rigid, flexible = extremes(elastic.rigid.cycle), extremes(elastic.cycle)
    firing = elastic.firing_comparison()
    assert firing["rigid"]["h_min_um"] == pytest.approx(rigid[0])
    assert firing["elastic"]["h_min_um"] == pytest.approx(flexible[0])
    assert firing["elastic"]["p_max_MPa"] == pytest.approx(flexible[1])
    assert firing_stroke(np.radians([0.0, 89.0, 91.0, 629.0, 631.0])).tolist() == [
        True, True, False, False, True]
    lines = headline(elastic)
    assert f"{rigid[0]:.3f} → {flexible[0]:.3f} µm" in lines["firing stroke"]
    split = elastic.bore_displacement
    assert split["pressure_m"] + split["inertia_m"] == pytest.approx(split["total_m"])
    node = int(np.argmin(np.abs(np.degrees(elastic.housing.angles) - split["shell_angle_deg"])))
    inertia = elastic.housing.inertia_deformation(np.radians(split["crank_angle_deg"]))
    assert split["inertia_m"] == pytest.approx(float(inertia[node]))
    assert f"{split['inertia_m'] * 1e6:+.2f} µm" in lines["bore at elastic h_min"]
    summary = json.loads((folder / "summary.json").read_text(encoding="utf-8"))
    assert summary["comparison"]["firing_stroke"]["elastic"]["h_min_um"] == pytest.approx(
        flexible[0])
    assert summary["comparison"]["units"]["side_flow_l_min"].endswith("[l/min]")
    assert summary["headline"]["film h_min"].startswith(f"{elastic.summary.film_h_min * 1e6:.3f}")


def test_stress_uses_the_pressure_of_the_run_it_is_given(elastic, folder, tmp_path):
    """From the folder of the elastic run: its own film pressure (film_pressure.npz) at the
    largest load loads the rod, and the resultant is that pressure's; from a case file with
    the short film, which cannot take the deformation: the rigid-bore pressure, said so."""
    _register_commands()
    runner = CliRunner()
    peak = float(elastic.cycle.crank_angle_deg[elastic.peak_load_index])
    result = runner.invoke(app, ["stress", str(folder), "--out", str(tmp_path / "s"),
                                 "--angles", f"{peak:g}"])
    assert result.exit_code == 0, result.output
    summary = json.loads((tmp_path / "s" / "stress_summary.json").read_text(encoding="utf-8"))
    assert "elastic run" in summary["pressure_source"] and "elastic run" in result.output
    resultant = np.asarray(summary[f"{peak:g}"]["resultant_N"])
    np.testing.assert_allclose(resultant, elastic.stresses["resultant_N"], rtol=1e-9)
    refused = runner.invoke(app, ["stress", str(folder), "--out", str(tmp_path / "t"),
                                  "--angles", "100"])
    assert refused.exit_code == 2 and "kept the film pressure at" in refused.output
    data = tomllib.loads((folder / "case.toml").read_text(encoding="utf-8"))
    data["solver"]["film"] = "short"
    case_file = tmp_path / "short.toml"
    case_file.write_text(toml_text(data), encoding="utf-8")
    rigid = runner.invoke(app, ["stress", str(case_file), "--out", str(tmp_path / "r"),
                                "--angles", "360"])
    assert rigid.exit_code == 0, rigid.output
    assert "rigid-bore run (short film)" in rigid.output


def test_report_of_the_elastic_run_has_the_rigid_vs_elastic_table(elastic, folder):
    """Rodin's Table 2 columns, rigid and elastic, over the cycle and the firing stroke,
    in the units of the headline; the figures of the deformed gap are said to be so."""
    from conrod.report import build_report

    html = build_report(folder)
    section = html.split("<h2>Rigid and elastic big end</h2>")[1].split("<h2>")[0]
    e, r = elastic.summary, elastic.rigid.summary
    for text in ("smallest film h_min over the cycle [µm]", "cycle mean side flow Q [l/min]",
                 "smallest film h_min, firing stroke [µm]", f"{r.film_h_min * 1e6:.4g}",
                 f"{e.film_h_min * 1e6:.4g}", "Bore displacement at the elastic h_min"):
        assert text in section, text
    assert "cm^3/s" not in html


def test_elastic_figures_drawn_ahead_are_those_the_writer_draws(elastic, tmp_path):
    """The elastic run's figures (rigid companion, deformed bore and film, rod stresses)
    drawn while ``conrod run`` waits for its last coarse orbit are the writer's own for the
    results the grid-error estimate leaves, byte for byte."""
    from test_figure_process import assert_drawn_ahead_as_written

    assert_drawn_ahead_as_written(elastic, tmp_path)
