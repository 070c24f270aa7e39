"""Implicit time step of the mass-conserving (JFO) film: the content balance over a step.

The instantaneous JFO problem (:meth:`MassConservingFilm.solve_with_memory`) takes the film
fraction ϑ as given and can pressurise only the cells that are already full. When the
journal moves towards a ruptured region, no velocity balances the load at that instant
(the ruptured cells cannot carry pressure), and an orbit that solves the force balance
there fails. Over a time step Δt the content balance has an answer for any motion: oil
squeezed into a shrinking gap fills the cell and then raises the pressure. Following
Ausas, Jai & Buscaglia (2009), the step is implicit in the content ϑh (backward Euler),

.. math:: a_P p̃_P − Σ a_{nb} p̃_{nb} + C_e ϑ_e − C_w ϑ_w
          + 12μΔxΔz\\,\\frac{ϑ_P h_P − ϑ_P^n h_P^n}{Δt} = 0,

with h, a, C at the end of the step, and is solved with ϑ for the Elrod–Adams
complementarity (p̃ > 0 ⇒ ϑ = 1, ϑ < 1 ⇒ p̃ = 0) by the Ausas sweep
(:func:`~conrod.film.mass_conserving.kernel.elrod_adams_step`).

The state handed in is the one at the end of the step, with its deformation field δ(θ, z)
when the bore deforms: h^{n+1} includes it and the stored h^n is the deformed film of the
step before, so the bore's own rate enters the content balance (ϑh)^{n+1} − (ϑh)^n and oil
is conserved on a moving bore too. With the content of the step
before, the step is BDF2 (second order, ∂q/∂t ≈ (3q^{n+1} − 4q^n + q^{n−1})/(2Δt)); in
the full film this is Reynolds' equation with ∂h/∂t of the journal velocity, since
3h^{n+1} − 4h^n + h^{n−1} = 2Δt ∂h/∂t for a rigid film moved by the same BDF2 step.

[1] R.F. Ausas, M. Jai, G.C. Buscaglia, "A mass-conserving algorithm for dynamical
    lubrication problems with cavitation", J. Tribol. 131 (2009) 031702.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from conrod.errors import ConvergenceError
from conrod.film.base import FilmState
from conrod.film.mass_conserving.kernel import content_step_sweep
from conrod.film.mass_conserving.memory import FULL, MassConservingMemory
from conrod.film.mass_conserving.results import axial_weights

STEP_TOLERANCE = 1.0e-10
"""Tightest relative change per sweep the step's Ausas sweep is asked for: tighter
tolerances stagnate in round-off on some fields [-]."""

SAME_FILM = 1.0e-9
"""Largest difference of the film thickness, share of the radial clearance, at which a
step's memory is the answer at a state [-]."""

_NONE = np.empty((0, 0))
"""What the compiled step takes for a field that is not there (a memory without thickness,
no step before, no warm pressure)."""


def content_step(
    film: Any, state: FilmState, memory: MassConservingMemory, dt: float,
    warm: MassConservingMemory | None = None, previous: MassConservingMemory | None = None,
) -> tuple[float, float, MassConservingMemory]:
    """Film force (F_x, F_y) [N] at the end of a step ``dt`` [s] that starts from the film
    content of ``memory``, and the memory at the end of the step.

    state : FilmState  End of the step; its velocity is the journal velocity there [m/s];
        its ``deformation`` δ(θ, z) [m], when set, is part of h^{n+1}.
    memory : MassConservingMemory  Film fraction ϑ^n (and h^n) at the start of the step.
    warm : MassConservingMemory or None  Start values of ϑ and p̃ for the sweep (an earlier
        trial of the same step); None: those of ``memory``.
    previous : MassConservingMemory or None  Content one step earlier: the step is BDF2,
        ∂q/∂t ≈ (3q^{n+1} − 4q^n + q^{n−1})/(2Δt), when both memories carry their
        thickness; else backward Euler.
    """
    if film.pressure_viscosity is not None:
        raise ConvergenceError("implicit film-content step: not available with a "
                               "pressure-viscosity law")
    f = film.fields(state)
    dx, dz = film.spacing()
    cell = 12.0 * state.viscosity * dx * dz / dt
    bdf2 = (previous is not None and memory.thickness is not None
            and previous.thickness is not None)
    first = warm if warm is not None else memory
    tolerance = max(film.tolerance, STEP_TOLERANCE)
    sweeps, change, pressure, fraction = content_step_sweep(
        f.edge, f.supply, f.fixed_pressure, f.h, f.squeeze, f.a_east, f.a_north,
        f.couette_east, cell, -film.reduced_cavitation(state), FULL, _field(memory.fraction),
        _field(memory.thickness), _field(previous.fraction if bdf2 else None),
        _field(previous.thickness if bdf2 else None), _field(first.fraction),
        _field(first.pressure), film.sor_factor, tolerance, film.max_iterations)
    film.last_iterations = sweeps
    if not change <= tolerance:
        raise ConvergenceError(
            f"mass-conserving film step did not converge in {sweeps} sweeps",
            where=f"e = ({state.eccentricity_x:.3e}, {state.eccentricity_y:.3e}) m",
            residual=change)
    fx, fy = shifted_pressure_force(film, pressure, state)
    fills = _hole_fill(f, memory, previous if bdf2 else None, cell, state.viscosity)
    return fx, fy, MassConservingMemory(fraction, pressure, f.h, *fills)


def _field(values: np.ndarray | None) -> np.ndarray:
    """``values`` as a C-contiguous float array for the compiled step; an empty (0, 0) one
    for None."""
    return _NONE if values is None else np.ascontiguousarray(values, dtype=float)


def accepted_result(film: Any, state: FilmState, memory: MassConservingMemory | None,
                    with_pressure: bool) -> Any:
    """FilmResult of the content step that ended at ``state`` with ``memory``: forces,
    extremes, friction and flows of the step's own pressure p̃ and film fraction ϑ (what
    the orbit accepted), not of a new instantaneous solve with ϑ frozen. None when
    ``memory`` holds no step answer or the film thickness of ``state`` is not the step's
    (within :data:`SAME_FILM` of the clearance)."""
    if memory is None or memory.thickness is None or memory.pressure is None:
        return None
    f = film.fields(state)
    if (np.shape(memory.thickness) != f.h.shape or float(np.max(np.abs(
            f.h - memory.thickness))) > SAME_FILM * film.geometry.radial_clearance):
        return None
    result = film.characteristics(state, f, memory.pressure,
                                  film.fraction_field(memory.fraction, f))
    if f.fed is not None:  # the oil the turning holes poured into the nodes they came over
        result.supply_flow += memory.held_fill
        result.extra["journal_hole_flow_m3_per_s"] += memory.hole_fill
    if with_pressure:
        result.pressure = film.gauge_pressure(memory.pressure, state)
    return result


def _hole_fill(f, memory: MassConservingMemory, previous: MassConservingMemory | None,
               cell: float, viscosity: float) -> tuple[float, float]:
    """Oil the journal's holes (all supply features) put into the nodes they hold at the
    end of a step besides their flux into the free nodes [m³/s]: the step's content change
    of those nodes, full
    at its end, from their stored contents ϑh before (backward Euler, or BDF2 with
    ``previous``; ``cell`` = 12μΔxΔz/Δt [Pa m/s]) — the filling of the partly filled nodes
    a turning hole comes over and the squeeze of the nodes it holds; 0 without journal
    holes. With the flux this is all the oil through the holes: summed over a periodic
    cycle the content of the whole film, held nodes included, balances supply and side
    flow (the shell's fixed features held by a fed hole part of the cycle included)."""
    if f.fed is None:
        return 0.0, 0.0
    before = _content(f, memory, cell)
    if previous is None:
        change = cell * f.h - before
    else:
        change = (1.5 * cell * f.h - 2.0 * before
                  + 0.5 * _content(f, previous, cell))
    scale = 1.0 / (12.0 * viscosity)
    return float(np.sum(change[f.fed])) * scale, float(np.sum(change[f.supply])) * scale


def _content(f, memory: MassConservingMemory, cell: float) -> np.ndarray:
    """12μΔxΔz ϑh/Δt of ``memory`` [Pa m³] with its own film fraction on every node (held
    nodes included); without its thickness, h^n = h − Δt ∂h/∂t (the backward Euler position
    of a rigid film). The step's own content, full on the nodes held now, is computed in
    its compiled call (:func:`~conrod.film.mass_conserving.kernel.content_step_sweep`)."""
    fraction = np.clip(np.asarray(memory.fraction, dtype=float), 0.0, 1.0)
    if memory.thickness is not None:
        return cell * fraction * memory.thickness
    return fraction * (cell * f.h - f.squeeze)


def shifted_pressure_force(film: Any, pressure: np.ndarray,
                           state: FilmState) -> tuple[float, float]:
    """Film force −∫∫ p (cos θ, sin θ) R dθ dz [N] from the shifted pressure p̃ [Pa]."""
    theta, _ = film.grid()
    _, dz = film.spacing()
    gauge = film.gauge_pressure(pressure, state)
    line_load = gauge @ axial_weights(pressure.shape[1], dz)
    factor = -film.geometry.radius * 2.0 * math.pi / theta.size
    cos_theta, sin_theta = film.node_directions
    return factor * float(cos_theta @ line_load), factor * float(sin_theta @ line_load)
