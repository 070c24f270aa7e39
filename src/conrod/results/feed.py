"""The crank-pin oil feed of a run: per-angle columns and cycle figures of the journal's
oil holes (``CycleResults.feed``, :mod:`conrod.loads.oil_feed`).

Keys of ``CycleResults.feed`` (arrays over the output angles, SI units):

* ``journal_hole_flow`` [m³/s]: oil through the journal holes, signed, positive into the
  bearing (negative: the film pushes oil back into the drilling);
* ``journal_hole_angle_shell`` [rad]: shell angle θ of the first hole's centre;
* ``journal_hole_pressure`` [Pa]: gauge feed pressure at the first hole's mouth;
* ``inlet_film_fraction`` [-] (mass-conserving film only): the film fraction where the oil
  enters the loaded zone (:data:`STARVED_FRACTION`).
"""

from __future__ import annotations

import numpy as np

STARVED_FRACTION = 0.9
"""Film fraction at the loaded zone's inlet below which the load zone runs partially
filled (starved) [-]. Measured on a 50 mm bearing under a rotating 1.5 kN load (48 × 8,
mass-conserving film): a full 3 mm groove at 3 bar keeps it ≥ 0.91 (mean 0.996), at
0.3 bar it falls to 0.62 (mean 0.83)."""
LITRES_PER_MINUTE = 6.0e4
"""m³/s → l/min [-]."""


def feed_summary_items(feed: dict | None) -> dict[str, float]:
    """summary.json items of the journal holes: mean, largest inflow and backflow [m³/s],
    share of the cycle with backflow [-], smallest inlet film fraction [-] ({} without)."""
    if feed is None:
        return {}
    flow = np.asarray(feed["journal_hole_flow"], dtype=float)
    items = {"journal_hole_flow_mean_m3_s": float(flow.mean()),
             "journal_hole_flow_max_m3_s": float(flow.max()),
             "journal_hole_flow_min_m3_s": float(flow.min()),
             "journal_hole_backflow_share": float(np.mean(flow < 0.0))}
    fraction = feed.get("inlet_film_fraction")
    if fraction is not None:
        items["inlet_film_fraction_min"] = float(np.min(fraction))
        items["starved_share"] = float(np.mean(np.asarray(fraction) < STARVED_FRACTION))
    return items


def feed_headline(feed: dict | None) -> dict[str, str]:
    """The headline line of the journal holes ({} without)."""
    items = feed_summary_items(feed)
    if not items:
        return {}
    text = (f"mean {items['journal_hole_flow_mean_m3_s'] * LITRES_PER_MINUTE:.3g} l/min "
            f"into the bearing, backflow over {items['journal_hole_backflow_share']:.0%} "
            "of the cycle")
    if "inlet_film_fraction_min" in items:
        text += (f"; inlet film fraction >= {items['inlet_film_fraction_min']:.2f} "
                 f"(starved {items['starved_share']:.0%} of the cycle)")
    return {"crank-pin hole": text}


def starvation_warnings(feed: dict | None, crank_angle_deg: np.ndarray) -> list[str]:
    """A warning when the loaded zone runs partially filled (inlet film fraction below
    :data:`STARVED_FRACTION`) at some output angle."""
    if feed is None or feed.get("inlet_film_fraction") is None:
        return []
    fraction = np.asarray(feed["inlet_film_fraction"], dtype=float)
    starved = fraction < STARVED_FRACTION
    if not starved.any():
        return []
    i = int(np.argmin(fraction))
    return [f"the load zone runs partially filled over {np.mean(starved):.0%} of the cycle "
            f"(inlet film fraction down to {fraction[i]:.2f} at crank angle "
            f"{crank_angle_deg[i]:.0f} deg, below {STARVED_FRACTION:g}): the crank-pin "
            "feed does not keep the film full; a higher gallery pressure, a larger hole or "
            "another hole angle feeds it"]
