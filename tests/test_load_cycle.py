"""LoadCycle: periodic interpolation and input checks."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.loads.cycle import LoadCycle


def make_cycle(n=8, cycle=2 * math.pi):
    angle = np.linspace(0.0, cycle, n, endpoint=False)
    return LoadCycle(
        crank_angle=angle, load_x=np.cos(angle), load_y=np.sin(angle),
        journal_speed=np.full(n, 100.0), shell_speed=np.zeros(n), crank_speed=100.0, cycle=cycle,
    )


def test_interpolation_is_periodic():
    cycle = make_cycle()
    wx_a, wy_a = cycle.load(0.3)
    wx_b, wy_b = cycle.load(0.3 + 2 * math.pi)
    assert (wx_a, wy_a) == pytest.approx((wx_b, wy_b), rel=1e-14)
    # between the last sample and the cycle end, it interpolates towards the first sample
    last = cycle.crank_angle[-1]
    mid = 0.5 * (last + 2 * math.pi)
    assert cycle.load(mid)[0] == pytest.approx(0.5 * (cycle.load_x[-1] + cycle.load_x[0]))


def test_period_time():
    assert make_cycle(cycle=4 * math.pi).period_time == pytest.approx(4 * math.pi / 100.0)


def test_rejects_non_increasing_and_non_finite():
    good = make_cycle()
    with pytest.raises(CaseError, match="strictly increasing"):
        LoadCycle(good.crank_angle[::-1], good.load_x, good.load_y, good.journal_speed,
                  good.shell_speed, 100.0, 2 * math.pi)
    bad = good.load_x.copy()
    bad[2] = np.nan
    with pytest.raises(CaseError, match="load_x must be finite"):
        LoadCycle(good.crank_angle, bad, good.load_y, good.journal_speed,
                  good.shell_speed, 100.0, 2 * math.pi)
