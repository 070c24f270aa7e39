"""``conrod report``: self-contained HTML of run and sweep folders, looked at in a real
headless browser (Debian's chromium): the page is not blank and every image loaded.

In CI (``CI`` set) a missing browser is a failure, not a skip.
"""

from __future__ import annotations

import html as html_module
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from matplotlib.image import imread
from typer.testing import CliRunner

import conrod.output  # noqa: F401  (registers the tables and figures)
from conrod import Case, Simulation
from conrod.cli.app import _register_commands, app
from conrod.errors import CaseError
from conrod.output.registry import write_results
from conrod.report import build_report, write_report
from conrod.sweep import Study, Sweep

REPO = Path(__file__).resolve().parents[1]
CASE = REPO / "examples" / "passenger_car_diesel_2000rpm.toml"
BROWSER_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                 "--no-first-run", "--disable-background-networking",
                 "--disable-component-update", "--disable-sync", "--hide-scrollbars"]
UNIT_IN_CAPTION = re.compile(
    r"(\bin |\[)(µm|MPa|W|kN|l/min|m|mm|Pa|m³/s|m\^3/s|°C|N|nm|J|deg|degrees|rpm)(\b|\])")
"""A unit in a caption, as "in MPa" or in the project's bracket style "[MPa]"."""
MARK_IMAGES = """<script>
window.addEventListener("load", function () {
  var images = document.images, broken = 0;
  for (var i = 0; i < images.length; i++) {
    if (!images[i].complete || images[i].naturalWidth === 0) { broken++; }
  }
  document.body.setAttribute("data-images", images.length);
  document.body.setAttribute("data-broken", broken);
});
</script></body>"""


def browser() -> str:
    found = shutil.which("chromium") or shutil.which("chromium-browser")
    if found is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is missing: the README's test command installs it in CI")
        pytest.skip("chromium not installed (CI installs it; here: apt-get install chromium)")
    return found


def look_at(html_file: Path, tmp: Path) -> tuple[np.ndarray, int, int]:
    """(screenshot RGB array, number of images, number of images that did not load)."""
    pixels, images, broken, _ = browse(html_file, tmp)
    return pixels, images, broken


def browse(html_file: Path, tmp: Path) -> tuple[np.ndarray, int, int, str]:
    """:func:`look_at` and the page's DOM as the browser built it."""
    exe, profile = browser(), tmp / "profile"
    page = tmp / "page.html"
    page.write_text(html_file.read_text(encoding="utf-8").replace("</body>", MARK_IMAGES),
                    encoding="utf-8")
    common = [exe, *BROWSER_FLAGS, f"--user-data-dir={profile}", "--virtual-time-budget=5000"]
    dom = subprocess.run([*common, "--dump-dom", page.as_uri()], capture_output=True,
                         text=True, timeout=120, check=True).stdout
    shot = tmp / "shot.png"
    subprocess.run([*common, f"--screenshot={shot}", "--window-size=1200,2400", page.as_uri()],
                   capture_output=True, timeout=120, check=True)
    images = int(re.search(r'data-images="(\d+)"', dom).group(1))
    broken = int(re.search(r'data-broken="(\d+)"', dom).group(1))
    return imread(shot)[..., :3], images, broken, dom


def assert_not_blank(pixels: np.ndarray) -> None:
    ink = (pixels.mean(axis=2) < 0.8).mean()  # dark pixels: text, lines, figures
    assert ink > 0.01, f"only {ink:.2%} of the page is not white"
    assert pixels.std() > 0.05


def assert_self_contained(html: str) -> None:
    for attribute in re.findall(r'(?:src|href)="([^"]*)"', html):
        assert attribute.startswith("data:"), attribute
    assert "<link" not in html and "@import" not in html


@pytest.fixture(scope="module")
def run_folder(tmp_path_factory):
    """A ``conrod run`` folder of the shipped passenger car (massless orbit, figures)."""
    out = tmp_path_factory.mktemp("run")
    results = Simulation(Case.from_toml(CASE), integrator="quasi_static").run()
    write_results(results, out, figures=True)
    return out


@pytest.fixture(scope="module")
def sweep_folder(tmp_path_factory):
    out = tmp_path_factory.mktemp("sweep")
    study = Study.from_dict({"base": str(CASE), "title": "clearance x speed",
                             "override": {"solver": {"integrator": "quasi_static"}},
                             "axis": [{"key": "bearing.radial_clearance",
                                       "values": [20e-6, 30e-6]},
                                      {"key": "engine.speed", "values": [1500.0, 2500.0]}]})
    Sweep(study, out, workers=1).run()
    return out


def test_run_report_in_a_browser(run_folder, tmp_path):
    (html_file,) = write_report(run_folder, tmp_path / "run.html", case_file=CASE)
    html = html_file.read_text(encoding="utf-8")
    assert_self_contained(html)
    for heading in ("Headline", "Cycle summary", "Case inputs", "Engine load diagrams",
                    "Load on the bearing", "Journal-centre orbit",
                    "Minimum film thickness and maximum pressure", "Friction and oil flow"):
        assert f"<h2>{heading}</h2>" in html
    assert "<h2>Contact and wear</h2>" not in html  # the journal never touches the shell
    captions = re.findall(r"<figcaption>(.*?)</figcaption>", html)
    assert len(captions) == html.count("<img ") >= 8
    assert all(UNIT_IN_CAPTION.search(c) for c in captions), captions
    # inputs carry the unit from the schema and the source from the case file's comment
    assert re.search(r"<td>engine.bore</td><td class=\"num\">0.081</td><td>m</td><td>81.01 mm "
                     r"cylinder bore: VW workshop manual", html)
    pixels, images, broken = look_at(html_file, tmp_path)
    assert images == len(captions) and broken == 0
    assert_not_blank(pixels)


@pytest.fixture(scope="module")
def warning_folder(tmp_path_factory):
    """A run that exits 4: 200 x the Flores load at 100 rpm, the film below the roughness and
    its rigid pressure above the lining hardness (two warnings), written as conrod run does."""
    from hardening_helpers import EXAMPLES, cheap_table_run, mutated

    data = mutated(mutated(mutated(cheap_table_run(), ("solver", "max_cycles"), 12),
                           ("load", "scale"), 200), ("load", "speed"), 100)
    out = tmp_path_factory.mktemp("exit4")
    results = Simulation(Case.from_dict(data, base_dir=EXAMPLES)).run()
    assert results.summary.exit_code == 4 and len(results.summary.warnings) == 2
    write_results(results, out, figures=True)
    return out


def test_report_of_an_exit_4_run_opens_with_its_headline_and_warnings(warning_folder,
                                                                        tmp_path):
    """The page opens with the warnings in a box and the headline the terminal printed,
    before the inputs and the figures, in the real browser; no --case needed (the folder
    records its case) and no path of this machine in the page."""
    (html_file,) = write_report(warning_folder)
    html = html_file.read_text(encoding="utf-8")
    summary = json.loads((warning_folder / "summary.json").read_text(encoding="utf-8"))
    headings = re.findall(r"<h2>(.*?)</h2>", html)
    assert headings[0] == "Headline" and headings.index("Case inputs") > 0
    assert str(warning_folder.parent) not in html
    pixels, images, broken, dom = browse(html_file, tmp_path)
    assert images == html.count("<img ") and broken == 0
    text = " ".join(html_module.unescape(re.sub(r"<[^>]+>", " ", dom)).split())
    first_figure = text.index("Figure 1.")
    box = text.index("2 warning(s): conrod run exits 4")
    assert box < first_figure and box < text.index("Case inputs")
    for warning in summary["warnings"]:
        assert text.index(" ".join(warning.split())) < first_figure
    for label, line in summary["headline"].items():
        assert f"{label} {' '.join(line.split())}" in text
    assert "exit code 4 (finished with warnings)" in text
    top = pixels[: pixels.shape[0] // 3]  # the warnings box's background near the top
    box_colour = (np.abs(top - np.array([1.0, 0.953, 0.878])) < 0.02).all(axis=2)
    assert box_colour.mean() > 0.01
    assert_not_blank(pixels)


def test_sweep_report_in_a_browser(sweep_folder, tmp_path):
    (html_file,) = write_report(sweep_folder)
    assert html_file == sweep_folder / "report.html"
    html = html_file.read_text(encoding="utf-8")
    assert_self_contained(html)
    for heading in ("Study", "Case inputs", "Best and worst variants", "Trends", "Variants"):
        assert f"<h2>{heading}</h2>" in html
    assert html.count("<img ") >= 5  # one trend plot per characteristic
    assert "swept (see the variant table)" in html
    variant_rows = re.search(r"<h2>Variants</h2>.*?<tbody>(.*?)</tbody>", html, re.S).group(1)
    assert variant_rows.count("<tr>") == 4
    pixels, images, broken = look_at(html_file, tmp_path)
    assert images == html.count("<img ") and broken == 0
    assert_not_blank(pixels)


def test_manifest_titles_and_captions_are_used(run_folder, tmp_path):
    """A folder with manifest.json: its titles and captions, and every figure it lists."""
    folder = tmp_path / "with_manifest"
    shutil.copytree(run_folder, folder)
    shutil.copy(folder / "orbit.png", folder / "rigid_vs_elastic.png")
    manifest = {"conrod_version": "0.1.0", "kind": "run",
                "tables": [{"file": "cycle.csv", "title": "Cycle table",
                            "caption": "One row per output crank angle."}],
                "figures": [{"file": "orbit.png", "title": "Orbit from the manifest",
                             "caption": "Journal centre in µm (manifest caption)."},
                            {"file": "rigid_vs_elastic.png", "title": "Rigid vs elastic",
                             "caption": "h_min in µm of the rigid and the elastic housing."}]}
    (folder / "manifest.json").write_text(json.dumps(manifest), encoding="utf-8")
    html = build_report(folder)
    assert "Orbit from the manifest" in html and "(manifest caption)" in html
    assert "<h2>Further figures</h2>" in html and "Rigid vs elastic" in html
    assert "<td>Cycle table</td>" in html
    # figures the manifest does not list are drawn from cycle.csv instead of being guessed
    assert "hmin_pmax" not in html and "<h2>Friction and oil flow</h2>" in html


def test_variant_folder_without_figures_gets_drawn_figures(sweep_folder, tmp_path):
    variant = next(p for p in (sweep_folder / "variants").iterdir())
    html = build_report(variant)
    assert "Sweep variant: bearing.radial_clearance" in html
    # engine loads (polar, over the cycle, wear diagram) from the variant's case; bearing
    # load, orbit, h_min/p_max, friction/flow drawn from its tables, contact and wear only
    # where the journal touched the shell
    touched = float(pd.read_csv(variant / "cycle.csv")["contact_force_N"].max()) > 0.0
    assert html.count("<img ") == 7 + touched
    assert ("<h2>Contact and wear</h2>" in html) == touched


def test_pdf(run_folder, tmp_path):
    browser()
    paths = write_report(run_folder, tmp_path / "r.html", case_file=CASE, pdf=True)
    pdf = paths[1].read_bytes()
    assert paths[1].suffix == ".pdf" and pdf.startswith(b"%PDF") and len(pdf) > 20_000


def test_pdf_without_a_browser_is_a_clear_error(run_folder, tmp_path, monkeypatch):
    monkeypatch.setenv("PATH", str(tmp_path))
    monkeypatch.delenv("CONROD_BROWSER", raising=False)
    _register_commands()
    result = CliRunner().invoke(app, ["report", str(run_folder), "--out",
                                      str(tmp_path / "r.html"), "--pdf"])
    assert result.exit_code == 2
    assert "--pdf needs a Chromium or Chrome browser" in result.output


def test_not_a_results_folder(tmp_path):
    with pytest.raises(CaseError, match="not a results folder"):
        build_report(tmp_path)
