"""Right-hand side of the slider-crank with two clearance joints ([D3], numba).

State ([D3] names), with the crank angle α = ω₁t as independent variable and
primes meaning d/dα:

    y = (x_c, x_c', y_c, y_c', φ₂, φ₂', x₃, x₃', W)

x_c, y_c : rod centre of mass [m]; φ₂ : rod angle [rad] (φ₂ = π at TDC: the unit
vector (cos φ₂, sin φ₂) points from the centre of mass to the big end); x₃ : piston-pin
centre on the cylinder axis [m]; W : work done on the rod and piston by the crank and
the gas minus the contact losses [J] (energy check only).

Frame: x along the cylinder axis from the crank centre towards the cylinder head,
crank-pin centre at (r cos α, r sin α); α = 0 at firing TDC.

Relative coordinates ([D3]): big end (shell of the rod on the crank pin)

    x₁₂ = x_c − r cos α + L₁ cos φ₂,   y₁₂ = y_c − r sin α + L₁ sin φ₂,

small end (shell of the rod on the piston pin)

    x₃₂ = x_c − (L − L₁) cos φ₂ − x₃,  y₃₂ = y_c − (L − L₁) sin φ₂.

Equations of motion ([D3], forces divided by m ω₁², moments by J_c2 ω₁²):

    m₂ x_c'' ω₁² = X₁₂ + X₃₂ + F₁₂ₓ,   m₂ y_c'' ω₁² = Y₁₂ + Y₃₂ + F₁₂ᵧ,
    J_c2 φ₂'' ω₁² = Σ M_C,              m₃ x₃'' ω₁² = −X₃₂ − P.

Sign convention: X₁₂, X₃₂ here are the forces **on the rod**; they push the shell
centre back towards the journal (−R·(x, y)/r). [D3] prints +R·(x, y)/r, which
with its own initial conditions would pull the surfaces into each other; the
restoring sign is the physical one and is used here. The big-end friction F₁₂ = f R
acts on the rod at the contact point against the sliding of the rod's surface over
the crank pin; its moment about the big-end centre is f R D/2 ([D3]: "+F₁₂·D/2").
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from conrod.mechanism.geometry import (
    contact_force,
    contact_point,
    exact_contact,
    penetration,
    penetration_rate,
    support_contacts,
    support_penetration,
)

# --- layout of the parameter vector -------------------------------------------------
CRANK_RADIUS, ROD_LENGTH, ROD_CG, ROD_MASS, ROD_INERTIA, PISTON_MASS = 0, 1, 2, 3, 4, 5
CRANK_SPEED, FRICTION_VELOCITY = 6, 7
BIG_END, SMALL_END = 8, 18
"""Offsets of the two joint blocks. The compiled callers pass them as ``np.int64(...)``: a
global int is a literal to numba, and a joint function called with the literals 8 and 18
from compiled code and with an int64 from Python compiled three times (a cold worn-joint
run: ``joint_loads`` 8.1 s, ``_exact_loads`` 4.2 s, ``joint_kinematics`` 2.9 s of compiling,
where one signature each takes about half)."""
(DIAMETER, MINOR, ECC_SQ, ELLIPSE_ANGLE, STIFFNESS, EXPONENT, DAMPING, FRICTION, MAJOR,
 GEOMETRY) = range(10)
"""Entries of a joint block (GEOMETRY: 0 radial penetration of [D3], 1 exact contact)."""
BLOCK_SIZE = 10
FX, FY, MOMENT, NORMAL, ELASTIC, LOSS, DEPTH_RATE, SLIDE, TANGENTIAL = range(9)
"""Entries of the tuple returned by :func:`joint_loads`."""
PARAMETER_COUNT = 28
STATE_SIZE = 9


@njit(cache=True)
def big_end_relative(y: np.ndarray, alpha: float, p: np.ndarray) -> tuple:
    """Big end: shell centre − crank-pin centre and its α-derivative [m, m/rad]."""
    r, cg = p[CRANK_RADIUS], p[ROD_CG]
    c, s = math.cos(y[4]), math.sin(y[4])
    dx = y[0] - r * math.cos(alpha) + cg * c
    dy = y[2] - r * math.sin(alpha) + cg * s
    vx = y[1] + r * math.sin(alpha) - cg * s * y[5]
    vy = y[3] - r * math.cos(alpha) + cg * c * y[5]
    return dx, dy, vx, vy


@njit(cache=True)
def small_end_relative(y: np.ndarray, p: np.ndarray) -> tuple:
    """Small end: shell centre − piston-pin centre and its α-derivative [m, m/rad]."""
    arm = p[ROD_LENGTH] - p[ROD_CG]
    c, s = math.cos(y[4]), math.sin(y[4])
    dx = y[0] - arm * c - y[6]
    dy = y[2] - arm * s
    vx = y[1] + arm * s * y[5] - y[7]
    vy = y[3] - arm * c * y[5]
    return dx, dy, vx, vy


@njit(cache=True)
def joint_depth(dx: float, dy: float, rod_angle: float, p: np.ndarray, block: int) -> float:
    """Penetration δ of one joint [m] (> 0: contact)."""
    if p[block + GEOMETRY] > 0.5:
        turn = p[block + ELLIPSE_ANGLE] + rod_angle
        c, s = math.cos(turn), math.sin(turn)
        return support_penetration(c * dx + s * dy, -s * dx + c * dy, p[block + DIAMETER],
                                   p[block + MAJOR], p[block + MINOR])[0]
    return penetration(dx, dy, rod_angle, p[block + DIAMETER], p[block + MINOR],
                       p[block + ECC_SQ], p[block + ELLIPSE_ANGLE])


@njit(cache=True)
def joint_kinematics(dx: float, dy: float, vx: float, vy: float, rod_angle: float,
                     rod_rate: float, p: np.ndarray, block: int) -> tuple:
    """(δ, nx, ny, work rate, δ', lever) of one joint; rates per radian of crank.

    The [D3] geometry: n = d/r, work rate ṙ, δ' = ṙ − p'(ϕ)ϕ', lever 0 (force through the
    shell centre). Exact geometry: n the contact normal, work rate = δ', lever (d × n)_z.
    """
    if p[block + GEOMETRY] > 0.5:
        depth, nx, ny, rate, lever = exact_contact(
            dx, dy, vx, vy, rod_angle, rod_rate, p[block + DIAMETER], p[block + MAJOR],
            p[block + MINOR], p[block + ELLIPSE_ANGLE])
        return depth, nx, ny, rate, rate, lever
    depth = joint_depth(dx, dy, rod_angle, p, block)
    radial, depth_rate = penetration_rate(dx, dy, vx, vy, rod_angle, rod_rate, p[block + MINOR],
                                          p[block + ECC_SQ], p[block + ELLIPSE_ANGLE])
    radius = math.sqrt(dx * dx + dy * dy) + 1.0e-30
    return depth, dx / radius, dy / radius, radial, depth_rate, 0.0


@njit(cache=True)
def joint_loads(dx: float, dy: float, vx: float, vy: float, rod_angle: float, rod_rate: float,
                journal_rate: float, p: np.ndarray, block: int) -> tuple:
    """Contact of one joint; rates per radian of crank angle.

    Returns (Fx, Fy, moment, normal, elastic, loss, depth_rate, slide_rate, tangential):
    force on the rod [N], moment about the shell centre (friction; exact geometry also the
    off-centre normal force) [N m], normal force R and its elastic part [N], the power the
    contact takes out of the mechanism (R ṙ − c δ^α δ̇ − F_t v_t: damping, clipping,
    friction, and the non-potential part of [D3]'s radial force on an elliptical shell)
    [W], δ̇ [m/s], sliding speed [m/s], friction force [N] (of the deepest point where the
    exact geometry has two, :func:`conrod.mechanism.geometry.support_contacts`; forces,
    moment, normal force and loss are summed over the points).
    journal_rate : rotation of the journal per radian of crank (1 crank pin, 0 piston pin).
    """
    if p[block + GEOMETRY] > 0.5:
        return _exact_loads(dx, dy, vx, vy, rod_angle, rod_rate, journal_rate, p, block)
    depth, nx, ny, radial, depth_rate, lever = joint_kinematics(
        dx, dy, vx, vy, rod_angle, rod_rate, p, block)
    if depth <= 0.0:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    return _point_loads(depth, nx, ny, radial, depth_rate, lever, vx, vy, rod_rate,
                        journal_rate, p, block, 1.0)


@njit(cache=True)
def _point_loads(depth: float, nx: float, ny: float, radial: float, depth_rate: float,
                 lever: float, vx: float, vy: float, rod_rate: float, journal_rate: float,
                 p: np.ndarray, block: int, sign: float) -> tuple:
    """:func:`joint_loads` of one contact point of depth δ > 0 [m], normal n, work rate
    and δ' [m/rad], lever [m], times ``sign`` (−1: the minimum between two points of the
    exact geometry)."""
    omega = p[CRANK_SPEED]
    normal, elastic = contact_force(depth, omega * depth_rate, p[block + STIFFNESS],
                                    p[block + EXPONENT], p[block + DAMPING])
    half_d = 0.5 * p[block + DIAMETER]
    slide = omega * (-ny * vx + nx * vy - half_d * (rod_rate - journal_rate))
    v_reg = p[FRICTION_VELOCITY]
    tangential = -p[block + FRICTION] * normal * slide / math.sqrt(slide * slide + v_reg * v_reg)
    fx = -normal * nx - tangential * ny
    fy = -normal * ny + tangential * nx
    loss = normal * omega * radial - elastic * omega * depth_rate - tangential * slide
    return (sign * fx, sign * fy, sign * (normal * lever - half_d * tangential), sign * normal,
            sign * elastic, sign * loss, omega * depth_rate, slide, sign * tangential)


@njit(cache=True)
def _exact_loads(dx: float, dy: float, vx: float, vy: float, rod_angle: float,
                 rod_rate: float, journal_rate: float, p: np.ndarray, block: int) -> tuple:
    """:func:`joint_loads` of the exact geometry: the sum over its contact points."""
    turn = p[block + ELLIPSE_ANGLE] + rod_angle
    c, s = math.cos(turn), math.sin(turn)
    found = support_contacts(c * dx + s * dy, -s * dx + c * dy, p[block + DIAMETER],
                             p[block + MAJOR], p[block + MINOR])
    total = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    for i in range(int(found[0])):
        depth, angle, sign = found[1 + 3 * i], found[2 + 3 * i], found[3 + 3 * i]
        if depth <= 0.0:
            continue
        _, nx, ny, rate, lever = contact_point(depth, angle + turn, dx, dy, vx, vy, rod_rate)
        point = _point_loads(depth, nx, ny, rate, rate, lever, vx, vy, rod_rate,
                             journal_rate, p, block, sign)
        if i == 0:
            total = point
        else:
            total = (total[0] + point[0], total[1] + point[1], total[2] + point[2],
                     total[3] + point[3], total[4] + point[4], total[5] + point[5],
                     total[6], total[7], total[8] + point[8])
    return total


@njit(cache=True)
def gas_force(alpha: float, table: np.ndarray) -> float:
    """Gas force P on the piston [N] (towards the crank when > 0), periodic over 4π.

    ``table`` holds P at equally spaced angles 0, 4π/n, …; linear interpolation.
    """
    n = table.shape[0]
    position = (alpha % (4.0 * math.pi)) / (4.0 * math.pi) * n
    index = int(position)
    weight = position - index
    if index >= n:
        index, weight = n - 1, 1.0
    return (1.0 - weight) * table[index] + weight * table[(index + 1) % n]


@njit(cache=True)
def mechanism_rhs(alpha: float, y: np.ndarray, p: np.ndarray, table: np.ndarray) -> np.ndarray:
    """dy/dα of the 9-state system ([D3] matrix of right-hand sides)."""
    omega = p[CRANK_SPEED]
    w2 = omega * omega
    phi, phi_rate = y[4], y[5]
    c, s = math.cos(phi), math.sin(phi)
    cg, arm = p[ROD_CG], p[ROD_LENGTH] - p[ROD_CG]
    bx, by, bvx, bvy = big_end_relative(y, alpha, p)
    big = joint_loads(bx, by, bvx, bvy, phi, phi_rate, 1.0, p, np.int64(BIG_END))
    sx, sy, svx, svy = small_end_relative(y, p)
    small = joint_loads(sx, sy, svx, svy, phi, phi_rate, 0.0, p, np.int64(SMALL_END))
    pressure_force = gas_force(alpha, table)
    moment = (cg * (c * big[FY] - s * big[FX]) + big[MOMENT]
              - arm * (c * small[FY] - s * small[FX]) + small[MOMENT])
    out = np.empty(STATE_SIZE)
    out[0] = y[1]
    out[1] = (big[FX] + small[FX]) / (p[ROD_MASS] * w2)
    out[2] = y[3]
    out[3] = (big[FY] + small[FY]) / (p[ROD_MASS] * w2)
    out[4] = phi_rate
    out[5] = moment / (p[ROD_INERTIA] * w2)
    out[6] = y[7]
    out[7] = (-small[FX] - pressure_force) / (p[PISTON_MASS] * w2)
    out[8] = _net_power(alpha, y, p, big, small, pressure_force) / omega
    return out


@njit(cache=True)
def _net_power(alpha: float, y: np.ndarray, p: np.ndarray, big: tuple, small: tuple,
               pressure_force: float) -> float:
    """Crank power + gas power − contact losses [W] (energy balance, see module doc).

    Loss of a joint: R ṙ − c δ^α δ̇ − F_t v_t (damping, clipping, friction and the
    non-potential part of [D3]'s radial force on an elliptical shell), summed over its
    contact points (:func:`joint_loads`).
    """
    omega, r = p[CRANK_SPEED], p[CRANK_RADIUS]
    pin_vx, pin_vy = -omega * r * math.sin(alpha), omega * r * math.cos(alpha)
    # crank-pin surface point at the contact moves with v_pin − ω₁ (D/2) t; F·t = F_t
    crank = (big[FX] * pin_vx + big[FY] * pin_vy
             - big[TANGENTIAL] * omega * 0.5 * p[BIG_END + DIAMETER])
    gas = -pressure_force * omega * y[7]
    return crank + gas - big[LOSS] - small[LOSS]


@njit(cache=True)
def penetrations(y: np.ndarray, alpha: float, p: np.ndarray) -> tuple:
    """Penetrations (δ_big, δ_small) [m] at state ``y`` (> 0: contact)."""
    bx, by, _, _ = big_end_relative(y, alpha, p)
    sx, sy, _, _ = small_end_relative(y, p)
    return (joint_depth(bx, by, y[4], p, np.int64(BIG_END)),
            joint_depth(sx, sy, y[4], p, np.int64(SMALL_END)))


@njit(cache=True)
def penetration_rates(y: np.ndarray, alpha: float, p: np.ndarray) -> tuple:
    """Penetration rates (δ̇_big, δ̇_small) [m/s] at state ``y``."""
    omega = p[CRANK_SPEED]
    bx, by, bvx, bvy = big_end_relative(y, alpha, p)
    sx, sy, svx, svy = small_end_relative(y, p)
    big = joint_kinematics(bx, by, bvx, bvy, y[4], y[5], p, np.int64(BIG_END))[4]
    small = joint_kinematics(sx, sy, svx, svy, y[4], y[5], p, np.int64(SMALL_END))[4]
    return omega * big, omega * small


@njit(cache=True)
def mechanical_energy(y: np.ndarray, alpha: float, p: np.ndarray) -> float:
    """Kinetic energy of rod and piston + elastic contact energy c δ^{α+1}/(α+1) [J]."""
    omega = p[CRANK_SPEED]
    kinetic = 0.5 * omega * omega * (
        p[ROD_MASS] * (y[1] ** 2 + y[3] ** 2) + p[ROD_INERTIA] * y[5] ** 2
        + p[PISTON_MASS] * y[7] ** 2)
    bx, by, _, _ = big_end_relative(y, alpha, p)
    sx, sy, _, _ = small_end_relative(y, p)
    return (kinetic + _elastic_energy(bx, by, y[4], p, np.int64(BIG_END))
            + _elastic_energy(sx, sy, y[4], p, np.int64(SMALL_END)))


@njit(cache=True)
def _elastic_energy(dx: float, dy: float, rod_angle: float, p: np.ndarray,
                    block: int) -> float:
    """Σ sign c δ^{α+1}/(α+1) over the contact points of one joint [J]."""
    exponent, stiffness = p[block + EXPONENT], p[block + STIFFNESS]
    if p[block + GEOMETRY] <= 0.5:
        depth = joint_depth(dx, dy, rod_angle, p, block)
        return stiffness * depth ** (exponent + 1.0) / (exponent + 1.0) if depth > 0.0 else 0.0
    turn = p[block + ELLIPSE_ANGLE] + rod_angle
    c, s = math.cos(turn), math.sin(turn)
    found = support_contacts(c * dx + s * dy, -s * dx + c * dy, p[block + DIAMETER],
                             p[block + MAJOR], p[block + MINOR])
    energy = 0.0
    for i in range(int(found[0])):
        depth, sign = found[1 + 3 * i], found[3 + 3 * i]
        if depth > 0.0:
            energy += sign * stiffness * depth ** (exponent + 1.0) / (exponent + 1.0)
    return energy
