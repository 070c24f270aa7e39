"""Figures of docs/signoff.md: the per-cell indicator maps of the shipped passenger car with
the finite-length film (36 × 8) and the engine map of the passenger-car study template.

Run from the repository root:  python docs/figures/make_signoff_figures.py
Writes docs/figures/pc2000_indicator_maps_shell.png, pc2000_indicator_maps_journal.png and
pc_engine_map_pressure_range.png from conrod's own plotting functions.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pandas as pd

from conrod import Case, Simulation
from conrod.plotting.indicator_plots import plot_indicator_maps
from conrod.plotting.save import save_figure
from conrod.plotting.sweep_maps import engine_map_figure
from conrod.sweep import Study, Sweep
from conrod.sweep.columns import axis_label

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
LIMITS = {"min_film_thickness": 0.6e-6, "max_pressure": 700e6, "pressure_range": 300e6,
          "asperity_pressure": 5e6, "max_temperature": 150.0}


def indicator_maps() -> None:
    case = Case.from_toml(ROOT / "examples" / "passenger_car_diesel_2000rpm_reynolds.toml")
    results = Simulation(case.with_(limits=LIMITS), n_theta=36, n_z=8).run()
    for frame in ("shell", "journal"):
        save_figure(plot_indicator_maps(results, frame),
                    HERE / f"pc2000_indicator_maps_{frame}.png", dpi=100)


def engine_map() -> None:
    study = Study.from_toml(ROOT / "examples" / "studies" / "passenger_car_engine_map.toml")
    with tempfile.TemporaryDirectory() as folder:
        Sweep(study, Path(folder) / "map", workers=1).run()
        frame = pd.read_parquet(Path(folder) / "map" / "sweep.parquet")
    x, y = "engine.speed_rpm", "engine.pressure_model.max_pressure_Pa"
    labels = {x: axis_label("engine.speed"), y: axis_label("engine.pressure_model.max_pressure")}
    limit = float(frame["limit_pressure_range_Pa"].iloc[0])
    save_figure(engine_map_figure(frame, x, y, "max_pressure_range_Pa", limit, labels,
                                  "largest pressure range Δp"),
                HERE / "pc_engine_map_pressure_range.png", dpi=100)


if __name__ == "__main__":
    indicator_maps()
    engine_map()
