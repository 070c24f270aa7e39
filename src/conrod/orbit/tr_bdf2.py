"""TR-BDF2: an L-stable, second-order implicit Runge–Kutta step with an embedded
third-order error estimate, for the stiff free flight of the journal centre.

One step of length h from u_n (Bank et al. 1985; Hosea & Shampine 1996, the method of
MATLAB's ``ode23tb``), d = 1 − √2/2, w = √2/4:

* trapezoidal stage to φ_n + 2d h:   z = u_n + d h (f_n + f(z)),
* BDF2 stage to φ_n + h:             u_{n+1} = u_n + h (w f_n + w f(z) + d f(u_{n+1})),
* error estimate (third-order companion weights ((1 − w)/3, (3w + 1)/3, d/3)), filtered
  through (I − d h J)⁻¹ as Shampine recommends for stiff problems.

Both implicit stages share the matrix I − d h J, J = ∂f/∂u; Newton is simplified (J kept
over steps while the iteration contracts, refreshed when it does not). Steps are
error-controlled (mixed absolute/relative RMS norm, as SciPy's) and never longer than
``max_step``. The step function is written once, with f, its Jacobian and the stage as
global names bound per film by :func:`specialise`: compiled with numba (and cached on disk)
for films with a compiled force (:mod:`conrod.orbit.compiled_flight`), run as plain Python
for films solved in Python, where each evaluation of f is a film solve.

[1] R.E. Bank, W.M. Coughran, W. Fichtner, E.H. Grosse, D.J. Rose, R.K. Smith, Transient
    simulation of silicon devices and circuits, IEEE Trans. CAD 4 (1985) 436–451.
[2] M.E. Hosea, L.F. Shampine, Analysis and implementation of TR-BDF2, Appl. Numer. Math.
    20 (1996) 21–37.
"""

from __future__ import annotations

import math
import types

import numba as nb
import numpy as np

GAMMA_HALF = 1.0 - 0.5 * math.sqrt(2.0)
"""d = γ/2 with γ = 2 − √2, the diagonal of both implicit stages [-]."""
WEIGHT = 0.25 * math.sqrt(2.0)
"""w = (1 − d)/2, weight of f_n and f(z) in the BDF2 stage [-]."""
NEWTON_ITERATIONS = 8
"""Most simplified-Newton iterations per stage [-]."""
NEWTON_KAPPA = 0.05
"""Newton stops when its estimated error is below this fraction of the tolerance [-]."""

STATUS_END, STATUS_HIT, STATUS_COLLAPSE, STATUS_NEWTON, STATUS_JACOBIAN = 0, 1, -1, -2, -3
"""Segment outcomes: end reached; contact circle reached; step size collapsed; Newton
failed with a fresh Jacobian at the smallest step; the Jacobian at an accepted state is not
finite (the film could not be solved there)."""


UNBOUND = ("a TR-BDF2 template function was called unbound; the step code runs only through "
           "specialise(), which binds the film's functions in its place")
"""Message of the template globals below: they name the callees of the one step code and are
replaced per film by :func:`specialise` (never called themselves)."""


def rhs(phi, u, params, data):
    """du/dφ [-]: a placeholder, bound per film by :func:`specialise`."""
    raise RuntimeError(UNBOUND)


def jacobian(phi, u, f0, params, data):
    """∂(du/dφ)/∂u [-]: a placeholder, bound per film by :func:`specialise`."""
    raise RuntimeError(UNBOUND)


def stage(phi, base, guess, dh, inverse, params, data, atol, rtol, eta, evaluate):
    """One implicit stage: a placeholder, bound per film by :func:`specialise`."""
    raise RuntimeError(UNBOUND)


def _fd_jacobian(phi, u, f0, params, data):
    """Forward-difference J = ∂f/∂u (n × n) [-] of the bound ``rhs``. The column is stored
    element by element: numba compiles a column assigned as a slice with its shape check
    and error message (2.8 s of a cold short-film run)."""
    jac = np.empty((u.size, u.size))
    for j in range(u.size):
        step = 1.0e-7 * max(1.0, abs(u[j]))
        shifted = u.copy()
        shifted[j] += step
        column = (rhs(phi, shifted, params, data) - f0) / step
        for i in range(u.size):
            jac[i, j] = column[i]
    return jac


@nb.njit(cache=True)
def _norm(v, scale):
    """RMS of v/scale [-]."""
    total = 0.0
    for i in range(v.size):
        total += (v[i] / scale[i]) ** 2
    return math.sqrt(total / v.size)


def _stage(phi, base, guess, dh, inverse, params, data, atol, rtol, eta, evaluate):
    """Solve z = base + d h f(φ, z) by simplified Newton with ``inverse`` = (I − d h J)⁻¹,
    stopping when the estimated iteration error η‖Δz‖ (η = ρ/(1 − ρ), ρ the contraction
    rate; ``eta`` from the previous stage before a rate is known) is below
    :data:`NEWTON_KAPPA` of the tolerance (Hairer & Wanner, Solving ODEs II, IV.8).
    Returns (z, f(z), converged, rate, η); f(z) is evaluated when ``evaluate``, else taken
    from the stage equation, f(z) = (z − base)/(d h): one film solve less per stage for
    an expensive f, and for a stiff f the Newton error is not amplified by the stiffness
    (Shampine). Used for the compiled grid film; the others evaluate it (with tolerances
    so loose that Newton stops after one iteration only the evaluated f keeps the method
    second order, and the Python films with finite-difference Jacobians were validated
    that way)."""
    z = guess.copy()
    previous = 0.0
    rate = 0.0
    converged = False
    f = np.zeros(z.size)
    for it in range(NEWTON_ITERATIONS):
        f = rhs(phi, z, params, data)
        delta = _apply(inverse, base + dh * f - z)
        z = z + delta
        size = _norm(delta, atol + rtol * np.abs(z))
        if it > 0:
            rate = size / previous if previous > 0.0 else 0.0
            if rate >= 0.9:  # no contraction: converged only if already at noise level
                converged = size < NEWTON_KAPPA
                break
            eta = rate / (1.0 - rate)
        if eta * size < NEWTON_KAPPA:
            converged = True
            break
        previous = size
    if converged:
        f = rhs(phi, z, params, data) if evaluate else (z - base) / dh
    return z, f, converged, rate, eta


@nb.njit(cache=True)
def _apply(matrix, v):
    """matrix @ v for a small dense matrix (any memory layout)."""
    out = np.zeros(v.size)
    for i in range(v.size):
        for j in range(v.size):
            out[i] += matrix[i, j] * v[j]
    return out


@nb.njit(cache=True)
def _hermite(theta, h, u0, f0, u1, f1):
    """Cubic Hermite interpolant at the fraction ``theta`` of a step [-]."""
    t2, t3 = theta * theta, theta * theta * theta
    return ((2 * t3 - 3 * t2 + 1) * u0 + (t3 - 2 * t2 + theta) * h * f0
            + (-2 * t3 + 3 * t2) * u1 + (t3 - t2) * h * f1)


@nb.njit(cache=True)
def _record(out_phi, out_u, next_out, reached, u):
    """Rows of ``out_u`` from ``next_out`` on whose output angle is at most ``reached``
    [rad] set to the state ``u`` there; returns the next row to fill. Each row is a step
    end, never an interpolant: on the stiff slow manifold of a loaded film the velocity of
    the cubic Hermite interpolant between step ends carries the step-end derivatives'
    acceleration error (the velocity error within tolerance times the stiffness, up to
    10⁶ per radian), and the film solved at it gave a cycle maximum of p_max up to 26 %
    high and single rows 100× below their neighbours (benchmarks/pmax_reference.md)."""
    while next_out < out_phi.size and out_phi[next_out] <= reached:
        for k in range(u.size):  # no array-slice assignment (compile time)
            out_u[next_out, k] = u[k]
        next_out += 1
    return next_out


@nb.njit(cache=True)
def _overshoot(u, circle):
    """|e|/r_c − 1 from the scaled position [-]; ``circle`` = r_c/c."""
    return math.hypot(u[0], u[1]) / circle - 1.0


@nb.njit(cache=True)
def _hit_fraction(h, u0, f0, u1, f1, circle):
    """Fraction of a step where the interpolant reaches the contact circle (bisection)."""
    low, high = 0.0, 1.0
    for _ in range(60):
        mid = 0.5 * (low + high)
        if _overshoot(_hermite(mid, h, u0, f0, u1, f1), circle) > 0.0:
            high = mid
        else:
            low = mid
    return high


def _segment(params, data, phi, end, u, h, max_step, rtol, atol, circle,
             out_phi, out_u, next_out, max_steps, refresh_rate, evaluate):
    """Integrate du/dφ = rhs(φ, u, params, data) from φ to ``end`` (free flight), with
    the ``rhs``, ``jacobian`` and ``stage`` bound by :func:`specialise`.

    u : scaled state (x/c, y/c, v_x/(c ω), v_y/(c ω)) [-], or any other size (a tilted
    journal's, :mod:`conrod.orbit.tilt_flight`); h, max_step [rad];
    circle : contact radius / c [-] (the segment stops where the centre reaches it);
    out_phi : output angles [rad]; rows of ``out_u`` from ``next_out`` on are filled as
    the steps reach them: a step that would pass the next output angle is shortened to
    end on it, so that every row is an accepted step end (:func:`_record`); J is
    refreshed after a step whose Newton contraction rate exceeded ``refresh_rate`` [-];
    ``evaluate``: stage derivatives by evaluating f (:func:`_stage`). Returns (status, φ,
    u, h, steps, next_out, jacobian evaluations).
    """
    f = rhs(phi, u, params, data)
    jac = jacobian(phi, u, f, params, data)
    fresh = True
    evaluations = 1
    eye = np.eye(u.size)
    dh_inverse = -1.0
    inverse = eye
    steps = 0
    eta = 1.0
    h_prev, u_prev, f_prev = 0.0, u, f
    tol = 1.0e-12 * max(1.0, abs(end))  # angles closer than this are the same [rad]
    next_out = _record(out_phi, out_u, next_out, phi + tol, u)
    while phi < end and steps < max_steps:
        h = min(h, max_step, end - phi)
        free = h  # the step error control asks for
        stop = end
        if next_out < out_phi.size and out_phi[next_out] < end - tol:
            stop = out_phi[next_out]
        aligned = phi + h >= stop - tol
        if aligned:  # end the step on the output angle (or the segment end)
            h = stop - phi
        elif phi + 2.0 * h > stop:  # two equal steps to it rather than a step and a sliver
            h = 0.5 * (stop - phi)
        dh = GAMMA_HALF * h
        if not np.all(np.isfinite(jac)):
            return STATUS_JACOBIAN, phi, u, h, steps, next_out, evaluations
        if dh != dh_inverse:
            inverse = np.linalg.inv(eye - dh * jac)
            dh_inverse = dh
        if h_prev > 0.0:  # extrapolate the previous step's interpolant
            guess = _hermite(1.0 + 2.0 * dh / h_prev, h_prev, u_prev, f_prev, u, f)
        else:
            guess = u + 2.0 * dh * f
        eta = max(eta, 1.0e-3) ** 0.8
        z, fz, ok, rate1, eta = stage(phi + 2.0 * dh, u + dh * f, guess, dh, inverse,
                                      params, data, atol, rtol, eta, evaluate)
        rate2 = 0.0
        if ok:
            base = u + h * WEIGHT * (f + fz)
            guess = _hermite(0.5 / GAMMA_HALF, 2.0 * dh, u, f, z, fz)
            u1, f1, ok, rate2, eta = stage(phi + h, base, guess, dh, inverse, params,
                                           data, atol, rtol, eta, evaluate)
        if not ok:
            if not fresh:
                jac = jacobian(phi, u, f, params, data)
                evaluations += 1
                fresh, dh_inverse = True, -1.0
                continue
            h *= 0.25
            if h < 1.0e-12 * max_step:
                return STATUS_NEWTON, phi, u, h, steps, next_out, evaluations
            continue
        estimate = h * ((1.0 - WEIGHT) / 3.0 - WEIGHT) * f \
            + h * ((3.0 * WEIGHT + 1.0) / 3.0 - WEIGHT) * fz \
            + h * (GAMMA_HALF / 3.0 - GAMMA_HALF) * f1
        estimate = _apply(inverse, estimate)
        scale = atol + rtol * np.maximum(np.abs(u), np.abs(u1))
        error = _norm(estimate, scale)
        if error > 1.0:
            h *= max(0.2, 0.9 * error ** (-1.0 / 3.0))
            if h < 1.0e-12 * max_step:
                return STATUS_COLLAPSE, phi, u, h, steps, next_out, evaluations
            continue
        steps += 1
        if _overshoot(u1, circle) > 0.0:  # no output angle inside the step: no rows
            fraction = _hit_fraction(h, u, f, u1, f1, circle)
            return (STATUS_HIT, phi + fraction * h, _hermite(fraction, h, u, f, u1, f1), h,
                    steps, next_out, evaluations)
        phi = stop if aligned else phi + h
        next_out = _record(out_phi, out_u, next_out, phi + tol, u1)
        h_prev, u_prev, f_prev = h, u, f
        u, f = u1, f1
        fresh = False
        if max(rate1, rate2) > refresh_rate:  # slow contraction: refresh J
            jac = jacobian(phi, u, f, params, data)
            evaluations += 1
            fresh, dh_inverse = True, -1.0
        h *= min(4.0, max(0.2, 0.9 * max(error, 1.0e-10) ** (-1.0 / 3.0)))
        if aligned:  # a step shortened to an output angle does not shorten the next
            h = max(h, free)
    status = STATUS_END if phi >= end else STATUS_COLLAPSE
    return status, phi, u, h, steps, next_out, evaluations


def bind_globals(template, name, functions):
    """``template`` with the global names in ``functions`` bound (same code, own name)."""
    bound = types.FunctionType(template.__code__, {**template.__globals__, **functions},
                               name)
    bound.__qualname__ = bound.__name__ = name
    bound.__doc__ = template.__doc__
    return bound


def specialise(name, rhs, jacobian=None, *, compiled, cache=False):
    """:func:`_segment` for ``rhs`` (φ, u, params, data) → du/dφ and ``jacobian``
    (φ, u, f, params, data) → ∂f/∂u (None: forward differences); compiled with numba
    (``rhs`` and ``jacobian`` numba functions) or plain Python. The compiled step is
    cached on disk when ``cache`` (then ``name`` must be unique and stable, and the bound
    functions module-level numba functions: numba caches only code whose callees are
    globals). Returns segment(params, data, φ, end, u, h, max_step, rtol, atol, circle,
    out_phi, out_u, next_out, max_steps, refresh_rate, evaluate) → (status, φ, u, h,
    steps, next_out, jacobian evaluations)."""
    jit = nb.njit(cache=True) if cache else nb.njit
    wrap = jit if compiled else (lambda function: function)
    functions = {"rhs": rhs}
    if jacobian is None:
        jacobian = wrap(bind_globals(_fd_jacobian, f"{name}_fd_jacobian", functions))
    inline = (nb.njit(cache=cache, inline="always") if compiled  # no library of its own
              else (lambda function: function))
    stage = inline(bind_globals(_stage, f"{name}_stage", functions))
    return wrap(bind_globals(_segment, f"{name}_segment",
                      {"rhs": rhs, "jacobian": jacobian, "stage": stage}))
