"""Hard contact of the journal with the shell ([D4] §4.1–4.2).

The journal centre may not leave the *contact circle* of radius r_c = c − h_c around the
shell centre (h_c = ``[solver] contact_film_thickness``, 0 as in [D4]). Notation of
[D4], written in our film frame (position e of the journal centre relative to the
shell centre, load W pressing the journal on the shell, film force F on the journal):

* contact test Z = |e|/r_c (eq. 4.1.1); projection e := e/Z when Z > 1 (4.1.2–4.1.3);
* contact direction n̂ = e/|e| ([D4]'s φ_c = atan2(y, x) + 180° because it tracks the
  shell centre relative to the journal), tangent t̂ = (−n̂_y, n̂_x);
* normal velocity removed, V_n = v·n̂ = 0, V_k = v·t̂, v = V_k t̂ (4.1.5–4.1.8);
* X = W + F (4.2.1–4.2.2), P_n = X·n̂, P_k = X·t̂ (4.2.3–4.2.4), contact force on the
  journal −P_c n̂ with P_c ≥ 0 (4.2.5), dry friction P_f = −μ_dry P_c sign(V_s) t̂ opposing
  the sliding speed V_s = V_k + (ω_j − ω_b) R of the journal surface over the shell (4.2.6),
  motion along the circle under K = P_k + P_f (4.2.7–4.2.9).

Beyond [D4], the normal balance keeps the centripetal term of the motion on the circle
and unequal masses M = diag(m_x, m_y): with the constraint n̂·ë = −V_k²/r_c,

.. math:: P_c = \\frac{n̂·M^{-1}X + V_k^2/r_c}{n̂·M^{-1}n̂ + μ s\\, n̂·M^{-1}t̂},
          \\qquad s = \\operatorname{sign}(V_s),

which is [D4]'s P_c = P_n for equal masses and slow sliding of the centre.

The sign of the sliding speed is regularised, s = tanh(V_s/v_reg) with
v_reg = :data:`FRICTION_REGULARISATION_SPEED`, so that a journal pressed without rotation
sticks (V_s → 0) instead of chattering between ±μ_dry P_c; for sliding speeds of engine
bearings (ω R ~ m/s) s = ±1 to machine precision.
"""

from __future__ import annotations

import math

import numba as nb

from conrod.film.massless import (  # noqa: F401  (the contact-circle rules)
    constrain_and_record,
    project_onto_circle,
    remove_normal_velocity,
)

FRICTION_REGULARISATION_SPEED = 1.0e-4
"""Sliding speed below which dry friction is regularised (tanh) [m/s]."""


@nb.njit(cache=True)
def contact_normal_force(
    x: float, y: float, vx: float, vy: float, force_x: float, force_y: float,
    mass_x: float, mass_y: float, dry_friction: float, radius: float, surface_speed: float,
) -> tuple[float, float]:
    """Unclamped normal force P_c [N] needed to keep the journal on the contact circle, and
    the regularised sign s of the sliding speed [-] (module docstring; [D4] eq. 4.2.5).
    P_c ≤ 0 means the journal leaves the shell."""
    e = math.hypot(x, y)
    nx = x / e
    ny = y / e
    v_k = vy * nx - vx * ny
    s = math.tanh((v_k + surface_speed) / FRICTION_REGULARISATION_SPEED)
    n_mn = nx * nx / mass_x + ny * ny / mass_y
    n_mt = -nx * ny / mass_x + ny * nx / mass_y
    accel_n = nx * force_x / mass_x + ny * force_y / mass_y
    return (accel_n + v_k * v_k / radius) / (n_mn + dry_friction * s * n_mt), s


@nb.njit(cache=True)
def contact_acceleration(
    x: float, y: float, vx: float, vy: float, force_x: float, force_y: float,
    mass_x: float, mass_y: float, dry_friction: float, radius: float,
    surface_speed: float, in_contact: bool,
) -> tuple[float, float, float, float]:
    """Acceleration (a_x, a_y) [m/s²], contact force P_c [N] and friction force μ P_c |s| [N].

    ``force_x, force_y``: X = W + F, every force on the journal but contact [N];
    ``surface_speed``: (ω_j − ω_b) R [m/s]. Free motion (a = M⁻¹X, P_c = 0) unless
    ``in_contact`` and the journal presses on the shell (P_c > 0); then
    M a = X − P_c n̂ − s μ_dry P_c t̂ (eqs 4.2.5–4.2.9).
    """
    ax = force_x / mass_x
    ay = force_y / mass_y
    e = math.hypot(x, y)
    if not in_contact or e == 0.0:
        return ax, ay, 0.0, 0.0
    p_c, s = contact_normal_force(
        x, y, vx, vy, force_x, force_y, mass_x, mass_y, dry_friction, radius, surface_speed
)
    if p_c <= 0.0:
        return ax, ay, 0.0, 0.0
    nx = x / e
    ny = y / e
    p_f = dry_friction * p_c * abs(s)
    fx = force_x - p_c * nx + s * dry_friction * p_c * ny
    fy = force_y - p_c * ny - s * dry_friction * p_c * nx
    return fx / mass_x, fy / mass_y, p_c, p_f
