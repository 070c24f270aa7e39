"""Figure of docs/elastic.md (the assembled bore).

Run from the repository root:  python docs/figures/make_assembly_figures.py
Writes docs/figures/kamaz_assembled_bore.png: the KamAZ-740 example's built-in rod with the
commented ``[housing.assembly]`` of the example switched on (75 kN per bolt, 40 µm crush),
drawn by the figure ``conrod housing`` writes (conrod.plotting.housing_plots).
"""

from __future__ import annotations

import tomllib
from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from conrod.cases.case import Case  # noqa: E402
from conrod.housing.housing import Housing  # noqa: E402
from conrod.plotting.housing_plots import assembled_bore_figure  # noqa: E402
from conrod.simulation.housing_study import housing_study  # noqa: E402

HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parents[1] / "examples" / "kamaz_740_truck_diesel.toml"
ASSEMBLY = {"bolt_preload": 75.0e3, "crush_height": 40.0e-6}


def main() -> None:
    data = tomllib.loads(EXAMPLE.read_text())
    data["housing"]["assembly"] = ASSEMBLY
    case = Case.from_dict(data, base_dir=EXAMPLE.parent)
    results = housing_study(Housing.from_case(case, use_cache=False), case)
    assembled_bore_figure(results).savefig(HERE / "kamaz_assembled_bore.png", dpi=110,
                                           bbox_inches="tight")


if __name__ == "__main__":
    main()
