"""Compliances and stiffnesses in the formats FE codes write, with their bore nodes: a small
scikit-fem solid ring condensed at its bore nodes (θ, z), written in each format, read back
through ``[housing] model = "compliance"``; files written by pyNastran read by conrod."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from conrod.housing import matrix_formats as formats
from conrod.housing import nastran_formats as nastran
from conrod.housing.housing import Housing
from solid_ring_helpers import (
    grid_nodes,
    imported_case,
    small_ring,
    write_nodes,
)

DATA = Path(__file__).resolve().parent / "data"
PYNASTRAN_LABELS = [(101, 1), (101, 2), (102, 1), (102, 2), (205, 1)]


@pytest.fixture(scope="module")
def ring_compliance() -> np.ndarray:
    """Radial compliance of the held ring at the film nodes (θ_j, z_k), row-major [m/N]."""
    from solid_ring_helpers import film_nodes

    return small_ring().bore_compliance(*film_nodes())


def _read(case) -> Housing:
    return Housing.from_case(case, use_cache=False)


def _close(matrix: np.ndarray, expected: np.ndarray, relative: float) -> bool:
    return float(np.max(np.abs(matrix - expected))) <= relative * float(np.max(np.abs(expected)))


def test_the_ring_compliance_is_three_dimensional(ring_compliance):
    """Not a plane housing in disguise: under a cosine load on the cap (±90° about θ = 180°,
    uniform over the width) the corrected bore opens more at the thin face (z = +L/2) than
    at the thick one (measured 24.0 against 22.5 µm; 30.1 against 28.2 µm on a ring meshed
    twice as finely)."""
    from conrod.housing.correction import bore_correction_projector
    from conrod.housing.transfer import node_forces
    from solid_ring_helpers import BORE, film_nodes

    theta, z = film_nodes()
    pressure = 1e7 * np.maximum(-np.cos(theta), 0.0)[:, None] * np.ones(len(z))
    forces = node_forces(pressure, z, theta, BORE)
    corrected = bore_correction_projector(theta, z, "least_squares_circle") @ ring_compliance
    cap = (corrected @ forces).reshape(len(theta), len(z))[len(theta) // 2]
    assert cap[-1] > 1.04 * cap[0] > 0.0


def test_matrix_market_round_trip(tmp_path, ring_compliance):
    """Matrix Market compliance (scipy.io.mmwrite, 17 digits) + node file of angles: the
    housing holds the same matrix on the same film nodes, to round-off."""
    ids, theta, z = grid_nodes()
    order = np.random.default_rng(3).permutation(len(ids))  # any node order in the file
    matrix = ring_compliance[np.ix_(order, order)]
    formats.write_matrix_market(tmp_path / "ring.mtx", matrix)
    write_nodes(tmp_path / "nodes.csv", ids[order], theta[order], z[order])
    housing = _read(imported_case({"compliance_file": str(tmp_path / "ring.mtx"),
                                   "node_file": str(tmp_path / "nodes.csv")}))
    assert not housing.uniform_in_z and housing.node_count == len(ids)
    assert _close(housing.compliance, ring_compliance, 1e-15)


@pytest.mark.parametrize(("field", "kind"), [("small", "compliance"), ("large", "stiffness"),
                                           ("free", "stiffness")])
def test_nastran_dmig_round_trip(tmp_path, ring_compliance, field, kind):
    """DMIG with component 1 = radial (a cylindrical nodal frame), nodes given by x, y, z:
    the radial stiffness K = C⁻¹ in large and free field, the compliance in small field
    (8 characters hold 4 digits of 2.591-10 m/N, too few for a stiffness whose inverse
    amplifies them by its condition number): C back within the field's precision."""
    ids, theta, z = grid_nodes()
    matrix = ring_compliance if kind == "compliance" else np.linalg.inv(ring_compliance)
    nastran.write_dmig(tmp_path / "ring.dmig", "KBORE", matrix,
                       [(int(node), 1) for node in ids], field)
    write_nodes(tmp_path / "nodes.csv", ids, theta, z, cartesian=True)
    housing = _read(imported_case({"compliance_file": str(tmp_path / "ring.dmig"),
                                   "node_file": str(tmp_path / "nodes.csv"),
                                   "matrix_kind": kind}))
    assert _close(housing.compliance, ring_compliance, 1e-3 if field == "small" else 1e-10)


@pytest.mark.parametrize("binary", [False, True], ids=["ascii", "binary"])
def test_nastran_op4_round_trip(tmp_path, ring_compliance, binary):
    """OP4 compliance (dense, double precision, ASCII 1P,3E23.16 or binary records)."""
    ids, theta, z = grid_nodes()
    nastran.write_op4(tmp_path / "ring.op4", "CBORE", ring_compliance, binary=binary)
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    housing = _read(imported_case({"compliance_file": str(tmp_path / "ring.op4"),
                                   "node_file": str(tmp_path / "nodes.csv")}))
    assert _close(housing.compliance, ring_compliance, 1e-15)


def test_abaqus_substructure_round_trip(tmp_path):
    """The ring's stiffness condensed to the x, y, z translations of its bore corner nodes
    (a superelement, as ``*SUBSTRUCTURE GENERATE`` retains them), written as Abaqus writes
    ``*SUBSTRUCTURE MATRIX OUTPUT``, Cartesian components: the radial compliance at the
    film nodes is that of unit radial point forces on the ring itself (1e-9)."""
    ring = small_ring()
    vertices = ring.bore_vertices()
    stiffness = ring.condensed_stiffness(vertices)
    node_ids = [5001 + k for k in range(len(vertices))]
    formats.write_abaqus(tmp_path / "ring.mtx", stiffness, node_ids, [1, 2, 3])
    xyz = ring.vertex_coordinates(vertices)
    angles = np.mod(np.arctan2(xyz[:, 1], xyz[:, 0]), 2 * np.pi)
    write_nodes(tmp_path / "nodes.csv", node_ids, angles, xyz[:, 2], cartesian=True)
    housing = _read(imported_case({"compliance_file": str(tmp_path / "ring.mtx"),
                                   "node_file": str(tmp_path / "nodes.csv"),
                                   "matrix_kind": "stiffness", "dof_frame": "cartesian"}))
    assert _close(housing.compliance, ring.point_compliance(vertices), 1e-9)


def test_pynastran_dmig_and_op4_are_read():
    """Files written by pyNastran 1.4.1 (large-field DMIG with D exponents and one column
    entry per term; dense and sparse ASCII OP4) give the matrix they were written from."""
    expected = np.loadtxt(DATA / "pynastran_matrix.csv", delimiter=",", comments="#")
    dmig = nastran.read_dmig(DATA / "pynastran_dmig.bdf")
    order = [dmig.labels.index(label) for label in PYNASTRAN_LABELS]
    assert _close(dmig.matrix[np.ix_(order, order)], expected, 1e-10)  # 11 digits written
    for name in ("pynastran_dense.op4", "pynastran_sparse.op4"):
        assert np.array_equal(nastran.read_op4(DATA / name).matrix, expected)


def test_abaqus_layouts_are_read(tmp_path):
    """Abaqus's layout: '** ELEMENT NODES' comments, a DOF line per node where it changes,
    four values a line with ' , ' separators, a mass matrix after the stiffness."""
    text = """**
** ELEMENT NUMBER 11 STEP NUMBER 2 INCREMENT NUMBER 1
*USER ELEMENT, NODES= 2, LINEAR
** ELEMENT NODES
** 7, 9
1, 2
2, 1
*MATRIX,TYPE=STIFFNESS
4.0 ,
1.0 , 5.0
0.5 , -1.0 , 6.0
*MATRIX,TYPE=MASS
1.0 ,
0.0 , 1.0
0.0 , 0.0 , 1.0
"""
    (tmp_path / "element.mtx").write_text(text)
    read = formats.read_abaqus(tmp_path / "element.mtx")
    assert read.labels == [(7, 1), (7, 2), (9, 1)]
    assert np.array_equal(read.matrix, [[4.0, 1.0, 0.5], [1.0, 5.0, -1.0], [0.5, -1.0, 6.0]])


def test_nastran_reals():
    for text, value in (("1.5", 1.5), ("1.5E-3", 1.5e-3), ("1.5D-3", 1.5e-3),
                        ("1.5-3", 1.5e-3), (".15+1", 1.5), ("-2.5+2", -250.0), ("", 0.0)):
        assert formats.nastran_real(text) == pytest.approx(value, rel=1e-15)
    for value in (6.023643249400513, -1.2345678e-7, 123456789.0, 0.0):
        for width in (8, 16):
            text = nastran.nastran_field_real(value, width)
            assert len(text) <= width
            assert formats.nastran_real(text) == pytest.approx(value, rel=0.5 * 10.0 ** (5 - width))


def test_a_plane_node_set_is_a_plane_housing(tmp_path):
    """Nodes all in one section (no axial positions): the plane path, uniform in z, on any
    film grid (here 24 film rows from 12 nodes)."""
    ids = np.arange(1, 13)
    theta = 2 * np.pi * np.arange(12) / 12
    plane = np.eye(12) * 1e-9 + 2e-10
    formats.write_matrix_market(tmp_path / "plane.mtx", plane)
    (tmp_path / "nodes.csv").write_text("node_id,angle_deg\n" + "".join(
        f"{node},{np.degrees(angle)}\n" for node, angle in zip(ids, theta, strict=True)))
    housing = _read(imported_case({"compliance_file": str(tmp_path / "plane.mtx"),
                                   "node_file": str(tmp_path / "nodes.csv")}, n_theta=24))
    assert housing.uniform_in_z and housing.compliance.shape == (24, 24)
    assert housing.info["axial"].startswith("uniform in z")


def test_film_grid_other_than_the_bore_nodes(tmp_path, ring_compliance):
    """Film nodes between the bore nodes take the interpolated compliance L C Lᵀ: under the
    same pressure p = p₀ cos 2θ (1 + z/L) the deformation on a twice finer film grid
    matches the one on the bore nodes at the shared nodes within 5 % of its range (a coarse
    12 × 5 node set, linear interpolation)."""
    from conrod.housing.transfer import node_forces

    ids, theta, z = grid_nodes()
    formats.write_matrix_market(tmp_path / "ring.mtx", ring_compliance)
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    files = {"compliance_file": str(tmp_path / "ring.mtx"),
             "node_file": str(tmp_path / "nodes.csv")}
    deformation = []
    for housing in (_read(imported_case(files)), _read(imported_case(files, n_theta=24,
                                                                     n_z=8))):
        pressure = 1e6 * np.cos(2 * housing.angles)[:, None] * (1 + housing.axial / 0.03)
        forces = node_forces(pressure, housing.axial, housing.angles, housing.radius)
        deformation.append(housing.field_view(housing.corrected_compliance @ forces))
    coarse, fine = deformation
    assert np.max(np.abs(fine[::2, ::2] - coarse)) < 0.05 * np.ptp(coarse)


def test_npz_with_axial_positions_and_a_3d_inertia_file(tmp_path, ring_compliance):
    """conrod's own ``.npz`` with ``axial_position_m`` holds a 3-D compliance (any node
    order); an inertia file with axial positions lands on the same film nodes, a plane one
    is repeated over the width."""
    ids, theta, z = grid_nodes()
    order = np.random.default_rng(4).permutation(len(ids))
    fields = np.random.default_rng(5).standard_normal((len(ids), 4)) * 1e-6
    np.savez(tmp_path / "c.npz", angle_deg=np.degrees(theta[order]),
             axial_position_m=z[order], compliance_m_per_N=ring_compliance[np.ix_(order, order)])
    np.savez(tmp_path / "u.npz", angle_deg=np.degrees(theta[order]),
             axial_position_m=z[order], inertia_base_m=fields[order])
    housing = _read(imported_case({"compliance_file": str(tmp_path / "c.npz"),
                                   "inertia_file": str(tmp_path / "u.npz")}))
    assert not housing.uniform_in_z
    assert _close(housing.compliance, ring_compliance, 1e-15)
    assert _close(housing.inertia_base, fields, 1e-15)
    plane_fields = fields[::5]
    np.savez(tmp_path / "u.npz", angle_deg=np.degrees(theta[::5]), inertia_base_m=plane_fields)
    housing = _read(imported_case({"compliance_file": str(tmp_path / "c.npz"),
                                   "inertia_file": str(tmp_path / "u.npz")}))
    assert np.array_equal(housing.inertia_base, np.repeat(plane_fields, 5, axis=0))
