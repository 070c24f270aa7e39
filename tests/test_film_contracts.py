"""Every film model through one battery: what the orbit may assume of any film
(:class:`conrod.film.base.FilmModel` plus the capabilities it declares)."""

from __future__ import annotations

import dataclasses
import math

import numba as nb
import numpy as np
import pytest

from conrod.contact.mixed import MixedLubricationFilm
from conrod.contact.running_in import WornShellFilm
from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmResult, FilmState, Groove
from conrod.film.capabilities import (
    CompiledKernel,
    HasCompiledKernel,
    HasMemory,
    SupportsDeformation,
)
from conrod.film.factory import GroovedShortBearingFilm
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.film.table.film import TabulatedFilm
from conrod.film.table.mobility import MobilityFilm
from conrod.orbit.memory import FilmSession
from conrod.registry import FILM_MODELS, FILM_NAMES, film_class

C = 25e-6
SPEED = 200.0
MU = 0.02


def plain(clearance: float = C) -> BearingGeometry:
    return BearingGeometry(diameter=0.05, width=0.025, radial_clearance=clearance)


def grooved(clearance: float = C) -> BearingGeometry:
    return BearingGeometry(diameter=0.05, width=0.025, radial_clearance=clearance,
                           grooves=(Groove(width=0.004),))


MODELS = {
    "short": lambda c, tmp: ShortBearingFilm(plain(c)),
    "short_two_lands": lambda c, tmp: GroovedShortBearingFilm.from_geometry(grooved(c)),
    "reynolds": lambda c, tmp: ReynoldsFilm(plain(c), n_theta=48, n_z=8),
    "mass_conserving": lambda c, tmp: MassConservingFilm(plain(c), n_theta=48, n_z=8),
    "table": lambda c, tmp: TabulatedFilm(ReynoldsFilm(plain(c), n_theta=24, n_z=4), n_eps=8,
                                          n_direction=16, cache_dir=tmp),
    "mobility": lambda c, tmp: MobilityFilm.short_bearing(plain(c), n_eps=10,
                                                          n_direction=16),
    "mixed_reynolds": lambda c, tmp: MixedLubricationFilm(
        ReynoldsFilm(plain(c), n_theta=48, n_z=8), (0.025, 0.025, 1e-9, 1e9), 0.1),
    "worn_reynolds": lambda c, tmp: WornShellFilm(
        ReynoldsFilm(plain(c), n_theta=48, n_z=8), lambda t, z: np.zeros((t.size, z.size))),
}
"""Every registered film model, the grooved short film and the wrappers [-]."""

STATES = [  # (e_x/c, e_y/c, v_x/(c ω), v_y/(c ω), ω_j/ω, ω_b/ω)
    (0.5, 0.2, 0.05, -0.1, 1.0, 0.0),
    (-0.3, 0.6, -0.2, 0.02, 0.4, -0.3),
    (0.1, -0.7, 0.0, 0.3, -1.0, 0.2),
]


def state(row, clearance: float = C, deformation=None) -> FilmState:
    ex, ey, vx, vy, wj, wb = row
    return FilmState(eccentricity_x=ex * clearance, eccentricity_y=ey * clearance,
                     velocity_x=vx * clearance * SPEED,
                     velocity_y=vy * clearance * SPEED, journal_speed=wj * SPEED,
                     shell_speed=wb * SPEED, viscosity=MU,
                     deformation=deformation)


def mirrored(s: FilmState) -> FilmState:
    """The state mirrored about the x axis (θ → −θ): y, v_y and both speeds change sign."""
    return dataclasses.replace(s, eccentricity_y=-s.eccentricity_y, velocity_y=-s.velocity_y,
                               journal_speed=-s.journal_speed, shell_speed=-s.shell_speed)


@pytest.fixture(params=list(MODELS))
def model(request, tmp_path):
    return request.param, MODELS[request.param]


def test_every_registered_name_is_in_the_battery_and_builds_itself():
    assert set(FILM_MODELS) == set(FILM_NAMES)
    assert set(FILM_NAMES) <= set(MODELS)
    for name in FILM_NAMES:
        assert hasattr(film_class(name), "from_settings")


def test_force_is_mirror_symmetric(model, tmp_path):
    """Mirroring the state about the x axis mirrors the force: (F_x, F_y) → (F_x, −F_y)."""
    _, make = model
    film = make(C, tmp_path)
    for row in STATES:
        fx, fy = film.force(state(row))
        mx, my = film.force(mirrored(state(row)))
        scale = math.hypot(fx, fy)
        assert abs(mx - fx) <= 1e-6 * scale and abs(my + fy) <= 1e-6 * scale


def test_no_force_at_the_centre_without_motion(model, tmp_path):
    """Concentric, at rest, no rotation: uniform gap and no squeeze, so p = 0 and F = 0."""
    _, make = model
    film = make(C, tmp_path)
    fx, fy = film.force(FilmState(eccentricity_x=0.0, eccentricity_y=0.0, viscosity=MU))
    assert fx == 0.0 and fy == 0.0


def test_deformation_is_honoured_or_refused(model, tmp_path):
    """A declared deformation support honours δ: a uniform δ equals a larger clearance
    c + δ (same h everywhere); a film without it refuses δ with a CaseError."""
    _, make = model
    film = make(C, tmp_path)
    theta, z = film.grid()
    extra = 0.2 * C
    row = STATES[0]
    if isinstance(film, SupportsDeformation):
        assert film.deformation_shape() == (theta.size, z.size)
        uniform = np.full(film.deformation_shape(), extra)
        deformed = film.force(state(row, deformation=uniform))
        wider = make(C + extra, tmp_path).force(state(row))
        assert deformed == pytest.approx(wider, rel=1e-6)
        assert deformed != pytest.approx(film.force(state(row)), rel=1e-3)
    else:
        with pytest.raises(CaseError, match="deformation"):
            film.force(state(row, deformation=np.full((theta.size, z.size), extra)))


def test_memory_snapshot_and_restore_continue_bit_identically(model, tmp_path):
    """The integrator's memory: a restored snapshot gives the same continuation, bit for
    bit, and a solve never changes the memory it was given; memoryless films are pure."""
    _, make = model
    film = make(C, tmp_path)
    states = [state(row) for row in STATES]
    session = FilmSession(film)
    session.solve(states[0])
    snapshot = session.snapshot()
    frozen = _copy_arrays(snapshot)
    first = [session.force(s) for s in states[1:]]
    session.advance(states[1], 1e-5)
    after_advance = session.force(states[2])
    session.restore(snapshot)
    again = [session.force(s) for s in states[1:]]
    session.advance(states[1], 1e-5)
    assert again == first
    assert session.force(states[2]) == after_advance
    assert _same_arrays(snapshot, frozen)
    if not isinstance(film, HasMemory):
        assert snapshot is None and film.force(states[1]) == first[0]


def _copy_arrays(memory):
    if memory is None:
        return None
    return {k: None if v is None else np.array(v) for k, v in vars(memory).items()}


def _same_arrays(memory, copy) -> bool:
    if memory is None:
        return copy is None
    return all((v is None and copy[k] is None) or np.array_equal(v, copy[k])
               for k, v in vars(memory).items())


def test_wrappers_declare_what_their_base_declares(tmp_path):
    reynolds = ReynoldsFilm(plain(), n_theta=48, n_z=8)
    short = ShortBearingFilm(plain())
    mixed_on_reynolds = MixedLubricationFilm(reynolds, (0.025, 0.025, 1e-9, 1e9))
    mixed_on_short = MixedLubricationFilm(short, (0.025, 0.025, 1e-9, 1e9))
    assert isinstance(mixed_on_reynolds, HasMemory)
    assert isinstance(mixed_on_reynolds, SupportsDeformation)
    assert not isinstance(mixed_on_short, HasMemory)
    assert not isinstance(mixed_on_short, SupportsDeformation)
    assert isinstance(short, HasCompiledKernel) and mixed_on_short.compiled_kernel() is None
    with pytest.raises(CaseError, match="worn shell"):
        WornShellFilm(short, lambda t, z: np.zeros((t.size, z.size)))


@nb.njit(cache=True)
def linear_squeeze_force(x, y, vx, vy, omega_sum, viscosity, params):
    """F = −μ b (ė − ω̄ × e): a squeeze damper in the frame turning at ω̄ [N]."""
    damping = viscosity * params[0]
    mean = 0.5 * omega_sum
    return -damping * (vx + mean * y), -damping * (vy - mean * x)


@dataclasses.dataclass
class LinearSqueezeFilm:
    """A film model that exists only in this test: it declares a compiled kernel."""

    geometry: BearingGeometry
    damping_per_viscosity: float
    name: str = "linear_squeeze"

    def compiled_kernel(self) -> CompiledKernel:
        return CompiledKernel(linear_squeeze_force, (self.damping_per_viscosity,))

    def force(self, state: FilmState) -> tuple[float, float]:
        return linear_squeeze_force(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed + state.shell_speed, state.viscosity,
            (self.damping_per_viscosity,))

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        fx, fy = self.force(state)
        return FilmResult(fx, fy, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        return np.zeros(1), np.zeros(1)

    def initial_history(self) -> None:
        return None


def test_a_film_declaring_a_compiled_kernel_runs_the_compiled_quasi_static_orbit(monkeypatch):
    """A test-only film with a compiled force gets the compiled massless loop (the Python
    loop is disabled here) and its orbit is exact: with ω_j = ω_b = 0 the balance
    F + W = 0 gives ė = W/(μ b), a straight drift x(φ) = W φ/(ω μ b)."""
    import conrod.orbit.quasi_static as qs
    from conrod.loads.cycle import LoadCycle
    from conrod.orbit import OrbitProblem, OrbitState

    omega, cycle, load, b = 200.0, 4.0 * math.pi, 50.0, 1.0e8
    phi = np.linspace(0.0, cycle, 72, endpoint=False)
    loads = LoadCycle(phi, np.full(72, load), np.zeros(72), np.zeros(72), np.zeros(72),
                      omega, cycle)
    film = LinearSqueezeFilm(plain(), b)
    problem = OrbitProblem(film, loads, MU, 1.0, 1.0)

    def no_python_loop(*args):
        raise AssertionError("the Python loop ran")

    monkeypatch.setattr(qs, "_velocity_solver", no_python_loop)
    assert isinstance(film, HasCompiledKernel) and qs.compiled_applies(problem)
    orbit = qs.quasi_static_cycle(problem, OrbitState(), 1.0, 2.0)
    drift = load * orbit.crank_angle / (omega * MU * b)
    assert drift[-1] < 0.9 * C  # the journal stays off the contact circle
    np.testing.assert_allclose(orbit.x, drift, rtol=1e-9, atol=1e-15)
    np.testing.assert_allclose(orbit.vx, load / (MU * b), rtol=1e-9)
    assert np.all(orbit.y == 0.0) and not np.any(orbit.in_contact)
