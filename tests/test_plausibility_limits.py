"""Results no engineer would believe are refused (exit 3, located), not written with a
warning."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from conrod.cases.case import Case
from conrod.errors import ConvergenceError
from conrod.simulation.simulation import Simulation

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def test_a_heat_balance_of_hundreds_of_thousands_of_degrees_is_refused():
    """The Flores table load × 1e-6: the journal stays centred, almost no oil leaks and the
    heat balance reaches 6.9e5 °C, which was written with a warning (exit 4)."""
    data = tomllib.loads((EXAMPLES / "flores2006_table_load.toml").read_text(encoding="utf-8"))
    data["load"]["scale"] = 1e-6
    case = Case.from_dict(data, base_dir=EXAMPLES)
    with pytest.raises(ConvergenceError, match=r"heat-balance temperature 6\.9e\+05 °C "
                       r"\(physical: <= 1000 °C.*at the heat balance of the cycle"):
        Simulation(case).run()


def test_the_shipped_example_stays_a_result():
    data = tomllib.loads((EXAMPLES / "flores2006_table_load.toml").read_text(encoding="utf-8"))
    results = Simulation(Case.from_dict(data, base_dir=EXAMPLES)).run()
    assert results.summary.effective_temperature < 200.0
