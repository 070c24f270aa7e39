"""Build a :class:`~conrod.housing.housing.Housing` from a case (``[housing] model``): the
structure's arrays, handed to the housing type that :meth:`Housing.from_case` passes in."""

from __future__ import annotations

import hashlib
import time
from pathlib import Path
from typing import Any

import numpy as np

from conrod.housing.cache import cache_key, load_or_build
from conrod.housing.fe import Material, clamp_dofs_on_boundary, vector_basis
from conrod.housing.geometry import RodGeometry
from conrod.housing.inertia import CrankKinematics
from conrod.housing.structure import rod_clamp_dofs, rod_mesh, structural_rod
from conrod.units import rpm_to_rad_s


def film_angles(n_theta: int) -> np.ndarray:
    """Film-grid nodes θ_j = 2πj/n [rad] (as :class:`conrod.film.characteristics.FilmGrid`)."""
    return 2.0 * np.pi * np.arange(n_theta) / n_theta


def crank_kinematics(case) -> CrankKinematics | None:
    """ω, r, λ of ``[engine]`` (None without it)."""
    engine = case.engine
    if engine is None:
        return None
    return CrankKinematics(rpm_to_rad_s(engine.speed), engine.crank_radius,
                           engine.crank_radius / engine.rod_length)


def material_of(section) -> Material:
    """Elastic constants and density of ``[housing]``."""
    return Material(section.youngs_modulus, section.poisson_ratio, section.density)


def housing_from_case(case, make: Any, *, cache_dir=None, use_cache: bool = True) -> Any:
    """Housing of ``case`` built by ``make`` (the :class:`~conrod.housing.housing.Housing`
    type; needs ``[bearing]``, ``[engine]`` for the inertia fields)."""
    case.require("housing", "bearing")
    section, angles = case.housing, film_angles(case.solver.n_theta)
    radius = 0.5 * case.bearing.diameter
    common = {"correction": section.correction, "kinematics": crank_kinematics(case)}
    if section.model not in ("builtin", "mesh"):
        from conrod.housing.as_built import warm_bore

        common["warm"] = warm_bore(case)  # no FE model: the bore grows as a free ring
    if section.model == "compliance":
        return _imported(case, make, angles, radius, common)
    if section.model in ("builtin", "mesh"):
        return _finite_element(case, make, angles, radius, common, cache_dir, use_cache)
    n = len(angles)
    return make(angles, radius, np.zeros((n, n)), np.zeros((n, 4)),
                   info={"model": "rigid"}, **common)


def _imported(case, make, angles, radius, common) -> Any:
    from conrod.housing.imported import imported_housing

    return imported_housing(case, make, angles, radius, common)


COUPLING_FIELDS = ("coupling_tolerance", "rigid_start_deg", "increment_share",
                   "coupling_iterations")
"""[housing] fields of the film coupling: not part of the cached structure [-]."""


def _cache_payload(case) -> dict:
    section = case.housing
    skip = {"stress_angles", "correction", "assembly", "thermal", *COUPLING_FIELDS}
    payload = {"housing": section.model_dump(mode="json", exclude=skip),
               "bearing": [case.bearing.diameter, case.bearing.width],
               "rod_length": case.engine.rod_length if case.engine else None,
               "n_theta": case.solver.n_theta}
    if section.model == "mesh":
        payload["mesh_sha256"] = hashlib.sha256(
            case.resolve(section.mesh_file).read_bytes()).hexdigest()
    return payload


def _finite_element(case, make, angles, radius, common, cache_dir, use_cache) -> Any:
    factory = _structure_factory(case, angles)
    holder: dict = {}

    def build() -> dict[str, np.ndarray]:
        start = time.perf_counter()
        structure = factory()
        holder["structure"] = structure
        fields = structure.inertia_fields()
        return {"compliance": structure.compliance(),
                "inertia_base": structure.film_displacement(fields),
                "build_seconds": np.array(time.perf_counter() - start),
                "n_dofs": np.array(structure.model.n_dofs),
                "n_elements": np.array(structure.model.fe_mesh.mesh.t.shape[1]),
                "bore_nodes": np.array(len(structure.bore_angles))}

    if case.housing.model == "mesh" and not case.resolve(case.housing.mesh_file).exists():
        from conrod.errors import CaseError

        raise CaseError(f"housing.mesh_file {str(case.resolve(case.housing.mesh_file))!r}: "
                        "no such file")
    start = time.perf_counter()
    arrays, from_cache = load_or_build(cache_key(_cache_payload(case)), build, cache_dir,
                                       use_cache)
    info = {"model": case.housing.model, "axial": "uniform in z (plane stress)",
            "from_cache": from_cache,
            "seconds": time.perf_counter() - start,
            **{name: arrays[name].item() for name in ("build_seconds", "n_dofs", "n_elements",
                                                       "bore_nodes")}}
    assembly = _assembly(case, factory, holder, cache_dir, use_cache, info)
    warm = _warm(case, factory, holder, cache_dir, use_cache, info)
    housing = make(angles, radius, arrays["compliance"], arrays["inertia_base"], info=info,
                      structure_factory=factory, assembly=assembly, warm=warm, **common)
    if "structure" in holder:
        housing.__dict__["structure"] = holder["structure"]
    return housing


def _assembly(case, factory, holder: dict, cache_dir, use_cache: bool, info: dict) -> Any:
    """The assembled bore of ``[housing.assembly]`` (None without preload and crush), from
    the cache or one static FE solve (:mod:`conrod.housing.assembly`)."""
    section = case.housing.assembly
    if section is None or not section.active:
        return None
    from conrod.housing.assembly import AssembledBore, solve_assembly

    def build() -> dict[str, np.ndarray]:
        start = time.perf_counter()
        if "structure" not in holder:
            holder["structure"] = factory()
        geometry, width = None, case.bearing.width
        head = case.housing.thicknesses(width)["head"]
        if case.housing.model == "builtin":
            geometry = RodGeometry(**case.housing.rod_outline(
                case.bearing.diameter, case.engine.rod_length if case.engine else None))
        elif section.bolt_preload > 0.0:  # an imported mesh split as [housing] split_angle
            from conrod.housing.joint import SplitLine

            geometry = SplitLine(np.radians(case.housing.split_angle),
                                 holder["structure"].bore_radius)
            head = case.housing.thickness if case.housing.thickness is not None else width
        shell = 0.5 * (case.housing.bore_diameter(case.bearing.diameter) - case.bearing.diameter)
        assembled = solve_assembly(holder["structure"], section, shell, width, geometry, head)
        return {**assembled.arrays(), "assembly_seconds": np.array(time.perf_counter() - start)}

    from conrod.housing.assembly import ASSEMBLY_FORMAT

    payload = {**_cache_payload(case), "assembly_format": ASSEMBLY_FORMAT,
               "assembly": section.model_dump(mode="json", exclude={"clearance_reference"})}
    arrays, from_cache = load_or_build(cache_key(payload), build, cache_dir, use_cache)
    info["assembly_from_cache"] = from_cache
    info["assembly_seconds"] = arrays.pop("assembly_seconds").item()
    return AssembledBore.from_arrays(arrays, section.clearance_reference)


def _warm(case, factory, holder: dict, cache_dir, use_cache: bool, info: dict) -> Any:
    """The warm bore of ``[housing.thermal]`` (None without it) with the FE thermal bore
    displacement: per unit strain for a uniform housing temperature (cached once), or of the
    conduction field from the shell-side temperatures (cached per thermal input)
    (:mod:`conrod.housing.thermal`, :mod:`conrod.housing.conduction`)."""
    from conrod.housing.as_built import film_start, warm_bore

    case = film_start(case)  # temperatures from the thermal film: its start at the supply
    if warm_bore(case) is None:
        return None
    from conrod.housing.conduction import Cooling
    from conrod.housing.thermal import field_bore, unit_strain_bore

    section = case.housing.thermal

    def build() -> dict[str, np.ndarray]:
        if "structure" not in holder:
            holder["structure"] = factory()
        if not section.conducting:
            return {"unit_strain_bore": unit_strain_bore(holder["structure"])}
        cooling = Cooling(section.conductivity, section.surface_heat_transfer,
                          section.ambient_temperature)
        bore, mean, shell, corners = field_bore(holder["structure"], section, cooling)
        return {"bore": bore, "temperatures": np.array([mean, shell]),
                "corner_temperature": corners}

    thermal = "unit strain" if not section.conducting else section.model_dump(
        mode="json", exclude={"journal_temperature", "journal_expansion", "shell_expansion"})
    from conrod.housing.thermal import THERMAL_FORMAT

    key = cache_key({**_cache_payload(case), "thermal_format": THERMAL_FORMAT,
                     "thermal": thermal})
    arrays, from_cache = load_or_build(key, build, cache_dir, use_cache)
    info["thermal_from_cache"] = from_cache
    if not section.conducting:
        strain = section.housing_expansion * (section.housing_temperature
                                              - section.reference_temperature)
        return warm_bore(case, strain * arrays["unit_strain_bore"])
    return warm_bore(case, arrays["bore"], tuple(float(t) for t in arrays["temperatures"]),
                     arrays["corner_temperature"])


def _structure_factory(case, angles):
    section = case.housing
    if section.model == "mesh":
        return lambda: _mesh_structure(case, angles)
    return lambda: _builtin_structure(case, angles)


def _builtin_structure(case, angles):
    section, bearing = case.housing, case.bearing
    outline = section.rod_outline(bearing.diameter,
                                  case.engine.rod_length if case.engine else None)
    geometry = RodGeometry(**outline)
    n_bore = len(angles) * section.bore_nodes_per_film_node
    fe_mesh = rod_mesh(geometry, n_bore, section.default_element_size(outline),
                       section.thicknesses(bearing.width))
    band = 0.5 * section.default_element_size(outline)
    clamp = rod_clamp_dofs(fe_mesh, geometry, section.clamp, section.clamp_position, band)
    return structural_rod(fe_mesh, material_of(section), clamp, angles)


def _mesh_structure(case, angles):
    from conrod.housing.mesh_io import read_housing_mesh

    section = case.housing
    thickness = section.thickness if section.thickness is not None else case.bearing.width
    fe_mesh = read_housing_mesh(Path(case.resolve(section.mesh_file)), thickness,
                                section.clamp_group)
    clamp = clamp_dofs_on_boundary(vector_basis(fe_mesh), fe_mesh, "clamp")
    return structural_rod(fe_mesh, material_of(section), clamp, angles)

