"""Per-crank-angle diagnostics of an elastohydrodynamic orbit.

At every output crank angle the elastic film's answer is read from the memory sampled
there: the end of the implicit step that the orbit with mass accepted there holds that
step's converged pressure on the deformation it solved
(:meth:`conrod.ehd.film.ElasticFilm.accepted_result`); elsewhere (the massless orbit) the
film is solved once more from that memory (the coupling is already converged, so this is
one film solve). It gives:

* ``coupling_iterations`` — film solves of the couplings on the accepted path of that step
  (the orbit's own trial solves for its Jacobian are not counted) [-];
* ``newton_updates`` — Newton updates of those couplings (the film solves less each
  coupling's solve at its start value and the line-search trials); written when the
  couplings are Newton iterations (not for the mass-conserving film's content step) [-];
* ``force_residual_N`` — |F + W| of the massless force balance (the normal component taken
  by the contact circle removed); with a moving mass, |F + W − m a| with a of the
  implicit step that ended there (orbit with mass on the elastic bore), else from the
  periodic central difference of the output velocities [N];
* ``deformation_increment_m`` — the last deformation increment max|Δu| of the coupling [m];
* ``bore_displacement_min_m`` / ``_max_m`` — range of the corrected bore displacement [m];
* ``coupling_residual_m`` — max|G(u)| of the coupling [m];
* ``asperity_force_N`` — with mixed lubrication carried by the film, the Greenwood–Tripp
  asperity force on the deformed film [N] (:mod:`conrod.ehd.asperity`).

Besides the columns: the film thickness on the deformed bore h = c − e_x cos θ − e_y sin θ
+ u at the bore nodes (every figure and table of the elastic run draws this gap), the
film pressure at the angle of the largest load and at further requested angles (the rod
stresses use them), and at a chosen angle the bore displacement split into its film-pressure
and inertia parts.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from conrod.film.capabilities import HasAcceptedAnswer, accepted_film


@dataclass(frozen=True)
class ElasticCycle:
    """The bore deformation and the coupling diagnostics over the output crank angles.

    deformation : ndarray  Corrected bore displacement u (n_out, n_θ) [m], outward +; for a
        housing that deforms along the width, its mean over the width.
    angles : ndarray  Bore-node angles θ [rad].
    columns : dict  Diagnostic columns (names with units) of length n_out.
    field : ndarray or None  u(θ, z) (n_out, n_θ, n_z + 1) [m] of a housing that deforms
        along the width; None for a plane one (uniform in z).
    """

    deformation: np.ndarray
    angles: np.ndarray
    columns: dict[str, np.ndarray]
    peak_load_index: int = 0
    peak_load_pressure: np.ndarray | None = None
    field: np.ndarray | None = None
    """Bore displacement u(θ, z) per output row (n_out, n_θ, n_z + 1) [m] of a housing that
    deforms along the width; None for a plane housing."""
    pressures: dict[int, np.ndarray] | None = None
    """Film pressure p(θ, z) [Pa] at the output rows asked for (row → field)."""

    def film_thickness(self, cycle, clearance: float, points: int = 361,
                       bore_shape: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """(shell angles θ, 0 … 2π, ``points`` of them [rad]; film thickness on the deformed
        bore h(φ, θ) = c − e_x cos θ − e_y sin θ + u(θ) at each output angle (n_out,
        ``points``) [m]; the width-mean u of a bore that deforms along the width),
        u interpolated linearly (periodically) between the bore nodes; ``bore_shape``: the
        housing's static bore shape h₀ at the bore nodes [m] (assembled, warm) added to u."""
        theta = np.linspace(0.0, 2.0 * np.pi, points)
        rows = self.deformation if bore_shape is None else self.deformation + bore_shape
        u = np.array([np.interp(theta, self.angles, row, period=2.0 * np.pi) for row in rows])
        h = (clearance - np.asarray(cycle.eccentricity_x)[:, None] * np.cos(theta)[None, :]
             - np.asarray(cycle.eccentricity_y)[:, None] * np.sin(theta)[None, :] + u)
        return theta, h


def elastic_cycle(problem, cycle, film_memory: list, massless: bool,
                  pressure_rows: tuple[int, ...] = ()) -> ElasticCycle:
    """Diagnostics of the last cycle of an orbit of the elastic film ``problem.film``, with
    the film pressure at the largest load and at the output rows ``pressure_rows``."""
    film = problem.film
    names = ("coupling_iterations", "coupling_residual_m", "deformation_increment_m",
             "bore_displacement_min_m", "bore_displacement_max_m")
    columns = {name: np.zeros(len(cycle.crank_angle)) for name in names}
    force = np.zeros((len(cycle.crank_angle), 2))
    updates = np.zeros(len(cycle.crank_angle))
    deformation = np.zeros((len(cycle.crank_angle), len(film.housing.angles)))
    fields: list[np.ndarray] | None = [] if not film.housing.uniform_in_z else None
    peak = int(np.argmax(np.hypot(cycle.load_x, cycle.load_y)))
    wanted = {peak, *pressure_rows}
    pressures = {}
    answers = isinstance(film, HasAcceptedAnswer)  # asked once for all rows
    for i, memory in enumerate(film_memory):
        state = problem.row_state(cycle, i)
        result, after = accepted_film(film, state, memory, with_pressure=i in wanted,
                                      answers=answers)
        if i in wanted:
            pressures[i] = result.pressure
        force[i] = result.force_x, result.force_y
        deformation[i] = film.housing.row_mean(after.deformation)
        if fields is not None:
            fields.append(film.housing.field_view(after.deformation))
        columns["coupling_iterations"][i] = memory.iterations
        updates[i] = memory.updates
        columns["coupling_residual_m"][i] = after.residual
        columns["deformation_increment_m"][i] = memory.increment
        columns["bore_displacement_min_m"][i] = after.deformation.min()
        columns["bore_displacement_max_m"][i] = after.deformation.max()
        if "asperity_force_N" in result.extra:
            columns.setdefault("asperity_force_N", np.zeros(len(cycle.crank_angle)))
            columns["asperity_force_N"][i] = result.extra["asperity_force_N"]
    if updates.any():
        columns["newton_updates"] = updates
    columns["force_residual_N"] = _force_residual(problem, cycle, force, massless,
                                                  _step_accelerations(film_memory))
    return ElasticCycle(deformation, np.asarray(film.housing.angles), columns, peak,
                        pressures.get(peak), None if fields is None else np.array(fields),
                        pressures)



def asperity_forces(problem, cycle, film_memory: list) -> np.ndarray:
    """The Greenwood–Tripp asperity force on the deformed film at each output angle [N]:
    one film solve per angle from the memory sampled there (zero where the film reports
    none)."""
    film = problem.film
    forces = np.zeros(len(cycle.crank_angle))
    answers = isinstance(film, HasAcceptedAnswer)
    for i, memory in enumerate(film_memory):
        result, _ = accepted_film(film, problem.row_state(cycle, i), memory, answers=answers)
        forces[i] = float(result.extra.get("asperity_force_N", 0.0))
    return forces


def displacement_split(film, cycle, deformation: np.ndarray, index: int) -> dict[str, float]:
    """The bore displacement at the output row ``index`` where the film is thinnest, split
    into the part the rod's inertia makes and the part the film pressure makes (the rest),
    at the bore node nearest the angle of h_min (outward +; the width-mean of a bore that
    deforms along the width) [m, deg]."""
    angles = np.asarray(film.housing.angles)
    theta = float(cycle.h_min_angle_shell[index])
    node = int(np.argmin(np.abs((angles - theta + np.pi) % (2.0 * np.pi) - np.pi)))
    inertia = film.housing.row_mean(film.inertia_deformation(float(cycle.crank_angle[index])))
    total = float(deformation[index, node])
    return {"crank_angle_deg": float(np.degrees(cycle.crank_angle[index])),
            "shell_angle_deg": float(np.degrees(angles[node]) % 360.0),
            "total_m": total, "inertia_m": float(inertia[node]),
            "pressure_m": total - float(inertia[node])}


def _step_accelerations(film_memory: list) -> np.ndarray | None:
    """The journal accelerations of the implicit steps that ended at the output angles
    (n_out, 2) [m/s²], None when the memories do not hold them (massless, rk2)."""
    values = [getattr(memory, "acceleration", None) for memory in film_memory]
    if any(value is None for value in values):
        return None
    return np.asarray(values, dtype=float)


def _force_residual(problem, cycle, force: np.ndarray, massless: bool,
                    accelerations: np.ndarray | None = None) -> np.ndarray:
    """|F + W (− m a)| [N], the contact circle's normal reaction removed; ``accelerations``
    [m/s²] of the steps, else a from the output velocities."""
    rx = force[:, 0] + cycle.load_x
    ry = force[:, 1] + cycle.load_y
    if not massless and accelerations is not None:
        rx = rx - problem.mass_x * accelerations[:, 0]
        ry = ry - problem.mass_y * accelerations[:, 1]
    elif not massless:
        dphi = float(cycle.crank_angle[1] - cycle.crank_angle[0])
        dt = dphi / problem.crank_speed
        ax = (np.roll(cycle.velocity_x, -1) - np.roll(cycle.velocity_x, 1)) / (2 * dt)
        ay = (np.roll(cycle.velocity_y, -1) - np.roll(cycle.velocity_y, 1)) / (2 * dt)
        rx, ry = rx - problem.mass_x * ax, ry - problem.mass_y * ay
    e = np.hypot(cycle.eccentricity_x, cycle.eccentricity_y)
    contact = np.asarray(cycle.in_contact, dtype=bool) & (e > 0)
    nx = np.where(contact, cycle.eccentricity_x / np.where(e > 0, e, 1.0), 0.0)
    ny = np.where(contact, cycle.eccentricity_y / np.where(e > 0, e, 1.0), 0.0)
    normal = np.maximum(rx * nx + ry * ny, 0.0)
    return np.hypot(rx - normal * nx, ry - normal * ny)
