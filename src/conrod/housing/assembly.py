"""The assembled big end: bolt preload and shell crush as one static load case of the FE
housing, computed once per housing (cached with the compliance, :mod:`conrod.housing.build`).

**Bolts** (built-in rod). Each of the two bolts crosses the split line perpendicularly, at
±b/2 from the rod axis along the split (``bolt_distance`` b). A preload F stretches the bolt
and presses the clamped parts together: the head pushes the cap towards the rod with F and
the thread pulls the rod towards the cap with F. Both act as smooth bands of body force
(weight 1 − (r/r_s)² at a distance r from a segment, r_s a sixth of the thinner head wall w
or the local element size if larger, exactly F each): the head's across the bolt just
inside the cap's outline (the bearing face, w/2 long), the thread's along the bolt axis
over the engagement, from ``bolt_thread_depth`` − w/4 to + w/4 past the split line. The
pair is self-equilibrated: it compresses the joint between them with F per side.

**Shell crush**. The two half shells are together 2Δh longer around than the housing bore
(Δh the crush height per half shell). Pressed in, the shell is a thin ring of stiffness
E_s t_s whose hoop force N presses on the bore with a uniform pressure p = N/R_b (no
friction, no bending stiffness of the shell); the bore opens by its mean radial displacement
ū = g p (g from the FE model under a unit pressure). Compatibility of the shell's
circumference with the opened bore gives

.. math:: p = \\frac{E_s t_s}{R_b^2}\\Big(\\frac{Δh}{π} − ū\\Big)
          = \\frac{k_s Δh/π}{1 + k_s g}, \\qquad k_s = \\frac{E_s t_s}{R_b^2}

(interference δ given instead: Δh = π δ). The shell's own radial compression is neglected.

**Joint**: bonded (:mod:`conrod.housing.joint`): the joint pressure is the normal stress
across the split line of this load case; where the running loads would pull the bonded joint
into tension, a real joint opens.

**In the film**: the raw assembled bore displacement u(θ) at the film nodes, corrected for
the rigid-body translation like every deformation, enters the film as a bore profile h₀(θ)
(outward + is more clearance) on top of which the running deformation acts. With
``clearance_reference = "assembled"`` (the default) its mean is removed: the clearance of
``[bearing]`` is the assembled bore's mean clearance, and only the out-of-round shape enters.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
from skfem import LinearForm, asm

from conrod.errors import CaseError

ASSEMBLY_FORMAT = 2
"""Version of the assembly load model, part of its cache key: bumped whenever the bolt,
crush or joint model changes its answer [-]."""
SPOT_SHARE = 1.0 / 6.0
"""Half-thickness of a bolt's load bands, share of the thinner head wall [-]."""
BAND_SHIFTS = 8
"""Largest number of shifts of a load band onto its line of action [-]."""


@dataclass(frozen=True)
class BoltLayout:
    """Where the bolt loads act (built-in rod), rod frame.

    heads, threads : ndarray  (2, 2) centres of the head and thread bands, side + then − [m].
    direction : ndarray  (2,) bolt axis, from the cap towards the rod [-].
    spot_radius : float  Half-thickness r_s of the load bands [m].
    band_length : float  Half-length of the head band (across the bolt) and of the thread band
        (along it) [m].
    """

    heads: np.ndarray
    threads: np.ndarray
    direction: np.ndarray
    spot_radius: float
    band_length: float


def bolt_layout(geometry, bolt_distance: float | None, thread_depth: float | None
                ) -> BoltLayout:
    """The bolts of the built-in rod ``geometry`` (module docstring); CaseError naming the
    field when a bolt would not lie in the wall."""
    normal = geometry.split_normal()
    tangent = np.array([-normal[1], normal[0]])
    r_b = geometry.bore_radius
    head_wall = geometry.head_outer_radius - r_b
    wall = min(head_wall, geometry.cap_outer_radius - r_b)
    spot = SPOT_SHARE * wall
    half = 0.5 * bolt_distance if bolt_distance is not None else r_b + 0.5 * wall
    depth = thread_depth if thread_depth is not None else 0.5 * head_wall
    if half < r_b + spot:
        raise CaseError(f"housing.assembly.bolt_distance = {2.0 * half:.6g}: the bolts cut "
                        f"the bore (allowed: > {2.0 * (r_b + spot):.6g} m)")
    joint_reach = min(geometry.head_outer_radius, geometry.cap_outer_radius)
    if half > joint_reach - spot:
        raise CaseError(f"housing.assembly.bolt_distance = {2.0 * half:.6g}: the bolts lie "
                        "outside the big-end wall at the split line (allowed: <= "
                        f"{2.0 * (joint_reach - spot):.6g} m)")
    reach = float(np.sqrt(geometry.cap_outer_radius**2 - half**2))  # to the cap's outline
    if reach < 3.0 * spot:
        raise CaseError(f"housing.assembly.bolt_distance = {2.0 * half:.6g}: the cap is only "
                        f"{reach:.3g} m deep along the bolts (allowed: bolts through the cap)")
    if np.hypot(half, depth) > geometry.head_outer_radius - 0.5 * spot:
        raise CaseError(f"housing.assembly.bolt_thread_depth = {depth:.6g}: the thread lies "
                        "outside the rod (allowed: a depth inside the head wall)")
    feet = np.array([half * tangent, -half * tangent])
    if depth < 0.25 * wall + spot:
        raise CaseError(f"housing.assembly.bolt_thread_depth = {depth:.6g}: the thread "
                        "engagement crosses the split line (allowed: >= "
                        f"{0.25 * wall + spot:.6g} m)")
    return BoltLayout(feet - (reach - spot) * normal, feet + depth * normal, normal, spot,
                      0.25 * wall)


def mesh_bolt_layout(mesh, split, bolt_distance: float | None, thread_depth: float | None
                     ) -> BoltLayout:
    """The bolts of an imported mesh ``mesh`` split along ``split``
    (:class:`~conrod.housing.joint.SplitLine`): both positions given (``bolt_distance``,
    ``bolt_thread_depth``), the wall and the cap's depth along the bolts found by ray casts
    on the mesh; CaseError naming the field when a bolt would not lie in the wall."""
    from conrod.housing.joint import mesh_reach, ray_reach

    if bolt_distance is None or thread_depth is None:
        raise CaseError("housing.assembly.bolt_preload on an imported mesh needs "
                        "bolt_distance and bolt_thread_depth (allowed: both given, in m)")
    normal = split.split_normal()
    tangent = np.array([-normal[1], normal[0]])
    r_b, half = split.bore_radius, 0.5 * bolt_distance
    joint_reach = min(mesh_reach(mesh, tangent, r_b), mesh_reach(mesh, -tangent, r_b))
    wall = joint_reach - r_b
    spot = SPOT_SHARE * wall
    if not r_b + spot <= half <= joint_reach - spot:
        raise CaseError(f"housing.assembly.bolt_distance = {bolt_distance:.6g}: the bolts do "
                        "not lie in the wall at the split line (allowed: >= "
                        f"{2.0 * (r_b + spot):.6g} and <= {2.0 * (joint_reach - spot):.6g} m)")
    feet = np.array([half * tangent, -half * tangent])
    reach = min(ray_reach(mesh, foot, -normal) for foot in feet)
    if reach < 3.0 * spot:
        raise CaseError(f"housing.assembly.bolt_distance = {bolt_distance:.6g}: the cap is "
                        f"only {reach:.3g} m deep along the bolts (allowed: bolts through the "
                        "cap)")
    depth_room = min(ray_reach(mesh, foot, normal) for foot in feet)
    if not 0.25 * wall + spot <= thread_depth <= depth_room - 0.25 * wall - spot:
        raise CaseError(f"housing.assembly.bolt_thread_depth = {thread_depth:.6g}: the thread "
                        "engagement does not lie in the rod (allowed: >= "
                        f"{0.25 * wall + spot:.6g} and <= "
                        f"{depth_room - 0.25 * wall - spot:.6g} m)")
    return BoltLayout(feet - (reach - spot) * normal, feet + thread_depth * normal, normal,
                      spot, 0.25 * wall)


def band_load(model, start: np.ndarray, end: np.ndarray, radius: float,
              force: np.ndarray) -> np.ndarray:
    """FE load vector [N] of a smooth band of body force, weight 1 − (r/r_s)² at the
    distance r from the segment ``start``–``end`` (2,) [m], r_s = ``radius`` [m], scaled to
    the resultant ``force`` (2,) [N] exactly, its line of action through the segment's
    mid-point (both on the model's own quadrature: the band is shifted across the force
    until its discrete centroid lies on that line, so that a bolt's two bands make no
    moment)."""
    basis = model.basis
    thickness = np.repeat(model.fe_mesh.thickness[:, None], basis.X.shape[1], axis=1)
    x, y = np.asarray(basis.global_coordinates())
    lateral = np.array([-force[1], force[0]]) / np.hypot(*force)
    target = float(lateral @ (0.5 * (start + end)))

    def offset(amount: float) -> tuple[float, float]:
        """(target − discrete centroid across the force [m], total weight [m³]) of the
        band shifted by ``amount`` across the force [m]."""
        moved = amount * lateral
        weights = basis.dx * thickness * _band_weight(x, y, start + moved, end + moved, radius)
        total = float(np.sum(weights))
        if total <= 0.0:
            raise CaseError("housing.assembly: a bolt load band holds no quadrature point "
                            "(allowed: a smaller housing.element_size)")
        return target - float(np.sum(weights * (lateral[0] * x + lateral[1] * y))) / total, total

    previous, (miss_before, total) = 0.0, offset(0.0)
    amount = miss_before
    for _ in range(BAND_SHIFTS):  # secant steps on the shift (a clipped band moves less)
        miss, total = offset(amount)
        if abs(miss) < 1.0e-9 * radius or miss == miss_before:
            break
        step = -miss * (amount - previous) / (miss - miss_before)
        previous, miss_before = amount, miss
        amount = amount + float(np.clip(step, -radius, radius))  # a clipped band: no leaps
    _, total = offset(amount)
    shift = amount * lateral

    @LinearForm
    def form(v, w):
        share = w.t * _band_weight(w.x[0], w.x[1], start + shift, end + shift, radius) / total
        return share * (force[0] * v[0] + force[1] * v[1])

    return asm(form, basis, t=thickness)


def _band_weight(x, y, start: np.ndarray, end: np.ndarray, radius: float):
    axis = end - start
    along = np.clip(((x - start[0]) * axis[0] + (y - start[1]) * axis[1]) / (axis @ axis),
                    0.0, 1.0)
    gap2 = (x - start[0] - along * axis[0]) ** 2 + (y - start[1] - along * axis[1]) ** 2
    return np.maximum(0.0, 1.0 - gap2 / radius**2)


def bolt_load(model, layout: BoltLayout, preload: float) -> np.ndarray:
    """FE load vector [N] of both bolts at ``preload`` [N] each (module docstring)."""
    push = preload * layout.direction
    across = layout.band_length * np.array([-layout.direction[1], layout.direction[0]])
    along = layout.band_length * layout.direction
    load = np.zeros(model.n_dofs)
    for head, thread in zip(layout.heads, layout.threads, strict=True):
        radius = max(layout.spot_radius, local_element_size(model, head))
        load += band_load(model, head - across, head + across, radius, push)
        radius = max(layout.spot_radius, local_element_size(model, thread))
        load += band_load(model, thread - along, thread + along, radius, -push)
    return load


def local_element_size(model, point: np.ndarray) -> float:
    """Edge length of an equilateral triangle of the mean area of the three elements whose
    centroids lie nearest ``point`` [m]: a load band at least this thick holds quadrature
    points of several elements."""
    mesh = model.fe_mesh.mesh
    corners = mesh.doflocs[:, mesh.t[:3]]  # (2, 3, n_elements)
    centroids = corners.mean(axis=1)
    nearest = np.argsort(np.hypot(centroids[0] - point[0], centroids[1] - point[1]))[:3]
    a, b, c = (corners[:, k, nearest] for k in range(3))
    area = 0.5 * np.abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
    return float(np.sqrt(4.0 * area.mean() / np.sqrt(3.0)))


def crush_pressure(crush_height: float, shell_stiffness: float, opening: float) -> float:
    """Contact pressure p [Pa] of the crushed shell (module docstring): crush height Δh [m],
    k_s = E_s t_s / R_b² [Pa/m], g = mean bore opening per unit pressure [m/Pa]."""
    return shell_stiffness * crush_height / np.pi / (1.0 + shell_stiffness * opening)


def uniform_pressure_forces(angles: np.ndarray, radius: float, width: float) -> np.ndarray:
    """Outward nodal forces [N] of a unit pressure [Pa] over the bore of ``radius`` [m] and
    ``width`` [m] at the film nodes θ [rad] (uniform spacing)."""
    return np.full(len(angles), 2.0 * np.pi / len(angles) * radius * width)


@dataclass(frozen=True)
class AssembledBore:
    """The assembled bore and joint of a housing (module docstring).

    displacement : ndarray  Raw radial bore displacement at the film nodes, outward + [m].
    crush_pressure : float  Contact pressure of the crushed shell [Pa].
    bolt_preload : float  Preload per bolt [N].
    clearance_reference : str  ``assembled`` or ``nominal`` (module docstring).
    joint : dict or None  Built-in rod: ``distance_m`` (2k,), ``side`` (2k,),
        ``stress_Pa`` σ_nn assembled (2k,), ``influence_Pa_per_N`` (2k, n) per unit film
        nodal force, ``inertia_Pa`` (2k, 4) per unit inertia coefficient, ``thickness_m``.
    """

    displacement: np.ndarray
    crush_pressure: float
    bolt_preload: float
    clearance_reference: str = "assembled"
    joint: dict[str, Any] | None = None

    def arrays(self) -> dict[str, np.ndarray]:
        """Everything as named arrays for the cache (:func:`from_arrays` reads them back)."""
        out = {"assembly_displacement": self.displacement,
               "assembly_crush_pressure": np.array(self.crush_pressure),
               "assembly_bolt_preload": np.array(self.bolt_preload)}
        for name, value in (self.joint or {}).items():
            out[f"joint_{name}"] = np.asarray(value)
        return out

    @classmethod
    def from_arrays(cls, arrays: dict[str, np.ndarray], reference: str) -> AssembledBore:
        """The assembled bore stored by :meth:`arrays`."""
        joint = {name[len("joint_"):]: value for name, value in arrays.items()
                 if name.startswith("joint_")}
        joint = {k: (v.item() if v.ndim == 0 else v) for k, v in joint.items()}
        return cls(arrays["assembly_displacement"],
                   float(arrays["assembly_crush_pressure"]),
                   float(arrays["assembly_bolt_preload"]), reference, joint or None)

    def joint_stress(self, forces: np.ndarray, coefficients: np.ndarray | None = None
                     ) -> np.ndarray:
        """σ_nn along the joint [Pa], shape (m, 2k): assembled plus the running loads of m
        crank angles, film nodal forces (m, n) [N] and inertia coefficients (m, 4) (None:
        without the rod's inertia) (linear superposition in the bonded joint)."""
        if self.joint is None:
            raise CaseError("housing.assembly: the joint is known on the built-in rod only "
                            "(allowed: model = 'builtin')")
        stress = self.joint["stress_Pa"][None, :] + np.asarray(forces) @ self.joint[
            "influence_Pa_per_N"].T
        if coefficients is not None:
            stress = stress + np.asarray(coefficients) @ self.joint["inertia_Pa"].T
        return stress

    def joint_force(self) -> np.ndarray:
        """Normal force across each joint side (+, −) as assembled [N] (negative: pressed
        together; −preload per side from the bolts, crush pulls it apart)."""
        from conrod.housing.joint import JointLine, joint_force

        joint = self.joint
        line = JointLine(np.zeros((len(joint["side"]), 2)), joint["distance_m"],
                         joint["side"], np.zeros(2), joint["segment_m"])
        return joint_force(line, joint["stress_Pa"], joint["thickness_m"])

    def bore_profile(self, projector: np.ndarray) -> np.ndarray:
        """h₀(θ_j) [m] of the film: the corrected displacement (projector P), its mean
        removed for ``clearance_reference = "assembled"``."""
        corrected = projector @ self.displacement
        if self.clearance_reference == "assembled":
            corrected = corrected - corrected.mean()
        return corrected


def solve_assembly(structure, section, shell_thickness: float, shell_width: float,
                   geometry=None, joint_thickness: float | None = None) -> AssembledBore:
    """The assembled bore of ``structure`` (:class:`~conrod.housing.structure.
    StructuralHousing`) under ``section`` (``[housing.assembly]``): shell of thickness t_s
    and width [m]; ``geometry`` (the built-in rod's outline, or the
    :class:`~conrod.housing.joint.SplitLine` of an imported mesh; None: crush only, no
    joint) places the bolts and the joint, whose plane-stress thickness is
    ``joint_thickness`` [m]."""
    model = structure.model
    unit = structure.film_load(uniform_pressure_forces(structure.film_angles,
                                                       structure.bore_radius, shell_width))
    load, pressure = np.zeros(model.n_dofs), 0.0
    if section.shell_crush_height > 0.0:
        opening = float(np.mean(structure.film_displacement(model.solve(unit))))
        stiffness = section.shell_youngs_modulus * shell_thickness / structure.bore_radius**2
        pressure = crush_pressure(section.shell_crush_height, stiffness, opening)
        load += pressure * unit
    if section.bolt_preload > 0.0:
        if hasattr(geometry, "head_outer_radius"):  # the built-in rod: its own outline
            layout = bolt_layout(geometry, section.bolt_distance, section.bolt_thread_depth)
        else:
            layout = mesh_bolt_layout(model.fe_mesh.mesh, geometry, section.bolt_distance,
                                      section.bolt_thread_depth)
        load += bolt_load(model, layout, section.bolt_preload)
    field = model.solve(load)
    joint = None if geometry is None else joint_arrays(structure, geometry, field,
                                                       joint_thickness)
    return AssembledBore(structure.film_displacement(field), pressure, section.bolt_preload,
                         section.clearance_reference, joint)


def joint_arrays(structure, geometry, field: np.ndarray, thickness: float | None
                 ) -> dict[str, Any]:
    """σ_nn along the joint (:mod:`conrod.housing.joint`) of the assembled ``field`` [m],
    per unit film nodal force and per unit inertia coefficient (see :class:`AssembledBore`)."""
    from conrod.housing.joint import joint_line, normal_stress_operator

    model = structure.model
    line = joint_line(geometry, model.fe_mesh.mesh)
    operator = normal_stress_operator(model, line.points, line.normal)
    unit_fields = model.solve(structure.film_load(np.eye(len(structure.film_angles))))
    return {"distance_m": line.distance, "side": line.side, "segment_m": line.segment,
            "stress_Pa": operator @ field,
            "influence_Pa_per_N": operator @ unit_fields,
            "inertia_Pa": operator @ structure.inertia_fields(),
            "thickness_m": float(thickness if thickness is not None else 0.0)}
