"""The compiled implicit free flight is loaded from numba's disk cache by a second process,
and the second process writes the same results bit for bit."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "passenger_car_diesel_2000rpm.toml"

RUN_AND_COUNT = """
import sys
from conrod.cli.app import main
from conrod.film.short.film import kernel_force
from conrod.orbit.compiled_flight import flight_segment

try:
    main()
except SystemExit as stop:
    code = stop.code
stats = flight_segment(kernel_force).stats
print("CACHE", sum(stats.cache_hits.values()), sum(stats.cache_misses.values()))
sys.exit(code)
"""


def _run(out: Path, cache: Path) -> tuple[int, int]:
    """(cache hits, cache misses) of the short film's compiled segment in a new process."""
    command = [sys.executable, "-c", RUN_AND_COUNT, "run", str(CASE), "--film", "short",
               "--integrator", "implicit", "--no-figures", "--out", str(out)]
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "NUMBA_CACHE_DIR": str(cache)}
    done = subprocess.run(command, capture_output=True, text=True, env=env, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    line = next(x for x in done.stdout.splitlines() if x.startswith("CACHE"))
    hits, misses = (int(v) for v in line.split()[1:])
    return hits, misses


def _summary(out: Path) -> dict:
    summary = json.loads((out / "summary.json").read_text(encoding="utf-8"))
    summary.pop("wall_time_s")
    return summary


def test_a_second_process_loads_the_compiled_flight_and_writes_the_same_results(tmp_path):
    cache = tmp_path / "numba"
    first = _run(tmp_path / "first", cache)
    second = _run(tmp_path / "second", cache)
    assert first == (0, 1)  # compiled and saved
    assert second == (1, 0)  # loaded, nothing compiled
    tables = sorted(path.name for path in (tmp_path / "first").glob("*.csv"))
    assert "cycle.csv" in tables
    assert tables == sorted(path.name for path in (tmp_path / "second").glob("*.csv"))
    for name in tables:
        assert (tmp_path / "first" / name).read_bytes() == \
            (tmp_path / "second" / name).read_bytes()
    assert _summary(tmp_path / "first") == _summary(tmp_path / "second")


def _spring_damper():
    """A closure force F = −k e − b ė [N] (k = 4 N/m, b = 2 N s/m): not cacheable."""
    import numba as nb

    @nb.njit
    def force(x, y, vx, vy, omega_sum, viscosity, params):
        return -params[0] * x - params[1] * vx, -params[0] * y - params[1] * vy

    return force


def test_a_closure_force_runs_the_same_segment_uncached_and_in_python():
    """Constant load W = 1 N on a spring k = 4 N/m with damping b = 2 N s/m, m = 1 kg,
    c = 1 m, ω = 1 rad/s: the centre settles at x = W/k (damping ratio 0.5; after 40 rad
    the transient is e^{-40})."""
    import numpy as np

    from conrod.orbit.compiled_flight import flight_segment
    from conrod.orbit.tr_bdf2 import STATUS_END, specialise

    angles = np.array([0.0, 2.0 * np.pi])
    table = np.array([[1.0, 0.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0]])
    data = (angles, table, 2.0 * np.pi, 0.01, 1.0, 1.0, 1.0, 1.0)
    params = (4.0, 2.0)
    force = _spring_damper()
    compiled = flight_segment(force)

    def python_rhs(phi, u, params, data):
        return np.array([u[2], u[3], 1.0 - 4.0 * u[0] - 2.0 * u[2], -4.0 * u[1] - 2.0 * u[3]])

    python = specialise("spring", python_rhs, compiled=False)
    results = []
    for segment in (compiled, python):
        status, phi, u, *_ = segment(params, data, 0.0, 40.0, np.zeros(4), 1e-4, 0.1, 1e-8,
                                     1e-10, 10.0, np.zeros(0), np.zeros((0, 4)), 0, 10**6,
                                     0.1, True)
        assert status == STATUS_END and phi == 40.0
        results.append(u)
    np.testing.assert_allclose(results[0], [0.25, 0.0, 0.0, 0.0], atol=1e-7)
    np.testing.assert_allclose(results[1], results[0], rtol=0, atol=1e-12)


def test_every_path_hands_the_multigrid_one_read_only_mask():
    """The Python film (full and mid-plane-symmetric grid, writable or read-only mask) and
    the compiled squeeze grid all give ``multigrid_solve`` a read-only mask, so numba
    compiles it (and its callees) for one mask type; the solved pressure is the same for
    a writable and a read-only mask, bit for bit."""
    import numpy as np

    from conrod.film.base import BearingGeometry, FilmState
    from conrod.film.reynolds import multigrid as multigrid
    from conrod.film.reynolds.film import ReynoldsFilm
    from conrod.film.reynolds.squeeze import SqueezeGrid

    geometry = BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5)
    film = ReynoldsFilm(geometry, n_theta=36, n_z=8)
    state = FilmState(eccentricity_x=15e-6, eccentricity_y=5e-6, velocity_x=1e-3,
                      velocity_y=0.0, journal_speed=200.0, viscosity=0.02)
    problem = film._problem(state)
    source = np.linspace(-1e-9, 1e-9, problem.h.size).reshape(problem.h.shape)
    fields = []
    for symmetric in (False, True):
        for fixed in (problem.fixed.copy(), multigrid.read_only(problem.fixed)):
            pressure = np.where(fixed, 0.0, 1e5)
            multigrid.solve_on_grid(pressure, problem.h, source, fixed, film.film_grid, 0.0,
                                    1e-10, 50, symmetric)
            fields.append(pressure)
    assert not SqueezeGrid(film, 0.02).fixed.flags.writeable
    assert np.array_equal(fields[0], fields[1]) and np.array_equal(fields[2], fields[3])
    masks = [signature[3] for signature in multigrid.multigrid_solve.signatures]
    assert masks and not any(mask.mutable for mask in masks)


SPECIALISATIONS = """
import json
import numpy as np
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.reynolds import multigrid
from conrod.film.reynolds.film import ReynoldsFilm
film = ReynoldsFilm(BearingGeometry(diameter=0.05, width=0.025, radial_clearance=2.5e-5),
                    n_theta=36, n_z=8)
problem = film._problem(FilmState(eccentricity_x=15e-6, eccentricity_y=5e-6,
                                  velocity_x=1e-3, velocity_y=0.0, journal_speed=200.0,
                                  viscosity=0.02))
source = np.linspace(-1e-9, 1e-9, problem.h.size).reshape(problem.h.shape)
for symmetric in (False, True):
    for fixed in (problem.fixed.copy(), multigrid.read_only(problem.fixed)):
        multigrid.solve_on_grid(np.where(fixed, 0.0, 1e5), problem.h, source, fixed,
                                film.film_grid, 0.0, 1e-10, 50, symmetric)
print(json.dumps({k.py_func.__name__: len(k.signatures) for k in (
    multigrid._fold, multigrid._descend, multigrid.gauss_seidel, multigrid.stencil)}))
"""


def test_the_multigrid_kernels_compile_one_specialisation_each(tmp_path):
    """On an empty numba cache (a new process: the kernels' signatures are those of these
    solves alone), the symmetric and full grids with a writable and a read-only mask compile
    _fold, _descend, gauss_seidel and stencil once each: int64 sweep counts and levels and
    one kind of mask at every call site (a literal argument or a read-only mask compiled a
    kernel once more)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "NUMBA_CACHE_DIR": str(tmp_path)}
    done = subprocess.run([sys.executable, "-c", SPECIALISATIONS], capture_output=True,
                          text=True, env=env, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    counts = json.loads(done.stdout.splitlines()[-1])
    assert counts == {"_fold": 1, "_descend": 1, "gauss_seidel": 1, "stencil": 1}


def test_the_compiled_flights_have_one_signature_whatever_the_film_carries():
    """The params of the compiled flight (and of the tilted one) have one numba type for a
    cylindrical bore, a tapered one (not mid-plane symmetric: the film's read-only profile on
    the full grid) and a viscosity field varying along z: the film's read-only fields enter
    as writable copies (a read-only array is typed apart, and the orbit's whole compiled
    flight, 40–100 s of numba, was compiled once more for it)."""
    import numba
    import numpy as np

    from conrod.film.base import BearingGeometry
    from conrod.film.profile import BoreProfile
    from conrod.film.reynolds.film import ReynoldsFilm

    def film(profile=None):
        return ReynoldsFilm(BearingGeometry(diameter=0.05, width=0.02, radial_clearance=25e-6,
                                            profile=profile), 24, 8)

    plain = film()
    shape = plain.deformation_shape()
    graded = plain.with_viscosity_field(np.tile(np.linspace(0.01, 0.02, shape[1]),
                                                (shape[0], 1)))
    films = (plain, film(BoreProfile(taper=4e-6)), graded)
    assert not films[1].symmetric and not graded.symmetric
    assert not films[1].profile.flags.writeable and not graded.viscosity_field.flags.writeable
    for kernel in ("flight_kernel", "tilt_flight_kernel"):
        kernels = [k for f in films if (k := getattr(f, kernel)(None, 1e-10)) is not None]
        assert len(kernels) == (3 if kernel == "flight_kernel" else 2)  # tilted: no μ field
        types = {str(numba.typeof(k.params)) for k in kernels}
        assert len(types) == 1, (kernel, types)


LOAD_AND_COUNT = """
from conrod.film.short.kernel import sommerfeld_angle

sommerfeld_angle(1.0, 0.5)
stats = sommerfeld_angle.stats
print("CACHE", sum(stats.cache_hits.values()), sum(stats.cache_misses.values()))
"""


def _hits_and_misses(packages: Path) -> tuple[int, int]:
    """(cache hits, cache misses) of a kernel of the conrod package below ``packages``,
    with numba's cache beside its modules (as in an installed package)."""
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["PYTHONPATH"] = str(packages)
    done = subprocess.run([sys.executable, "-c", LOAD_AND_COUNT], capture_output=True,
                          text=True, env=env, check=False, cwd=packages)
    assert done.returncode == 0, done.stderr[-2000:]
    line = next(x for x in done.stdout.splitlines() if x.startswith("CACHE"))
    hits, misses = (int(v) for v in line.split()[1:])
    return hits, misses


def test_a_copy_with_new_times_loads_the_kernels_compiled_beside_its_sources(tmp_path):
    """What ``pip install .`` does to the kernels compiled while the wheel was built
    (docs/install.md): pip writes the files anew, so every modification time is new; the
    content stamp still finds the kernel. A changed module compiles it again."""
    import shutil
    import time

    built = tmp_path / "built"
    shutil.copytree(ROOT / "src" / "conrod", built / "conrod",
                    ignore=shutil.ignore_patterns("__pycache__"))
    assert _hits_and_misses(built) == (0, 1)  # compiled beside the sources
    time.sleep(0.01)
    installed = tmp_path / "installed"
    shutil.copytree(built, installed, copy_function=shutil.copyfile)  # new times
    module = installed / "conrod" / "film" / "short" / "kernel.py"
    assert module.stat().st_mtime_ns != (built / "conrod/film/short/kernel.py").stat().st_mtime_ns
    assert _hits_and_misses(installed) == (1, 0)
    edited = installed / "conrod" / "units.py"  # another module of the package changed
    edited.write_text(edited.read_text() + "\n# edited\n")
    assert _hits_and_misses(installed) == (0, 1)


def test_no_layer_of_the_compiled_flights_compiles_the_film_twice():
    """numba links every compiled callee into its caller's library and LLVM optimises it
    there again, so each layer between the segment and the film's multigrid costs a
    compile of all the code below it (``conrod.orbit.tilt_flight.tilt_segment``): the
    tilted segment inlines its right-hand side and Jacobian (its film's force and Jacobian
    are the compiled functions), the aligned segment calls a right-hand side into which
    the film's force is inlined (inlining both copies the force into each of the segment's
    calls)."""
    from conrod.film.reynolds.flight import reynolds_force, reynolds_jacobian
    from conrod.film.reynolds.tilt_flight import reynolds_tilt_force, reynolds_tilt_jacobian
    from conrod.orbit.compiled_flight import flight_segment
    from conrod.orbit.tilt_flight import tilt_segment

    def inlined(function) -> bool:
        return function.targetoptions.get("inline") == "always"

    tilted = tilt_segment(reynolds_tilt_force, reynolds_tilt_jacobian).py_func.__globals__
    assert inlined(tilted["rhs"]) and inlined(tilted["jacobian"])
    assert not inlined(reynolds_tilt_force) and not inlined(reynolds_tilt_jacobian)
    aligned = flight_segment(reynolds_force, reynolds_jacobian).py_func.__globals__
    assert not inlined(aligned["rhs"]) and not inlined(aligned["jacobian"])
    assert inlined(reynolds_force) and inlined(reynolds_jacobian)


def test_the_adaptive_free_phase_runs_the_flights_disk_cached_right_hand_side():
    """The ``adaptive`` integrator's compiled free phase is the compiled flight's right-hand
    side, one disk-cached kernel per force function (it was compiled in every process and
    for every parameter values: 1.0–1.9 s of each warm run of the shipped adaptive
    example), and it answers as the film's Python force does."""
    import numpy as np

    from conrod.orbit.adaptive import Phases
    from conrod.orbit.compiled_flight import flight_rhs, flight_segment
    from conrod.orbit.problem import OrbitState
    from orbit_helpers import engine_like_load, load_cycle, short_problem

    problem = short_problem(load_cycle(*engine_like_load()))
    kernel = problem.compiled_force
    rhs = flight_rhs(kernel.force)
    assert flight_segment(kernel.force).py_func.__globals__["rhs"] is rhs
    assert type(rhs._cache).__name__ != "NullCache"  # numba keeps it on disk
    compiled = Phases(problem, OrbitState())
    python = Phases(problem, OrbitState())
    python.compiled_rhs = None
    for phi, u in ((0.3, [0.2, -0.5, 0.01, 0.03]), (2.0, [-0.7, 0.1, -0.2, 0.05])):
        u = np.array(u)
        expected = python.free_rhs(phi, u)
        np.testing.assert_allclose(compiled.free_rhs(phi, u), expected, rtol=1e-12,
                                   atol=1e-12 * np.abs(expected).max())
        np.testing.assert_array_equal(compiled.free_rhs(phi, u[::-1][::-1]),
                                      compiled.free_rhs(phi, u))


def test_the_quasi_static_contact_forces_are_one_cached_kernel_per_film_force():
    """The contact forces of the compiled quasi-static orbit are compiled once per film
    force and kept on disk (with the force as an argument, every process compiled them:
    0.3–0.4 s of a warm 2.3 s run), and they equal the Python loop's on the rows where the
    journal sits on the contact circle; the other rows are left alone."""
    import numpy as np

    from conrod.orbit.quasi_static import _contact_forces, bound_contact_forces
    from orbit_helpers import engine_like_load, load_cycle, short_problem

    problem = short_problem(load_cycle(*engine_like_load()))
    kernel = problem.compiled_force
    bound = bound_contact_forces(kernel.force)
    assert bound is bound_contact_forces(kernel.force)
    assert type(bound._cache).__name__ != "NullCache"
    radius = problem.contact_radius
    table = np.zeros((3, 7))
    for row, angle in enumerate((0.3, 1.5, 3.0)):
        table[row, :4] = 0.9 * radius * np.cos(angle), 0.9 * radius * np.sin(angle), 0.0, 0.0
    table[[0, 2], 6] = 1.0  # on the circle
    load_x, load_y = np.array([2e6, 5e3, -2e6]), np.array([6e5, 2e3, 3e5])  # outwards
    speeds = np.full(3, 200.0)
    compiled, python = table.copy(), table.copy()
    bound(kernel.params, compiled, load_x, load_y, speeds, problem.viscosity,
          problem.dry_friction)
    _contact_forces(problem, python, load_x, load_y, speeds, np.zeros(3))
    np.testing.assert_allclose(compiled, python, rtol=1e-10, atol=0.0)
    assert compiled[0, 4] > 0.0 and compiled[2, 4] > 0.0 and compiled[1, 4] == 0.0


COMPILE_AT_THE_SIGNAL = """
import json, sys, time
from pathlib import Path
import conrod  # noqa: F401 - guards numba's cache
from conrod.film.short.kernel import short_bearing_force

ready, go = Path(sys.argv[1]), Path(sys.argv[2])
ready.write_text("")
while not go.exists():
    time.sleep(0.001)
short_bearing_force(3e-5, -1e-5, 0.01, 0.02, 400.0, 0.01, 0.05, 0.025, 5e-5)
stats = short_bearing_force.stats
print(json.dumps([sum(stats.cache_hits.values()), sum(stats.cache_misses.values())]))
"""


def test_two_processes_missing_the_same_kernel_compile_it_once(tmp_path):
    """Two processes call the same uncompiled kernel at the same moment on one empty cache
    folder: one compiles it while the other waits for its lock and loads what it saved
    (without the lock both miss and both compile)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"),
           "NUMBA_CACHE_DIR": str(tmp_path / "cache")}
    go = tmp_path / "go"
    processes = [subprocess.Popen([sys.executable, "-c", COMPILE_AT_THE_SIGNAL,
                                   str(tmp_path / f"ready{k}"), str(go)], env=env,
                                  stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
                 for k in range(2)]
    while not all((tmp_path / f"ready{k}").exists() for k in range(2)):
        assert all(process.poll() is None for process in processes)
        time.sleep(0.01)
    go.write_text("")
    counts = []
    for process in processes:
        out, err = process.communicate(timeout=300)
        assert process.returncode == 0, err[-2000:]
        counts.append(json.loads(out.splitlines()[-1]))
    assert sorted(counts) == [[0, 1], [1, 0]]  # (hits, misses) of each process


FAIL_TO_COMPILE = """
import json
import conrod  # noqa: F401 - guards numba's cache
from conrod.io import numba_cache
from conrod.film.short.kernel import short_bearing_force

try:
    short_bearing_force("not a number", 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 5e-5)
except Exception as error:
    failed = type(error).__name__
print(json.dumps([failed, len(numba_cache._locks["held"]),
                  len(short_bearing_force.stats.cache_misses)]))
"""


def test_a_compile_that_raises_releases_its_kernel_lock(tmp_path):
    """A kernel called with arguments it cannot compile for misses the cache, takes its lock
    and raises numba's typing error: the lock is released at once (numba saves nothing), so
    that another process of a long-lived program does not wait for it."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "NUMBA_CACHE_DIR": str(tmp_path)}
    done = subprocess.run([sys.executable, "-c", FAIL_TO_COMPILE], capture_output=True,
                          text=True, env=env, check=False)
    assert done.returncode == 0, done.stderr[-2000:]
    failed, held, misses = json.loads(done.stdout.splitlines()[-1])
    assert (failed, misses) == ("TypingError", 1)  # it did miss, lock and fail
    assert held == 0
