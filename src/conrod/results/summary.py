"""Cycle summary ([D2] Table 1 'cycle' columns) from the per-angle results."""

from __future__ import annotations

import math

import numpy as np

from conrod.results.axial import axial_headline
from conrod.results.cycle_results import CycleResults, RunResults, RunSummary

CONTACT_SHARE_WARNING = 0.25
"""Share of the load carried by hard contact above which a run is flagged: the film does
not carry the bearing [-]."""


def contact_friction_power(cycle: CycleResults) -> np.ndarray:
    """Dry-friction power of hard contact at each angle, |μ_dry P_c| |V_slide| [W]."""
    return np.abs(cycle.friction_force) * np.abs(cycle.sliding_speed)


def contact_load_share(cycle: CycleResults) -> np.ndarray:
    """Share of the bearing load carried by hard contact at each angle, P_c / |F| [-]."""
    load = np.hypot(cycle.load_x, cycle.load_y)
    return np.divide(cycle.contact_force, load, out=np.zeros_like(load), where=load > 0.0)


def contact_intervals(cycle: CycleResults) -> list[tuple[float, float]]:
    """(start, end) crank angles [deg] of the runs of output angles in hard contact."""
    touching = np.asarray(cycle.in_contact, dtype=bool)
    degrees = cycle.crank_angle_deg
    edges = np.flatnonzero(np.diff(np.concatenate([[0], touching.astype(int), [0]])))
    return [(float(degrees[a]), float(degrees[b - 1])) for a, b in zip(
        edges[::2], edges[1::2], strict=True)]


def summarise(
    cycle: CycleResults, orbit, problem, solver, temperature: float | None,
    cycles: int, thermal_iterations: int, integrator: str | None = None,
) -> RunSummary:
    """Minimum h_min and maximum p_max with their angles, cycle means, diagnostics.

    ``orbit``: :class:`conrod.orbit.PeriodicOrbit`; ``problem``: the final
    :class:`OrbitProblem`; ``solver``: the ``[solver]`` section used; ``integrator``: name
    of the integrator (default: the one of ``solver``).
    """
    i_h, i_p = int(np.argmin(cycle.h_min)), int(np.argmax(cycle.p_max))
    warnings = []
    if not orbit.periodic:
        warnings.append(
            f"orbit not periodic after {orbit.cycles} cycles: periodicity error "
            f"{orbit.periodicity_error:.3g} > tolerance {solver.periodicity_tolerance:.3g} "
            "(raise solver.max_cycles)"
)
    error = orbit.periodicity_error
    return RunSummary(
        h_min=float(cycle.h_min[i_h]), h_min_crank_angle=float(cycle.crank_angle[i_h]),
        p_max=float(cycle.p_max[i_p]), p_max_crank_angle=float(cycle.crank_angle[i_p]),
        mean_h_min=float(cycle.h_min.mean()), mean_p_max=float(cycle.p_max.mean()),
        mean_friction_power=float(cycle.friction_power.mean()),
        mean_contact_friction_power=float(contact_friction_power(cycle).mean()),
        mean_side_flow=float(cycle.side_flow.mean()),
        mean_supply_flow=float(cycle.supply_flow.mean()),
        effective_temperature=temperature, viscosity=problem.viscosity, cycles=cycles,
        periodicity_error=float(error) if math.isfinite(error) else 1.0,
        periodic=bool(orbit.periodic), film_model=str(problem.film.name),
        integrator=str(integrator or solver.integrator), wall_time=0.0,
        thermal_iterations=thermal_iterations,
        max_contact_force=float(cycle.contact_force.max()), warnings=tuple(warnings),
)


def contact_warnings(cycle: CycleResults) -> list[str]:
    """A warning when hard contact carries more than :data:`CONTACT_SHARE_WARNING` of the
    load: the result is a contact result, not a film result."""
    share = contact_load_share(cycle)
    i = int(np.argmax(share))
    if share[i] <= CONTACT_SHARE_WARNING:
        return []
    return [f"hard contact carries up to {share[i]:.0%} of the load (crank angle "
            f"{cycle.crank_angle_deg[i]:.0f} deg; {_intervals_text(cycle)}): the film does "
            "not carry this bearing (contact-dominated result)"]


def _intervals_text(cycle: CycleResults) -> str:
    spans = contact_intervals(cycle)
    if not spans:
        return "none"
    return ", ".join(f"{a:.0f}–{b:.0f}°" for a, b in spans)


def headline(results: RunResults) -> dict[str, str]:
    """The lines an engineer reads first (label → text), in order; printed by ``conrod
    run`` and written at the top of summary.json. ``results.headline_extra`` is appended.

    h_min is the smallest FILM thickness, over the angles without hard contact; where the
    journal touches the shell the gap is the contact threshold h_c, reported on the
    contact line instead."""
    s, cycle, model = results.summary, results.cycle, results.model or {}
    lines = {"model": ", ".join(filter(None, (
        f"{s.film_model} film", f"{s.integrator} integrator", model.get("housing"),
        model.get("viscosity"))))}
    lines["film h_min"] = _film_h_min_text(cycle)
    if cycle.axial is not None:  # a tilted journal or a profiled bore: edge h_min, moments
        lines.update(axial_headline(cycle.crank_angle, cycle.axial))
    lines["contact"] = _contact_text(cycle, results.contact)
    lines["p_max"] = f"{s.p_max / 1e6:.2f} MPa at {math.degrees(s.p_max_crank_angle):.0f}°"
    lines["friction power"] = (f"{s.mean_total_friction_power:.1f} W = film "
                               f"{s.mean_friction_power:.1f} W + contact "
                               f"{s.mean_contact_friction_power:.1f} W (cycle means)"
                               + _boundary_friction_note(results.contact))
    lines["oil flow"] = (f"side {s.mean_side_flow * 6e4:.3g} l/min, supply "
                         f"{s.mean_supply_flow * 6e4:.3g} l/min (cycle means)")
    lines["temperature"] = ("no heat balance (no oil flow)" if s.effective_temperature is None
                            else f"{s.effective_temperature:.1f} °C effective (heat balance "
                            "with film and contact friction)")
    lines["orbit"] = (f"{'periodic' if s.periodic else 'NOT periodic'} after {s.cycles} "
                      f"cycles (error {s.periodicity_error:.2g} c)")
    lines["warnings"] = str(len(s.warnings)) if s.warnings else "none"
    lines.update(results.headline_extra or {})
    return lines


def _film_h_min_text(cycle: CycleResults) -> str:
    free = ~np.asarray(cycle.in_contact, dtype=bool)
    if not np.any(free):
        return "no film: the journal touches the shell over the whole cycle"
    i = int(np.flatnonzero(free)[np.argmin(cycle.h_min[free])])
    return f"{cycle.h_min[i] * 1e6:.3f} µm at {cycle.crank_angle_deg[i]:.0f}° (outside contact)"


def _contact_text(cycle: CycleResults, contact=None) -> str:
    """Hard contact (intervals, load share) and, under mixed lubrication, the asperity
    contact the film shares the load with."""
    parts = []
    touching = np.asarray(cycle.in_contact, dtype=bool)
    if np.any(touching):
        share = contact_load_share(cycle)
        i = int(np.argmax(share))
        parts.append(f"{_intervals_text(cycle)} ({touching.mean():.0%} of the cycle); carries "
                     f"up to {share[i]:.0%} of the load at {cycle.crank_angle_deg[i]:.0f}°")
    asperity = _asperity_text(cycle, contact)
    if asperity:
        parts.append(asperity)
    return "; ".join(parts) if parts else "none"


def _asperity_force(contact) -> np.ndarray | None:
    """Greenwood–Tripp asperity force per output angle [N]; None without asperities
    carrying load."""
    if contact is None or contact.model != "greenwood_tripp":
        return None
    force = np.asarray(contact.contact_force, dtype=float)
    return force if np.any(force > 0.0) else None


def _boundary_friction_note(contact) -> str:
    """Under Greenwood–Tripp contact: that its boundary friction (on the contact line) is
    not in this sum nor in the heat balance, which take film and hard-contact friction."""
    if _asperity_force(contact) is None:
        return ""
    return "; the asperities' boundary friction is not in this sum or the heat balance"


def _asperity_text(cycle: CycleResults, contact) -> str:
    """Greenwood–Tripp asperity contact: its largest force [N] and load share, and the
    cycle mean of its boundary friction power μ F_a |V_slide| [W]; '' without it."""
    force = _asperity_force(contact)
    if force is None:
        return ""
    load = np.hypot(cycle.load_x, cycle.load_y)
    i = int(np.argmax(force))
    share = force[i] / load[i] if load[i] > 0.0 else float("inf")
    power = float(np.mean(np.abs(contact.friction_force * cycle.sliding_speed)))
    return (f"asperities (Greenwood–Tripp) carry up to {force[i]:.3g} N ({share:.1%} of the "
            f"load) at {cycle.crank_angle_deg[i]:.0f}°, boundary friction {power:.3g} W "
            "(cycle mean)")


STEP_STUDY_TOLERANCE = 0.02
"""Relative change of the smallest h_min between a fixed step and half of it above which a
fixed-step orbit is flagged as under-resolved [-]."""


def step_study_warnings(coarse: RunSummary, fine: RunSummary, step_deg: float | None
                        ) -> list[str]:
    """A warning when halving the fixed step moves the smallest h_min by more than
    :data:`STEP_STUDY_TOLERANCE` (the answer still depends on the step). With rk2's automatic
    step (``step_deg`` None) ``fine`` is the error-controlled implicit orbit instead."""
    change = abs(coarse.h_min - fine.h_min) / max(fine.h_min, 1e-300)
    if change <= STEP_STUDY_TOLERANCE:
        return []
    if step_deg is None:
        return [f"under-resolved: h_min {coarse.h_min * 1e6:.3g} µm with rk2's automatic step "
                f"but {fine.h_min * 1e6:.3g} µm with the error-controlled implicit integrator "
                f"({change:.1%} > {STEP_STUDY_TOLERANCE:.0%}); set solver.step_deg "
                "(--step-deg) or use integrator = 'implicit'"]
    return [f"under-resolved: h_min {coarse.h_min * 1e6:.3g} µm at step {step_deg:g} deg but "
            f"{fine.h_min * 1e6:.3g} µm at {step_deg / 2:g} deg ({change:.1%} > "
            f"{STEP_STUDY_TOLERANCE:.0%}); reduce solver.step_deg (--step-deg)"]
