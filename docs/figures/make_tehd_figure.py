"""Figure of docs/thermal.md (the bore warm from the thermal film).

Run from the repository root:  python docs/figures/make_tehd_figure.py
Writes docs/figures/kamaz_tehd_warm_bore.png: examples/kamaz_740_truck_diesel_tehd.toml as
shipped (Reynolds 72 × 16 on the built-in elastic rod, assembled, the bore warm from the
film; no rigid companion run), drawn by the figure ``conrod run`` writes as
``warm_bore.png`` (conrod.plotting.thermal_plots.plot_warm_bore).
"""

from __future__ import annotations

from pathlib import Path

import matplotlib

matplotlib.use("Agg")

from conrod.cases.case import Case  # noqa: E402
from conrod.plotting.thermal_plots import plot_warm_bore  # noqa: E402
from conrod.simulation.simulation import Simulation  # noqa: E402

HERE = Path(__file__).resolve().parent
EXAMPLE = HERE.parents[1] / "examples" / "kamaz_740_truck_diesel_tehd.toml"


def main() -> None:
    results = Simulation(Case.from_toml(EXAMPLE), rigid_companion=False).run()
    plot_warm_bore(results.elastic.thermal_film).savefig(HERE / "kamaz_tehd_warm_bore.png",
                                                         dpi=110, bbox_inches="tight")


if __name__ == "__main__":
    main()
