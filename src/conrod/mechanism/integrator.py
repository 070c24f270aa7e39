"""Explicit Runge–Kutta 5(4) integrator with contact-entry events, compiled with numba.

Why explicit: the contact oscillation (period ≈ 2π√(m/k), k = α c δ^{α−1}) must be
resolved to get rebounds and impact velocities right, so an implicit method could not
take much longer steps; an explicit embedded pair with step-size control is then the
cheapest accurate choice (≈ 10⁴–10⁵ steps per cycle at ~1 µs each).

* Dormand–Prince 5(4) pair [1] with local extrapolation; step control
  h_new = h·min(5, max(0.2, 0.9·err^(−1/5))); ``err`` is the RMS of the embedded
  error over the absolute scales ``scale`` (clearance-sized for positions).
  With ``adaptive = False`` the same formula runs at a fixed step (validation).
* Dense output by cubic Hermite interpolation between accepted steps (y and dy/dα at
  both ends), used for the output grid and for locating contact entries.
* An impact is recorded at every **contact entry** of a joint: the penetration δ
  crosses 0 upwards. The entry is located by bisection on the interpolant and the
  impact velocity is the normal relative velocity δ̇ there. A joint re-arms only after
  the surfaces have separated by more than ``separation[j]`` (hysteresis), so numerical
  chatter around δ = 0 while sliding along the shell is not counted as new impacts.

[1] J.R. Dormand, P.J. Prince, "A family of embedded Runge–Kutta formulae",
    J. Comput. Appl. Math. 6 (1980) 19–26.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from conrod.mechanism.kernel import mechanism_rhs, penetration_rates, penetrations

# Dormand–Prince 5(4) coefficients (published tableau, [1] above)
C2, C3, C4, C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = (9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                           -5103.0 / 18656.0)
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0,
                          22.0 / 525.0, -1.0 / 40.0)

OK, TOO_MANY_STEPS, STEP_TOO_SMALL, NOT_FINITE = 0, 1, 2, 3
ALIGN_BELOW, MIN_ALIGNED_STEP, LAND_PAST = 0.98, 1e-9, 1e-6
"""A step in which a joint enters or leaves contact before this fraction is redone to end
just (LAND_PAST relative) past the switch, unless that step would be shorter than
MIN_ALIGNED_STEP [rad]: the Runge–Kutta stages then never straddle the kink of the
contact law, which keeps the method's order and saves rejected steps."""
"""Status codes returned by :func:`integrate`."""


@njit(cache=True)
def dopri_step(alpha, y, f0, h, p, table):
    """One Dormand–Prince step: returns (y_new, f_new, error_vector)."""
    k2 = mechanism_rhs(alpha + C2 * h, y + h * A21 * f0, p, table)
    k3 = mechanism_rhs(alpha + C3 * h, y + h * (A31 * f0 + A32 * k2), p, table)
    k4 = mechanism_rhs(alpha + C4 * h, y + h * (A41 * f0 + A42 * k2 + A43 * k3), p, table)
    k5 = mechanism_rhs(alpha + C5 * h,
                       y + h * (A51 * f0 + A52 * k2 + A53 * k3 + A54 * k4), p, table)
    k6 = mechanism_rhs(alpha + h,
                       y + h * (A61 * f0 + A62 * k2 + A63 * k3 + A64 * k4 + A65 * k5), p, table)
    y_new = y + h * (B1 * f0 + B3 * k3 + B4 * k4 + B5 * k5 + B6 * k6)
    f_new = mechanism_rhs(alpha + h, y_new, p, table)
    error = h * (E1 * f0 + E3 * k3 + E4 * k4 + E5 * k5 + E6 * k6 + E7 * f_new)
    return y_new, f_new, error


@njit(cache=True)
def hermite(y0, f0, y1, f1, h, s):
    """Cubic Hermite interpolant at fraction ``s`` of a step of length ``h``."""
    s2, s3 = s * s, s * s * s
    return ((2.0 * s3 - 3.0 * s2 + 1.0) * y0 + (s3 - 2.0 * s2 + s) * h * f0
            + (3.0 * s2 - 2.0 * s3) * y1 + (s3 - s2) * h * f1)


@njit(cache=True)
def locate_switch(y0, f0, y1, f1, alpha, h, p, joint):
    """Fraction s ∈ (0, 1] of the step where the contact state of ``joint`` (δ > 0 or not)
    first differs from its state at the step start (bisection on the interpolant)."""
    start_in_contact = penetrations(y0, alpha, p)[joint] > 0.0
    low, high = 0.0, 1.0
    for _ in range(60):
        middle = 0.5 * (low + high)
        depth = penetrations(hermite(y0, f0, y1, f1, h, middle), alpha + middle * h, p)[joint]
        if (depth > 0.0) != start_in_contact:
            high = middle
        else:
            low = middle
    return high


@njit(cache=True)
def first_switch(y0, f0, y1, f1, alpha, h, p, depth, new_depth):
    """Earliest fraction of the step where a joint enters or leaves contact (2 if none)."""
    first = 2.0
    for joint in range(2):
        if (depth[joint] > 0.0) != (new_depth[joint] > 0.0):
            first = min(first, locate_switch(y0, f0, y1, f1, alpha, h, p, joint))
    return first


@njit(cache=True)
def _error_norm(error, scale):
    total = 0.0
    for i in range(error.shape[0]):
        total += (error[i] / scale[i]) ** 2
    return math.sqrt(total / error.shape[0])


@njit(cache=True)
def _store_row(out, row, values):
    """out[row] = values, element by element: numba compiles a row assigned whole with its
    shape check and error message (3.6 s of a cold worn-joint run, 6.1 s with its string
    formatting)."""
    for k in range(values.size):
        out[row, k] = values[k]


@njit(cache=True)
def integrate(y0, alpha0, alpha_end, p, table, scale, h_first, h_max, adaptive,
              out_alpha, separation, max_steps, max_impacts):
    """Integrate from ``alpha0`` to ``alpha_end`` [rad]; sample at ``out_alpha`` (sorted).

    Returns (out_y, impacts, n_impacts, n_steps, n_rejected, status, alpha_reached) with
    ``impacts`` rows (entry angle [rad], joint 0 big/1 small, impact velocity [m/s]).
    """
    out_y = np.full((out_alpha.shape[0], y0.shape[0]), np.nan)
    impacts = np.zeros((max_impacts, 3))
    n_impacts, n_steps, n_rejected, status = 0, 0, 0, OK
    alpha, y, h = alpha0, y0.copy(), h_first
    f = mechanism_rhs(alpha, y, p, table)
    depth = penetrations(y, alpha, p)
    armed = np.array([depth[0] < -separation[0], depth[1] < -separation[1]])
    next_out = 0
    landing = False
    while next_out < out_alpha.shape[0] and out_alpha[next_out] < alpha0:
        next_out += 1
    while alpha < alpha_end:
        if n_steps >= max_steps:
            status = TOO_MANY_STEPS
            break
        h = min(h, h_max, alpha_end - alpha)
        y_new, f_new, error = dopri_step(alpha, y, f, h, p, table)
        err = _error_norm(error, scale) if adaptive else 0.0
        if not math.isfinite(err) or not np.all(np.isfinite(y_new)):
            if not adaptive or h < 1e-14:
                status = NOT_FINITE
                break
            h *= 0.2
            n_rejected += 1
            continue
        if err > 1.0:
            n_rejected += 1
            h *= max(0.2, 0.9 * err ** -0.2)
            landing = False
            if h < 1e-14:
                status = STEP_TOO_SMALL
                break
            continue
        new_depth = penetrations(y_new, alpha + h, p)
        if adaptive and not landing:
            switch = first_switch(y, f, y_new, f_new, alpha, h, p, depth, new_depth)
            if switch < ALIGN_BELOW and switch * h > MIN_ALIGNED_STEP:
                h = switch * h * (1.0 + LAND_PAST)  # end the step just past the switch
                landing = True
                continue
        landing = False
        n_steps += 1
        for joint in range(2):
            if armed[joint] and depth[joint] <= 0.0 < new_depth[joint]:
                s = locate_switch(y, f, y_new, f_new, alpha, h, p, joint)
                y_hit = hermite(y, f, y_new, f_new, h, s)
                if n_impacts < max_impacts:
                    impacts[n_impacts, 0] = alpha + s * h
                    impacts[n_impacts, 1] = joint
                    impacts[n_impacts, 2] = penetration_rates(y_hit, alpha + s * h, p)[joint]
                n_impacts += 1
                armed[joint] = False
            if new_depth[joint] < -separation[joint]:
                armed[joint] = True
        while next_out < out_alpha.shape[0] and out_alpha[next_out] <= alpha + h:
            s = (out_alpha[next_out] - alpha) / h
            _store_row(out_y, next_out, hermite(y, f, y_new, f_new, h, s))
            next_out += 1
        alpha, y, f, depth = alpha + h, y_new, f_new, new_depth
        if adaptive:
            h *= min(5.0, max(0.2, 0.9 * max(err, 1e-10) ** -0.2))
    while next_out < out_alpha.shape[0] and out_alpha[next_out] <= alpha + 1e-9:
        _store_row(out_y, next_out, y)  # last sample on the end point despite round-off
        next_out += 1
    return out_y, impacts, n_impacts, n_steps, n_rejected, status, alpha
