"""Repeat cycles from the concentric start until the orbit is periodic.

The orbit with mass by the ``implicit`` integrator (also through ``auto``) starts, when
``[solver] massless_start`` is on (off by default), from the end of the periodic massless
(quasi-static) orbit instead of the concentric position: the mass changes the orbit
little, so it is periodic within two cycles with mass (without the shooting accelerator:
passenger car 3 → 2 cycles; constant load on a Reynolds film 5 → 2). With shooting (the
default) the concentric start is periodic within two cycles on the shipped examples as
well and the massless cycles only cost time (docs/orbit.md). Cycles and periodicity error
are those of the orbit with mass. Not on an elastic bore: there the massless orbit costs
as much as the one with mass, which is periodic as fast from rest.

With ``[solver] accelerate_cycles`` (default) a cycle does not start where the last one
ended but at the Anderson extrapolation of the cycle-to-cycle map
(:mod:`conrod.orbit.acceleration`) on the state at φ = 0 (position and velocity scaled by
c and c ω; the position alone for the massless orbit, whose velocity follows from it).
Only while the plainly repeated cycles converge slowly (the periodicity error falling by
less than 20× per cycle); not across a contact at φ = 0. A film whose memory is a
transported content (mass-conserving) joins its film fraction ϑ to the mixed state
(weighted so that its root mean square counts as one component): the content is the slow
part of such an orbit, and a start that moved the journal but kept the old content
would not be a point of the cycle map.

Periodicity error of cycle k: max over the output angles of |e_k(φ) − e_{k−1}(φ)|/c [-]
(for a cycle repeated from where the last one ended: it is then the last cycle's
closure seen along the whole cycle). A cycle from an extrapolated start is measured by its
own closure, max(|e_k(end) − e_k(0)|/c, |ė_k(end) − ė_k(0)|/(c ω)) (position only for
the massless orbit; with a film content also the root mean square of the change of the
film fraction over the cycle): the previous cycle started elsewhere and says nothing
about it.
With ``[solver] periodic_accelerator = "shooting"`` (default) the start of every cycle
after the first is the quasi-Newton shooting step on F(X₀) = P(X₀) − X₀
(:mod:`conrod.orbit.shooting`, same state as the mixing; with no secant pair yet the
plain repetition), and every cycle, the first included, is measured by its own closure:
a cycle repeated from where the last one ended is accepted when it closes on itself,
one cycle before the difference of two plain cycles could say so (passenger car from
the concentric start: 3 → 2 cycles); the closure of a tilted run includes the tilt
(ℓγ/c, ℓγ̇/(c ω), ℓ = L/2). The memory of a film whose own unknowns are solved only with
the journal's step (the elastic Reynolds bore) is not moved: each cycle starts where the last one
ended, the deformation follows the journal (slaved), and the cycle is measured by the
journal's closure. A film content that cannot be mixed (the mass-conserving film on an
elastic bore) keeps the plain repetition. ``"anderson"`` is the mixing above.

The orbit with mass on an elastic bore whose deformation is solved with the journal's step
(slaved, shooting) starts with a lead-in (``[solver] lead_in``, half a cycle by default):
the integrator's ``lead_in`` runs only the last share of a cycle from the concentric start
(the journal at rest mid-cycle), and the first whole cycle from its end at φ = 0 is judged
by its own closure. The start's transient decays within that share of a cycle (README main
job: closure 2.2e-4 after a 360° lead-in, 2.7e-7 after a whole cycle), so the orbit is
periodic after 1.5 cycles instead of 2, within the tolerance of the whole-cycle one
(KamAZ-740 at 144 × 16: 2.6e-5 c; the shipped elastic examples 5e-9–2.1e-4 c,
``tests/test_orbit_lead_in.py``); a case whose transient is slower takes one cycle more.
The lead-in is not a cycle: ``previous`` is None after it, ``cycles`` counts whole cycles
and :attr:`PeriodicOrbit.cycles_run` adds the lead-in's share.

The orbit is periodic when it is at most ``[solver] periodicity_tolerance``; if it is not
after ``max_cycles``, the result says so (``periodic = False`` plus a warning) instead of
returning silently.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable
from dataclasses import dataclass, replace

import numpy as np

from conrod import registry
from conrod.film.capabilities import HasMixableContent
from conrod.orbit.acceleration import AndersonMixing
from conrod.orbit.implicit_step import needs_journal_step
from conrod.orbit.integrators import Integrator, declared, resolved
from conrod.orbit.problem import OrbitProblem, OrbitState, initial_state
from conrod.orbit.progress import reporting
from conrod.orbit.shooting import CycleShooting
from conrod.orbit.trajectory import CycleTrajectory

MIXING_LIMIT = 0.999
"""Extrapolated starts stay inside this fraction of the contact circle [-]."""
FAST_CONTRACTION = 0.05
"""No extrapolation while the periodicity error falls by more than 20× per cycle (the
shipped engine cases: periodic after 2–3 cycles either way) [-]."""


@dataclass
class PeriodicOrbit:
    """The last cycle and how it converged.

    last : CycleTrajectory  Samples of the last cycle.
    previous : CycleTrajectory or None  The cycle before it.
    cycles : int  Cycles integrated [-].
    periodicity_error : float  max |Δe|/c between the last two cycles [-] (inf after one).
    periodic : bool  Error within the tolerance [-].
    history : list  Periodicity error after each cycle [-].
    lead_in : float  Share of a cycle run before the first one from the concentric start
        (``[solver] lead_in``), 0 without [cycles].
    """

    last: CycleTrajectory
    previous: CycleTrajectory | None
    cycles: int
    periodicity_error: float
    periodic: bool
    history: list[float]
    lead_in: float = 0.0

    @property
    def cycles_run(self) -> float:
        """Cycles integrated, the lead-in counted by its share [cycles] (an int without)."""
        return self.cycles + self.lead_in if self.lead_in else self.cycles


def integrate_cycle(
    problem: OrbitProblem, state: OrbitState, settings, integrator: str | Integrator | None = None
) -> CycleTrajectory:
    """One cycle with ``integrator`` (an object, a registered name, or None: the name in
    ``settings``, the ``[solver]`` section)."""
    return _integrator(integrator or settings.integrator).cycle(problem, state, settings)


def _integrator(choice: str | Integrator) -> Integrator:
    return registry.integrator(choice) if isinstance(choice, str) else choice


def cycle_difference(a: CycleTrajectory, b: CycleTrajectory, clearance: float) -> float:
    """max |e_a − e_b|/c at the same output angles [-]."""
    return float(np.max(np.hypot(a.x - b.x, a.y - b.y)) / clearance)


def cycle_closure(start: OrbitState, end: OrbitState, problem: OrbitProblem,
                  with_mass: bool, content: HasMixableContent | None = None,
                  tilt: bool = False) -> float:
    """How far one cycle is from closing on itself: max(|e_end − e_0|/c, with mass
    |ė_end − ė_0|/(c ω), with a ``content`` film the root mean square of the change of its
    film fraction ϑ; with ``tilt`` of a tilted run also |ℓ(γ_end − γ_0)|/c and, with mass,
    |ℓ(γ̇_end − γ̇_0)|/(c ω), ℓ = L/2 the lever of the tilt) [-]."""
    c, w = problem.clearance, problem.crank_speed
    closure = math.hypot(end.x - start.x, end.y - start.y) / c
    if with_mass:
        closure = max(closure, math.hypot(end.vx - start.vx, end.vy - start.vy) / (c * w))
    if tilt and problem.tilt is not None and start.tilt is not None and end.tilt is not None:
        lever = problem.tilt.lever
        closure = max(closure, lever * math.hypot(end.tilt[0] - start.tilt[0],
                                                  end.tilt[1] - start.tilt[1]) / c)
        if with_mass:
            closure = max(closure, lever * math.hypot(end.tilt[2] - start.tilt[2],
                                                      end.tilt[3] - start.tilt[3]) / (c * w))
    if content is not None and start.film_memory is not None and end.film_memory is not None:
        change = (content.content_vector(end.film_memory)
                  - content.content_vector(start.film_memory))
        closure = max(closure, float(np.sqrt(np.mean(change**2))))
    return closure


def periodic_orbit(
    problem: OrbitProblem,
    settings,
    *,
    integrator: str | Integrator | None = None,
    start: OrbitState | None = None,
    on_cycle: Callable[[int, float], None] | None = None,
    on_angle: Callable[[int, float], None] | None = None,
) -> PeriodicOrbit:
    """Integrate cycles from ``start`` (concentric) until periodic or ``max_cycles``;
    ``on_cycle(cycle, periodicity error)`` after each cycle, ``on_angle(cycle, crank angle
    reached in it [rad])`` whenever the integrator reports (:mod:`conrod.orbit.progress`).
    With the shooting accelerator a ``start`` given by the caller continues a run (the
    heat balance's next viscosity from the last orbit's end): its first cycle is accepted
    when it closes on itself (``min_cycles`` counts the cycles of the run it continues)."""
    chosen = _integrator(integrator or settings.integrator)
    continued = start is not None
    if start is None and getattr(settings, "massless_start", False) and _implicit(chosen,
                                                                                 problem):
        start = _massless_start(problem, settings)
    mixing = _mixing(problem, chosen, settings)
    fewest = 1 if continued and mixing is not None and mixing.shooting else settings.min_cycles
    lead = None
    if start is None and mixing is not None and mixing.shooting:
        lead = _lead_in(chosen, problem, settings, on_angle)
    if lead is not None:  # the first cycle is measured by its own closure
        start, fewest = lead.end_state, 1
    state = start or initial_state()
    lead_in = 0.0 if lead is None else 1.0 - float(lead.crank_angle[0]) / problem.loads.cycle
    previous: CycleTrajectory | None = None
    history: list[float] = []
    error = float("inf")
    extrapolated = False
    for cycle in range(1, settings.max_cycles + 1):
        with reporting(None if on_angle is None else functools.partial(on_angle, cycle)):
            current = integrate_cycle(problem, state, settings, chosen)
        if extrapolated or (mixing is not None and mixing.shooting):
            error = cycle_closure(state, current.end_state, problem, mixing.with_mass,
                                  mixing.content, tilt=mixing.shooting)
        elif previous is not None:
            error = cycle_difference(current, previous, problem.clearance)
        history.append(error)
        if on_cycle is not None:
            on_cycle(cycle, error)
        if cycle >= fewest and error <= settings.periodicity_tolerance:
            return PeriodicOrbit(current, previous, cycle, error, True, history, lead_in)
        previous = current
        state, extrapolated = _next_start(mixing, state, current.end_state, problem,
                                          _slow(history))
    return PeriodicOrbit(current, previous, settings.max_cycles, error, False, history,
                         lead_in)


def _lead_in(chosen: Integrator, problem: OrbitProblem, settings,
             on_angle: Callable[[int, float], None] | None) -> CycleTrajectory | None:
    """The integrator's lead-in from the concentric start (``on_angle`` reports it as
    cycle 0), None where it has none (:mod:`conrod.orbit.integrators`)."""
    lead_in = getattr(_integrator(chosen), "lead_in", None)
    if lead_in is None:
        return None
    with reporting(None if on_angle is None else functools.partial(on_angle, 0)):
        return lead_in(problem, initial_state(), settings)


def _mixing(problem: OrbitProblem, chosen: Integrator, settings) -> _Mixing | None:
    """The Anderson mixing of this run, None when it is off or cannot apply."""
    mixable = isinstance(problem.film, HasMixableContent)
    shooting = getattr(settings, "periodic_accelerator", "shooting") == "shooting"
    slaved = problem.has_film_content and not mixable and needs_journal_step(problem.film)
    if not getattr(settings, "accelerate_cycles", False) or (
            problem.has_film_content and not mixable and not (slaved and shooting)):
        return None
    limit = MIXING_LIMIT * problem.contact_radius / problem.clearance
    scheme = CycleShooting(limit) if shooting else AndersonMixing(limit)
    return _Mixing(scheme, declared(resolved(chosen, problem), "with_mass"),
                   problem.film if problem.has_film_content and not slaved else None,
                   shooting, slaved)


@dataclass
class _Mixing:
    anderson: AndersonMixing | CycleShooting
    """The scheme proposing the next start (Anderson mixing or quasi-Newton shooting)."""
    with_mass: bool
    content: HasMixableContent | None = None
    """The film whose content joins the mixed state (None: position and velocity only)."""
    shooting: bool = False
    """Shooting: every proposal taken, every cycle measured by its own closure."""
    slaved: bool = False
    """A film memory that is only the state of unknowns solved with the journal's step
    (the elastic Reynolds bore's deformation, :func:`needs_journal_step`): not moved, every
    cycle starts where the last ended and is measured by the journal's closure."""

    def pack(self, state: OrbitState, scale: np.ndarray) -> np.ndarray:
        """Scaled state of the mixing: position (and velocity), then the film content
        weighted by 1/√n (its root mean square counts as one component)."""
        values = np.array([state.x, state.y, state.vx, state.vy])[:scale.size] / scale
        if self.content is None:
            return values
        content = self.content.content_vector(state.film_memory)
        return np.concatenate([values, content / math.sqrt(content.size)])

    def unpack(self, proposal: np.ndarray, end: OrbitState, scale: np.ndarray) -> OrbitState:
        """``end`` moved to the extrapolated ``proposal`` (content included)."""
        values = np.array([end.x, end.y, end.vx, end.vy])
        values[:scale.size] = proposal[:scale.size] * scale
        memory = end.film_memory
        if self.content is not None:
            content = proposal[scale.size:] * math.sqrt(proposal.size - scale.size)
            memory = self.content.with_content(memory, content)
        return replace(end, x=float(values[0]), y=float(values[1]), vx=float(values[2]),
                       vy=float(values[3]), film_memory=memory)


def _slow(history: list[float]) -> bool:
    """The periodicity error of plainly repeated cycles falls by less than
    :data:`FAST_CONTRACTION` per cycle (extrapolation pays only then)."""
    finite = [e for e in history if np.isfinite(e)]
    return len(finite) >= 2 and finite[-1] > FAST_CONTRACTION * finite[-2]


def _next_start(mixing: _Mixing | None, start: OrbitState, end: OrbitState,
                problem: OrbitProblem, slow: bool) -> tuple[OrbitState, bool]:
    """Start of the next cycle and whether it is extrapolated (else ``end`` itself); the
    mixing records every cycle but extrapolates only when convergence is ``slow``."""
    if mixing is None or mixing.slaved:
        return end, False
    if start.in_contact or end.in_contact:
        mixing.anderson.reset()
        return end, False
    if mixing.content is not None and (start.film_memory is None or end.film_memory is None):
        return end, False
    c, w = problem.clearance, problem.crank_speed
    scale = np.array([c, c, c * w, c * w])[:4 if mixing.with_mass else 2]
    proposal = mixing.anderson.propose(mixing.pack(start, scale), mixing.pack(end, scale))
    if proposal is None or not (slow or mixing.shooting):
        return end, False
    return mixing.unpack(proposal, end, scale), True


def _implicit(chosen: Integrator, problem: OrbitProblem) -> bool:
    """An orbit with mass that the massless start pays for (an integrator that declares
    ``massless_start``, :mod:`conrod.orbit.integrators`): not for a film whose own unknowns
    are solved with the journal's step (the elastic bore), whose massless orbit costs as
    much as the one with mass (KamAZ-740, 36 × 8: periodic after 3 cycles from rest either
    way); nor for a tilted journal or a profiled bore, whose massless orbit is not compiled."""
    return (declared(resolved(chosen, problem), "massless_start")
            and not needs_journal_step(problem.film) and problem.tilt is None
            and not getattr(problem.film.geometry.profile, "active", False))


def _massless_start(problem: OrbitProblem, settings) -> OrbitState | None:
    """End state of the periodic massless orbit (None, the concentric start, when it
    cannot be computed, e.g. a quasi-static step that does not divide the output step)."""
    from conrod.errors import CaseError, ConvergenceError

    try:
        return periodic_orbit(problem, settings, integrator="quasi_static").last.end_state
    except (CaseError, ConvergenceError):
        return None
