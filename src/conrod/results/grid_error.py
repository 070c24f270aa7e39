"""Grid-error estimate of a grid film's h_min and p_max: Richardson extrapolation from the
run grid and two coarser grids at the run's critical crank angles, with the observed order
of convergence (Celik et al. 2008, "Procedure for estimation and reporting of uncertainty
due to discretization in CFD applications", J. Fluids Eng. 130, 078001; Roache 1998).

With the values φ₁ (run grid), φ₂, φ₃ (coarser) and the representative cell sizes
h ∝ 1/√(n_θ n_z), r₂₁ = h₂/h₁, r₃₂ = h₃/h₂, ε₂₁ = φ₂ − φ₁, ε₃₂ = φ₃ − φ₂, the observed order
p solves

.. math::

    p = \\frac{1}{\\ln r_{21}} \\left| \\ln\\left|\\frac{ε_{32}}{ε_{21}}\\right|
        + \\ln\\frac{r_{21}^p - s}{r_{32}^p - s} \\right|, \\qquad s = \\operatorname{sign}
        \\frac{ε_{32}}{ε_{21}},

and the extrapolated value is φ_ext = (r₂₁ᵖ φ₁ − φ₂)/(r₂₁ᵖ − 1); the grid error of the run's
value is φ_ext − φ₁. Where the three values do not converge monotonically (oscillating, or
an order outside :data:`ORDER_RANGE`) the order is not observed: the error is then bounded
by the largest change between the grids and said so.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

ORDER_RANGE = (0.5, 4.0)
"""Observed orders accepted as asymptotic convergence [-]."""
UNITS = {"h_min": ("µm", 1e6), "p_max": ("MPa", 1e-6)}
"""Quantity → (display unit, factor from SI)."""


@dataclass(frozen=True)
class GridEstimate:
    """The grid error of one quantity at one crank angle.

    quantity : str  "h_min" [m] or "p_max" [Pa].
    crank_angle_deg : float  The run's critical angle (of the smallest film h_min, of the
        largest p_max) [deg].
    values : tuple  The quantity there on the run grid and the coarser ones, finest
        first [m or Pa].
    order : float or None  Observed order of convergence [-]; None where not observed.
    error : float  Extrapolated minus run-grid value (signed; the bound where the order is
        not observed) [m or Pa].
    """

    quantity: str
    crank_angle_deg: float
    values: tuple[float, ...]
    order: float | None
    error: float

    @property
    def relative_error(self) -> float:
        """error / run-grid value [-]."""
        return self.error / self.values[0] if self.values[0] else math.inf

    def as_json_items(self) -> dict:
        """``summary.json["grid_error"][quantity]`` (SI units in the names)."""
        unit = "m" if self.quantity == "h_min" else "Pa"
        return {"crank_angle_deg": self.crank_angle_deg,
                f"values_{unit}": list(self.values), "observed_order": self.order,
                f"error_{unit}": self.error, "relative_error": self.relative_error}


@dataclass(frozen=True)
class GridError:
    """Grid-error estimates of h_min and p_max from the run grid and two coarser grids.

    grids : tuple  (n_θ, n_z) of the run grid and the coarser grids, finest first [-].
    h_min : GridEstimate  At the crank angle of the smallest film h_min.
    p_max : GridEstimate  At the crank angle of the largest p_max.
    """

    grids: tuple[tuple[int, int], ...]
    h_min: GridEstimate
    p_max: GridEstimate

    def estimate(self, quantity: str) -> GridEstimate:
        """The estimate of "h_min" or "p_max"."""
        return self.h_min if quantity == "h_min" else self.p_max

    def text(self, quantity: str) -> str:
        """The headline words, e.g. 'grid error +0.33 µm (+11 %; Richardson 36×8, 26×6,
        18×4 at 59°, observed order 0.8)'."""
        item = self.estimate(quantity)
        unit, factor = UNITS[quantity]
        grids = ", ".join(f"{a}×{b}" for a, b in self.grids)
        order = (f"observed order {item.order:.2g}" if item.order is not None else
                 "no observed order: bounded by the largest change between the grids")
        return (f"grid error {item.error * factor:+.3g} {unit} ({100 * item.relative_error:+.1f} %;"
                f" Richardson {grids} at {item.crank_angle_deg:.0f}°, {order})")

    def as_json_items(self) -> dict:
        """``summary.json["grid_error"]``."""
        return {"method": "Richardson extrapolation from the run grid and two coarser "
                          "grids at the critical crank angles, observed order (Celik et "
                          "al. 2008)",
                "grids": [list(grid) for grid in self.grids],
                "h_min": self.h_min.as_json_items(), "p_max": self.p_max.as_json_items()}


def cell_size(grid: tuple[int, int]) -> float:
    """Representative cell size of a (n_θ, n_z) grid, 1/√(n_θ n_z) [-]."""
    return 1.0 / math.sqrt(grid[0] * grid[1])


def richardson(values: tuple[float, float, float], sizes: tuple[float, float, float]
               ) -> tuple[float | None, float]:
    """(observed order or None, extrapolated − finest value) from three values on grids of
    representative sizes ``sizes``, finest first (see the module docstring)."""
    phi1, phi2, phi3 = values
    r21, r32 = sizes[1] / sizes[0], sizes[2] / sizes[1]
    e21, e32 = phi2 - phi1, phi3 - phi2
    largest = max(abs(e21), abs(e32))
    if e21 == 0.0 or e32 == 0.0 or e32 / e21 < 0.0:  # no change, or oscillating
        return None, math.copysign(largest, -e21 if e21 else -e32)
    s = 1.0
    order = abs(math.log(abs(e32 / e21))) / math.log(r21)
    for _ in range(100):  # fixed point of the order equation for unequal ratios
        new = abs(math.log(abs(e32 / e21)) + math.log((r21**order - s) / (r32**order - s))
                  ) / math.log(r21)
        if abs(new - order) < 1e-10:
            break
        order = new
    if not (ORDER_RANGE[0] <= order <= ORDER_RANGE[1]) or not math.isfinite(order):
        return None, -math.copysign(largest, e21)
    return order, -e21 / (r21**order - 1.0)
