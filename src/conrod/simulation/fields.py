"""The fields on the film grid over the last cycle and the sign-off built on them (per-cell
indicators, cavitation erosion, margins against ``[limits]``).

At each output crank angle the film is solved once more as the characteristics solve it
(:func:`conrod.orbit.characteristics.film_results`: the accepted step's own answer where
the memory holds it, the warm start threaded from angle to angle otherwise), now with its
pressure field. Besides the pressure:

* film thickness h(θ, z) = c − (e_x + z γ_y) cos θ − (e_y − z γ_x) sin θ + h₀(θ, z) + δ(θ, z)
  (docs/conventions.md), with the bore profile h₀ and a declared deformation δ;
* film fraction ϑ of a film with a content (:class:`~conrod.film.capabilities.HasMixableContent`);
* every field the film declares (:class:`~conrod.film.capabilities.HasFilmFields`: the
  elastic bore's deformation, a thermal film's temperature, ...);
* with Greenwood–Tripp contact, the asperity pressure p_a(h) on that film thickness
  (:func:`conrod.contact.asperity.asperity_pressure`).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass

import numpy as np

from conrod.contact.asperity import asperity_pressure
from conrod.errors import CaseError
from conrod.film.base import FilmState
from conrod.film.capabilities import HasFilmFields, HasMixableContent
from conrod.film.profile import profile_field
from conrod.orbit.problem import OrbitProblem
from conrod.results.cycle_results import CycleResults
from conrod.results.erosion import erosion_map
from conrod.results.fields import FIELD_SPECS, CycleFields, FieldSpec
from conrod.results.indicators import cell_indicators
from conrod.results.margins import SignOff, margins


def cycle_fields(problem: OrbitProblem, cycle: CycleResults, film_memory: list | None,
                 solved: list | None = None) -> CycleFields | None:
    """The fields at every output angle of ``cycle`` (module docstring); None for a film
    without a pressure field (table, mobility). ``solved``: the film results the cycle's
    characteristics came from, with their pressure fields
    (:func:`conrod.orbit.characteristics.row_results`): the film is not solved again
    where the rows need no film memory (a film without fields or content of its own
    whose orbit carried none: the same solves, warm-started alike, so the same bits)."""
    film = problem.film
    theta, z = (np.asarray(a, dtype=float) for a in film.grid())
    session = problem.session()
    rows: dict[str, list[np.ndarray]] = {}
    specs: dict[str, FieldSpec] = {}
    extremes: list[tuple[float, float, float, float]] = []
    declares = (isinstance(film, HasFilmFields), isinstance(film, HasMixableContent))
    if film_memory or any(declares) or solved is None or len(solved) != len(cycle.crank_angle):
        solved = None
    nodes = (theta, z, np.cos(theta)[:, None], np.sin(theta)[:, None])  # once per cycle
    for i in range(len(cycle.crank_angle)):
        state = problem.row_state(cycle, i)
        if solved is not None and solved[i].pressure is not None:
            result = solved[i]
        elif film_memory:
            session.restore(film_memory[i])
            result = session.accepted(state, with_pressure=True)
        else:
            result = session.solve(state, with_pressure=True)
        if result.pressure is None:
            return None
        extremes.append((result.max_pressure, result.max_pressure_angle,
                         result.min_film_thickness, result.min_film_angle))
        for name, (values, spec) in _row(problem, state, session.memory, result.pressure,
                                         nodes, declares).items():
            rows.setdefault(name, []).append(values)
            specs.setdefault(name, spec)
    g, reported = film.geometry, np.array(extremes)
    return CycleFields(
        np.asarray(cycle.crank_angle, dtype=float), theta, z,
        np.asarray(cycle.journal_rotation, dtype=float),
        {name: np.array(values) for name, values in rows.items()}, specs,
        problem.loads.cycle, problem.crank_speed, g.cavitation_pressure, str(film.name),
        row_extremes={"pressure": (reported[:, 0], reported[:, 1]),
                      "film_thickness": (reported[:, 2], reported[:, 3])})


def _row(problem, state, memory, pressure, nodes, declares: tuple[bool, bool]) -> dict:
    """name → (field (n_θ, n_z), spec) at one output angle; ``nodes`` (θ, z, cos θ, sin θ)
    of the film grid and ``declares`` (whether the film declares fields of its own and a
    mixable content), both once per cycle."""
    film = problem.film
    has_fields, mixable = declares
    out = {"pressure": (np.asarray(pressure, dtype=float), FIELD_SPECS["pressure"])}
    declared = film.film_fields(state, memory) if has_fields else {}
    deformation = declared["deformation"].values if "deformation" in declared else None
    h = film_thickness_field(film.geometry, state, *nodes[:2], deformation, nodes[2:])
    out["film_thickness"] = (h, FIELD_SPECS["film_thickness"])
    if mixable and memory is not None:
        fraction = film.content_vector(memory).reshape(h.shape)
        out["film_fraction"] = (fraction, FIELD_SPECS["film_fraction"])
    for name, item in declared.items():  # the declaration's own unit and long name
        out[name] = (np.asarray(item.values, dtype=float),
                     FieldSpec(item.units, item.long_name))
    if problem.asperity is not None:
        _, _, roughness, scale = problem.asperity
        out["asperity_pressure"] = (np.asarray(asperity_pressure(h, roughness, scale),
                                               dtype=float), FIELD_SPECS["asperity_pressure"])
    return out


def film_thickness_field(geometry, state: FilmState, theta: np.ndarray, z: np.ndarray,
                         deformation: np.ndarray | None = None,
                         trig: tuple[np.ndarray, np.ndarray] | None = None) -> np.ndarray:
    """h(θ, z) [m] of ``state`` on the nodes θ × z (module docstring); ``trig``: cos θ and
    sin θ as columns (n_θ, 1), when the caller has them."""
    cos, sin = trig if trig is not None else (np.cos(theta)[:, None], np.sin(theta)[:, None])
    zz = z[None, :]
    h = (geometry.radial_clearance - (state.eccentricity_x + zz * state.tilt_y) * cos
         - (state.eccentricity_y - zz * state.tilt_x) * sin)
    profile = profile_field(geometry, theta, z) if geometry.profile is not None else None
    if profile is not None:
        h = h + profile
    if deformation is not None:
        h = h + deformation
    return h



def sign_off(problem: OrbitProblem, cycle: CycleResults, film_memory: list | None, summary,
             limits: dict[str, float], stride_deg: float | None = None,
             solved: list | None = None) -> SignOff:
    """Per-cell indicators, the erosion indicator and the margins against ``limits``; the
    fields kept at ``stride_deg`` [deg] when asked for (None: not kept); ``solved``: the
    rows' film results of the characteristics (:func:`cycle_fields`)."""
    fields = cycle_fields(problem, cycle, film_memory, solved)
    notes: list[str] = []
    if fields is None:
        notes.append(f"film {problem.film.name!r} gives no pressure field: no per-cell maps")
        return SignOff(None, margins(limits, summary, cycle, None), None, tuple(notes))
    erosion, note = erosion_map(fields)
    indicators = cell_indicators(fields, erosion, note)
    kept = None if stride_deg is None else fields.every(stride_deg)
    return SignOff(indicators, margins(limits, summary, cycle, indicators), kept, tuple(notes))


def check_fields_stride(stride: float | None) -> float | None:
    """The stride of the fields over the cycle [deg]: None or a number in (0, 720]."""
    if stride is None:
        return None
    if isinstance(stride, bool) or not isinstance(stride, int | float) or not (
            0.0 < stride <= 720.0):
        raise CaseError(f"--fields (Simulation fields) = {stride!r}: out of range (allowed: "
                        "> 0 and <= 720 deg of crank angle between kept rows, or None)")
    return float(stride)


@dataclass(frozen=True)
class SignOffRequest:
    """What a :class:`~conrod.simulation.simulation.Simulation` is asked to sign off.

    wanted : bool  Compute the per-cell indicators and the margins against ``[limits]``.
    stride_deg : float or None  Keep the fields over the last cycle every this many degrees
        of crank angle (``conrod run --fields``) [deg]; None: not kept.
    """

    wanted: bool = True
    stride_deg: float | None = None


def signoff_request(keywords: dict) -> tuple[SignOffRequest, dict]:
    """(the sign-off asked for, the other keywords) from the keywords of a Simulation:
    ``signoff`` (bool, default True: per-cell indicators and margins, ``results.signoff``)
    and ``fields`` (the stride of the fields kept over the cycle [deg], default None)."""
    rest = dict(keywords)
    wanted = rest.pop("signoff", True)
    if not isinstance(wanted, bool):
        raise CaseError(f"Simulation signoff = {wanted!r}: True or False is required")
    return SignOffRequest(wanted, check_fields_stride(rest.pop("fields", None))), rest


def signed_off(results, thermal, case, request: SignOffRequest):
    """``results`` of the converged orbit ``thermal`` (problem, orbit) with its sign-off
    (:func:`with_sign_off`) against the case's ``[limits]``; unchanged when not asked for."""
    if not request.wanted:
        return results
    limits = case.limits.given() if case.limits is not None else {}
    return with_sign_off(results, thermal.problem, thermal.orbit.last.film_memory, limits,
                         request.stride_deg, thermal.rows)


def with_sign_off(results, problem, film_memory, limits, stride_deg=None, solved=None):
    """``results`` with its :class:`SignOff` and a warning per crossed limit (``solved``:
    the rows' film results of the characteristics, :func:`cycle_fields`)."""
    signoff = sign_off(problem, results.cycle, film_memory, results.summary, limits,
                       stride_deg, solved)
    summary = dataclasses.replace(
        results.summary, warnings=(*results.summary.warnings, *signoff.warnings()))
    return dataclasses.replace(results, summary=summary, signoff=signoff)


__all__ = ["SignOffRequest", "check_fields_stride", "cycle_fields", "film_thickness_field",
           "sign_off", "signed_off", "signoff_request", "with_sign_off"]
