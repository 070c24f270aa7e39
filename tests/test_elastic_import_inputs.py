"""Bad imported compliances and node files: one CaseError line naming the file or field,
the value and what is allowed; ``conrod run`` exits 2 and writes nothing."""

from __future__ import annotations

import numpy as np
import pytest
from typer.testing import CliRunner

from conrod.errors import CaseError
from conrod.housing import matrix_formats as formats
from conrod.housing import nastran_formats as nastran
from conrod.housing.housing import Housing
from solid_ring_helpers import BORE, grid_nodes, imported_case, write_nodes

N = 60
"""Nodes of the film grid 12 × 5 of :func:`imported_case` [-]."""


def _compliance() -> np.ndarray:
    rng = np.random.default_rng(7)
    half = rng.standard_normal((N, N))
    return 1e-12 * (half @ half.T + N * np.eye(N))


def _fails(files: dict, match: str, **extra) -> str:
    with pytest.raises(CaseError, match=match) as error:
        Housing.from_case(imported_case({**files, **extra}), use_cache=False)
    message = str(error.value)
    assert "\n" not in message
    return message


@pytest.fixture
def files(tmp_path):
    """A valid Matrix Market compliance and its node file (angles)."""
    ids, theta, z = grid_nodes()
    formats.write_matrix_market(tmp_path / "c.mtx", _compliance())
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    return {"compliance_file": str(tmp_path / "c.mtx"), "node_file": str(tmp_path / "nodes.csv")}


def test_the_valid_files_are_read(files):
    assert Housing.from_case(imported_case(files)).node_count == N


def test_wrong_node_count(files, tmp_path):
    ids, theta, z = grid_nodes()
    write_nodes(tmp_path / "nodes.csv", ids[:-1], theta[:-1], z[:-1])
    _fails(files, r"compliance_file '.*c\.mtx': has 60 rows, the node file lists 59 nodes "
           r"\(allowed: 59, 177 or 354 rows")


def test_non_symmetric_matrix(files, tmp_path):
    matrix = _compliance()
    matrix[3, 7] *= 1.5
    from scipy.io import mmwrite

    mmwrite(str(tmp_path / "c.mtx"), matrix, symmetry="general")
    _fails(files, r"c\.mtx': is not symmetric: max\|A - A\^T\|/max\|A\| = .* "
           r"\(allowed: <= 1e-06\)")


def test_node_off_the_bore_radius(files, tmp_path):
    ids, theta, z = grid_nodes()
    write_nodes(tmp_path / "nodes.csv", ids, theta, z, cartesian=True, radius=BORE)
    Housing.from_case(imported_case(files))  # on the bore: fine
    radius = np.full(N, BORE)
    radius[4] = 0.050
    with (tmp_path / "nodes.csv").open("w") as handle:
        handle.write("node_id,x_m,y_m,z_m\n")
        for k in range(N):
            handle.write(f"{ids[k]},{radius[k] * np.cos(theta[k])},"
                         f"{radius[k] * np.sin(theta[k])},{z[k]}\n")
    _fails(files, r"node_file '.*nodes\.csv': node 1005 \(row 6\) lies at radius 50 mm, off "
           r"the bore \(allowed: 39\.2\.\.43\.35 mm")


def test_node_off_the_bore_width(files, tmp_path):
    ids, theta, z = grid_nodes()
    z = z.copy()
    z[2] = 0.02
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    _fails(files, r"node 1003 \(row 4\) lies at z = 20 mm, off the bore \(allowed: \|z\| <= "
           r"15\.3 mm")


def test_two_nodes_at_one_position(files, tmp_path):
    ids, theta, z = grid_nodes()
    theta, z = theta.copy(), z.copy()
    theta[1], z[1] = theta[0], z[0]
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    _fails(files, r"two nodes share the position of node 1001")


def test_node_file_without_coordinates(files, tmp_path):
    (tmp_path / "nodes.csv").write_text("node_id,radius_m\n1,0.04\n")
    _fails(files, r"node_file '.*': has the columns node_id, radius_m \(allowed: node_id with "
           r"angle_deg, axial_position_m or with x_m, y_m, z_m\)")


def test_unknown_format(files, tmp_path):
    (tmp_path / "c.xyz").write_text("1 2 3\n")
    _fails({**files, "compliance_file": str(tmp_path / "c.xyz")},
           r"compliance_file '.*c\.xyz': unknown format '\.xyz' \(allowed: \.npz, \.csv, "
           r"\.mtx")
    with pytest.raises(CaseError, match=r"housing\.compliance_format = 'ansys': Input should "
                       r"be 'auto', 'npz'.*'abaqus'"):
        imported_case({**files, "compliance_format": "ansys"})


def test_a_matrix_file_without_its_node_file(files):
    with pytest.raises(CaseError, match=r"housing\.node_file is required with "
                       r"compliance_file = '.*c\.mtx'"):
        imported_case({"compliance_file": files["compliance_file"]})


def test_free_free_stiffness_is_refused(files, tmp_path):
    """A stiffness with rigid-body modes (a model that is not held) has no compliance."""
    theta = np.repeat(2 * np.pi * np.arange(12) / 12, 5)
    modes = np.column_stack([np.cos(theta), np.sin(theta)])
    stiffness = 1e10 * (np.eye(N) - modes @ np.linalg.pinv(modes))
    formats.write_matrix_market(tmp_path / "c.mtx", stiffness)
    _fails(files, r"the stiffness is not positive definite .*the model is not held",
           matrix_kind="stiffness")


def test_dmig_rows_of_unknown_nodes_and_several_matrices(files, tmp_path):
    ids, _, _ = grid_nodes()
    labels = [(int(node), 1) for node in ids]
    labels[2] = (77, 1)
    nastran.write_dmig(tmp_path / "k.dmig", "KBORE", np.linalg.inv(_compliance()), labels)
    files = {**files, "compliance_file": str(tmp_path / "k.dmig")}
    _fails(files, r"row \d+ belongs to node 77, which the node file does not list",
           matrix_kind="stiffness")
    labels[2] = (int(ids[2]), 1)
    nastran.write_dmig(tmp_path / "a.dmig", "KBORE", np.linalg.inv(_compliance()), labels)
    nastran.write_dmig(tmp_path / "b.dmig", "MBORE", np.eye(N), labels)
    (tmp_path / "k.dmig").write_text((tmp_path / "a.dmig").read_text()
                                     + (tmp_path / "b.dmig").read_text())
    _fails(files, r"holds the DMIG matrices KBORE, MBORE \(set housing\.matrix_name",
           matrix_kind="stiffness")
    assert Housing.from_case(imported_case({**files, "matrix_kind": "stiffness",
                                            "matrix_name": "KBORE"})).node_count == N


def test_indefinite_compliance(files, tmp_path):
    matrix = _compliance()
    matrix[0, 0] = -matrix[0, 0]
    formats.write_matrix_market(tmp_path / "c.mtx", matrix)
    _fails(files, r"is not positive semi-definite: smallest eigenvalue")


def test_run_with_a_bad_node_file_exits_2_and_writes_nothing(files, tmp_path):
    from conrod.cli.app import _register_commands, app
    from hardening_helpers import write_case

    ids, theta, z = grid_nodes()
    z = z.copy()
    z[0] = -0.05
    write_nodes(tmp_path / "nodes.csv", ids, theta, z)
    case = imported_case(files, film="reynolds")
    path = write_case(tmp_path, case.model_dump(mode="json", exclude_unset=True), "bad.toml")
    _register_commands()
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out)])
    assert result.exit_code == 2, result.output
    assert "node 1001 (row 2) lies at z = -50 mm, off the bore" in result.output
    assert "Traceback" not in result.output
    assert not out.exists()
