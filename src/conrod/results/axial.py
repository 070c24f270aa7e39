"""The axial dimension of a run's results: journal tilt, tilting moments and where h_min sits
along the width, for a tilted journal or a profiled bore (``CycleResults.axial``).

Per output angle (SI, keys of :data:`conrod.results.columns.AXIAL_COLUMNS`): ``tilt_x``,
``tilt_y`` [rad] and their rates [rad/s]; ``moment_x``, ``moment_y`` [N m], the moments of
the film pressure on the journal about the bearing centre (:mod:`conrod.film.base`);
``external_moment_x``, ``external_moment_y`` [N m] of a solved tilt; ``h_min_axial_position``
[m] (z of h_min, 0 = mid-width); ``h_min_at_edge`` (h_min on an edge node z = ±L/2);
``edge_h_min`` [m], the smallest film thickness on the two edges. Cycle items for
summary.json and the headline: the smallest edge h_min and the largest moment, with their
crank angles.
"""

from __future__ import annotations

import math

import numpy as np

AXIAL_KEYS = ("tilt_x", "tilt_y", "tilt_rate_x", "tilt_rate_y", "moment_x", "moment_y",
              "external_moment_x", "external_moment_y", "h_min_axial_position",
              "h_min_at_edge", "edge_h_min")
"""Per-angle arrays of ``CycleResults.axial``."""


def axial_columns(results: list, tilt: np.ndarray | None, external: np.ndarray | None,
                  width: float) -> dict[str, np.ndarray]:
    """The per-angle arrays from the film results at the output angles, the tilt (n, 4)
    [rad, rad/s] (None: aligned) and the external moment (n, 2) [N m] (None: zero) of a
    bearing of ``width`` [m]."""
    n = len(results)

    def column(name: str) -> np.ndarray:
        return np.array([getattr(r, name) for r in results], dtype=float)

    tilt = np.zeros((n, 4)) if tilt is None else np.asarray(tilt, dtype=float)
    external = np.zeros((n, 2)) if external is None else np.asarray(external, dtype=float)
    position = column("min_film_axial_position")
    edge = np.array([r.min_film_thickness if r.edge_min_film_thickness is None
                     else r.edge_min_film_thickness for r in results], dtype=float)
    return {"tilt_x": tilt[:, 0], "tilt_y": tilt[:, 1], "tilt_rate_x": tilt[:, 2],
            "tilt_rate_y": tilt[:, 3], "moment_x": column("moment_x"),
            "moment_y": column("moment_y"), "external_moment_x": external[:, 0],
            "external_moment_y": external[:, 1], "h_min_axial_position": position,
            "h_min_at_edge": np.abs(position) >= 0.5 * width * (1.0 - 1e-9),
            "edge_h_min": edge}


def axial_summary_items(crank_angle: np.ndarray, axial: dict) -> dict[str, float]:
    """summary.json items: smallest edge h_min [m] and its crank angle [deg], largest moment
    |M| [N m] and its crank angle, largest tilt |γ| [rad], share of the cycle with h_min at
    an edge [-]."""
    edge = np.asarray(axial["edge_h_min"])
    moment = np.hypot(axial["moment_x"], axial["moment_y"])
    tilt = np.hypot(axial["tilt_x"], axial["tilt_y"])
    i, j = int(np.argmin(edge)), int(np.argmax(moment))
    return {"edge_h_min_m": float(edge[i]),
            "edge_h_min_crank_angle_deg": float(np.degrees(crank_angle[i])),
            "max_moment_N_m": float(moment[j]),
            "max_moment_crank_angle_deg": float(np.degrees(crank_angle[j])),
            "max_tilt_rad": float(tilt.max()),
            "h_min_at_edge_share": float(np.mean(axial["h_min_at_edge"]))}


def axial_headline(crank_angle: np.ndarray, axial: dict) -> dict[str, str]:
    """Headline lines: the edge h_min and the moments (label → text)."""
    items = axial_summary_items(crank_angle, axial)
    tilt = items["max_tilt_rad"]
    at_edge = items["h_min_at_edge_share"]
    return {
        "edge h_min": (f"{items['edge_h_min_m'] * 1e6:.3f} µm at "
                       f"{items['edge_h_min_crank_angle_deg']:.0f}° (h_min at an edge over "
                       f"{at_edge:.0%} of the cycle)"),
        "moments": (f"up to {items['max_moment_N_m']:.4g} N m at "
                    f"{items['max_moment_crank_angle_deg']:.0f}° (film on the journal, about "
                    f"the bearing centre); tilt up to {tilt * 1e3:.3g} mrad"
                    if math.isfinite(tilt) else ""),
    }
