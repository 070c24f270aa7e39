"""Film characteristics of the mass-conserving model from its discrete fields.

Forces by trapezoidal quadrature of −∫∫ p (cos θ, sin θ) R dθ dz; shear moments from
τ = ±μ R(ω_j − ω_b) ϑ_c/h − (h/2) ∂p/∂x with the pressure part integrated by parts,
∫∫ (h/2) ∂p/∂x dx dz = −∫∫ (p/2) ∂h/∂θ dθ dz (periodic); ϑ_c = ϑ ('film_fraction') or 1
('full_film', Raimondi & Boyd's convention). Flows are the discrete face fluxes of the
cell balance, so supply − side flow − d(content)/dt vanishes to solver tolerance.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from conrod.film.base import FilmResult, FilmState
from conrod.film.mass_conserving.kernel import cell_balance
from conrod.film.mass_conserving.memory import FilmFields
from conrod.film.tilt import axial_summary, moment_weights


def axial_weights(n_z: int, dz: float) -> np.ndarray:
    """Trapezoidal weights across the width [m]."""
    weights = np.full(n_z, dz)
    weights[0] = weights[-1] = 0.5 * dz
    return weights


def film_characteristics(
    model: Any, state: FilmState, f: FilmFields,
    pressure: np.ndarray, fraction: np.ndarray, inflows: tuple[float, float],
) -> FilmResult:
    """FilmResult from the shifted pressure p̃ [Pa], film fraction ϑ [-] and the 12μ-scaled
    inflows from edge and supply nodes of :func:`~.mass_conserving_kernel.cell_balance`."""
    g = model.geometry
    theta, _ = model.grid()
    dx, dz = model.spacing()
    d_theta = 2.0 * math.pi / theta.size
    gauge = model.gauge_pressure(pressure, state)
    weights = axial_weights(pressure.shape[1], dz)
    line_load = gauge @ weights
    force_x = -g.radius * d_theta * float(np.cos(theta) @ line_load)
    force_y = -g.radius * d_theta * float(np.sin(theta) @ line_load)
    dh_dtheta = (np.roll(f.h, -1, axis=0) - np.roll(f.h, 1, axis=0)) / (2.0 * d_theta)
    wedge_part = g.radius * d_theta * float(np.sum(0.5 * gauge * dh_dtheta * weights))
    sliding = state.journal_speed - state.shell_speed
    shear = fraction if model.friction == "film_fraction" else 1.0
    law = model.pressure_viscosity
    if law is not None:  # μ(p)/μ₀ in the Couette shear
        shear = shear * law.viscosity_ratio(gauge, state.viscosity)
    couette = (g.radius**3 * d_theta * state.viscosity * sliding
               * float(np.sum(shear / f.h * weights)))
    edge_in, supply_in = (flow / (12.0 * state.viscosity) for flow in inflows)
    k_h = int(np.argmin(f.h))
    cos_theta, sin_theta = model.node_directions
    axial = axial_summary(f.h, k_h // f.h.shape[1], model.film_grid, g.radial_clearance,
                          gauge, moment_weights(cos_theta, sin_theta, model.film_grid.z,
                                                model.film_grid.area_weights), False)
    k_p = int(np.argmax(gauge))
    free = f.free
    content = float(np.sum((fraction * f.h)[free])) * dx * dz
    extra = {"film_content_m3": content}
    if law is not None:
        extra.update(law.diagnostics(pressure + model.reduced_cavitation(state), gauge,
                                     state.viscosity))
    if f.fed is not None:  # the journal's oil holes: their inflow, signed
        _, _, hole_in = cell_balance(pressure, fraction, free, f.edge | (f.supply & ~f.fed),
                                     f.a_east, f.a_north, f.couette_east, f.squeeze)
        extra["journal_hole_flow_m3_per_s"] = hole_in / (12.0 * state.viscosity)
    extra["inlet_film_fraction"] = inlet_film_fraction(  # upstream: against the transport
        gauge, fraction, free, state.journal_speed + state.shell_speed)
    return FilmResult(
        force_x=force_x, force_y=force_y,
        friction_torque_journal=wedge_part - couette,
        friction_torque_shell=wedge_part + couette,
        side_flow=-edge_in, supply_flow=supply_in,
        min_film_thickness=float(f.h.flat[k_h]),
        min_film_angle=float(theta[k_h // f.h.shape[1]]),
        max_pressure=float(gauge.flat[k_p]),
        max_pressure_angle=float(theta[k_p // gauge.shape[1]]),
        cavitated_fraction=float(np.mean(pressure[free] <= 0.0)) if free.any() else 0.0,
        friction_power=abs((wedge_part - couette) * sliding),
        extra=extra, **axial,
    )


LOAD_ZONE_SHARE = 0.1
"""The loaded zone: the columns upstream of p_max whose pressure exceeds this share of
p_max; its inlet is the first column below it [-]."""


def inlet_film_fraction(gauge: np.ndarray, fraction: np.ndarray, free: np.ndarray,
                        transport: float) -> float:
    """Film fraction ϑ [-] where oil enters the loaded zone: mean over the free interior
    nodes of the first θ column upstream of p_max (against the oil's transport, the sign
    of ``transport`` = ω_j + ω_b [rad/s]) whose largest pressure is at most
    :data:`LOAD_ZONE_SHARE` × p_max (1: the load zone is fed by a full film; below 1 it
    runs partially filled). 1 when no pressure builds up."""
    column_max = gauge.max(axis=1)
    peak = int(np.argmax(column_max))
    if not column_max[peak] > 0.0:
        return 1.0
    step = -1 if transport >= 0.0 else 1
    n = column_max.size
    for k in range(1, n):
        i = (peak + step * k) % n
        if column_max[i] <= LOAD_ZONE_SHARE * column_max[peak]:
            nodes = free[i, 1:-1]
            return float(np.mean(fraction[i, 1:-1][nodes])) if nodes.any() else 1.0
    return 1.0


def convection(couette_east: np.ndarray, fraction: np.ndarray) -> np.ndarray:
    """Upwind Couette-flux balance C_e ϑ_e − C_w ϑ_w per cell [Pa m³]."""
    forward = couette_east[0, couette_east.shape[1] // 2] >= 0.0
    east = couette_east * (fraction if forward else np.roll(fraction, -1, axis=0))
    return east - np.roll(east, 1, axis=0)


def film_end_angle(theta: np.ndarray, pressure: np.ndarray, inlet: int) -> float:
    """First mid-plane node after the inlet where the film is ruptured [rad]."""
    mid = pressure.shape[1] // 2
    order = (inlet + 1 + np.arange(theta.size)) % theta.size
    ruptured = pressure[order, mid] <= 0.0
    peak = int(np.argmax(pressure[order, mid]))
    after = np.nonzero(ruptured[peak:])[0]
    if after.size == 0:
        return float(theta[inlet])
    return float(theta[order[peak + after[0]]])
