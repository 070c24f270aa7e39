"""Contact geometry and contact law of a worn (elliptical) rod-bearing shell ([D3]).

A worn shell is an ellipse with semi-axes

.. math::

    a = (D + Δ_{max})/2, \\quad b = (D + Δ_{min})/2, \\quad e^2 = 1 - b^2/a^2,

its major axis at the angle γ to the rod axis. The radius from the shell centre to
the shell surface in the direction ϕ measured from the major axis is

.. math::

    p(ϕ) = \\frac{b}{\\sqrt{1 - e^2 \\cos^2 ϕ}}

([D3] prints ``b / (√(1 − cos²ϕ)·ε²)``, misplacing the root; corrected here:
p(0) = a, p(π/2) = b). With the shell centre displaced by ``r`` from the journal
centre in the direction ϕ, [D3]'s penetration along that ray is

.. math::

    δ = (r + D/2) - p(ϕ),

and the normal contact force, zero for δ ≤ 0, is ([D3], reaction R₁₂/R₃₂)

.. math::

    R = c δ^α + β \\dot δ, \\qquad β = 2 μ \\sqrt{c\\, m_{eff}} .

the printed [D3] multiplies β by ṙ; here the penetration rate δ̇ = ṙ − ṗ is used
(identical for circular shells, where ṗ = 0). A damping term that would pull the
surfaces together (R < 0 while separating) is clipped to R = 0.

All functions are numba kernels usable on scalars; SI units.
"""

from __future__ import annotations

import math

from numba import njit


def shell_semi_axes(diameter: float, clearance_max: float, clearance_min: float) -> tuple:
    """Semi-axes ``(a, b)`` [m] and squared eccentricity ``e²`` [-] of a worn shell.

    diameter : float  Journal (or pin) diameter D [m].
    clearance_max, clearance_min : float  Diametral clearances Δmax ≥ Δmin [m].
    """
    major = 0.5 * (diameter + clearance_max)
    minor = 0.5 * (diameter + clearance_min)
    return major, minor, 1.0 - (minor / major) ** 2


@njit(cache=True)
def shell_radius(angle: float, minor: float, eccentricity_sq: float) -> float:
    """Ellipse radius p(ϕ) = b/√(1 − e² cos²ϕ) [m]; ``angle`` ϕ from the major axis [rad]."""
    cosine = math.cos(angle)
    return minor / math.sqrt(1.0 - eccentricity_sq * cosine * cosine)


@njit(cache=True)
def shell_radius_slope(angle: float, minor: float, eccentricity_sq: float) -> float:
    """dp/dϕ = −b e² sinϕ cosϕ / (1 − e² cos²ϕ)^{3/2} [m/rad]."""
    cosine = math.cos(angle)
    denominator = 1.0 - eccentricity_sq * cosine * cosine
    numerator = -minor * eccentricity_sq * math.sin(angle) * cosine
    return numerator / (denominator * math.sqrt(denominator))


@njit(cache=True)
def penetration(
    dx: float, dy: float, rod_angle: float, diameter: float,
    minor: float, eccentricity_sq: float, ellipse_angle: float,
) -> float:
    """Penetration δ = (r + D/2) − p(ϕ) [m] of a journal in a worn shell (> 0: contact).

    dx, dy : float  Shell centre minus journal centre, engine frame [m].
    rod_angle : float  Rod angle φ₂ in the engine frame [rad].
    ellipse_angle : float  Major axis to rod axis γ [rad].
    The direction in the shell frame is ϕ = atan2(dy, dx) − γ − φ₂ ([D3]).
    """
    radius = math.sqrt(dx * dx + dy * dy)
    angle = math.atan2(dy, dx) - ellipse_angle - rod_angle
    return radius + 0.5 * diameter - shell_radius(angle, minor, eccentricity_sq)


@njit(cache=True)
def penetration_rate(
    dx: float, dy: float, vx: float, vy: float, rod_angle: float, rod_rate: float,
    minor: float, eccentricity_sq: float, ellipse_angle: float,
) -> tuple:
    """Radial rate ṙ and penetration rate δ̇ = ṙ − p'(ϕ)·ϕ̇ (same time unit as vx, vy).

    vx, vy : float  Rates of dx, dy; rod_rate : float  rate of φ₂ (consistent units).
    ϕ̇ = (dx·vy − vx·dy)/r² − φ̇₂ ([D3], derivative of p₁, p₂).
    """
    radius_sq = dx * dx + dy * dy + 1.0e-50
    radius = math.sqrt(radius_sq)
    radial_rate = (dx * vx + dy * vy) / radius
    angle = math.atan2(dy, dx) - ellipse_angle - rod_angle
    angle_rate = (dx * vy - vx * dy) / radius_sq - rod_rate
    slope = shell_radius_slope(angle, minor, eccentricity_sq)
    return radial_rate, radial_rate - slope * angle_rate


@njit(cache=True)
def contact_force(depth: float, depth_rate: float, stiffness: float, exponent: float,
                  damping: float) -> tuple:
    """Normal force R = c δ^α + β δ̇ (≥ 0) and its elastic part c δ^α [N]; 0 if δ ≤ 0."""
    if depth <= 0.0:
        return 0.0, 0.0
    elastic = stiffness * depth**exponent
    return max(elastic + damping * depth_rate, 0.0), elastic


def seed_free_play_is_convex(diameter: float, clearance_max: float, clearance_min: float,
                             samples: int = 3600) -> bool:
    """True when the seed geometry's free-play region r(ϕ) ≤ p(ϕ) − D/2 is convex.

    A region bounded by the polar curve r(ϕ) is convex iff r² + 2r'² − r r'' ≥ 0 for every
    ϕ (its curvature keeps its sign). With p(ϕ) of a worn shell and D comparable to the
    shell, the subtraction of D/2 dents the region along the minor axis once Δmin falls
    well below Δmax (about Δmin < 2/3 Δmax for engine joints); the seed's radial
    penetration is then not a distance and impacts along the dent are spurious. Exact
    geometry (:func:`exact_contact`) has a convex region for every ellipse.
    """
    import numpy as np

    major, minor, eccentricity_sq = shell_semi_axes(diameter, clearance_max, clearance_min)
    angle = np.linspace(0.0, 2.0 * math.pi, samples, endpoint=False)
    cosine, sine = np.cos(angle), np.sin(angle)
    q = 1.0 - eccentricity_sq * cosine**2
    p = minor / np.sqrt(q)
    dq = 2.0 * eccentricity_sq * cosine * sine
    d2q = 2.0 * eccentricity_sq * (cosine**2 - sine**2)
    slope = -0.5 * minor * q**-1.5 * dq
    curvature = minor * (0.75 * q**-2.5 * dq**2 - 0.5 * q**-1.5 * d2q)
    radius = p - 0.5 * diameter
    measure = radius**2 + 2.0 * slope**2 - radius * curvature
    return bool(np.all(measure >= -1e-12 * major**2))


def damping_coefficient(damping_factor: float, stiffness: float, effective_mass: float) -> float:
    """[D3] damping β = 2 μ √(c m_eff) [N s/m for α = 1]."""
    return 2.0 * damping_factor * math.sqrt(stiffness * effective_mass)


# --- exact ellipse–circle contact (option ``contact_geometry = "exact"``) ----------------
#
# A journal of diameter D with centre c (relative to the shell centre, shell frame) lies
# inside the convex shell K iff c·n ≤ H(n) − D/2 for every unit normal n, with the
# ellipse support function H(ψ) = √(a² cos²ψ + b² sin²ψ). The penetration is the largest
# violation δ = max_ψ [c·n(ψ) − H(ψ) + D/2]: exactly 0 on contact, the distance outside
# the free-play region for small clearances, and its maximiser n is the contact normal.
# The shell-centre offset d = −c gives the same δ with the normal reversed (K symmetric).

@njit(cache=True)
def _support(angle: float, major: float, minor: float) -> tuple:
    """Ellipse support function H(ψ) and its first two derivatives [m, m/rad, m/rad²]."""
    c, s = math.cos(angle), math.sin(angle)
    value = math.sqrt(major * major * c * c + minor * minor * s * s)
    half_diff = 0.5 * (minor * minor - major * major)
    first = half_diff * math.sin(2.0 * angle) / value
    second = (2.0 * half_diff * math.cos(2.0 * angle) - first * first) / value
    return value, first, second


@njit(cache=True)
def _penetration_curve(angle: float, u: float, v: float, diameter: float, major: float,
                       minor: float) -> tuple:
    """g(ψ) = u cos ψ + v sin ψ − H(ψ) + D/2 and its first two derivatives [m, m/rad,
    m/rad²]: the depth of the journal beyond the shell's tangent of normal ψ."""
    value, first, second = _support(angle, major, minor)
    c, s = math.cos(angle), math.sin(angle)
    return (u * c + v * s - value + 0.5 * diameter, -u * s + v * c - first,
            -u * c - v * s - second)


@njit(cache=True)
def _climb(u: float, v: float, diameter: float, major: float, minor: float, angle: float,
           sense: float) -> tuple:
    """(ψ, g(ψ), g''(ψ), converged) at the local maximum (``sense`` 1) or minimum (−1) of g
    reached from ``angle`` by safeguarded Newton steps that never lose height: the extremum
    of the basin ``angle`` lies in [rad, m, m/rad², -]."""
    value, slope, curvature = _penetration_curve(angle, u, v, diameter, major, minor)
    for _ in range(100):
        bent = sense * curvature
        step = -slope / curvature if bent < 0.0 else math.copysign(0.1, sense * slope)
        step = min(max(step, -0.3), 0.3)
        for _ in range(40):  # halve until the step does not lose height
            trial = _penetration_curve(angle + step, u, v, diameter, major, minor)
            if sense * (trial[0] - value) >= -1e-15 * major or abs(step) < 1e-14:
                break
            step *= 0.5
        angle += step
        value, slope, curvature = trial
        if abs(step) < 1e-13:
            return angle, value, curvature, sense * curvature < 0.0
    return angle, value, curvature, False


@njit(cache=True)
def _apart(first: float, second: float, limit: float) -> bool:
    """True when the angles ``first`` and ``second`` [rad] are more than ``limit`` apart."""
    return abs(math.sin(0.5 * (second - first))) > math.sin(0.5 * limit)


@njit(cache=True)
def _two_contacts_possible(u: float, v: float, diameter: float, major: float,
                           minor: float) -> bool:
    """False when g has one maximum only, or its second cannot be a contact: the offset
    lies outside the evolute of the ellipse, (a|u|)^{2/3} + (b|v|)^{2/3} = (a² − b²)^{2/3}
    (one normal to the ellipse through the point, hence one maximum), or the tip of the
    major axis is wider than the journal (b²/a ≥ D/2: a journal touching there has one
    contact point)."""
    if minor * minor / major >= 0.5 * diameter:
        return False
    reach = (major * major - minor * minor) ** (2.0 / 3.0)
    return (major * abs(u)) ** (2.0 / 3.0) + (minor * abs(v)) ** (2.0 / 3.0) < reach


@njit(cache=True)
def support_contacts(u: float, v: float, diameter: float, major: float,
                     minor: float) -> tuple:
    """Contact points of a journal offset (u, v) in the shell frame (major axis along u).

    The journal touches the shell where g(ψ) = u cos ψ + v sin ψ − H(ψ) + D/2 has a local
    maximum: once in general, twice in the worn tip of the major axis when that is
    narrower than the journal (curvature radius b²/a < D/2, i.e. Δmin < ~Δmax/2), where it
    lies in a wedge and is pushed from both flanks. Returns (count as a float, (depth, ψ,
    sign) × 3): the deepest maximum first, then, when there are two, the other maximum and
    the minimum of g between them (the bottom of the wedge) with sign −1. The contact force
    is the sum over these points of sign × the contact law at their depth (those with
    depth > 0): continuous where two maxima appear or merge (a maximum and the minimum
    beside it meet with equal depth and normal and cancel), and the gradient of the
    potential Σ sign c δ^{α+1}/(α+1) (envelope theorem at every critical point)."""
    first, depth, _, _ = _climb(u, v, diameter, major, minor, math.atan2(v, u), 1.0)
    if not _two_contacts_possible(u, v, diameter, major, minor):
        return 1.0, depth, first, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    tip = 0.0 if u >= 0.0 else math.pi  # the tip of the major axis on the journal's side
    middle, low, _, valley = _climb(u, v, diameter, major, minor, tip, -1.0)
    side = math.copysign(1.0, math.sin(middle - first))  # from the minimum away from `first`
    other, other_depth, _, peak = _climb(u, v, diameter, major, minor,
                                         middle + side * 1e-3, 1.0)
    wedge = (valley and peak and not _apart(tip, middle, 0.5 * math.pi)
             and not _apart(tip, other, 0.5 * math.pi) and _apart(first, other, 1e-6)
             and low < min(depth, other_depth))
    if not wedge:
        return 1.0, depth, first, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    if other_depth > depth:
        first, depth, other, other_depth = other, other_depth, first, depth
    return 3.0, depth, first, 1.0, other_depth, other, 1.0, low, middle, -1.0


@njit(cache=True)
def support_penetration(u: float, v: float, diameter: float, major: float,
                        minor: float) -> tuple:
    """Exact penetration for an offset (u, v) in the shell frame (major axis along u).

    Returns (δ [m], ψ contact-normal angle [rad]): the largest violation
    max_ψ g(ψ), g = u cos ψ + v sin ψ − H(ψ) + D/2, at the deepest contact point of
    :func:`support_contacts`.
    """
    found = support_contacts(u, v, diameter, major, minor)
    return found[1], found[2]


@njit(cache=True)
def exact_contact(dx: float, dy: float, vx: float, vy: float, rod_angle: float,
                  rod_rate: float, diameter: float, major: float, minor: float,
                  ellipse_angle: float) -> tuple:
    """Exact contact of a shell-centre offset d = (dx, dy) (engine frame) at its deepest
    point.

    Returns (δ, nx, ny, δ̇, lever): contact normal n (engine frame, along which the shell
    is pushed back: force on the shell −R n), penetration rate
    δ̇ = n·ḋ − φ̇₂ (d × n)_z (envelope theorem; rates in the units of vx, rod_rate) and the
    lever (d × n)_z [m] giving the moment R (d × n)_z of the normal force about the shell
    centre (the contact point is off the line of centres on an ellipse).
    """
    turn = ellipse_angle + rod_angle
    c, s = math.cos(turn), math.sin(turn)
    depth, angle = support_penetration(c * dx + s * dy, -s * dx + c * dy, diameter, major,
                                       minor)
    return contact_point(depth, angle + turn, dx, dy, vx, vy, rod_rate)


@njit(cache=True)
def contact_point(depth: float, normal_angle: float, dx: float, dy: float, vx: float,
                  vy: float, rod_rate: float) -> tuple:
    """(δ, nx, ny, δ̇, lever) of one contact point of depth δ [m] with its normal at
    ``normal_angle`` (engine frame) [rad] (:func:`exact_contact`)."""
    nx, ny = math.cos(normal_angle), math.sin(normal_angle)
    lever = dx * ny - dy * nx
    return depth, nx, ny, nx * vx + ny * vy - rod_rate * lever, lever
