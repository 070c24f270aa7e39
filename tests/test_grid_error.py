"""The grid-error estimate of h_min and p_max (Richardson from the run grid and two coarser
grids, observed order): exact on a manufactured convergence, honest where the values do not
converge monotonically, and on shipped examples within a factor 2 of the three-grid
Richardson error from the run grid, 2x and 4x finer."""

from __future__ import annotations

import math

import pytest

from conrod.results.grid_error import (
    GridError,
    GridEstimate,
    cell_size,
    extrapolated_error,
    observed_order,
    richardson,
)
from conrod.simulation.grid_error import coarser_grids


@pytest.mark.parametrize("order", [1.0, 1.5, 2.0, 3.0])
def test_observed_order_of_a_manufactured_convergence_on_unequal_ratios(order):
    """φ(h) = 3 − 7 h^p on the grids conrod picks for 72 × 16 (ratios 1.36 and 1.47):
    the observed order is p; at p = 2 the error of the run grid is exactly 7 h₁²."""
    grids = ((72, 16), *coarser_grids((72, 16)))
    sizes = tuple(cell_size(g) for g in grids)
    values = tuple(3.0 - 7.0 * h**order for h in sizes)
    observed, error = richardson(values, sizes)
    assert observed == pytest.approx(order, rel=1e-8)
    assert extrapolated_error(values, sizes, order) == pytest.approx(7.0 * sizes[0] ** order,
                                                                     rel=1e-8)
    if order == 2.0:
        assert error == pytest.approx(7.0 * sizes[0] ** 2, rel=1e-8)


def test_values_that_do_not_converge_monotonically_give_no_order():
    sizes = (1.0, 1.4, 2.0)
    assert observed_order((10.0, 10.5, 9.0), sizes) is None  # oscillating
    assert observed_order((10.0, 10.0, 10.0), sizes) is None  # no change at all
    order, error = richardson((10.0, 10.5, 9.0), sizes)
    assert order is None and error == pytest.approx(-0.5 / (1.4**2 - 1.0))


def test_coarser_grids_are_even_within_the_limits_and_coarser():
    for grid in ((36, 8), (72, 16), (144, 16), (144, 12), (8, 4)):
        coarse = coarser_grids(grid)
        sizes = [cell_size(g) for g in (grid, *coarse)]
        assert all(b > 1.2 * a for a, b in zip(sizes, sizes[1:], strict=False))
        assert all(n % 2 == 0 and m % 2 == 0 and n >= 8 and m >= 4 for n, m in coarse)
    assert coarser_grids((8, 4)) == []  # nothing coarser: no estimate


def test_headline_words_name_grids_angles_and_order():
    estimate = GridEstimate("h_min", 53.0, (3.04e-6, 2.99e-6, 2.88e-6), 2.1, 0.06e-6,
                            (53.0, 52.0, 49.0))
    grid = GridError(((144, 16), (102, 12), (72, 8)), estimate,
                     GridEstimate("p_max", 30.0, (160e6, 161e6, 163e6), None, -2e6))
    text = grid.text("h_min")
    assert text.startswith("grid error +0.06 µm (+2.0 %;")
    assert "144×16 (53°) / 102×12 (52°), order 2; observed order 2.1 with 72×8 (49°)" in text
    assert "asymptotic" not in text
    assert "not observed" in grid.text("p_max") and "read the error" in grid.text("p_max")
    items = grid.as_json_items()
    assert items["grids"] == [[144, 16], [102, 12], [72, 8]]
    assert items["h_min"]["error_m"] == pytest.approx(0.06e-6)
    assert math.isclose(items["p_max"]["relative_error"], -2e6 / 160e6)


@pytest.mark.slow
@pytest.mark.parametrize("example, fine", [
    ("passenger_car_diesel_2000rpm_reynolds", (108, 24)), ("kamaz_740_truck_diesel", (144, 32))])
def test_estimate_within_a_factor_2_of_the_three_grid_richardson_error(example, fine):
    """The shipped examples at the default grid 72 × 16 (the KamAZ-740 bearing on a rigid
    bore: its elastic run at 144 × 16 is measured in benchmarks/grid_error_check.md): the
    estimate from the run grid and the coarser grids agrees within a factor 2 with the
    three-grid Richardson error of the run grid from 36 × 8, 72 × 16 and a finer grid
    (order observed on those): 144 × 32, or 108 × 24 for the passenger car's mixed film
    (58 s at 144 × 32 against 30 s). Where those three do not converge monotonically there
    is no such reference, and the estimate must not claim the asymptotic range either."""
    from conrod import Case, Simulation
    from conrod.simulation.grid_error import with_grid_error
    from hardening_helpers import EXAMPLES

    case = Case.from_toml(EXAMPLES / f"{example}.toml")
    options = {"film": "reynolds", "rigid_companion": False, "housing": "rigid"}
    simulation = Simulation(case, n_theta=72, n_z=16, **options)
    estimate = with_grid_error(simulation.run(), simulation).summary.grid_error
    assert estimate.grids == ((72, 16), (52, 12), (36, 8))
    finest = Simulation(case, n_theta=fine[0], n_z=fine[1], **options).run()
    for quantity in ("h_min", "p_max"):
        ours = estimate.estimate(quantity)
        best = (finest.summary.film_h_min if quantity == "h_min" else finest.summary.p_max)
        three = (best, ours.values[0], ours.values[2])  # fine, 72x16, 36x8
        sizes = tuple(cell_size(g) for g in (fine, (72, 16), (36, 8)))
        order = observed_order(three, sizes)
        if order is None:
            assert not ours.asymptotic
            continue
        reference = best + extrapolated_error(three, sizes, order) - ours.values[0]
        assert 0.5 <= ours.error / reference <= 2.0, (quantity, ours, reference)


def test_a_coarse_orbit_that_fails_leaves_the_run_with_a_warning(monkeypatch):
    """A coarser orbit of the estimate that does not converge (a coarse grid can close the
    film where the run grid does not) keeps the run's answer and says the grid error is
    missing, instead of failing the run."""
    import dataclasses
    from types import SimpleNamespace

    from conrod.errors import ConvergenceError
    from conrod.simulation import grid_error

    def failing(simulation, grid, progress):
        raise ConvergenceError(f"h_min = -1.2e-07 m at crank angle 20.0 deg on {grid}")

    @dataclasses.dataclass(frozen=True)
    class Summary:
        film_model: str = "reynolds"
        warnings: tuple = ()
        grid_error: object = None

    @dataclasses.dataclass(frozen=True)
    class Results:
        summary: Summary
        cycle: object = None

    monkeypatch.setattr(grid_error, "coarse_cycle", failing)
    simulation = SimpleNamespace(solver=SimpleNamespace(n_theta=36, n_z=8, film="reynolds"))
    results = grid_error.with_grid_error(Results(Summary()), simulation)
    assert results.summary.grid_error is None
    (warning,) = results.summary.warnings
    assert warning.startswith("grid error not estimated") and "26 × 6" in warning
    assert "crank angle 20.0 deg" in warning
