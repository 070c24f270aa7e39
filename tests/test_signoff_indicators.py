"""Per-cell sign-off indicators, cavitation erosion and margins on synthetic film histories
with known answers (no orbit: milliseconds)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.cases.case import Case
from conrod.errors import CaseError
from conrod.results.erosion import (
    boundary_pressure_rate,
    erosion_map,
    interval_times,
    reformation_intensity,
)
from conrod.results.fields import FIELD_SPECS, CycleFields, stride_rows
from conrod.results.indicators import cell_indicators, journal_frame
from conrod.results.margins import Margin, margins

N_ROWS, N_THETA, N_Z = 12, 8, 5
OMEGA = 200.0
"""Crank speed of the synthetic histories [rad/s]."""


def _fields(values: dict[str, np.ndarray], rotation=None, cycle=4 * math.pi) -> CycleFields:
    phi = np.arange(N_ROWS) * cycle / N_ROWS
    theta = np.arange(N_THETA) * 2 * math.pi / N_THETA
    z = np.linspace(-0.01, 0.01, N_Z)
    rotation = np.zeros(N_ROWS) if rotation is None else rotation
    return CycleFields(phi, theta, z, rotation, values,
                       {name: FIELD_SPECS[name] for name in values}, cycle, OMEGA, 0.0, "test")


def _front_history(pressure_rise: float = 5e6):
    """A reformation front: cell j cavitated (ϑ = 0, p = 0) until row j + 2, full film
    (ϑ = 1, p = pressure_rise) from then on, every axial node alike."""
    fraction = np.zeros((N_ROWS, N_THETA, N_Z))
    pressure = np.zeros((N_ROWS, N_THETA, N_Z))
    for j in range(N_THETA):
        fraction[j + 2:, j] = 1.0
        pressure[j + 2:, j] = pressure_rise
    return fraction, pressure


def test_reformation_front_has_the_known_intensity_where_and_when_it_passes():
    """Each cell the front closes over in one interval Δt scores (1/Δt) x the pressure rise,
    at the crank angle it becomes full; cells never cavitated score 0."""
    fraction, pressure = _front_history(5e6)
    fields = _fields({"pressure": pressure, "film_fraction": fraction})
    dt = (4 * math.pi / N_ROWS) / OMEGA
    np.testing.assert_allclose(interval_times(fields), dt)
    item, note = erosion_map(fields)
    np.testing.assert_allclose(item.values, 5e6 / dt, rtol=1e-12)
    for j in range(N_THETA):  # the front reaches cell j at row j + 2
        np.testing.assert_allclose(item.crank_angle[j], fields.crank_angle[j + 2])
    assert item.worst_value == pytest.approx(5e6 / dt, rel=1e-12)
    j = int(np.argmin(np.abs(fields.theta - item.worst_theta)))
    assert item.worst_crank_angle == fields.crank_angle[j + 2]
    assert item.worst_z == 0.0  # the middle of the equal axial nodes
    assert "reformation intensity" in item.long_name and "Pa/s" in note


def test_reformation_intensity_scales_with_the_recovery_rate_and_the_rise():
    """Half the recovery (ϑ 0 → 0.5) and twice the rise: the same intensity; no rise (the
    film refills at constant pressure) or no recovery: zero."""
    fraction, pressure = _front_history(5e6)
    half = _fields({"pressure": 2.0 * pressure, "film_fraction": 0.5 * fraction})
    full = _fields({"pressure": pressure, "film_fraction": fraction})
    np.testing.assert_allclose(reformation_intensity(half), reformation_intensity(full))
    flat = _fields({"pressure": np.full_like(pressure, 1e6), "film_fraction": fraction})
    assert not reformation_intensity(flat).any()
    full_film = _fields({"pressure": pressure, "film_fraction": np.ones_like(fraction)})
    assert not reformation_intensity(full_film).any()


def test_reynolds_proxy_is_the_pressure_rate_where_the_boundary_passes():
    """Without a film fraction the labelled proxy: the pressure rise rate at cells leaving
    the cavitation pressure."""
    _, pressure = _front_history(3e6)
    fields = _fields({"pressure": pressure})
    dt = (4 * math.pi / N_ROWS) / OMEGA
    rate = boundary_pressure_rate(fields)
    assert np.count_nonzero(rate) == N_THETA * N_Z  # each cell once
    np.testing.assert_allclose(rate.max(axis=0), 3e6 / dt)
    item, note = erosion_map(fields)
    assert item.long_name.startswith("proxy") and note.startswith("cavitation erosion, proxy")


def test_cell_maps_and_their_worst_cells():
    """max p, Δp = max − min and min h per cell, with the worst cell's value, place and
    crank angle; the worst film pressure refined by the film's parabola through the three
    nodes around it (a cosine peak between two nodes)."""
    rng = np.random.default_rng(3)
    pressure = rng.uniform(0.0, 1e6, (N_ROWS, N_THETA, N_Z))
    pressure[7, 3, 2] = 9e6  # the peak at row 7, node (3, 2), neighbours in θ lower
    pressure[7, 2, 2], pressure[7, 4, 2] = 6e6, 4e6
    pressure[1, 5, 1] = -2e6  # a negative (sub-ambient) pressure widens the range there
    thickness = rng.uniform(2e-6, 5e-6, (N_ROWS, N_THETA, N_Z))
    thickness[4, 6, 0] = 0.5e-6
    fields = _fields({"pressure": pressure, "film_thickness": thickness})
    indicators = cell_indicators(fields)
    p_map = indicators.get("max_pressure")
    np.testing.assert_array_equal(p_map.values, pressure.max(axis=0))
    np.testing.assert_array_equal(indicators.get("pressure_range").values,
                                  pressure.max(axis=0) - pressure.min(axis=0))
    np.testing.assert_array_equal(indicators.get("min_film_thickness").values,
                                  thickness.min(axis=0))
    # the parabola through 6, 9, 4 MPa: shift s = (6 − 4)/(2 (6 − 18 + 4)) · (−1)
    shift = 0.5 * (6e6 - 4e6) / (6e6 - 2 * 9e6 + 4e6)
    peak = 9e6 - 0.25 * (6e6 - 4e6) * shift
    assert p_map.worst_value == pytest.approx(peak, rel=1e-14) and peak > 9e6
    assert p_map.worst_theta == pytest.approx(fields.theta[3] + shift * 2 * math.pi / N_THETA)
    assert (p_map.worst_z, p_map.worst_crank_angle) == (fields.z[2], fields.crank_angle[7])
    range_map = indicators.get("pressure_range")
    assert range_map.worst_value == pytest.approx(9e6 - pressure[:, 3, 2].min())
    h_map = indicators.get("min_film_thickness")
    assert h_map.worst_crank_angle == fields.crank_angle[4] and h_map.worst_z == fields.z[0]
    assert indicators.get("max_temperature") is None  # no temperature field: no map


def test_journal_frame_turns_each_row_by_its_rotation():
    """A journal that turns by whole cells: the journal map is the shell row shifted (a
    point fixed on the journal sees the shell node α + ψ); its extremes are the shell's."""
    pressure = np.zeros((N_ROWS, N_THETA, N_Z))
    step = 2 * math.pi / N_THETA
    rotation = np.arange(N_ROWS) * step  # one cell per row
    for i in range(N_ROWS):
        pressure[i, (i + 1) % N_THETA] = 1e6 * (i + 1)  # the load follows the journal node 1
    fields = _fields({"pressure": pressure}, rotation=rotation)
    on_journal = journal_frame(pressure, fields)
    for i in range(N_ROWS):
        np.testing.assert_array_equal(on_journal[i, 1], pressure[i, (i + 1) % N_THETA])
    indicators = cell_indicators(fields)
    journal = indicators.get("max_pressure", "journal")
    shell = indicators.get("max_pressure", "shell")
    assert np.count_nonzero(journal.values.max(axis=1)) == 1  # only journal node 1 is loaded
    assert journal.worst_value == shell.worst_value == 1e6 * N_ROWS
    assert journal.worst_theta == pytest.approx(step)


def test_stride_keeps_the_rows_at_each_multiple():
    phi = np.radians(np.arange(0.0, 720.0, 0.5))
    rows = stride_rows(phi, math.radians(1.0))
    np.testing.assert_allclose(np.degrees(phi[rows]), np.arange(0.0, 720.0, 1.0))
    assert stride_rows(phi, math.radians(0.1)).size == phi.size


class _Summary:
    film_h_min, film_h_min_crank_angle = 0.5e-6, math.radians(40.0)
    p_max, p_max_crank_angle = 200e6, math.radians(20.0)
    effective_temperature = 130.0


class _Cycle:
    crank_angle = np.radians([0.0, 20.0, 40.0])
    h_min_angle_shell = np.radians([0.0, 5.0, 10.0])
    p_max_angle_shell = np.radians([0.0, 3.0, 6.0])


def test_margins_use_the_headline_numbers_and_sign_the_margin():
    """MOFT and POFP from the summary (the headline's), θ from the same output row; MOFT
    is a lower limit, the others upper ones; a temperature without a field is the heat
    balance's; a limit without its field is listed as not checked."""
    rows = margins({"min_film_thickness": 0.6e-6, "max_pressure": 250e6,
                    "max_temperature": 120.0, "asperity_pressure": 1e6},
                   _Summary, _Cycle, None)
    moft, pofp, temperature, asperity = rows
    assert moft.value == _Summary.film_h_min and moft.margin == pytest.approx(-1 / 6)
    assert moft.crossed and moft.theta == _Cycle.h_min_angle_shell[2]
    assert pofp.value == _Summary.p_max and pofp.margin == pytest.approx(0.2)
    assert not pofp.crossed and pofp.theta == _Cycle.p_max_angle_shell[1]
    assert temperature.value == 130.0 and temperature.crossed
    assert asperity.value is None and not asperity.crossed and "not checked" in asperity.text()
    assert moft.text().startswith("0.500 µm vs limit ≥ 0.600 µm") and "CROSSED" in moft.text()


def test_limits_section_is_validated_and_optional():
    base = {"bearing": {"diameter": 0.05, "width": 0.02, "radial_clearance": 25e-6}}
    case = Case.from_dict({**base, "limits": {"max_pressure": 250e6}})
    assert case.limits.given() == {"max_pressure": 250e6}
    assert Case.from_dict(base).limits is None
    assert Case.from_dict(base).content_hash() == Case.from_dict(base).content_hash()
    with pytest.raises(CaseError, match="min_film_thickness"):
        Case.from_dict({**base, "limits": {"min_film_thickness": -1e-6}})
    with pytest.raises(CaseError, match="max_presure"):
        Case.from_dict({**base, "limits": {"max_presure": 1e8}})
    assert isinstance(Margin("max_pressure", "POFP", "Pa", 1e8, 2e8).margin, float)


def test_extremes_over_rows_are_numpys_with_the_first_row_on_a_tie():
    """largest/smallest_over_rows give max/min(axis=0) and argmax/argmin(axis=0) — the
    first row reaching the extreme where several do (coarse values: many ties)."""
    from conrod.results.indicators import largest_over_rows, smallest_over_rows

    rows = np.round(np.random.default_rng(5).uniform(-3.0, 3.0, (40, 7, 3)))
    values, when = largest_over_rows(rows)
    np.testing.assert_array_equal(values, rows.max(axis=0))
    np.testing.assert_array_equal(when, rows.argmax(axis=0))
    values, when = smallest_over_rows(rows)
    np.testing.assert_array_equal(values, rows.min(axis=0))
    np.testing.assert_array_equal(when, rows.argmin(axis=0))


def test_reynolds_proxy_is_the_dense_formula_bit_for_bit():
    """The proxy computed at the crossing cells alone equals the formula over every cell
    and interval: (p_(i+1) − p_i)/Δt where p_i is cavitated and p_(i+1) is not, else 0."""
    rng = np.random.default_rng(11)
    pressure = rng.uniform(-1e5, 8e6, (N_ROWS, N_THETA, N_Z))
    pressure[rng.random(pressure.shape) < 0.5] = 0.0
    fields = _fields({"pressure": pressure})
    following = np.roll(pressure, -1, axis=0)
    level = max(float(np.max(np.abs(pressure))), 1.0) * 1e-9
    crossing = (pressure <= level) & (following > level)
    dense = np.where(crossing, (following - pressure) / interval_times(fields)[:, None, None],
                     0.0)
    assert crossing.any()
    np.testing.assert_array_equal(boundary_pressure_rate(fields), dense)
