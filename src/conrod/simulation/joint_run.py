"""The bonded rod/cap joint over an elastic run (``summary.json["elastic"]["joint_over_run"]``):
its assembled normal stress plus that of the run's own film pressure on the deformed bore
and of the rod's inertia, at every output angle of the last cycle."""

from __future__ import annotations

from typing import Any

import numpy as np


def joint_over_run(housing: Any, results: Any, pressures: dict[int, np.ndarray]
                   ) -> dict[str, Any]:
    """The bonded joint over the last cycle of an elastic run: its assembled stress plus that
    of the film pressure on the deformed bore (the run's own, at every output angle) and the
    rod's inertia (``summary.json["elastic"]["joint_over_run"]``, units in the key names)."""
    theta, z = results.pressure_grid
    angles = np.asarray(results.cycle.crank_angle)
    forces = np.array([housing.nodal_forces(pressures[row], z, theta)
                       for row in range(len(angles))])
    coefficients = None if housing.kinematics is None else np.array(
        [housing.inertia_coefficients(phi) for phi in angles])
    stress = housing.assembly.joint_stress(forces, coefficients)
    row, point = np.unravel_index(int(np.argmax(stress)), stress.shape)
    joint = housing.assembly.joint
    return {"opens": bool(stress.max() > 0.0),
            "open_share_of_joint": float(np.mean(stress.max(axis=0) > 0.0)),
            "smallest_pressure_Pa": float(-stress[row, point]),
            "at_crank_angle_deg": float(np.degrees(angles[row])),
            "at_side": "+y" if joint["side"][point] > 0 else "-y",
            "at_distance_from_bore_centre_m": float(joint["distance_m"][point]),
            "running_loads": "film pressure of this run on the deformed bore and the rod's "
                             "own inertia, at every output angle of the last cycle"}
