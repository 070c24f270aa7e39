"""Rod stresses under the two load schemes compared by Rodin (2004, ch. 3).

At a crank angle φ the FE rod (clamped as for the compliance) carries its own inertia
(:mod:`conrod.housing.inertia`) plus, on the big-end bore,

* scheme (a) ``pressure``: the film pressure field itself (nodal forces through
  :mod:`conrod.housing.transfer`);
* scheme (b) ``cosine``: the same resultant W spread as q(θ) = q₀ cos(θ − θ_W) over
  |θ − θ_W| ≤ 90°, the textbook load distribution.

The small end carries the clamp reaction in both schemes (the seed loads it with a cosine
distribution; the big-end stresses are not affected). Von Mises stresses are evaluated at
the element centroids (plane stress).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from conrod.housing.fe import centroid_stresses, von_mises

BIG_END = ("cap", "head")
"""Regions of the big end (an imported mesh has the single region "all")."""


@dataclass(frozen=True)
class StressField:
    """Von Mises stress of one load case.

    von_mises : ndarray  Per element, at the centroid [Pa].
    centroids : ndarray  Element centroids (n_elements, 2), rod frame [m].
    region : ndarray  Region index per element [-]; names in ``region_names``.
    region_names : tuple  Region names [-].
    bore_displacement : ndarray  Raw radial displacement at the film nodes [m].
    largest_displacement : float  Largest displacement magnitude in the rod [m].
    """

    von_mises: np.ndarray
    centroids: np.ndarray
    region: np.ndarray
    region_names: tuple[str, ...]
    bore_displacement: np.ndarray
    largest_displacement: float

    @property
    def maximum(self) -> float:
        """Largest von Mises stress [Pa]."""
        return float(self.von_mises.max())

    def maximum_in(self, regions: tuple[str, ...]) -> float:
        """Largest von Mises stress in the named regions (all when none match) [Pa]."""
        chosen = [k for k, name in enumerate(self.region_names) if name in regions]
        mask = np.isin(self.region, chosen) if chosen else np.ones(len(self.region), bool)
        return float(self.von_mises[mask].max())

    @property
    def maximum_location(self) -> tuple[float, float]:
        """Centroid (x, y) of the most stressed element [m]."""
        k = int(np.argmax(self.von_mises))
        return float(self.centroids[k, 0]), float(self.centroids[k, 1])

    def zones(self) -> dict[str, dict[str, float]]:
        """Per region: largest stress [Pa], where (x, y [m], θ [deg] about the big end)."""
        result = {}
        for index, name in enumerate(self.region_names):
            members = np.flatnonzero(self.region == index)
            if len(members) == 0:
                continue
            k = members[np.argmax(self.von_mises[members])]
            x, y = self.centroids[k]
            result[name] = {"max_von_mises_Pa": float(self.von_mises[k]), "x_m": float(x),
                            "y_m": float(y),
                            "angle_deg": float(np.degrees(np.mod(np.arctan2(y, x), 2 * np.pi)))}
        return result


def cosine_forces(angles: np.ndarray, resultant: np.ndarray) -> np.ndarray:
    """Nodal forces [N] of a cosine load over ±90° whose discrete resultant is ``resultant``
    (x, y) [N] (outward on the housing)."""
    direction = np.arctan2(resultant[1], resultant[0])
    relative = np.cos(angles - direction)
    shape = np.where(relative > 0.0, relative, 0.0)
    return float(np.hypot(*resultant)) * shape / np.sum(shape * relative)


def force_resultant(angles: np.ndarray, forces: np.ndarray) -> np.ndarray:
    """Resultant (x, y) [N] of outward nodal forces [N] at the film angles [rad]."""
    return np.array([np.sum(forces * np.cos(angles)), np.sum(forces * np.sin(angles))])


def stress_field(housing, forces: np.ndarray, crank_angle: float | None) -> StressField:
    """Von Mises field of the rod under bore forces [N] plus inertia at φ [rad] (if given)."""
    structure = housing.structure
    model = structure.model
    load = structure.film_load(forces)
    if crank_angle is not None and housing.kinematics is not None:
        load = load + model.body_load(housing.kinematics.body_force(crank_angle))
    displacement = model.solve(load)
    mesh = model.fe_mesh.mesh
    corners = mesh.doflocs[:, mesh.t]
    magnitude = np.hypot(displacement[0::2], displacement[1::2])
    return StressField(
        von_mises=von_mises(centroid_stresses(model, displacement)),
        centroids=corners.mean(axis=1).T,
        region=model.fe_mesh.region,
        region_names=model.fe_mesh.region_names,
        bore_displacement=structure.film_displacement(displacement),
        largest_displacement=float(magnitude.max()),
    )


def compare_schemes(housing, forces: np.ndarray, crank_angle: float) -> dict:
    """Both schemes at φ [rad] for film nodal forces [N]: fields and their differences."""
    resultant = force_resultant(housing.angles, forces)
    pressure = stress_field(housing, forces, crank_angle)
    cosine = stress_field(housing, cosine_forces(housing.angles, resultant), crank_angle)
    corrected = [np.ptp(housing.correct(field.bore_displacement)) for field in (pressure,
                                                                                 cosine)]
    return {
        "pressure": pressure, "cosine": cosine,
        "resultant_N": resultant,
        "stress_ratio": pressure.maximum / cosine.maximum,
        "big_end_stress_ratio": pressure.maximum_in(BIG_END) / cosine.maximum_in(BIG_END),
        "displacement_ratio": pressure.largest_displacement / cosine.largest_displacement,
        "bore_distortion_ratio": float(corrected[0] / corrected[1]),
    }
