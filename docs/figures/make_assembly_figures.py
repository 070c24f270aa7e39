"""Figures of docs/elastic.md (the assembled bore, the warm bore).

Run from the repository root:  python docs/figures/make_assembly_figures.py
Writes docs/figures/kamaz_assembled_bore.png: the KamAZ-740 example's built-in rod with the
commented ``[housing.assembly]`` of the example switched on (75 kN per bolt, 40 µm crush),
and docs/figures/kamaz_housing_temperature.png: the same rod conducting from a shell-side
temperature of 125 / 115 / 118 / 115 °C at 0 / 90 / 180 / 270° to a 90 °C crankcase; both
drawn by the figures ``conrod housing`` writes (conrod.plotting.housing_plots).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from conrod.cases.case import Case  # noqa: E402
from conrod.housing.housing import Housing  # noqa: E402
from conrod.plotting.housing_plots import (  # noqa: E402
    assembled_bore_figure,
    housing_temperature_figure,
)
from conrod.simulation.housing_study import housing_study  # noqa: E402

HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parents[1] / "examples" / "kamaz_740_truck_diesel.toml"
ASSEMBLY = {"bolt_preload": 75.0e3, "crush_height": 40.0e-6}
CONDUCTING = {"journal_temperature": 105.0, "shell_temperature_angles": [0.0, 90.0, 180.0, 270.0],
              "shell_temperatures": [125.0, 115.0, 118.0, 115.0], "ambient_temperature": 90.0}


def main() -> None:
    data = tomllib.loads(EXAMPLE.read_text())
    data["housing"]["assembly"] = ASSEMBLY
    case = Case.from_dict(data, base_dir=EXAMPLE.parent)
    results = housing_study(Housing.from_case(case, use_cache=False), case)
    assembled_bore_figure(results).savefig(HERE / "kamaz_assembled_bore.png", dpi=110,
                                           bbox_inches="tight")
    data["housing"]["thermal"] = CONDUCTING
    case = Case.from_dict(data, base_dir=EXAMPLE.parent)
    housing = Housing.from_case(case, use_cache=False)
    housing_temperature_figure(housing.structure, housing.warm).savefig(
        HERE / "kamaz_housing_temperature.png", dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
