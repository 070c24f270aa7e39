"""The TR-BDF2 free flight (:mod:`conrod.orbit.tr_bdf2`) compiled per film force, cached
on disk by numba.

numba caches a compiled function only when everything it calls is named by a global: a
function created at run time as a closure, or passed in as an argument, is compiled anew in
every process, which for the Reynolds film's multigrid takes 35–100 s. Here the right-hand
side du/dφ, the Jacobian and the segment are the one source of :mod:`conrod.orbit.tr_bdf2`
with the film's force (and Jacobian) bound as globals
(:func:`~conrod.orbit.tr_bdf2.specialise`), named after the force; a second process loads
them from the cache (``__pycache__`` beside the modules, or ``NUMBA_CACHE_DIR``). A force
that is not a module-level numba function (a closure) gets the same code compiled per
process.

The scaled state is u = (x/c, y/c, v_x/(c ω), v_y/(c ω)) over the crank angle; data =
(angles [rad], load table, cycle [rad], μ [Pa s], c [m], ω [rad/s], m_x [kg], m_y [kg]).
"""

from __future__ import annotations

import functools
import sys

import numba as nb
import numpy as np

from conrod.orbit.problem import periodic_sample, scaled_free_rhs
from conrod.orbit.tr_bdf2 import UNBOUND, bind_globals, specialise


def force(x, y, vx, vy, omega_sum, viscosity, params):
    """Film force (F_x, F_y) [N]: a placeholder, bound per film by :func:`flight_segment`."""
    raise RuntimeError(UNBOUND)


def film_jacobian(x, y, vx, vy, omega_sum, viscosity, params):
    """(F, ∂F/∂(e, ė)) [N, N/m, N s/m]: a placeholder, bound by :func:`flight_segment`."""
    raise RuntimeError(UNBOUND)


def _rhs(phi, u, params, data):
    """du/dφ [-] of the journal centre under the load and the bound film ``force``."""
    angles, table, cycle, mu, c, omega, mass_x, mass_y = data
    row = periodic_sample(phi, angles, table, cycle)
    c_omega = c * omega
    fx, fy = force(u[0] * c, u[1] * c, u[2] * c_omega, u[3] * c_omega, row[2] + row[3],
                   mu, params)
    return scaled_free_rhs(u, row, fx, fy, c_omega, omega, mass_x, mass_y)


def _jacobian(phi, u, f0, params, data):
    """∂(du/dφ)/∂u [-] from the bound ``film_jacobian`` ∂F/∂(e, ė) (``f0`` unused)."""
    angles, table, cycle, mu, c, omega, mass_x, mass_y = data
    row = periodic_sample(phi, angles, table, cycle)
    c_omega = c * omega
    _, film = film_jacobian(u[0] * c, u[1] * c, u[2] * c_omega, u[3] * c_omega,
                            row[2] + row[3], mu, params)
    return scaled_jacobian(film, c, omega, mass_x, mass_y)


@nb.njit(cache=True)
def scaled_jacobian(film, c, omega, mass_x, mass_y):
    """∂(du/dφ)/∂u [-] from the film's ∂F/∂(e, ė) (2 × 4) [N/m, N s/m]."""
    out = np.zeros((4, 4))
    out[0, 2] = out[1, 3] = 1.0
    for row in range(2):
        scale = (mass_x if row == 0 else mass_y) * c * omega * omega
        for col in range(2):
            out[2 + row, col] = film[row, col] * c / scale
            out[2 + row, 2 + col] = film[row, 2 + col] * c * omega / scale
    return out


@functools.cache
def flight_segment(film_force, film_force_jacobian=None):
    """Compiled segment (:func:`conrod.orbit.tr_bdf2.specialise`) for a compiled film force
    ``(x, y, v_x, v_y, ω_j + ω_b, μ, params) -> (F_x, F_y)`` [N] and optionally its
    ``(F, ∂F/∂(e, ė))`` (None: forward differences of du/dφ); disk-cached when both
    are module-level numba functions."""
    cache = is_global(film_force) and (film_force_jacobian is None
                                       or is_global(film_force_jacobian))
    name = stable_name(film_force) + ("" if film_force_jacobian is None else "_with_jacobian")
    jit = nb.njit(cache=True) if cache else nb.njit
    rhs = flight_rhs(film_force)
    jacobian = None
    if film_force_jacobian is not None:
        jacobian = jit(bind_globals(_jacobian, f"{name}_jacobian",
                             {"film_jacobian": film_force_jacobian}))
    return specialise(name, rhs, jacobian, compiled=True, cache=cache)


@functools.cache
def flight_rhs(film_force):
    """du/dφ(φ, u, params, data) [-] of the journal under the load and the compiled film
    ``force`` (module docstring), compiled once per force and disk-cached for a module-level
    numba function: the right-hand side of the compiled flight's segment and of the
    ``adaptive`` integrator's compiled free phase
    (:func:`conrod.orbit.adaptive.compiled_free_rhs`)."""
    return bound_to_force(_rhs, film_force, "rhs")


def bound_to_force(template, film_force, suffix: str):
    """``template`` compiled with ``film_force`` bound as its global ``force``, named after
    the force with ``suffix``; disk-cached for a module-level numba function
    (:func:`is_global`), compiled per process otherwise."""
    jit = nb.njit(cache=True) if is_global(film_force) else nb.njit
    return jit(bind_globals(template, f"{stable_name(film_force)}_{suffix}",
                            {"force": film_force}))


def is_global(function) -> bool:
    """True for a numba function bound to its name in its module (not a closure)."""
    py_func = getattr(function, "py_func", None)
    module = sys.modules.get(getattr(py_func, "__module__", None) or "")
    return (py_func is not None and py_func.__closure__ is None
            and getattr(module, py_func.__name__, None) is function)


def stable_name(function) -> str:
    """A stable identifier from the function's module and name."""
    py_func = getattr(function, "py_func", function)
    return f"{py_func.__module__}.{py_func.__name__}".replace(".", "_")
