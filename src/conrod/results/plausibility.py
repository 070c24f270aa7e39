"""Physical plausibility of results: pure functions, results in → warnings out.

A result that cannot be physical raises :class:`~conrod.errors.ConvergenceError` naming
where (field and crank angle); a doubtful one gives a warning sentence that goes into
``summary.json["warnings"]`` and on stderr.

Orbit (``conrod run``):

* non-finite values → error;
* negative peak pressure or film thickness, film thickness above the largest possible
  2c → error;
* contact force above :data:`CONTACT_FORCE_ERROR_FACTOR` × the peak load → error, above
  :data:`CONTACT_FORCE_WARNING_FACTOR` × → warning (a rigid journal cannot press harder
  than load plus inertia);
* journal-centre displacement beyond the clearance by more than
  :data:`PENETRATION_SHARE` of it → warning; on a deforming bore beyond the orbit's
  contact circle (widened by one clearance: the bore gives way, the deformed film is what
  stops the journal) by more than that share;
* minimum film thickness below the combined roughness σ (h/σ < 1) while hard contact is
  not active → warning (hard contact alone: the asperities would touch, mixed lubrication
  not modelled; Greenwood–Tripp: boundary lubrication, the answer rests on the asperity
  model); h/σ < 3 (mixed lubrication) is stated in the headline;
* heat-balance temperature above ``lubricant.max_temperature`` → warning, above
  :data:`TEMPERATURE_LIMIT` → error (no oil film exists there);
* peak film pressure above :data:`FILM_PRESSURE_LIMIT` → warning (a rigid bore under a
  load its film cannot carry: the lining would yield, the real bore deforms);
* a tabulated film extrapolated past its largest eccentricity ratio → warning
  (:func:`table_range_warnings`).

Mechanism (``conrod mechanism``):

* non-finite values → error;
* impact velocity above the crank-pin surface speed ω D/2 → warning (a clearance-joint
  impact is driven by the relative motion of the rod and the crank, whose scale is that
  speed);
* contact force above :data:`MECHANISM_FORCE_LIMIT`, or above
  :data:`MECHANISM_FORCE_FACTOR` × (peak gas force + inertia force) → warning;
* exact geometry on a shell whose curvature radius at the major vertex b²/a is below the
  journal radius (two-point contact, modelled by the deeper point) → warning;
* penetration deeper than :data:`PENETRATION_SHARE` of the joint's smallest radial
  clearance → warning;
* ``contact_geometry = "seed"`` with a non-convex free-play region → warning.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from conrod.errors import ConvergenceError

PENETRATION_SHARE = 0.5
"""Penetration (or excursion beyond the clearance) allowed as a share of the clearance [-]."""
CONTACT_FORCE_WARNING_FACTOR = 3.0
"""Contact force / peak bearing load above which a run is flagged [-]."""
CONTACT_FORCE_ERROR_FACTOR = 100.0
"""Contact force / peak bearing load above which a run is meaningless [-]."""
FILM_PRESSURE_LIMIT = 1.0e9
"""Peak film pressure above which a rigid-bore result is flagged [Pa]. It is above the
hardness of every connecting-rod lining alloy of ISO 4383:2012 (Annex A: AlSn20Cu
30–40 HBW ≈ 0.3–0.4 GPa, CuPb24Sn4 60–90 HBW ≈ 0.6–0.9 GPa), so a film pressure beyond
it would flatten the lining and bend the big end, which a rigid bore ignores; it is also
the default ``pressure_viscosity_limit``, beyond which the pressure–viscosity law is not
used. Rigid-bore peaks of several hundred MPa are usual for big ends."""
TEMPERATURE_LIMIT = 1000.0
"""Heat-balance temperature above which a run is not physical [°C]: far above the
autoignition temperature of mineral and synthetic engine oils (about 300–400 °C) and the
melting range of the big-end lining alloys of ISO 4383 (tin- and lead-based overlays and
AlSn linings melt at 230–630 °C); a heat balance reaching it (a load so light that the
journal stays centred and no oil leaks, a roughness of the order of the clearance, a
bearing metres wide) describes no lubricated bearing."""
MECHANISM_FORCE_LIMIT = 1.0e6
"""Joint contact force above which a mechanism run is flagged [N]."""
MECHANISM_FORCE_FACTOR = 10.0
"""Joint contact force / (peak gas force + peak inertia force m R ω²) above which a
mechanism run is flagged (impact peaks exceed the load, but not tenfold) [-]."""


def _angle(crank_angle: np.ndarray, index: int) -> str:
    return f"crank angle {math.degrees(float(crank_angle[index])):.1f} deg"


def check_finite(record: Any, crank_angle: np.ndarray, what: str) -> None:
    """ConvergenceError naming the first non-finite float array attribute of ``record``."""
    for name, values in vars(record).items():
        if isinstance(values, np.ndarray) and values.dtype.kind == "f":
            bad = ~np.isfinite(values)
            if np.any(bad):
                column = int(np.flatnonzero(bad.reshape(-1, bad.shape[-1]).any(axis=0))[0])
                where = _angle(crank_angle, column) if column < crank_angle.size else ""
                raise ConvergenceError(f"{what}: {name} is not finite", where=where)


def check_run(results: Any, case: Any, contact_radius: float | None = None) -> list[str]:
    """Warnings for an orbit run; ConvergenceError where the result is meaningless.

    results : RunResults; case : Case (``[contact]``, ``[lubricant]`` are read);
    contact_radius : the orbit's contact circle [m] (None: the clearance), beyond which
        the centre may go by :data:`PENETRATION_SHARE` of the clearance.
    """
    cycle, c = results.cycle, results.clearance
    angle = cycle.crank_angle
    check_finite(cycle, angle, "orbit result")
    _check_film_range(cycle, c)
    warnings = _contact_force_warnings(cycle)
    widening = 0.0 if contact_radius is None else max(contact_radius / c - 1.0, 0.0)
    allowed = PENETRATION_SHARE + widening
    excursion = float(np.max(cycle.eccentricity_ratio)) - 1.0
    if excursion > allowed:
        i = int(np.argmax(cycle.eccentricity_ratio))
        circle = "clearance circle" if widening == 0.0 else "clearance circle of the rigid bore"
        warnings.append(f"journal centre {excursion:.2g} c beyond the {circle} at "
                        f"{_angle(angle, i)} (allowed: <= {allowed:g} c)")
    warnings += _roughness_warnings(cycle, case)
    warnings += _film_pressure_warnings(cycle)
    temperature = results.summary.effective_temperature
    limit = case.lubricant.max_temperature if case.lubricant is not None else math.inf
    source = ("film's mean temperature" if getattr(results, "thermal_film", None) is not None
              else "heat-balance temperature")
    if temperature is not None and not temperature <= TEMPERATURE_LIMIT:
        raise ConvergenceError(
            f"implausible result: {source} {temperature:.3g} °C (physical: "
            f"<= {TEMPERATURE_LIMIT:g} °C, and <= lubricant.max_temperature = {limit:g} °C "
            "for the oil data); the friction power cannot be carried away by the side flow "
            "of this bearing — check the load, the clearance, the width and the roughness",
            where="the heat balance of the cycle")
    if temperature is not None and temperature > limit:
        warnings.append(f"{source} {temperature:.1f} °C is above the oil's "
                        f"valid range (lubricant.max_temperature = {limit:g} °C)")
    if getattr(results, "thermal_film", None) is not None:  # the film's temperature field
        warnings += results.thermal_film.warnings()
    return warnings


def _check_film_range(cycle: Any, clearance: float) -> None:
    angle = cycle.crank_angle
    for name, values, low, high in (("p_max", cycle.p_max, 0.0, math.inf),
                                    ("h_min", cycle.h_min, 0.0, 2.0 * clearance)):
        bad = (values < low) | (values > high)
        if np.any(bad):
            i = int(np.flatnonzero(bad)[0])
            unit = "Pa" if name == "p_max" else "m"
            raise ConvergenceError(
                f"film model out of its range: {name} = {values[i]:.3g} {unit} (physical: "
                f">= {low:g}" + (f" and <= {high:.3g} {unit})" if high < math.inf else ")"),
                where=_angle(angle, i))


def _contact_force_warnings(cycle: Any) -> list[str]:
    load = float(np.max(np.hypot(cycle.load_x, cycle.load_y)))
    force = float(np.max(cycle.contact_force))
    if load <= 0.0 or force <= CONTACT_FORCE_WARNING_FACTOR * load:
        return []
    i = int(np.argmax(cycle.contact_force))
    text = (f"contact force {force:.3g} N at {_angle(cycle.crank_angle, i)} is "
            f"{force / load:.3g} x the peak load {load:.3g} N")
    if force > CONTACT_FORCE_ERROR_FACTOR * load:
        raise ConvergenceError(f"implausible result: {text} (film model past its range?)")
    return [text + f" (plausible: <= {CONTACT_FORCE_WARNING_FACTOR:g} x)"]


def _film_pressure_warnings(cycle: Any) -> list[str]:
    peak = float(np.max(cycle.p_max))
    if peak <= FILM_PRESSURE_LIMIT:
        return []
    i = int(np.argmax(cycle.p_max))
    return [f"p_max {peak / 1e6:.4g} MPa at {_angle(cycle.crank_angle, i)} is above "
            f"{FILM_PRESSURE_LIMIT / 1e6:.0f} MPa, the hardness of the hardest big-end lining "
            "alloys (ISO 4383): not a physical film pressure — the rigid bore carries a load "
            "its film cannot; read h_min, or add the elastic big end ([housing], "
            "docs/ehd.md)"]


def _roughness_warnings(cycle: Any, case: Any) -> list[str]:
    """h/σ below 1 outside hard contact: the film is thinner than the combined roughness.
    Under hard contact alone the asperities' contact is not modelled (the advice names the
    model that is); under Greenwood–Tripp they carry part of the load, boundary lubrication,
    where the answer rests on the asperity model more than on the film."""
    contact = getattr(case, "contact", None)
    if contact is None or not contact.roughness:
        return []
    free = ~np.asarray(cycle.in_contact, dtype=bool)
    thin = (cycle.h_min < contact.roughness) & free
    if not np.any(thin):
        return []
    i = int(np.flatnonzero(thin)[np.argmin(cycle.h_min[thin])])
    ratio = float(cycle.h_min[i]) / contact.roughness
    text = (f"film thickness {cycle.h_min[i] * 1e6:.3g} µm at {_angle(cycle.crank_angle, i)} "
            f"is below the combined roughness {contact.roughness * 1e6:.3g} µm (h/σ = "
            f"{ratio:.2g} < 1)")
    if contact.model == "hard":
        return [text + " without contact: asperities touch (consider [contact] model = "
                "\"greenwood_tripp\")"]
    return [text + ": boundary lubrication, the asperities carry part of the load and the "
            "result rests on the asperity-contact model"]


def _mechanism_load_scale(results: Any, mechanism: Any) -> float:
    """Peak gas force plus the inertia scale (m_piston + m_rod) R ω² [N]."""
    crank = getattr(mechanism, "crank", None)
    inertia = 0.0
    if crank is not None and hasattr(crank, "piston_mass"):
        inertia = (crank.piston_mass + crank.rod_mass) * crank.crank_radius * (
            crank.crank_speed**2)
    gas = getattr(results, "gas_force", None)
    peak_gas = float(np.max(np.abs(gas))) if gas is not None and np.size(gas) else 0.0
    return max(peak_gas + inertia, 1e-300)


def check_mechanism(results: Any, mechanism: Any) -> list[str]:
    """Warnings for a clearance-mechanism run (``MechanismResults``, ``Mechanism``)."""
    from conrod.mechanism.geometry import seed_free_play_is_convex
    from conrod.mechanism.results import JOINT_NAMES

    check_finite(results, results.crank_angle, "mechanism result")
    warnings = []
    surface_speed = abs(mechanism.crank.crank_speed) * 0.5 * mechanism.big_end.diameter
    impacts = results.settled_impacts()
    joints = (mechanism.big_end, mechanism.small_end)
    for index, (name, joint) in enumerate(zip(JOINT_NAMES, joints, strict=True)):
        speeds = impacts.of_joint(index)
        if speeds.size and float(speeds.max()) > surface_speed:
            warnings.append(f"{name}: impact velocity {float(speeds.max()):.3g} m/s is above "
                            f"the crank-pin surface speed {surface_speed:.3g} m/s")
        force = float(np.max(results.contact_force[index]))
        load = _mechanism_load_scale(results, mechanism)
        if force > MECHANISM_FORCE_LIMIT:
            warnings.append(f"{name}: contact force {force:.3g} N is above "
                            f"{MECHANISM_FORCE_LIMIT:.0e} N")
        elif force > MECHANISM_FORCE_FACTOR * load:
            warnings.append(f"{name}: contact force {force:.3g} N is {force / load:.3g} x the "
                            f"peak gas plus inertia force {load:.3g} N")
        depth = float(np.max(-results.gap[index]))
        if depth > PENETRATION_SHARE * joint.radial_clearance_min:
            warnings.append(f"{name}: penetration {depth:.3g} m is more than "
                            f"{PENETRATION_SHARE:g} of the radial clearance "
                            f"{joint.radial_clearance_min:.3g} m")
        major, minor = 0.5 * (joint.diameter + joint.clearance_max), 0.5 * (
            joint.diameter + joint.clearance_min)
        if mechanism.contact_geometry == "exact" and minor**2 / major < 0.5 * joint.diameter:
            warnings.append(f"{name}: the worn shell's curvature radius at the major vertex "
                            f"b²/a = {minor**2 / major:.4g} m is below the journal radius: "
                            "two-point contact is modelled by the deeper point only")
        if mechanism.contact_geometry == "seed" and not seed_free_play_is_convex(
                joint.diameter, joint.clearance_max, joint.clearance_min):
            warnings.append(f"{name}: the seed contact geometry makes the free-play region "
                            "non-convex for this worn shell; impacts may be spurious (use "
                            "clearance.contact_geometry = \"exact\")")
    return warnings


def table_range_warnings(cycle: Any, eccentricity_max: float) -> list[str]:
    """A warning where the orbit goes past the largest tabulated eccentricity ratio of a
    table or mobility film (its values there are extrapolated, not tabulated) [-]."""
    ratio = np.asarray(cycle.eccentricity_ratio)
    past = ratio > eccentricity_max
    if not past.any():
        return []
    i = int(np.argmax(ratio))
    share = 100.0 * float(np.mean(past))
    return [f"journal eccentricity ratio up to {ratio[i]:.5g} at {_angle(cycle.crank_angle, i)}"
            f", past the film table's last node ({eccentricity_max:g}) at {share:.0f} % of the "
            "output angles: values there are extrapolated, not tabulated (a finer film, e.g. "
            "--film reynolds, or a table with a larger eccentricity_max)"]
