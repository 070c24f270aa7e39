"""The shipped engine-map study templates and the sweep report's contour maps with the
limit contours and the warned variants marked, looked at in a real browser."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from conrod.report import write_report
from conrod.sweep import Study, Sweep
from test_report import assert_not_blank, browse

STUDIES = Path(__file__).resolve().parents[1] / "examples" / "studies"
TEMPLATES = ("passenger_car_engine_map.toml", "truck_engine_map.toml")


@pytest.mark.parametrize("name", TEMPLATES)
def test_templates_are_speed_by_load_maps_with_limits(name):
    """Each template: the product of an engine-speed axis and a peak-pressure axis, every
    variant valid, the lining's limits set in every variant."""
    study = Study.from_toml(STUDIES / name)
    data = tomllib.loads((STUDIES / name).read_text(encoding="utf-8"))
    keys = [axis["key"] for axis in data["axis"]]
    assert keys == ["engine.speed", "engine.pressure_model.max_pressure"]
    assert set(data["override"]["limits"]) >= {"min_film_thickness", "max_pressure",
                                               "pressure_range", "max_temperature"}
    variants = study.variants()
    assert len(variants) == 16


@pytest.fixture(scope="module")
def map_folder(tmp_path_factory):
    """The passenger-car template on a 3 x 2 corner of its map (seconds)."""
    data = tomllib.loads((STUDIES / TEMPLATES[0]).read_text(encoding="utf-8"))
    data["base"] = str((STUDIES / data["base"]).resolve())
    data["axis"][0]["values"] = [1500.0, 3000.0, 4500.0]
    data["axis"][1]["values"] = [10.0e6, 16.0e6]
    out = tmp_path_factory.mktemp("engine_map")
    Sweep(Study.from_dict(data), out, workers=1).run()
    return out


def test_sweep_table_carries_the_signoff_columns(map_folder):
    frame = pd.read_parquet(map_folder / "sweep.parquet")
    for column in ("film_h_min_m", "p_max_Pa", "max_pressure_range_Pa",
                   "mean_total_friction_power_W", "mean_side_flow_m3_s",
                   "effective_temperature_C", "limit_max_pressure_Pa", "limits_crossed"):
        assert column in frame and frame[column].notna().all(), column
    crossed = frame["limits_crossed"] > 0
    assert (frame.loc[crossed, "status"] == "warning").all()
    # Δp = max − min at one point ≤ p_max − 0: the half-Sommerfeld film never goes below 0
    assert np.all(frame["max_pressure_range_Pa"] <= frame["p_max_Pa"] * (1 + 1e-12))
    assert np.all(frame["max_pressure_range_Pa"] > 0.5 * frame["p_max_Pa"])


def test_sweep_report_draws_the_engine_maps_in_a_browser(map_folder, tmp_path):
    (html_file,) = write_report(map_folder, tmp_path / "map.html")
    html = html_file.read_text(encoding="utf-8")
    assert "<h2>Engine maps</h2>" in html
    maps = html[html.index("<h2>Engine maps</h2>"):html.index("<h2>Trends</h2>")]
    for title in ("MOFT (film h_min)", "POFP (film p_max)", "largest pressure range Δp",
                  "friction power", "oil flow (side)", "largest temperature"):
        assert title in maps, title
    assert maps.count("<img ") == 6 and maps.count("limit contour") >= 1
    pixels, images, broken, _ = browse(html_file, tmp_path)
    assert broken == 0 and images == html.count("<img ")
    assert_not_blank(pixels)


def test_engine_map_marks_failed_and_warned_variants_and_draws_the_limit():
    """A 3 x 3 map with a failed variant (a hole) and warned ones: the figure draws the
    filled contours, the limit contour and one legend entry per status with its count."""
    from conrod.plotting.sweep_maps import engine_map_figure

    speed, load = np.meshgrid([1000.0, 2000.0, 3000.0], [8e6, 12e6, 16e6])
    frame = pd.DataFrame({"engine.speed_rpm": speed.ravel(),
                          "engine.pressure_model.max_pressure_Pa": load.ravel()})
    frame["p_max_Pa"] = 20.0 * frame["engine.pressure_model.max_pressure_Pa"] \
        + 1e4 * frame["engine.speed_rpm"]
    frame["status"] = np.where(frame["p_max_Pa"] > 250e6, "warning", "ok")
    frame.loc[4, ["status", "p_max_Pa"]] = ["failed", np.nan]
    fig = engine_map_figure(frame, "engine.speed_rpm", "engine.pressure_model.max_pressure_Pa",
                            "p_max_Pa", 250e6, title="POFP")
    ax = fig.axes[0]
    legend = [text.get_text() for text in ax.get_legend().get_texts()]
    assert "limit 250 MPa" in legend and "failed (1)" in legend
    assert any(t.startswith("ok (") for t in legend)
    assert any(t.startswith("warning (limit crossed or doubtful) (") for t in legend)
    assert ax.get_ylabel().endswith("[MPa]")
