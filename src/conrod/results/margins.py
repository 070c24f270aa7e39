"""Margins against the ``[limits]`` of the case: the sign-off table.

One truth: the film h_min (MOFT) and p_max (POFP) of the table are the numbers the headline
prints (``summary.film_h_min`` and ``summary.p_max``, from ``cycle.csv``), with the place
on the shell from the same output row; the pressure range and the asperity pressure are the
worst cells of their maps (:mod:`conrod.results.indicators`); the temperature is the film's
temperature field where a film declares one, else the heat balance's effective temperature
of the headline. The margin is relative to the limit, positive inside it:
(limit − value)/limit for an upper limit, (value − limit)/limit for the lower one (MOFT).
A crossed limit is a warning (exit 4).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from conrod.results.fields import CycleFields
from conrod.results.indicators import Indicators

LIMITS = {
    "min_film_thickness": ("MOFT (film h_min)", "m", "min"),
    "max_pressure": ("POFP (film p_max)", "Pa", "max"),
    "pressure_range": ("pressure range Δp (lining fatigue)", "Pa", "max"),
    "asperity_pressure": ("asperity pressure", "Pa", "max"),
    "max_temperature": ("film temperature", "degC", "max"),
}
"""``[limits]`` key → label, SI unit, which side is allowed ('min': at least the limit)."""
DISPLAY = {"m": (1e6, "µm", "{:.3f}"), "Pa": (1e-6, "MPa", "{:.2f}"),
           "degC": (1.0, "°C", "{:.1f}")}
"""SI unit → (factor, engineering unit, format) of the headline: the formats of its film
h_min, p_max and temperature lines, so that a margin prints the headline's number."""


@dataclass(frozen=True)
class Margin:
    """One row of the margins table.

    name : str  The ``[limits]`` key [-].
    label : str  What is checked, in words [-].
    units : str  SI unit of ``value`` and ``limit`` ('m', 'Pa', 'degC') [-].
    limit : float  The limit, in ``units``.
    value : float or None  The run's worst value, in ``units``; None: not computed.
    crank_angle : float or None  Where in the cycle [rad].
    theta : float or None  Shell angle [rad].
    z : float or None  Axial position [m].
    source : str  Where the value comes from, or why it is not checked [-].
    """

    name: str
    label: str
    units: str
    limit: float
    value: float | None
    crank_angle: float | None = None
    theta: float | None = None
    z: float | None = None
    source: str = ""

    @property
    def margin(self) -> float | None:
        """(limit − value)/limit, or (value − limit)/limit for MOFT; positive inside [-]."""
        if self.value is None:
            return None
        if LIMITS[self.name][2] == "min":
            return (self.value - self.limit) / self.limit
        return (self.limit - self.value) / self.limit

    @property
    def crossed(self) -> bool:
        """True when the value is beyond the limit [-]."""
        return self.margin is not None and self.margin < 0.0

    def display(self, value: float | None) -> str:
        """A value of this row in engineering units, e.g. '0.541 µm'."""
        if value is None:
            return "–"
        factor, unit, style = DISPLAY[self.units]
        return f"{style.format(value * factor)} {unit}"

    def where(self) -> str:
        """'at 37°, θ 205°, z −3.0 mm' (what is known of it)."""
        parts = []
        if self.crank_angle is not None:
            parts.append(f"at {math.degrees(self.crank_angle):.0f}°")
        if self.theta is not None:
            parts.append(f"θ {math.degrees(self.theta) % 360.0:.0f}°")
        if self.z is not None:
            parts.append(f"z {self.z * 1e3:+.1f} mm")
        return ", ".join(parts)

    def text(self) -> str:
        """The headline line of this row."""
        if self.value is None:
            return f"limit {self.display(self.limit)}: not checked ({self.source})"
        sign = "≥" if LIMITS[self.name][2] == "min" else "≤"
        state = "CROSSED" if self.crossed else "ok"
        where = self.where() or self.source
        return (f"{self.display(self.value)} vs limit {sign} {self.display(self.limit)}: "
                f"margin {self.margin:+.0%} {state} ({where})")

    def as_json_items(self) -> dict:
        """summary.json items (SI units in the keys' suffixes)."""
        unit = self.units
        return {"label": self.label, f"value_{unit}": self.value, f"limit_{unit}": self.limit,
                "margin": self.margin, "crossed": self.crossed,
                "crank_angle_deg": (None if self.crank_angle is None
                                    else math.degrees(self.crank_angle)),
                "theta_deg": None if self.theta is None else math.degrees(self.theta) % 360.0,
                "z_m": self.z, "source": self.source}


@dataclass(frozen=True)
class SignOff:
    """What a bearing is signed off on: the per-cell indicators, the margins against the
    case's ``[limits]`` and, when asked for, the fields over the cycle.

    indicators : Indicators or None  Per-cell maps (None: the film gives no fields).
    margins : tuple  :class:`Margin` per given limit.
    fields : CycleFields or None  The fields over the last cycle at the asked stride
        (``conrod run --fields``); None when not asked for.
    notes : tuple  What the indicators leave out, in words [-].
    """

    indicators: Indicators | None
    margins: tuple[Margin, ...] = ()
    fields: CycleFields | None = None
    notes: tuple[str, ...] = ()

    def warnings(self) -> list[str]:
        """One warning per crossed limit."""
        return [f"limit crossed: {m.label} {m.text()}" for m in self.margins if m.crossed]

    def headline(self) -> dict[str, str]:
        """Headline lines: one per limit ('margin MOFT (film h_min)' → text), the erosion."""
        lines = {f"margin {m.name}": m.text() for m in self.margins}
        if self.indicators is not None and self.indicators.erosion_note:
            lines["erosion"] = self.indicators.erosion_note
        elif self.indicators is None and self.notes:
            lines["sign-off maps"] = "; ".join(self.notes)
        return lines

    def flat_items(self) -> dict[str, float | None]:
        """Scalars for summary.json's top level (a sweep table's columns): the worst
        pressure range [Pa], asperity pressure [Pa], film temperature [°C] and erosion
        indicator [Pa/s] over the cycle where computed, and each given limit in SI units
        (the engine-map report draws its contour)."""
        items: dict[str, float | None] = {}
        found = self.indicators
        for key, name in (("max_pressure_range_Pa", "pressure_range"),
                          ("max_asperity_pressure_Pa", "max_asperity_pressure"),
                          ("max_film_temperature_C", "max_temperature"),
                          ("max_erosion_indicator_Pa_s", "erosion")):
            item = None if found is None else found.get(name)
            if item is not None:
                items[key] = item.worst_value
        for m in self.margins:
            items[f"limit_{m.name}_{m.units.replace('degC', 'C')}"] = m.limit
        items["limits_crossed"] = float(sum(m.crossed for m in self.margins))
        return items

    def as_json_items(self) -> dict:
        """summary.json["signoff"]: margins, the maps' worst values, notes."""
        return {"margins": {m.name: m.as_json_items() for m in self.margins},
                "indicators": (None if self.indicators is None
                               else self.indicators.summary_items()),
                "notes": list(self.notes)}


def margins(limits: dict[str, float], summary, cycle, indicators: Indicators | None
            ) -> tuple[Margin, ...]:
    """A :class:`Margin` per given limit (module docstring)."""
    rows = []
    for name, limit in limits.items():
        label, units, _ = LIMITS[name]
        found = _value(name, summary, cycle, indicators)
        if isinstance(found, str):
            rows.append(Margin(name, label, units, float(limit), None, source=found))
        else:
            rows.append(Margin(name, label, units, float(limit), *found))
    return tuple(rows)


def _value(name, summary, cycle, indicators):
    """(value, crank angle, θ, z, source) of the limit ``name``, or why it is not checked."""
    if name == "min_film_thickness":
        if summary.film_h_min is None:
            return "no film: the journal touches the shell over the whole cycle"
        return _headline_row(cycle, summary.film_h_min, summary.film_h_min_crank_angle,
                             "h_min_angle_shell", indicators, "min_film_thickness")
    if name == "max_pressure":
        return _headline_row(cycle, summary.p_max, summary.p_max_crank_angle,
                             "p_max_angle_shell", indicators, "max_pressure")
    if name == "max_temperature" and (indicators is None
                                      or indicators.get("max_temperature") is None):
        if summary.effective_temperature is None:
            return "no temperature: no heat balance (no oil flow) and no film temperature field"
        return (summary.effective_temperature, None, None, None,
                "effective temperature of the heat balance, the headline's")
    source = {"pressure_range": "pressure_range", "asperity_pressure": "max_asperity_pressure",
              "max_temperature": "max_temperature"}[name]
    if indicators is None:
        return "the film gives no fields: a table or mobility film"
    item = indicators.get(source)
    if item is None:
        return _missing(name)
    return (item.worst_value, item.worst_crank_angle, item.worst_theta, item.worst_z,
            f"worst cell of the {source} map")


def _headline_row(cycle, value, crank_angle, theta_column, indicators, map_name):
    """The headline's value and crank angle, θ from the same output row of cycle.csv, z
    from the indicator map where its worst cell is at that crank angle."""
    i = int(np.argmin(np.abs(np.asarray(cycle.crank_angle) - crank_angle)))
    theta = float(getattr(cycle, theta_column)[i])
    item = None if indicators is None else indicators.get(map_name)
    z = item.worst_z if item is not None and item.worst_crank_angle == crank_angle else None
    return value, crank_angle, theta, z, "the headline's value (cycle.csv)"


def _missing(name: str) -> str:
    return {"asperity_pressure": "no asperity contact: [contact] model is not greenwood_tripp",
            "max_temperature": "no film temperature field"}.get(name, "not computed")
