"""Characteristics of a solved Reynolds film (:class:`~conrod.film.reynolds.film.ReynoldsFilm`):
forces, tilting moments and extremes of the pressure, friction torques of the shear with
μ(p), flows and cavitation from the discrete flow balance of the solved field ([D2] ch. 3),
the axial position of h_min and the edge h_min (:mod:`conrod.film.tilt`)."""

from __future__ import annotations

import math
from typing import Any

from conrod.film import characteristics as chars
from conrod.film.base import FilmResult, FilmState
from conrod.film.reynolds import kernel as kernel
from conrod.film.reynolds.viscosity_field import state_field
from conrod.film.tilt import axial_summary


def reynolds_characteristics(film: Any, problem: Any, reduced, pressure, state: FilmState,
                             info: dict) -> FilmResult:
    """Characteristics; flows and cavitation from the solved (reduced) field [Pa], forces,
    p_max and shear from the pressure [Pa] with μ(p); ``problem`` the film's discrete
    problem of ``state``, ``info`` the solver's diagnostics."""
    grid, h = film.film_grid, problem.h
    p_cav = problem.cavitation
    omega_sum = state.journal_speed + state.shell_speed
    a_east, a_north, source = problem.coefficients or kernel.assemble_coefficients(
        h, problem.h_rate, grid.radius, grid.d_theta, grid.d_z, omega_sum, state.viscosity
    )
    lost, leaking, supply, cavitated_width = kernel.flow_balance(
        reduced, a_east, a_north, source, problem.fixed, p_cav, grid.axial_weights)
    to_flow = 1.0 / (12.0 * state.viscosity)
    fraction = None
    if film.friction == "film_fraction":
        direction = 1 if omega_sum >= 0.0 else -1
        fraction = kernel.film_fraction_swift_stieber(
            reduced, h, problem.fixed, p_cav, direction)
    law = film.pressure_viscosity
    viscosity = (state.viscosity if law is None
                 else state.viscosity * law.viscosity_ratio(pressure, state.viscosity))
    field = state_field(state, film.viscosity_field, h.shape)
    if field is not None:  # the local viscosity in the shear
        viscosity = field
    torque_j, torque_b = chars.friction_torques(
        pressure, h, grid, state.journal_speed, state.shell_speed, viscosity, fraction)
    w_x, w_y = film.force_weights
    sum_x, sum_y, i_p, j_p, i_h, j_h = kernel.force_and_extremes(pressure, w_x, w_y, h)
    fx, fy = -sum_x, -sum_y
    profile = film.geometry.profile  # one with kinks in θ: the parabola would overshoot
    smooth = film.profile is None or profile.smooth_around
    h_min, h_angle = (chars.minimum_film_at(h, grid, i_h, j_h) if smooth
                      else (float(h[i_h, j_h]), float(grid.theta[i_h])))
    axial = axial_summary(h, i_h, grid, film.geometry.radial_clearance, pressure,
                          film.moment_weights, refine=smooth)
    p_max, p_angle = chars.peak_pressure_at(pressure, grid, i_p, j_p)
    info = dict(info)
    info["cavitation_flow_m3_per_s"] = lost * to_flow
    if problem.journal_holes is not None:  # signed: positive into the bearing
        imbalance = kernel.node_imbalance(reduced, a_east, a_north, source)
        info["journal_hole_flow_m3_per_s"] = float(imbalance[problem.journal_holes].sum()) * to_flow
    info["friction_full_film"] = float(film.friction == "full_film")
    if law is not None:
        info.update(law.diagnostics(reduced, pressure, state.viscosity))
    return FilmResult(
        force_x=fx, force_y=fy,
        friction_torque_journal=torque_j, friction_torque_shell=torque_b,
        side_flow=-leaking * to_flow, supply_flow=supply * to_flow,
        min_film_thickness=h_min, min_film_angle=h_angle,
        max_pressure=p_max, max_pressure_angle=p_angle,
        cavitated_fraction=cavitated_width * grid.d_theta / (2.0 * math.pi * grid.width),
        friction_power=-(torque_j * state.journal_speed + torque_b * state.shell_speed),
        extra=info, **axial,
    )
