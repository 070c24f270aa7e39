"""The crank-pin oil feed over the cycle: where the journal's oil holes are and at what
pressure they deliver oil, at any crank angle.

A hole drilled in the crank pin turns with the crank; the shell of a big end turns with the
rod, so relative to the shell (the film frame) the hole turns at ω_j − ω_b = ω − Ω_rod and
its shell angle is θ = α + ψ(φ), α its angle on the pin from the outward crank radius and

.. math:: ψ(φ) = \\int_0^φ \\frac{ω_j − ω_b}{ω}\\,dφ'

(= φ + β for a crank pin, the crank angle plus the rod obliquity: at φ = 0 the crank radius
lies along the rod axis θ = 0; docs/conventions.md, "Oil holes in the crank pin"). The
oil column in the crank drilling turns with the crank at ω, so the pressure at the hole's
mouth is the gallery pressure plus the centrifugal head, less the drilling's losses:

.. math:: p_h(φ) = (1 − k)\\,\\bigl(p_g(φ) + ρ ω^2 (r_{out}^2 − r_{in}^2)/2\\bigr)

(gauge, ≥ 0: a drilling whose head is negative drains to ambient).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from conrod.cases.base import range_error
from conrod.film.base import JournalFeed
from conrod.loads.cycle import LoadCycle

SAMPLES_PER_CYCLE = 2880
"""Crank angles at which ψ(φ) is integrated over one cycle (0.25° over 720°) [-]."""


def centrifugal_head(density: float, crank_speed: float, inner_radius: float,
                     outer_radius: float) -> float:
    """Pressure rise ρ ω² (r_out² − r_in²)/2 of an oil column turning with the crank at
    ``crank_speed`` [rad/s] from ``inner_radius`` to ``outer_radius`` [m] [Pa]."""
    return 0.5 * density * crank_speed**2 * (outer_radius**2 - inner_radius**2)


def mouth_radius(crank_radius: float, pin_radius: float, angle: float) -> float:
    """Distance from the crank axis of a point on the pin surface at ``angle`` [rad] from
    the outward crank radius [m]."""
    return math.hypot(crank_radius + pin_radius * math.cos(angle),
                      pin_radius * math.sin(angle))


@dataclass(frozen=True)
class HoleSupply:
    """Feed of one journal hole: gallery pressure (constant or periodic table), centrifugal
    head and loss share.

    gallery_angles : ndarray or None  Crank angles of the gallery table [rad]; None: constant.
    gallery_pressure : ndarray  Gauge gallery pressure [Pa] (one value when constant).
    head : float  Centrifugal head ρ ω² (r_out² − r_in²)/2 [Pa].
    loss : float  Share of the ideal feed pressure lost in the drilling [-].
    cycle : float  Period of the table [rad].
    """

    gallery_angles: np.ndarray | None
    gallery_pressure: np.ndarray
    head: float
    loss: float
    cycle: float

    def pressure(self, crank_angle: float) -> float:
        """Gauge pressure at the hole's mouth at ``crank_angle`` [rad] [Pa] (≥ 0)."""
        if self.gallery_angles is None:
            gallery = float(self.gallery_pressure[0])
        else:
            gallery = float(np.interp(crank_angle, self.gallery_angles, self.gallery_pressure,
                                      period=self.cycle))
        return max((1.0 - self.loss) * (gallery + self.head), 0.0)


@dataclass(frozen=True)
class FeedSchedule:
    """The journal feed at any crank angle: ψ(φ) sampled over one cycle, one
    :class:`HoleSupply` per journal hole.

    angles : ndarray  Crank angles 0 … cycle [rad];  turned : ndarray  ψ there [rad].
    cycle : float  Period [rad];  supplies : tuple  One :class:`HoleSupply` per hole.
    """

    angles: np.ndarray
    turned: np.ndarray
    cycle: float
    supplies: tuple[HoleSupply, ...]

    def journal_angle(self, crank_angle: float) -> float:
        """ψ(φ): angle of the journal's reference direction in the film frame [rad]."""
        turns = math.floor(crank_angle / self.cycle)
        rest = crank_angle - turns * self.cycle
        return turns * float(self.turned[-1]) + float(np.interp(rest, self.angles, self.turned))

    def at(self, crank_angle: float) -> JournalFeed:
        """The :class:`~conrod.film.base.JournalFeed` at ``crank_angle`` [rad]."""
        return JournalFeed(self.journal_angle(crank_angle),
                           tuple(s.pressure(crank_angle) for s in self.supplies))


def journal_turn(loads: LoadCycle) -> tuple[np.ndarray, np.ndarray]:
    """(φ over one cycle [rad], ψ(φ) = ∫ (ω_j − ω_b)/ω dφ' [rad]) by the trapezoid rule on
    :data:`SAMPLES_PER_CYCLE` intervals of the load cycle's periodic speeds."""
    angles = np.linspace(0.0, loads.cycle, SAMPLES_PER_CYCLE + 1)
    journal, shell = loads.speeds(angles)
    rate = (np.asarray(journal) - np.asarray(shell)) / loads.crank_speed
    turned = np.concatenate([[0.0], np.cumsum(0.5 * (rate[1:] + rate[:-1]) * np.diff(angles))])
    return angles, turned


def hole_supply(section: Any, angle: float, loads: LoadCycle, density: float,
                crank_radius: float | None, pin_radius: float, name: str) -> HoleSupply:
    """:class:`HoleSupply` of a ``[[bearing.journal_holes]]`` entry at pin ``angle`` [rad];
    CaseError naming the field when its drilling does not end on the pin surface."""
    outer = section.drilling_outer_radius
    if crank_radius is not None:
        low, high = crank_radius - pin_radius, crank_radius + pin_radius
        if outer is None:
            outer = mouth_radius(crank_radius, pin_radius, angle)
        elif not low - 1e-9 <= outer <= high + 1e-9:
            raise range_error(f"{name}.drilling_outer_radius", outer, f">= {low:g} and <= "
                              f"{high:g} (on the pin surface: crank radius {crank_radius:g} m "
                              f"-/+ pin radius {pin_radius:g} m)", "m")
    elif outer is None:
        raise range_error(f"{name}.drilling_outer_radius", None, "a radius > 0 (required "
                          "without [engine], which gives the crank radius)", "m")
    table = section.gallery_pressure
    if isinstance(table, list):
        rows = np.asarray(table, dtype=float)
        angles, values = np.radians(rows[:, 0]), rows[:, 1]
    else:
        angles, values = None, np.array([float(table)])
    head = centrifugal_head(density, loads.crank_speed, section.drilling_inner_radius, outer)
    return HoleSupply(angles, values, head, section.loss_coefficient, loads.cycle)


def feed_schedule(case: Any, loads: LoadCycle, density: float,
                  wear_angle: float | None) -> FeedSchedule | None:
    """The feed of the case's ``[[bearing.journal_holes]]`` (None without one) at the oil
    density ``density`` [kg/m³]; ``wear_angle`` [rad] for holes at 'wear_diagram'."""
    holes = case.bearing.journal_holes
    if not holes:
        return None
    crank_radius = 0.5 * case.engine.stroke if case.engine is not None else None
    pin_radius = 0.5 * case.bearing.diameter
    supplies = tuple(
        hole_supply(section, section.to_journal_hole(wear_angle).angle, loads, density,
                    crank_radius, pin_radius, f"bearing.journal_holes[{k}]")
        for k, section in enumerate(holes))
    angles, turned = journal_turn(loads)
    return FeedSchedule(angles, turned, loads.cycle, supplies)


def wear_diagram_angle(case: Any) -> float | None:
    """The least-worn journal angle of the case's engine loads [rad] when a journal hole
    asks for it (``angle = "wear_diagram"``); None otherwise."""
    bearing = case.bearing
    if bearing is None or not any(h.angle == "wear_diagram" for h in bearing.journal_holes):
        return None
    if case.engine is None:
        return None  # the hole's own CaseError names the field
    from conrod.loads.engine_loads import compute_engine_loads

    return compute_engine_loads(case).oil_hole_angle()
