"""Cycle summary ([D2] Table 1 'cycle' columns) from the per-angle results."""

from __future__ import annotations

import math

import numpy as np

from conrod.contact.analysis import contact_runs
from conrod.results.axial import axial_headline
from conrod.results.cycle_results import CycleResults, RunResults, RunSummary
from conrod.results.feed import feed_headline

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
    """(start, end) crank angles [deg] of the runs of output angles in hard contact, the
    rows of ``cycle.csv`` with ``in_contact`` 1 (:func:`conrod.contact.analysis.contact_runs`;
    a run over the end of the cycle ends beyond the cycle length)."""
    phi = np.asarray(cycle.crank_angle, dtype=float)
    step = float(np.median(np.diff(phi))) if phi.size > 1 else 0.0
    length = float(phi[-1] - phi[0] + step) if phi.size else 0.0
    return [(math.degrees(a), math.degrees(b))
            for a, b in contact_runs(phi, np.asarray(cycle.in_contact, dtype=bool), length)]


def film_minimum(cycle: CycleResults) -> tuple[float, float] | None:
    """(smallest h_min [m], its crank angle [rad]) over the output angles without hard
    contact; None when the journal touches the shell at every angle. The one place the
    film h_min of the headline, ``summary.json`` and the figures comes from."""
    free = ~np.asarray(cycle.in_contact, dtype=bool)
    if not np.any(free):
        return None
    i = int(np.flatnonzero(free)[np.argmin(cycle.h_min[free])])
    return float(cycle.h_min[i]), float(cycle.crank_angle[i])


def summarise(
    cycle: CycleResults, orbit, problem, solver, temperature: float | None,
    cycles: float, thermal_iterations: int, integrator: str | None = None,
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
            f"orbit not periodic after {orbit.cycles_run:g} cycles: periodicity error "
            f"{orbit.periodicity_error:.3g} > tolerance {solver.periodicity_tolerance:.3g} "
            "(raise solver.max_cycles)"
)
    error = orbit.periodicity_error
    film = film_minimum(cycle)
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
        film_h_min=None if film is None else film[0],
        film_h_min_crank_angle=None if film is None else film[1],
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


MIXED_LUBRICATION_RATIO = 3.0
"""Film thickness over combined roughness h/σ below which the asperities touch: mixed
lubrication (Hamrock, Fundamentals of Fluid Film Lubrication, ch. 1) [-]."""
LITRES_PER_MINUTE = 6.0e4
"""m³/s → l/min, the one unit of oil flow in every display [-]."""
EXIT_MEANINGS = {0: "success", 3: "not converged: the orbit is not periodic, results for "
                 "diagnosis only", 4: "finished with warnings"}
"""Exit code of ``conrod run`` → meaning, for the status line [-]."""


def headline(results: RunResults) -> dict[str, str]:
    """The lines an engineer reads first (label → text), in order; printed by ``conrod
    run``, written at the top of summary.json and opening the report.
    ``results.headline_extra`` is appended.

    h_min is the smallest FILM thickness, over the angles without hard contact
    (:func:`film_minimum`, ``summary.json["film_h_min_m"]``); where the journal touches the
    shell the gap is the contact threshold h_c, reported on the contact line instead.
    Oil flows in l/min, positive into the bearing for the supply and out of it for the
    side flow; powers in W; pressures in MPa; film thickness in µm."""
    s, cycle, model = results.summary, results.cycle, results.model or {}
    lines = {"model": ", ".join(filter(None, (
        f"{s.film_model} film", f"{s.integrator} integrator", model.get("housing"),
        model.get("viscosity"))))}
    lines["film h_min"] = _film_h_min_text(s)
    if cycle.axial is not None:  # a tilted journal or a profiled bore: edge h_min, moments
        lines.update(axial_headline(cycle.crank_angle, cycle.axial))
    lines.update(feed_headline(cycle.feed))  # crank-pin oil holes (if any)
    lines["contact"] = _contact_text(cycle, results.contact)
    lines["p_max"] = (f"{s.p_max / 1e6:.2f} MPa at {math.degrees(s.p_max_crank_angle):.0f}°"
                      + _grid_error_text(s, "p_max") + _peak_step_text(cycle))
    lines["friction power"] = (
        f"{s.mean_total_friction_power:.1f} W = film {s.mean_friction_power:.1f} W + hard "
        f"contact {s.mean_contact_friction_power:.1f} W + boundary (asperities) "
        f"{s.mean_boundary_friction_power:.1f} W (cycle means)")
    lines["oil flow"] = _flow_text(s)
    lines["temperature"] = ("no heat balance (no oil flow)" if s.effective_temperature is None
                            else f"{s.effective_temperature:.1f} °C effective (heat balance "
                            "with film, hard-contact and boundary friction)")
    thermal = getattr(results, "thermal_film", None)
    if thermal is not None:  # the film's temperature field
        lines["temperature"] = thermal.headline_text()
    lead_in = s.cycles % 1.0  # a lead-in from the concentric start: a share of a cycle
    lines["orbit"] = (f"{'periodic' if s.periodic else 'NOT periodic'} after {s.cycles:g} "
                      "cycles (" + (f"the first {lead_in:g} of a cycle a lead-in from the "
                                    "concentric start; " if lead_in else "")
                      + f"error {s.periodicity_error:.2g} c)")
    if results.signoff is not None:  # margins against [limits], the erosion indicator
        lines.update(results.signoff.headline())
    lines["warnings"] = str(len(s.warnings)) if s.warnings else "none"
    lines["status"] = f"exit code {s.exit_code} ({EXIT_MEANINGS[s.exit_code]})"
    lines.update(results.headline_extra or {})
    return lines


def _film_h_min_text(s: RunSummary) -> str:
    if s.film_h_min is None or s.film_h_min_crank_angle is None:
        return "no film: the journal touches the shell over the whole cycle"
    text = (f"{s.film_h_min * 1e6:.3f} µm at {math.degrees(s.film_h_min_crank_angle):.0f}° "
            "(outside contact)")
    ratio = s.film_thickness_ratio
    if ratio is not None:
        text += f", h/σ = {ratio:.2g}"
        if ratio < MIXED_LUBRICATION_RATIO:
            text += (f" < {MIXED_LUBRICATION_RATIO:g}: mixed lubrication (the asperities "
                     f"of σ = {s.roughness * 1e6:.2g} µm touch)")
    return text + _grid_error_text(s, "h_min")


def _grid_error_text(s: RunSummary, quantity: str) -> str:
    """'; grid error ...' of the h_min or p_max estimate, '' without one."""
    if s.grid_error is None:
        return ""
    return "; " + s.grid_error.text(quantity)


PEAK_STEP_SHARE = 0.10
"""A p_max standing this share above both neighbouring output angles is a peak the output
step does not resolve [-]."""


def peak_step_jump(cycle: CycleResults) -> float:
    """How far the largest p_max stands above the larger of its two neighbouring output
    angles, p_max/max(neighbours) − 1 [-] (0 for a resolved, smooth peak)."""
    p = np.asarray(cycle.p_max, dtype=float)
    i = int(np.argmax(p))
    neighbours = max(p[i - 1], p[(i + 1) % p.size])
    return float(p[i] / neighbours - 1.0) if neighbours > 0.0 else 0.0


def _peak_step_text(cycle: CycleResults) -> str:
    jump = peak_step_jump(cycle)
    if jump <= PEAK_STEP_SHARE:
        return ""
    return (f"; stands {jump:.0%} above both neighbouring output angles: the peak is not "
            "resolved in crank angle (a smaller solver.output_step_deg)")


def _flow_text(s: RunSummary) -> str:
    """Side flow (out of the bearing) and supply flow (into it), cycle means [l/min]."""
    text = (f"side {s.mean_side_flow * LITRES_PER_MINUTE:.3g} l/min out at the edges, supply "
            f"{s.mean_supply_flow * LITRES_PER_MINUTE:.3g} l/min into the bearing (cycle "
            "means)")
    if s.mean_supply_flow < 0.0:
        text += ("; negative: the grooves and holes take oil out of the film (at the supply "
                 "pressure the film pushes oil into them)")
    return text


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


def _asperity_text(cycle: CycleResults, contact) -> str:
    """Greenwood–Tripp asperity contact: its largest force [N] and load share, and the
    cycle mean of its boundary friction power μ F_a |V_slide| [W]; '' without it."""
    force = getattr(contact, "asperity_force", None)
    if force is None or not np.any(force > 0.0):
        return ""
    load = np.hypot(cycle.load_x, cycle.load_y)
    i = int(np.argmax(force))
    share = force[i] / load[i] if load[i] > 0.0 else float("inf")
    power = float(np.mean(contact.boundary_friction_power))
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
