"""Cavitation erosion on the shell: where and when the film reforms violently.

Erosion damage in engine bearings comes from vapour and gas cavities that collapse where the
cavitated film fills again under a fast pressure rise (Garner, James & Warriner 1980,
docs/references.md). Per film cell, over the intervals between output crank angles
(φ_i → φ_(i+1), time Δt = Δφ/ω, the last interval closing the cycle):

* **mass-conserving film** (film fraction ϑ): the reformation intensity

  .. math:: E = \\frac{\\max(ϑ_{i+1} - ϑ_i, 0)}{Δt} \\cdot \\max(p_{i+1} - p_i, 0)
            \\quad \\text{where } ϑ_i < 1

  — how fast the film fraction recovers times the pressure rise at the cell as it does
  [Pa/s]; the cell's indicator is its largest E over the cycle, with the crank angle
  φ_(i+1) where it happens. A cell that refills slowly, or whose pressure does not rise as
  it refills, scores low; a cell the film closes over in one interval under a steep
  pressure rise scores high. It ranks the cells and the operating points of one bearing;
  it is not a damage rate (no material, no bubble dynamics).
* **Reynolds film** (Swift–Stieber, no film content): a labelled proxy, the rate of the
  pressure rise max(p_(i+1) − p_i, 0)/Δt at cells that were at the cavitation pressure at
  φ_i and are pressurised at φ_(i+1) (the reformation boundary passing over the cell)
  [Pa/s]. Without a film content the model does not know how much the cavity held: read it
  as where the boundary moves under a fast pressure rise, not as an intensity.
"""

from __future__ import annotations

import math

import numpy as np

from conrod.results.fields import CycleFields
from conrod.results.indicators import CellMap, largest_over_rows, middle_of_ties

FULL_FILM = 1.0 - 1e-9
"""Film fraction below which a cell counts as cavitated [-]."""
CAVITATED_SHARE = 1e-9
"""A Reynolds node within this share of the pressure scale of the cavitation pressure is
cavitated [-]."""
MASS_CONSERVING = "reformation intensity (film-fraction recovery rate x pressure rise)"
REYNOLDS_PROXY = ("proxy: pressure-rise rate where the reformation boundary passes "
                  "(a film without a film content: Reynolds, short)")


def interval_times(fields: CycleFields) -> np.ndarray:
    """Δt of the intervals φ_i → φ_(i+1), the last one closing the cycle (n,) [s]."""
    phi = np.asarray(fields.crank_angle, dtype=float)
    steps = np.append(np.diff(phi), fields.cycle_length - (phi[-1] - phi[0]))
    return steps / fields.crank_speed


def reformation_intensity(fields: CycleFields) -> np.ndarray:
    """E per interval and cell (n, n_θ, n_z) [Pa/s] of the mass-conserving film (module
    docstring)."""
    theta_now = fields["film_fraction"]
    theta_next = np.roll(theta_now, -1, axis=0)
    p_now = fields["pressure"]
    rise = np.maximum(np.roll(p_now, -1, axis=0) - p_now, 0.0)
    dt = interval_times(fields)[:, None, None]
    recovery = np.maximum(theta_next - theta_now, 0.0) / dt
    return np.where(theta_now < FULL_FILM, recovery * rise, 0.0)


def boundary_pressure_rate(fields: CycleFields) -> np.ndarray:
    """The Reynolds proxy per interval and cell (n, n_θ, n_z) [Pa/s] (module docstring);
    the rate computed at the crossing cells alone (a few per cell and cycle)."""
    p_now = fields["pressure"]
    scale = max(float(p_now.max()), -float(p_now.min()), 1.0) * CAVITATED_SHARE
    cavitated = p_now <= fields.cavitation_pressure + scale
    i, j, k = np.nonzero(cavitated & ~np.roll(cavitated, -1, axis=0))
    rate = np.zeros(p_now.shape)
    following = (i + 1) % p_now.shape[0]
    rate[i, j, k] = (p_now[following, j, k] - p_now[i, j, k]) / interval_times(fields)[i]
    return rate


def erosion_map(fields: CycleFields) -> tuple[CellMap | None, str]:
    """(the erosion indicator on the shell, what it is) for the fields of a run: the
    reformation intensity with a film fraction, the labelled proxy without; (None, why)
    without a pressure field."""
    if "pressure" not in fields:
        return None, "no cavitation-erosion indicator: the film gives no pressure field"
    if "film_fraction" in fields:
        per_interval, words = reformation_intensity(fields), MASS_CONSERVING
    else:
        per_interval, words = boundary_pressure_rate(fields), REYNOLDS_PROXY
    values, when = largest_over_rows(per_interval)
    after = (when + 1) % fields.crank_angle.size  # the interval ends at φ_(i+1)
    j, node = np.unravel_index(int(values.argmax()), values.shape)
    k = middle_of_ties(values[j], int(node))
    item = CellMap("erosion", words, "Pa/s", "shell", values, fields.crank_angle[after],
                   "max", float(values[j, k]), float(fields.theta[j]), float(fields.z[k]),
                   float(fields.crank_angle[after[j, k]]))
    return item, _note(words, item)


def _note(words: str, item: CellMap) -> str:
    if item.worst_value <= 0.0:
        return f"cavitation erosion, {words}: no reformation over the cycle"
    return (f"cavitation erosion, {words}: worst {item.worst_value:.3g} Pa/s at "
            f"θ {math.degrees(item.worst_theta):.0f}°, z {item.worst_z * 1e3:.1f} mm, "
            f"{math.degrees(item.worst_crank_angle):.0f}°")
