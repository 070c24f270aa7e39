"""``[housing]`` section: the big-end housing — rigid, built-in FE rod, imported mesh or
imported compliance matrix (docs/elastic.md).

Dimensions of the built-in rod left out are scaled from the bearing diameter d and the
engine's rod length (defaults in each description; d_b = d + 2 × shell thickness is the
housing bore). Example::

    [housing]
    model = "builtin"
    big_end_wall_thickness = 0.016
    cap_thickness = 0.013
    split_angle = 0.0
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Literal

from pydantic import Field, model_validator

from conrod.cases.assembly import AssemblySection, ThermalExpansionSection
from conrod.cases.base import Section
from conrod.errors import CaseError

COUPLING_TOLERANCE = 1e-7
"""Default largest bore-displacement residual of the elastohydrodynamic coupling, relative
to the radial clearance [-] (``coupling_tolerance``): 1e-4 of the periodicity tolerance
(1e-3 c) and about 1e-4 of the README main job's h_min grid error (+0.066 µm, 1.3e-3 of its
50 µm clearance), 1000 × the Reynolds film's own noise (≈ 1e-10 c). With the implicit step's force
balance to :data:`conrod.ehd.bore_system.STEP_FORCE_TOLERANCE` it takes 16 % fewer film
solves than 1e-9 c with 1e-8 of the load (README main job 7054 → 5910 at 144 × 16; the
shipped elastic examples 14–16 %), the h_min and p_max of every output angle within 4e-7
of the cycle's h_min and 7e-7 of its p_max (docs/ehd.md)."""

HousingModelName = Literal["rigid", "builtin", "mesh", "compliance"]
ClampName = Literal["small_end", "mid_shank"]


def _length(description: str, upper: float = 5.0, default: float | None = None):
    return Field(default=default, gt=0.0, le=upper, description=description)


CorrectionName = Literal["least_squares_circle", "centroid", "none"]
"""Rigid-body corrections of the bore displacement (:mod:`conrod.housing.correction`)."""

MatrixFormatName = Literal["auto", "npz", "csv", "matrix_market", "nastran_dmig",
                           "nastran_op4", "abaqus"]
"""Formats of an imported matrix (:mod:`conrod.housing.imported`, docs/elastic.md)."""
NODE_FILE_FORMATS = ("matrix_market", "nastran_dmig", "nastran_op4", "abaqus")
"""Formats whose bore nodes are given by ``node_file``."""
_SUFFIX_NEEDS_NODES = (".mtx", ".op4", ".dmig", ".bdf", ".dat", ".pch", ".inc", ".blk")


class HousingSection(Section):
    """How the big-end housing deforms (rigid by default)."""

    model: HousingModelName = Field(
        default="rigid", description="rigid, builtin (parametric FE rod), mesh (imported "
        "2-D mesh) or compliance (imported matrix) [-]")
    correction: CorrectionName = Field(
        default="least_squares_circle", description="Rigid-body correction of the bore "
        "deformation: least_squares_circle, centroid or none [-]")
    shell_thickness: float | None = _length("Bearing-shell thickness; default 0.03 d [m]", 0.5)
    big_end_wall_thickness: float | None = _length(
        "Radial wall of the head on the rod side of the split line; default 0.20 d_b [m]", 1.0)
    cap_thickness: float | None = _length("Radial thickness of the cap; default 0.16 d_b [m]",
                                          1.0)
    split_angle: float = Field(default=0.0, ge=0.0, le=60.0, description="Inclination of the "
                               "split line from the perpendicular to the rod axis (built-in "
                               "rod; an imported mesh's bolted joint) [deg]")
    shank_width_big_end: float | None = _length(
        "Shank width at the big-end centre; default 0.45 d_b [m]", 2.0)
    shank_width_small_end: float | None = _length(
        "Shank width at the small-end centre; default 0.30 d_b [m]", 2.0)
    centre_distance: float | None = _length(
        "Big-end to small-end centre distance; default engine.rod_length, else 2.8 d [m]", 10.0)
    small_end_bore_diameter: float | None = _length(
        "Small-end bore (pin bush outside) diameter; default 0.45 d [m]", 2.0)
    small_end_outer_diameter: float | None = _length(
        "Small-end eye outer diameter; default 1.45 small-end bore [m]", 2.0)
    head_thickness: float | None = _length(
        "Axial (plane-stress) thickness of head and cap; default bearing width [m]", 2.0)
    shank_thickness: float | None = _length(
        "Equivalent plane-stress thickness of the shank (I-section area / shank width); "
        "default 0.5 head thickness [m]", 2.0)
    small_end_thickness: float | None = _length(
        "Axial thickness of the small end; default 0.8 head thickness [m]", 2.0)
    fillet_radius: float | None = Field(default=None, ge=0.0, le=1.0, description=(
        "Blend radius between head, shank and small end; default 0.3 shank_width_small_end "
        "[m]"))
    element_size: float | None = _length(
        "Largest element edge; default a third of the thinner head wall [m]", 1.0)
    bore_nodes_per_film_node: int = Field(default=1, ge=1, le=4, description=(
        "Built-in mesh: FE bore nodes per film node (the bore nodes include the film nodes) "
        "[-]"))
    clamp: ClampName = Field(default="small_end", description=(
        "Built-in rod held at the small-end bore or across the shank (mid_shank) [-]"))
    clamp_position: float = Field(default=0.5, gt=0.0, lt=1.0, description=(
        "mid_shank clamp: distance from the big-end centre / centre distance [-]"))
    youngs_modulus: float = Field(default=2.1e11, gt=1.0e9, le=1.0e12,
                                  description="Young's modulus E (steel default) [Pa]")
    poisson_ratio: float = Field(default=0.3, ge=0.0, lt=0.5, description="Poisson ratio ν [-]")
    density: float = Field(default=7850.0, gt=100.0, le=25000.0,
                           description="Density ρ (steel default) [kg/m^3]")
    mesh_file: Path | None = Field(default=None, strict=False, description=(
        "2-D mesh (gmsh .msh or any meshio format) in metres, big-end bore centred at the "
        "origin, physical groups big_end_bore (required) and clamp [-]"))
    clamp_group: str = Field(default="clamp", description=(
        "Physical group held fixed in mesh_file; falls back to small_end_bore [-]"))
    thickness: float | None = _length(
        "Plane-stress thickness of an imported mesh; default bearing width [m]", 2.0)
    compliance_file: Path | None = Field(default=None, strict=False, description=(
        "Compliance or stiffness matrix: .npz (angle_deg, [axial_position_m,] "
        "compliance_m_per_N), .csv, Matrix Market, Nastran DMIG or OP4, Abaqus .mtx [-]"))
    compliance_format: MatrixFormatName = Field(default="auto", description=(
        "Format of compliance_file: auto (by its suffix), npz, csv, matrix_market, "
        "nastran_dmig, nastran_op4 or abaqus [-]"))
    node_file: Path | None = Field(default=None, strict=False, description=(
        "Bore nodes of compliance_file (Matrix Market, DMIG, OP4, Abaqus): CSV of node_id "
        "with angle_deg, axial_position_m or with x_m, y_m, z_m (rod frame) [-]"))
    matrix_kind: Literal["compliance", "stiffness"] = Field(default="compliance", description=(
        "compliance_file holds a compliance [m/N] or the stiffness of a held model [N/m] "
        "[-]"))
    dof_frame: Literal["cylindrical", "cartesian"] = Field(default="cylindrical", description=(
        "Components 1, 2, 3 of a node are along (r, θ, z) or (x, y, z) of the rod frame [-]"))
    matrix_name: str | None = Field(default=None, description=(
        "DMIG or OP4 matrix to read when the file holds several [-]"))
    inertia_file: Path | None = Field(default=None, strict=False, description=(
        ".npz with angle_deg and inertia_base_m (n, 4): inertia base fields [-]"))
    stress_angles: list[float] = Field(default_factory=list, description=(
        "Crank angles of the stress analysis; empty: peak load and 360 [deg]"))
    coupling_tolerance: float = Field(default=COUPLING_TOLERANCE, gt=0.0, le=1e-3, description=(
        "Elastohydrodynamic coupling: largest bore-displacement residual accepted, relative "
        "to the radial clearance [-]"))
    rigid_start_deg: float = Field(default=20.0, ge=0.0, le=720.0, description=(
        "Crank angle run with a rigid bore from the orbit start (Rodin 2004: 10-40) [deg]"))
    increment_share: float = Field(default=0.5, gt=0.0, le=1.0, description=(
        "Largest bore-deformation increment per coupling update, share of h_min [-]"))
    coupling_iterations: int = Field(default=40, ge=2, le=1000, description=(
        "Film solves per coupling before the step fails [-]"))
    assembly: AssemblySection | None = Field(default=None, description=(
        "Bolt preload and shell crush of the assembled big end ([housing.assembly]) [-]"))
    thermal: ThermalExpansionSection | None = Field(default=None, description=(
        "Journal and housing at their running temperatures ([housing.thermal]) [-]"))

    @model_validator(mode="after")
    def _check_model_inputs(self) -> HousingSection:
        if self.model == "mesh" and self.mesh_file is None:
            raise ValueError("housing.mesh_file is required with model = 'mesh' (a 2-D .msh "
                             "file in metres)")
        if self.model == "compliance" and self.compliance_file is None:
            raise ValueError("housing.compliance_file is required with model = 'compliance' "
                             "(.npz, .csv, Matrix Market, Nastran DMIG or OP4, Abaqus .mtx)")
        if self.model == "compliance" and self.node_file is None and (
                self.compliance_format in NODE_FILE_FORMATS or (
                    self.compliance_format == "auto"
                    and Path(self.compliance_file).suffix.lower() in _SUFFIX_NEEDS_NODES)):
            raise ValueError(f"housing.node_file is required with compliance_file = "
                             f"{str(self.compliance_file)!r} (CSV of node_id with angle_deg, "
                             "axial_position_m or with x_m, y_m, z_m)")
        if self.assembly is not None and self.assembly.active and self.model not in (
                "builtin", "mesh"):
            raise ValueError(f"housing.assembly needs a finite-element housing, not model = "
                             f"{self.model!r} (allowed: builtin or mesh)")
        if (self.assembly is not None and self.assembly.bolt_preload > 0.0
                and self.model == "mesh" and (self.assembly.bolt_distance is None
                                              or self.assembly.bolt_thread_depth is None)):
            raise ValueError("housing.assembly.bolt_preload on an imported mesh needs "
                             "bolt_distance and bolt_thread_depth (the built-in rod knows its "
                             "bolts; a mesh is split as housing.split_angle)")
        if (self.thermal is not None and self.thermal.conducting
                and self.model not in ("builtin", "mesh")):
            raise ValueError(f"housing.thermal.shell_temperatures need a finite-element "
                             f"housing to conduct in, not model = {self.model!r} (allowed: "
                             "builtin or mesh; or a uniform housing_temperature)")
        for angle in self.stress_angles:
            if not 0.0 <= angle <= 720.0:
                raise ValueError(f"housing.stress_angles contains {angle!r}: out of range "
                                 "(allowed: >= 0 and <= 720 deg)")
        return self

    def bore_diameter(self, bearing_diameter: float) -> float:
        """Housing bore d_b = d + 2 × shell thickness [m]."""
        shell = self.shell_thickness if self.shell_thickness is not None else 0.03 * (
            bearing_diameter)
        return bearing_diameter + 2.0 * shell

    def rod_outline(self, bearing_diameter: float, rod_length: float | None) -> dict[str, float]:
        """The built-in rod's outline dimensions (the fields of
        :class:`conrod.housing.geometry.RodGeometry`) [m, rad]; CaseError naming the field
        when the rod does not close (:func:`outline_problems`)."""
        d_b = self.bore_diameter(bearing_diameter)
        small_bore = _pick(self.small_end_bore_diameter, 0.45 * bearing_diameter)
        small_width = _pick(self.shank_width_small_end, 0.30 * d_b)
        centre = _pick(self.centre_distance,
                       rod_length if rod_length is not None else 2.8 * bearing_diameter)
        outline = dict(
            bore_radius=0.5 * d_b,
            head_outer_radius=0.5 * d_b + _pick(self.big_end_wall_thickness, 0.20 * d_b),
            cap_outer_radius=0.5 * d_b + _pick(self.cap_thickness, 0.16 * d_b),
            split_angle=math.radians(self.split_angle),
            shank_width_big_end=_pick(self.shank_width_big_end, 0.45 * d_b),
            shank_width_small_end=small_width,
            centre_distance=centre,
            small_end_bore_radius=0.5 * small_bore,
            small_end_outer_radius=0.5 * _pick(self.small_end_outer_diameter, 1.45 * small_bore),
            fillet_radius=_pick(self.fillet_radius, 0.3 * small_width),
        )
        problems = outline_problems(outline)
        if problems:
            name, value, allowed = problems[0]
            raise CaseError(f"housing.{name} = {value:.6g}: the built-in rod does not close "
                            f"(allowed: {allowed})")
        return outline

    def thicknesses(self, bearing_width: float) -> dict[str, float]:
        """Plane-stress thickness per region (cap, head, shank, small_end) [m]."""
        head = _pick(self.head_thickness, bearing_width)
        return {"cap": head, "head": head,
                "shank": _pick(self.shank_thickness, 0.5 * head),
                "small_end": _pick(self.small_end_thickness, 0.8 * head)}

    def default_element_size(self, outline: dict[str, float]) -> float:
        """Largest element edge [m] (``element_size`` or a third of the thinner wall) of the
        rod ``outline`` (:meth:`rod_outline`)."""
        wall = min(outline["head_outer_radius"], outline["cap_outer_radius"]) - outline[
            "bore_radius"]
        return _pick(self.element_size, wall / 3.0)


def outline_problems(o: dict[str, float]) -> list[tuple[str, float, str]]:
    """Why the built-in rod of ``o`` (:meth:`HousingSection.rod_outline`) does not close:
    (field, value, allowed) triples, empty when it does."""
    problems = []
    if o["head_outer_radius"] <= o["bore_radius"]:
        problems.append(("big_end_wall_thickness", o["head_outer_radius"] - o["bore_radius"],
                         "> 0 m"))
    if o["cap_outer_radius"] <= o["bore_radius"]:
        problems.append(("cap_thickness", o["cap_outer_radius"] - o["bore_radius"], "> 0 m"))
    if o["shank_width_big_end"] >= 2.0 * o["head_outer_radius"]:
        problems.append(("shank_width_big_end", o["shank_width_big_end"],
                         f"< head outer diameter {2.0 * o['head_outer_radius']:g} m"))
    if o["shank_width_small_end"] >= 2.0 * o["small_end_outer_radius"]:
        problems.append(("shank_width_small_end", o["shank_width_small_end"],
                         f"< small-end outer diameter {2.0 * o['small_end_outer_radius']:g} m"))
    if o["small_end_outer_radius"] <= o["small_end_bore_radius"]:
        problems.append(("small_end_outer_diameter", 2.0 * o["small_end_outer_radius"],
                         f"> small-end bore diameter {2.0 * o['small_end_bore_radius']:g} m"))
    reach = max(o["head_outer_radius"], o["cap_outer_radius"]) + o["small_end_outer_radius"]
    if o["centre_distance"] <= reach:
        problems.append(("centre_distance", o["centre_distance"],
                         f"> head outer radius + small-end outer radius = {reach:g} m "
                         "(the small end overlaps the big end)"))
    return problems


def _pick(value: float | None, default: float) -> float:
    return default if value is None else value
