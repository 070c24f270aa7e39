"""The one interface every oil-film model implements.

Frame and signs (see ``docs/conventions.md``)
----------------------------------------------
All quantities are given in one *film frame* with axes x, y in the bearing mid-plane:

* ``eccentricity_x, eccentricity_y`` [m]: position of the **journal centre relative to the
  shell (bearing) centre**;  ``velocity_x, velocity_y`` [m/s]: its rate of change, both
  as components in the film frame.
* ``journal_speed`` ω_j and ``shell_speed`` ω_b [rad/s]: angular velocities of the journal
  and of the shell surface *relative to the film frame*, positive from +x towards +y.
  In a frame fixed to the shell (the connecting rod for a big end), ω_b = 0 and
  ω_j = ω_crank − dβ/dt.
* θ [rad] is measured on the shell from +x towards +y; z [m] is axial, 0 at mid-width.
* Film thickness of the rigid bearing, the journal's tilt γ_x, γ_y [rad] about the x and y
  axes (right-handed, z along the bearing axis; the journal axis at z passes through
  (e_x + z γ_y, e_y − z γ_x)), the bore/shell profile h₀(θ, z) of the geometry
  (:mod:`conrod.film.profile`, fixed in the film frame) and an additive field δ(θ, z) [m]:

  .. math:: h(θ, z) = c - (e_x + z γ_y) \\cos θ - (e_y - z γ_x) \\sin θ + h_0(θ, z) + δ(θ, z)

  (docs/conventions.md, "Journal tilt"); the tilt rates γ̇_x, γ̇_y enter ∂h/∂t.

* Reynolds equation solved by every model (incompressible, isoviscous):

  .. math:: \\frac{1}{R^2}\\partial_θ(h^3 \\partial_θ p) + \\partial_z(h^3 \\partial_z p)
            = 6 μ (ω_j + ω_b) \\partial_θ h + 12 μ \\partial_t h

  so ω_j = −ω_b with a stationary centre gives no wedge action (Booker).
* ``force_x, force_y`` [N]: force of the film **on the journal**. A journal carrying an
  external load W is in equilibrium when F + W = 0.
* ``moment_x, moment_y`` [N m]: moment of the film pressure on the journal about the x and
  y axes through the bearing centre (mid-width), M = ∫∫ r × (−p n) dA, i.e.
  M_x = ∫∫ p z sin θ dA, M_y = −∫∫ p z cos θ dA: the generalised forces of the tilt angles
  (virtual work M_x δγ_x + M_y δγ_y).
* ``friction_torque_journal`` / ``friction_torque_shell`` [N m]: moments of the film
  shear on each surface about its centre, positive from +x towards +y.
* Pressures are gauge [Pa] relative to the ambient pressure at the bearing edges.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Protocol, runtime_checkable

import numpy as np

from conrod.errors import CaseError

GEOMETRY_LIMITS = {"diameter": (1.0e-3, 20.0), "length_to_diameter": (1.0e-3, 20.0),
                   "clearance_to_radius": (1.0e-6, 0.1)}
"""Ranges a :class:`BearingGeometry` is checked against: journal diameter [m], width as a
multiple of it [-], radial clearance as a multiple of the journal radius [-]."""
MAX_FILM_VISCOSITY = 1.0e6
"""Largest viscosity a :class:`FilmState` accepts [Pa s] (bitumen; oils are below 10)."""
MAX_TILT = 0.1
"""Largest tilt angle a :class:`FilmState` accepts [rad]: far beyond any bearing (a tilt
of c/(L/2) ≈ 1e-3 rad closes the film at the edge); larger is an input error."""


@dataclass(frozen=True)
class Groove:
    """Circumferential oil groove in the shell (full when ``extent`` = 2π).

    start_angle : float  Angle θ where the groove starts [rad].
    extent : float  Angular extent, 2π for a full groove [rad].
    width : float  Axial width [m].
    axial_position : float  Axial position of the groove centre, 0 = mid-width [m].
    fed_by_journal_holes : bool  The groove is fed by the journal's oil holes (the common
        half groove): held at the pressure of a journal hole while one opens into it, at
        the supply pressure otherwise; False: always at the supply pressure.
    """

    start_angle: float = 0.0
    extent: float = 2.0 * np.pi
    width: float = 0.0
    axial_position: float = 0.0
    fed_by_journal_holes: bool = False


@dataclass(frozen=True)
class FeedHole:
    """Circular oil-feed hole in the shell.

    angle : float  Angle θ of the hole centre [rad].
    diameter : float  Hole diameter [m].
    axial_position : float  Axial position of the hole centre, 0 = mid-width [m].
    """

    angle: float
    diameter: float
    axial_position: float = 0.0


@dataclass(frozen=True)
class JournalHole:
    """Oil hole drilled in the journal (crank pin): it turns with the journal, so it sweeps
    the shell at the relative speed ω_j − ω_b (docs/conventions.md, "Oil holes").

    angle : float  Angle of the hole centre on the journal [rad], from the journal's
        reference direction (for a crank pin the outward crank radius) towards the
        direction of rotation; its shell angle is θ = angle + ``JournalFeed.journal_angle``.
    diameter : float  Hole diameter at the journal surface [m].
    axial_position : float  Axial position of the hole centre, 0 = mid-width [m].
    """

    angle: float
    diameter: float
    axial_position: float = 0.0


@dataclass(frozen=True)
class JournalFeed:
    """Where the journal's oil holes are and what they deliver at one instant.

    journal_angle : float  Angle θ of the journal's reference direction in the film frame
        [rad] (a crank pin: φ + β, the crank angle plus the rod obliquity).
    pressures : tuple  Gauge pressure at the mouth of each journal hole [Pa], one per
        :attr:`BearingGeometry.journal_holes` (gallery pressure plus centrifugal head less
        losses, :mod:`conrod.loads.oil_feed`).
    """

    journal_angle: float
    pressures: tuple[float, ...]

    def __post_init__(self) -> None:
        """Finite angle; finite pressures ≥ 0 [Pa] (gauge: ambient at the bearing edges)."""
        if not (_is_number(self.journal_angle) and math.isfinite(self.journal_angle)):
            raise CaseError(f"JournalFeed journal_angle = {self.journal_angle!r}: out of range "
                            "(allowed: a finite number of rad)")
        for k, value in enumerate(self.pressures):
            check_range("JournalFeed", f"pressures[{k}]", value, 0.0, 1.0e9, "Pa")


def check_journal_hole(owner: str, hole: JournalHole, diameter: float, width: float) -> None:
    """:class:`CaseError` unless ``hole`` fits a journal of ``diameter`` [m] in a bearing of
    ``width`` [m]: smaller than the width (a land on both sides), inside it, and smaller
    than half the journal circumference."""
    if not (_is_number(hole.angle) and math.isfinite(hole.angle)):
        raise CaseError(f"{owner} angle = {hole.angle!r}: out of range (allowed: a finite "
                        "number of rad)")
    largest = min(width, 0.5 * math.pi * diameter)
    if not (_is_number(hole.diameter) and 0.0 < hole.diameter < largest):
        raise CaseError(f"{owner} diameter = {hole.diameter!r}: out of range (allowed: > 0 "
                        f"and < {largest:g} m, the smaller of the bearing width and half the "
                        "journal circumference)")
    reach = 0.5 * (width - hole.diameter)
    check_range(owner, "axial_position", hole.axial_position, -reach, reach,
                f"m, the hole of {hole.diameter:g} m inside the bearing width {width:g} m")


def check_viscosity_field(values: Any, shape: tuple[int, int] | None = None) -> None:
    """:class:`CaseError` unless ``values`` is a 2-D array of finite viscosities in
    (0, :data:`MAX_FILM_VISCOSITY`] [Pa s], of ``shape`` when given (the film grid)."""
    array = np.asarray(values)
    if array.ndim != 2 or (shape is not None and array.shape != tuple(shape)):
        wanted = "2-D" if shape is None else f"{tuple(shape)} = (n_theta, n_z + 1)"
        raise CaseError(f"FilmState viscosity_field shape = {array.shape}: out of range "
                        f"(allowed: {wanted})")
    if not (np.all(np.isfinite(array)) and array.min() > 0.0
            and array.max() <= MAX_FILM_VISCOSITY):
        raise CaseError(f"FilmState viscosity_field = [{array.min():g}, {array.max():g}]: out "
                        f"of range (allowed: > 0 and <= {MAX_FILM_VISCOSITY:g} Pa s)")


def check_range(owner: str, name: str, value: Any, low: float, high: float, unit: str, *,
                low_open: bool = False) -> None:
    """:class:`CaseError` naming ``owner.name``, the value, the range and the unit unless
    ``value`` is a real number in [``low``, ``high``] (``low`` excluded with ``low_open``)."""
    lower = f"> {low:g}" if low_open else f">= {low:g}"
    allowed = f"(allowed: {lower} and <= {high:g} {unit})"
    if not _is_number(value):
        raise CaseError(f"{owner} {name} = {value!r}: a number is required {allowed}")
    above_low = value > low if low_open else value >= low
    if not (above_low and value <= high):
        raise CaseError(f"{owner} {name} = {value!r}: out of range {allowed}")


def _is_number(value: Any) -> bool:
    """A real number (not a bool)."""
    return not isinstance(value, bool) and isinstance(value, int | float | np.integer | np.floating)


def _refuse_positional(cls: type, args: tuple, why: str, example: str) -> None:
    """TypeError naming the keywords when a constructor of lengths gets positional values."""
    if args:
        raise TypeError(f"{cls.__name__} takes keyword arguments only, got {len(args)} "
                        f"positional ({why}): e.g. {cls.__name__}({example})")


@dataclass(frozen=True, kw_only=True)
class BearingGeometry:
    """Journal-bearing geometry and oil supply, SI units.

    Keyword arguments only: diameter, width and clearance are all lengths in metres, and a
    positional call would hide which is which (``BearingGeometry(diameter=0.05,
    width=0.025, radial_clearance=25e-6)``).

    diameter : float  Journal diameter D [m].
    width : float  Axial length L of the film (shell width) [m].
    radial_clearance : float  Radial clearance c [m].
    grooves : tuple  Circumferential grooves held at ``supply_pressure``.
    feed_holes : tuple  Feed holes held at ``supply_pressure``.
    journal_holes : tuple  Oil holes in the journal (:class:`JournalHole`): they turn with
        it, where and at what pressure at each instant is ``FilmState.journal_feed``.
    supply_pressure : float  Gauge supply pressure [Pa].
    cavitation_pressure : float  Gauge cavitation pressure [Pa] (≤ 0 ≤ supply).
    profile : BoreProfile or None  Bore/shell profile h₀(θ, z) added to the film thickness,
        fixed in the film (bearing) frame (:class:`conrod.film.profile.BoreProfile`);
        None: a cylindrical bore. Only the grid films honour it.
    """

    diameter: float
    width: float
    radial_clearance: float
    grooves: tuple[Groove, ...] = ()
    feed_holes: tuple[FeedHole, ...] = ()
    journal_holes: tuple[JournalHole, ...] = ()
    supply_pressure: float = 0.0
    cavitation_pressure: float = 0.0
    profile: Any = None

    def __new__(cls, *args: object, **kwargs: object) -> BearingGeometry:
        _refuse_positional(cls, args, "diameter, width and clearance are all in metres",
                           "diameter=0.05, width=0.025, radial_clearance=25e-6")
        return super().__new__(cls)

    def __post_init__(self) -> None:
        """Lengths within physical ranges (:data:`GEOMETRY_LIMITS`), pressures finite with
        cavitation ≤ 0 ≤ supply."""
        owner = "BearingGeometry"
        check_range(owner, "diameter", self.diameter, *GEOMETRY_LIMITS["diameter"], "m")
        low, high = GEOMETRY_LIMITS["length_to_diameter"]
        check_range(owner, "width", self.width, low * self.diameter, high * self.diameter,
                    f"m, i.e. {low:g} to {high:g} x diameter")
        low, high = GEOMETRY_LIMITS["clearance_to_radius"]
        check_range(owner, "radial_clearance", self.radial_clearance, low * self.radius,
                    high * self.radius, f"m, i.e. {low:g} to {high:g} x journal radius")
        check_range(owner, "supply_pressure", self.supply_pressure, 0.0, 1.0e9, "Pa")
        cavitation = self.cavitation_pressure
        if not (_is_number(cavitation) and math.isfinite(cavitation) and cavitation <= 0.0):
            raise CaseError(f"{owner} cavitation_pressure = {cavitation!r}: out of range "
                            "(allowed: finite and <= 0 Pa; very negative: no cavitation)")
        for name, kind in (("grooves", Groove), ("feed_holes", FeedHole),
                           ("journal_holes", JournalHole)):
            items = getattr(self, name)
            if not isinstance(items, tuple) or not all(isinstance(i, kind) for i in items):
                raise CaseError(f"{owner} {name} = {items!r}: a tuple of {kind.__name__} is "
                                "required")
        for k, hole in enumerate(self.journal_holes):
            check_journal_hole(f"{owner} journal_holes[{k}]", hole, self.diameter, self.width)
        if self.profile is not None and not callable(getattr(self.profile, "field", None)):
            raise CaseError(f"{owner} profile = {self.profile!r}: a BoreProfile "
                            "(conrod.film.profile) or None is required")

    @property
    def radius(self) -> float:
        """Journal radius R = D/2 [m]."""
        return 0.5 * self.diameter

    @property
    def length_to_diameter(self) -> float:
        """Slenderness L/D [-]."""
        return self.width / self.diameter


@dataclass(frozen=True, kw_only=True)
class FilmState:
    """Kinematic state handed to a film model (see the module docstring for the frame).

    Keyword arguments only: eccentricities are lengths in metres, not ratios to the
    clearance, and a positional call would hide that (``FilmState(eccentricity_x=15e-6,
    eccentricity_y=0.0, journal_speed=300.0, viscosity=0.01)``).

    eccentricity_x, eccentricity_y : float  Journal centre relative to shell centre [m].
    velocity_x, velocity_y : float  Rate of the above [m/s].
    journal_speed, shell_speed : float  Surface angular velocities ω_j, ω_b [rad/s].
    viscosity : float  Dynamic viscosity μ [Pa s].
    deformation : ndarray or None  Additive film-thickness field δ(θ, z) [m] on the
        model's grid (:meth:`FilmModel.grid`), None for a rigid bearing.
    history : ndarray or None  Internal film history carried by the integrator
        (e.g. film content of a mass-conserving model) [-]; None for memoryless models.
    tilt_x, tilt_y : float  Journal tilt γ_x, γ_y about the film's x and y axes [rad]
        (module docstring); 0: aligned.
    tilt_rate_x, tilt_rate_y : float  Their rates γ̇_x, γ̇_y [rad/s] (squeeze term).
    journal_feed : JournalFeed or None  Position and pressures of the journal's oil holes
        at this instant (required when the geometry has journal holes); None: none.
    viscosity_field : ndarray or None  Viscosity μ(θ, z) [Pa s] on the model's grid (a
        film temperature field, :mod:`conrod.film.thermal`), for films that declare
        :class:`~conrod.film.capabilities.HasViscosityField`; ``viscosity`` is then the
        reference viscosity of the source terms. None: μ = ``viscosity`` everywhere.
    """

    eccentricity_x: float
    eccentricity_y: float
    velocity_x: float = 0.0
    velocity_y: float = 0.0
    journal_speed: float = 0.0
    shell_speed: float = 0.0
    viscosity: float = 0.01
    deformation: np.ndarray | None = None
    history: np.ndarray | None = None
    tilt_x: float = 0.0
    tilt_y: float = 0.0
    tilt_rate_x: float = 0.0
    tilt_rate_y: float = 0.0
    journal_feed: JournalFeed | None = None
    viscosity_field: np.ndarray | None = None

    def __new__(cls, *args: object, **kwargs: object) -> FilmState:
        _refuse_positional(cls, args, "eccentricities are in metres, not ratios to the "
                           "clearance", "eccentricity_x=15e-6, eccentricity_y=0.0, "
                           "velocity_x=0.0, velocity_y=0.0, journal_speed=300.0, viscosity=0.01")
        return super().__new__(cls)

    def __post_init__(self) -> None:
        """A viscosity every film can use: finite and > 0 [Pa s]; finite tilt angles
        (|γ| ≤ 0.1 rad) and rates."""
        viscosity = self.viscosity
        if not (isinstance(viscosity, float) and 0.0 < viscosity < math.inf):  # the fast path
            check_range("FilmState", "viscosity", viscosity, 0.0, MAX_FILM_VISCOSITY, "Pa s",
                        low_open=True)
        if self.tilt_x or self.tilt_y or self.tilt_rate_x or self.tilt_rate_y:
            for name in ("tilt_x", "tilt_y"):
                check_range("FilmState", name, getattr(self, name), -MAX_TILT, MAX_TILT, "rad")
            for name in ("tilt_rate_x", "tilt_rate_y"):
                rate = getattr(self, name)
                if not (_is_number(rate) and math.isfinite(rate)):
                    raise CaseError(f"FilmState {name} = {rate!r}: out of range (allowed: "
                                    "a finite number of rad/s)")
        if self.viscosity_field is not None:
            check_viscosity_field(self.viscosity_field)

    @property
    def tilted(self) -> bool:
        """True when the journal is tilted or tilting (any tilt angle or rate ≠ 0) [-]."""
        return bool(self.tilt_x or self.tilt_y or self.tilt_rate_x or self.tilt_rate_y)


@dataclass
class FilmResult:
    """Everything a film model returns for one state (units in brackets)."""

    force_x: float
    """Film force on the journal, x component [N]."""
    force_y: float
    """Film force on the journal, y component [N]."""
    friction_torque_journal: float
    """Shear moment of the film on the journal [N m]."""
    friction_torque_shell: float
    """Shear moment of the film on the shell [N m]."""
    side_flow: float
    """Oil leaving through both bearing edges [m^3/s]."""
    supply_flow: float
    """Oil entering through grooves and holes [m^3/s]."""
    min_film_thickness: float
    """Minimum film thickness h_min [m]."""
    min_film_angle: float
    """Shell angle θ of h_min [rad]."""
    max_pressure: float
    """Maximum gauge film pressure p_max [Pa]."""
    max_pressure_angle: float
    """Shell angle θ of p_max [rad]."""
    cavitated_fraction: float
    """Share of the film area that is cavitated [-]."""
    friction_power: float = 0.0
    """Power dissipated in the film [W]."""
    moment_x: float = 0.0
    """Moment of the film pressure on the journal about the x axis through the bearing
    centre [N m] (module docstring; 0 for a film uniform along the width)."""
    moment_y: float = 0.0
    """Moment of the film pressure on the journal about the y axis [N m]."""
    min_film_axial_position: float = 0.0
    """Axial position z of h_min [m]: the middle of the axial nodes within round-off of
    the smallest value in its θ column (0 for a film uniform along the width)."""
    edge_min_film_thickness: float | None = None
    """Smallest film thickness on the two edges z = ±L/2 [m] (None: equal to
    ``min_film_thickness``, a film uniform along the width)."""
    pressure: np.ndarray | None = None
    """Pressure field p(θ, z) on :meth:`FilmModel.grid` [Pa], when requested."""
    history_rate: np.ndarray | None = None
    """Time derivative of ``FilmState.history`` [1/s], for models with memory."""
    extra: dict[str, float] = field(default_factory=dict)
    """Model-specific diagnostics (iterations, residual, ...), units in the key names."""


@runtime_checkable
class FilmModel(Protocol):
    """What the orbit solver may assume about a film model — and nothing more."""

    @property
    def name(self) -> str:
        """Short identifier: 'short', 'reynolds', 'mass_conserving', 'mobility', 'table'."""
        ...

    @property
    def geometry(self) -> BearingGeometry:
        """Bearing geometry and oil supply."""
        ...

    def solve(self, state: FilmState, *, with_pressure: bool = False) -> FilmResult:
        """Full result for one state."""
        ...

    def force(self, state: FilmState) -> tuple[float, float]:
        """Film force on the journal (F_x, F_y) [N] — the fast path of the orbit."""
        ...

    def grid(self) -> tuple[np.ndarray, np.ndarray]:
        """Nodes θ [rad] and z [m] of the pressure/deformation field."""
        ...

    def initial_history(self) -> np.ndarray | None:
        """Initial film history for models with memory; None when memoryless."""
        ...


def film_thickness(
    geometry: BearingGeometry,
    eccentricity_x: float,
    eccentricity_y: float,
    theta: np.ndarray,
    deformation: np.ndarray | None = None,
) -> np.ndarray:
    """Film thickness h(θ[, z]) = c − e_x cos θ − e_y sin θ + δ [m].

    ``theta`` [rad] is 1-D; with ``deformation`` of shape (n_theta, n_z) the result
    has that shape, otherwise it is 1-D.
    """
    rigid = (
        geometry.radial_clearance
        - eccentricity_x * np.cos(theta)
        - eccentricity_y * np.sin(theta)
)
    if deformation is None:
        return rigid
    return rigid[:, None] + deformation
