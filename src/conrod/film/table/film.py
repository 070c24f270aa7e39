"""Tabulated quasi-static film ([D0] §3.3): precomputed squeeze-force maps, cached on disk.

Any :class:`~conrod.film.base.FilmModel` (``base``) is solved once per table node for a pure
squeeze state (ω_j = ω_b = 0) at eccentricity ε_j along +x and unit-direction velocity
β_k; Booker's reduction (:mod:`conrod.film.table.kernel`) turns every later state, with any
journal and shell speeds, into such a squeeze state, so one table serves all speeds and
viscosities. Forces are interpolated quadratically in the (stretched) eccentricity and
linearly in the velocities; side/supply flow and p_max the same way.

Valid for bearings whose film does not depend on the line-of-centres angle and scales with
speed: no feed holes, only full circumferential grooves at ambient pressure, cavitation at
ambient pressure (others raise :class:`~conrod.errors.CaseError`). Friction moments are
the exact rigid-bearing values in Raimondi & Boyd's full-film convention,
M_j = −2πμR³L(ω_j − ω_b)/(c√(1−ε²)) − e F_t/2, M_b = +2πμR³L(ω_j − ω_b)/(c√(1−ε²)) − e F_t/2.

Tables are stored as ``<sha256>.npz`` in ``cache_dir`` (default ``~/.cache/conrod/tables``),
the key hashing the geometry, the base model and its grid, and the table grid. Each file
stores a SHA-256 checksum of its tables; a file that is unreadable, truncated, of the wrong
shape, non-finite or fails the checksum is rebuilt with a :class:`~conrod.errors.CacheWarning`.
A cache folder that cannot be used is skipped with one :class:`~conrod.errors.CacheWarning`.
"""

from __future__ import annotations

import contextlib
import dataclasses
import hashlib
import json
import math
import time
import warnings
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numba as nb
import numpy as np

from conrod.errors import CacheWarning, CaseError, ConvergenceError
from conrod.film.base import BearingGeometry, FilmModel, FilmResult, FilmState
from conrod.film.capabilities import (
    CompiledKernel,
    HasMemory,
    QuasiStaticRequest,
    film_memory,
    refuse_deformation,
)
from conrod.film.table.checks import check_tabulable
from conrod.film.table.kernel import (
    CLUSTERING,
    WEIGHT_POWER,
    direction_of,
    interpolate,
    squeeze_velocity,
    stretched,
    table_force,
    unit_force,
)
from conrod.io.atomic import atomic_path

TABLE_FORMAT = 4
"""Bumped whenever the stored content changes meaning (part of the cache key) [-]."""
DEFAULT_CACHE_DIR = Path("~") / ".cache" / "conrod" / "tables"
QUANTITIES = ("log_magnitude", "turning", "side_flow", "supply_flow", "max_pressure",
              "peak_cos", "peak_sin", "cavitated")
PER_SPEED = ("side_flow", "supply_flow", "max_pressure")
"""Tabulated per unit squeeze speed (scale with |v_s|); the rest are direction-only."""
UNUSABLE_FOLDERS: set[str] = set()
"""Cache folders found unusable in this process (each warned about once)."""
KEPT_IN_MEMORY: dict[str, dict[str, np.ndarray]] = {}
"""Tables built in this process whose cache folder was unusable, by cache key."""
REFERENCE_VISCOSITY = 0.01
"""Viscosity of the table solves [Pa s] (results are scaled out)."""
REFERENCE_RATE = 100.0
"""Squeeze speed of the table solves per clearance, |v| = c · rate [1/s]."""


@nb.njit(cache=True)
def kernel_force(x, y, vx, vy, omega_sum, viscosity, params):
    """:func:`table_force` [N] in the calling convention of
    :class:`~conrod.film.capabilities.CompiledKernel`; params = (R³L/c³ [-·m], c [m],
    Δs [-], log-magnitude table, turning table)."""
    return table_force(x, y, vx, vy, omega_sum, viscosity, params[0], params[1], params[2],
                       params[3], params[4])


def base_description(base: FilmModel) -> dict:
    """What identifies the base model in the cache key."""
    keys = ("n_theta", "n_z", "tolerance", "friction")
    params = {k: getattr(base, k) for k in keys if hasattr(base, k)}
    return {"class": type(base).__name__, "name": base.name, **params}


@dataclass
class TabulatedFilm:
    """Quasi-static film from a precomputed, disk-cached squeeze-force map.

    base : FilmModel  Model solved at the table nodes (any film model).
    n_eps : int  Eccentricity nodes, uniform in s = −ln(1 − ε) from 0 to eccentricity_max [-].
    n_direction : int  Squeeze-velocity directions over 360° (even) [-].
    eccentricity_max : float  Last eccentricity node; beyond it values are extrapolated [-].
    cache_dir : path or None  Table folder (None: ``~/.cache/conrod/tables``).
    use_cache : bool  Read/write the disk cache.
    """

    base: FilmModel
    n_eps: int = 28
    n_direction: int = 48
    eccentricity_max: float = 0.995
    cache_dir: str | Path | None = None
    use_cache: bool = True
    name: str = "table"
    build_seconds: float = field(default=0.0, init=False)
    loaded_from_cache: bool = field(default=False, init=False)

    def __post_init__(self) -> None:
        if not isinstance(self.base, FilmModel):
            raise CaseError(f"TabulatedFilm: base = {type(self.base).__name__}: a film model "
                            "is required (e.g. ReynoldsFilm(geometry))")
        self.geometry = self.base.geometry
        check_tabulable(self.geometry)
        if getattr(self.base, "pressure_viscosity", None) is not None:
            raise CaseError("table film over a piezoviscous base: not allowed (the table "
                            "assumes force ∝ μω); use the base film directly")
        if not all(isinstance(n, int) and not isinstance(n, bool)
                   for n in (self.n_eps, self.n_direction)) or (
                self.n_eps < 3 or self.n_direction < 8 or self.n_direction % 2):
            raise CaseError(f"table grid n_eps = {self.n_eps}, n_direction = {self.n_direction}: "
                            "allowed n_eps >= 3, n_direction even >= 8")
        if not (isinstance(self.eccentricity_max, float) and 0.0 < self.eccentricity_max < 1.0):
            raise CaseError(f"eccentricity_max = {self.eccentricity_max}: allowed (0, 1) [-]")
        g = self.geometry
        self.s_step = stretched(self.eccentricity_max) / (self.n_eps - 1)
        self.force_scale = g.radius**3 * g.width / g.radial_clearance**3
        self.tables = self._load_or_build()

    @classmethod
    def from_settings(cls, geometry: BearingGeometry, settings: Any) -> TabulatedFilm:
        """Table of a Reynolds film on the ``[solver]`` grid (``n_theta``, ``n_z``,
        ``film_tolerance``)."""
        from conrod.film.reynolds.film import ReynoldsFilm

        return cls(ReynoldsFilm.from_settings(geometry, settings))

    # ------------------------------------------------------------------ cache
    def cache_key(self) -> str:
        """SHA-256 of geometry, base model and table grid."""
        payload = {
            "format": TABLE_FORMAT, "geometry": {k: v for k, v in dataclasses.asdict(
                self.geometry).items() if k != "profile"},  # refused, not in the key
            "base": base_description(self.base),
            "grid": [self.n_eps, self.n_direction, self.eccentricity_max, CLUSTERING],
        }
        text = json.dumps(payload, sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()

    def cache_path(self) -> Path:
        """Where this table is stored."""
        folder = Path(self.cache_dir) if self.cache_dir is not None else DEFAULT_CACHE_DIR
        return folder.expanduser() / f"{self.cache_key()}.npz"

    def _load_or_build(self) -> dict[str, np.ndarray]:
        if not self.use_cache:
            return self._build()
        key = self.cache_key()
        if key in KEPT_IN_MEMORY:  # built earlier in this process; its folder is unusable
            return KEPT_IN_MEMORY[key]
        try:
            path = self.cache_path()
            tables = (read_cached_tables(path, (self.n_eps, self.n_direction))
                      if path.exists() else None)
        except (OSError, RuntimeError) as error:  # RuntimeError: no home folder
            warn_cache_unusable(self.cache_dir, error)
            return KEPT_IN_MEMORY.setdefault(key, self._build())
        if tables is not None:
            self.loaded_from_cache = True
            return tables
        tables = self._build()
        save: Any = np.savez  # numpy's stub types the keyword arrays as allow_pickle
        try:
            with atomic_path(path) as tmp:
                save(tmp, checksum=np.frombuffer(tables_checksum(tables), dtype=np.uint8),
                     **tables)
        except OSError as error:
            warn_cache_unusable(self.cache_dir, error)
            KEPT_IN_MEMORY[key] = tables
        return tables

    def _build(self) -> dict[str, np.ndarray]:
        start = time.perf_counter()
        tables = build_squeeze_tables(self.base, self.eccentricities(), self.directions())
        self.build_seconds = time.perf_counter() - start
        return tables

    def directions(self) -> np.ndarray:
        """Squeeze-velocity directions β_k = β(u_k), u_k = −π + 2πk/n [rad] (clustered)."""
        uniform = -math.pi + 2.0 * math.pi * np.arange(self.n_direction) / self.n_direction
        return np.array([direction_of(u) for u in uniform])

    def eccentricities(self) -> np.ndarray:
        """Eccentricity nodes ε_j = 1 − exp(−j Δs) [-]."""
        return 1.0 - np.exp(-self.s_step * np.arange(self.n_eps))

    # ------------------------------------------------------------- interface
    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """Grid of the base model (no pressure field is tabulated)."""
        return self.base.grid()

    def initial_history(self) -> None:
        """Tables are memoryless."""
        return None

    def compiled_kernel(self) -> CompiledKernel:
        """Interpolated force and the table's exact massless inverse."""
        t = self.tables
        params = (self.force_scale, self.geometry.radial_clearance, self.s_step,
                  t["log_magnitude"], t["turning"])
        return CompiledKernel(kernel_force, params, self._quasi_static_cycle)

    def _quasi_static_cycle(self, r: QuasiStaticRequest) -> Any:
        from conrod.film.massless import table_cycle

        t = self.tables
        return table_cycle(
            r.x, r.y, r.dt, r.load_x, r.load_y, r.journal_speed, r.shell_speed,
            r.record_every, r.viscosity, self.force_scale, self.geometry.radial_clearance,
            self.s_step, t["log_magnitude"], t["turning"], r.contact_radius)

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N]."""
        refuse_deformation(state, self.name)
        return table_force(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed + state.shell_speed, state.viscosity, self.force_scale,
            self.geometry.radial_clearance, self.s_step,
            self.tables["log_magnitude"], self.tables["turning"],
)

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Interpolated characteristics (no pressure field: ``with_pressure`` is ignored)."""
        refuse_deformation(state, self.name)
        g = self.geometry
        c = g.radial_clearance
        eps, cos_psi, sin_psi, v_r, v_t = squeeze_velocity(
            state.eccentricity_x, state.eccentricity_y, state.velocity_x, state.velocity_y,
            state.journal_speed + state.shell_speed, c)
        if eps >= 1.0:
            raise self.beyond_range(eps, "the journal touches the shell")
        values = self._interpolate(eps, v_r, v_t)
        mu = state.viscosity
        if eps > self.eccentricity_max and not (values["max_pressure"] >= 0.0 and all(
                math.isfinite(value) for value in values.values())):
            raise self.beyond_range(eps, "the extrapolated film is not physical (p_max = "
                                    f"{mu * values['max_pressure']:.3g} Pa)")
        f_r, f_t = (mu * self.force_scale * values[k] for k in ("radial", "tangential"))
        eps_c = min(eps, 1.0 - 1e-9)
        couette = (2.0 * math.pi * mu * g.radius**3 * g.width
                   * (state.journal_speed - state.shell_speed) / (c * math.sqrt(1 - eps_c**2)))
        wedge = -0.5 * eps * c * f_t
        psi = math.atan2(sin_psi, cos_psi)
        peak_angle = psi + math.atan2(values["peak_sin"], values["peak_cos"])
        sliding = state.journal_speed - state.shell_speed
        return FilmResult(
            force_x=f_r * cos_psi - f_t * sin_psi, force_y=f_r * sin_psi + f_t * cos_psi,
            friction_torque_journal=wedge - couette, friction_torque_shell=wedge + couette,
            side_flow=values["side_flow"], supply_flow=values["supply_flow"],
            min_film_thickness=c * (1.0 - eps), min_film_angle=psi % (2.0 * math.pi),
            max_pressure=mu * values["max_pressure"],
            max_pressure_angle=peak_angle % (2.0 * math.pi),
            cavitated_fraction=min(max(values["cavitated"], 0.0), 1.0),
            friction_power=abs((wedge - couette) * sliding),
            extra={"eccentricity_ratio": eps},
)

    def beyond_range(self, eps: float, why: str) -> ConvergenceError:
        """The error of a state past the last eccentricity node (``why`` it is unusable)."""
        gap = self.geometry.radial_clearance * (1.0 - eps)
        return ConvergenceError(
            f"journal eccentricity ratio {eps:.6g} (h_min = {gap:.3g} m) is beyond the table's "
            f"eccentricity range (<= {self.eccentricity_max:g}), where {why}: the film of this "
            "table cannot carry the load there")

    def _interpolate(self, eps: float, v_r: float, v_t: float) -> dict[str, float]:
        """Dimensionless force (radial, tangential) × |v_s| and the other quantities."""
        speed = math.hypot(v_r, v_t)
        names = ("radial", "tangential", *QUANTITIES[2:])
        if speed == 0.0:
            return dict.fromkeys(names, 0.0) | {"peak_cos": 1.0}
        beta = math.atan2(v_t, v_r)
        t = self.tables
        f_r, f_t = unit_force(eps, beta, self.s_step, t["log_magnitude"], t["turning"])
        values = {q: interpolate(t[q], eps, beta, self.s_step) for q in QUANTITIES[2:]}
        for q in PER_SPEED:
            values[q] *= speed
        return values | {"radial": f_r * speed, "tangential": f_t * speed}

    # ------------------------------------------------------------- accuracy
    def interpolation_error(
        self, n_points: int = 24, *, eccentricity_max: float | None = None, seed: int = 0
) -> dict[str, float]:
        """Max and RMS of |F_table − F_base|/|F_base| at random off-grid states [-].

        States have random ε ∈ [0.02, eccentricity_max], squeeze direction, journal and
        shell speeds (so Booker's reduction is checked too); seeded, deterministic.
        """
        rng = np.random.default_rng(seed)
        c = self.geometry.radial_clearance
        top = self.eccentricity_max if eccentricity_max is None else eccentricity_max
        errors = []
        for _ in range(n_points):
            state = random_state(rng, c, top)
            fx, fy = self.force(state)
            bx, by = self.base.force(state)
            errors.append(math.hypot(fx - bx, fy - by) / math.hypot(bx, by))
        errors_arr = np.asarray(errors)
        return {"max_relative": float(errors_arr.max()),
                "rms_relative": float(np.sqrt(np.mean(errors_arr**2))), "n_points": n_points}


def tables_checksum(tables: dict[str, np.ndarray]) -> bytes:
    """SHA-256 over the names, shapes and bytes of the tabulated quantities."""
    digest = hashlib.sha256()
    for name in QUANTITIES:
        values = np.ascontiguousarray(tables[name], dtype=np.float64)
        digest.update(f"{name}{values.shape}".encode())
        digest.update(values.tobytes())
    return digest.digest()


def warn_cache_unusable(cache_dir: str | Path | None, error: BaseException) -> None:
    """A :class:`CacheWarning`, once per folder and process: the table cache folder cannot
    be used; the run goes on, its tables kept in memory (:data:`KEPT_IN_MEMORY`)."""
    folder = Path(cache_dir) if cache_dir is not None else DEFAULT_CACHE_DIR
    with contextlib.suppress(RuntimeError):
        folder = folder.expanduser()
    if str(folder) not in UNUSABLE_FOLDERS:
        UNUSABLE_FOLDERS.add(str(folder))
        reason = getattr(error, "strerror", None) or str(error) or type(error).__name__
        warnings.warn(f"film table cache folder {str(folder)!r} cannot be used ({reason}); "
                      "going on without it (tables built in this process are kept in memory)",
                      CacheWarning, stacklevel=4)


def read_cached_tables(path: Path, shape: tuple[int, int]) -> dict[str, np.ndarray] | None:
    """Tables stored at ``path`` if intact: readable, every quantity of ``shape``, finite,
    matching the stored checksum. Otherwise None, with a :class:`CacheWarning` (the caller
    rebuilds and overwrites the file). A file that cannot be opened raises ``OSError``
    (the folder cannot be used)."""
    with open(path, "rb") as handle:
        tables, reason = _intact_tables(handle, shape)
    if reason:
        warnings.warn(f"film table cache {str(path)!r} is corrupt ({reason}); rebuilding it",
                      CacheWarning, stacklevel=3)
        return None
    return tables


def _intact_tables(handle: Any, shape: tuple[int, int]) -> tuple[dict[str, np.ndarray], str]:
    """(tables, "") when the stored tables are intact, else ({}, what is wrong)."""
    try:
        with np.load(handle, allow_pickle=False) as stored:
            tables = {q: np.array(stored[q], dtype=np.float64) for q in QUANTITIES}
            checksum = bytes(np.asarray(stored["checksum"], dtype=np.uint8))
    except Exception as error:  # truncated, garbage, empty, old format: all mean rebuild
        return {}, f"unreadable ({type(error).__name__})"
    if any(values.shape != shape for values in tables.values()):
        return {}, "wrong table shape"
    if not all(np.all(np.isfinite(values)) for values in tables.values()):
        return {}, "non-finite values"
    if checksum != tables_checksum(tables):
        return {}, "checksum mismatch"
    return tables, ""


def random_state(rng: np.random.Generator, clearance: float, eps_max: float) -> FilmState:
    """Random off-grid state: ε, line-of-centres angle, squeeze velocity, speeds."""
    eps = rng.uniform(0.02, eps_max)
    psi, beta = rng.uniform(-math.pi, math.pi, size=2)
    omega_j, omega_b = rng.uniform(-200.0, 200.0, size=2)
    speed = clearance * rng.uniform(10.0, 200.0)
    ex, ey = eps * clearance * math.cos(psi), eps * clearance * math.sin(psi)
    mean = 0.5 * (omega_j + omega_b)
    vx = speed * math.cos(psi + beta) - mean * ey
    vy = speed * math.sin(psi + beta) + mean * ex
    return FilmState(eccentricity_x=ex, eccentricity_y=ey, velocity_x=vx, velocity_y=vy,
                     journal_speed=omega_j, shell_speed=omega_b, viscosity=0.02)


def build_squeeze_tables(
    base: FilmModel, eccentricities: np.ndarray, directions: np.ndarray
) -> dict[str, np.ndarray]:
    """Solve ``base`` at every (ε_j, β_k) squeeze node; tables of shape (n_eps, n_direction).

    ``directions`` are symmetric, β_{n−k} = −β_k, from β_0 = −π. Only β ∈ [0, π] is solved:
    the mirror image about the line of centres gives |f̄|(−β) = |f̄|(β), A(−β) = −A(β).
    """
    c = base.geometry.radial_clearance
    speed = c * REFERENCE_RATE
    scale = REFERENCE_VISCOSITY * speed
    force_scale = base.geometry.radius**3 * base.geometry.width / c**3
    n_direction = directions.size
    tables = {q: np.zeros((eccentricities.size, n_direction)) for q in QUANTITIES}
    mirror = {"turning", "peak_sin"}
    memory = film_memory(base)  # warm start carried from node to node
    for j, eps in enumerate(eccentricities):
        for k in range(n_direction // 2, n_direction + 1):
            beta = math.pi if k == n_direction else float(directions[k])
            state = FilmState(eccentricity_x=eps * c, eccentricity_y=0.0,
                              velocity_x=speed * math.cos(beta), velocity_y=speed * math.sin(beta),
                              viscosity=REFERENCE_VISCOSITY)
            if isinstance(base, HasMemory):
                result, memory = base.solve_with_memory(state, memory)
            else:
                result = base.solve(state)
            row = _table_row(result, beta, eps, scale * force_scale, speed, scale)
            for q, value in row.items():
                tables[q][j, k % n_direction] = value
                tables[q][j, (n_direction - k) % n_direction] = -value if q in mirror else value
    return tables


def _table_row(r: FilmResult, beta: float, eps: float, force_unit: float, speed: float,
               pressure_unit: float) -> dict[str, float]:
    """Tabulated quantities of one base solution."""
    magnitude = math.hypot(r.force_x, r.force_y) / force_unit
    turning = math.atan2(r.force_y, r.force_x) - beta - math.pi
    return {
        "log_magnitude": math.log(magnitude) + WEIGHT_POWER * math.log(1.0 - eps * eps),
        "turning": (turning + math.pi) % (2.0 * math.pi) - math.pi,
        "side_flow": r.side_flow / speed, "supply_flow": r.supply_flow / speed,
        "max_pressure": r.max_pressure / pressure_unit,
        "peak_cos": math.cos(r.max_pressure_angle), "peak_sin": math.sin(r.max_pressure_angle),
        "cavitated": r.cavitated_fraction,
    }
