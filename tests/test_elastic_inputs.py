"""Bad housing input: one CaseError line naming the field or file, the value and the range."""

from __future__ import annotations

import numpy as np
import pytest

from conrod.errors import CaseError
from conrod.housing.housing import Housing
from conrod.housing.mesh_io import write_housing_mesh
from conrod.housing.mesher import annulus_mesh
from elastic_helpers import kamaz_case, write_ring_msh


@pytest.mark.parametrize(("dimensions", "field"), [
    ({"shank_width_big_end": 0.2}, "shank_width_big_end"),
    ({"small_end_outer_diameter": 0.03, "small_end_bore_diameter": 0.04},
     "small_end_outer_diameter"),
    ({"centre_distance": 0.07}, "centre_distance"),
    ({"shank_width_small_end": 0.2}, "shank_width_small_end"),
])
def test_a_rod_that_does_not_close_is_rejected(dimensions, field):
    with pytest.raises(CaseError, match=rf"housing\.{field} = .*does not close.*allowed"):
        kamaz_case(dimensions)


def test_negative_wall_is_a_range_error():
    with pytest.raises(CaseError, match=r"housing\.cap_thickness = -0\.01.*allowed: > 0"):
        kamaz_case({"cap_thickness": -0.01})


def test_mesh_without_the_bore_group(tmp_path):
    points, triangles = annulus_mesh(0.04, 0.07, 24, 3)
    lines = np.column_stack([np.arange(24), (np.arange(24) + 1) % 24])
    path = tmp_path / "no_bore.msh"
    write_housing_mesh(path, points, triangles, {"clamp": lines})
    case = kamaz_case({"model": "mesh", "mesh_file": str(path)})
    with pytest.raises(CaseError, match=r"mesh_file .*no_bore\.msh.*lacks .*big_end_bore"):
        Housing.from_case(case, use_cache=False)


def test_unreadable_mesh_file(tmp_path):
    path = tmp_path / "broken.msh"
    path.write_text("this is not a mesh\n")
    case = kamaz_case({"model": "mesh", "mesh_file": str(path)})
    with pytest.raises(CaseError, match=r"mesh_file .*broken\.msh.*cannot be read"):
        Housing.from_case(case, use_cache=False)


def test_mesh_bore_off_centre(tmp_path):
    path = write_ring_msh(tmp_path / "ring.msh", 0.04, 0.07, 24, 3)
    import meshio

    mesh = meshio.read(path)
    mesh.points[:, 0] += 0.01
    meshio.write(path, mesh, file_format="gmsh22", binary=False)
    case = kamaz_case({"model": "mesh", "mesh_file": str(path)})
    with pytest.raises(CaseError, match=r"centred at .*allowed: the origin"):
        Housing.from_case(case, use_cache=False)


def _spd(n: int) -> np.ndarray:
    a = np.random.default_rng(0).normal(size=(n, n))
    return (a @ a.T + n * np.eye(n)) * 1e-9


ANGLES = np.arange(0.0, 360.0, 30.0)


@pytest.mark.parametrize(("angles", "matrix", "message"), [
    (ANGLES, _spd(12)[:, :11], r"shape \(12, 11\).*square"),
    (ANGLES, _spd(12) + np.triu(np.full((12, 12), 1e-10), 1), r"not symmetric.*allowed: <= 1e-06"),
    (ANGLES, -_spd(12), r"no positive eigenvalue"),
    (ANGLES, _spd(12) - 2e-6 * np.outer(np.cos(np.radians(ANGLES)), np.cos(np.radians(ANGLES))),
     r"not positive semi-definite.*allowed: >= -1e-09 × the largest"),
    (ANGLES, np.where(np.eye(12) > 0, np.nan, _spd(12)), r"NaN"),
    (ANGLES[::-1].copy(), _spd(12), r"not strictly increasing"),
    (ANGLES + 30.0, _spd(12), r"allowed: >= 0 and < 360 deg"),
])
def test_ill_formed_compliance_files(tmp_path, angles, matrix, message):
    path = tmp_path / "c.npz"
    np.savez(path, angle_deg=angles, compliance_m_per_N=matrix)
    case = kamaz_case({"model": "compliance", "compliance_file": str(path)})
    with pytest.raises(CaseError, match=r"housing\.compliance_file .*c\.npz.*" + message):
        Housing.from_case(case)


def test_compliance_csv_round_trip_and_bad_csv(tmp_path):
    matrix = _spd(12)
    good = tmp_path / "c.csv"
    rows = [",".join(["angle_deg"] + [f"c{k}" for k in range(12)])]
    table = np.column_stack([ANGLES, matrix])
    rows += [",".join(repr(float(v)) for v in row) for row in table]
    good.write_text("\n".join(rows) + "\n")
    housing = Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(good)},
                                           n_theta=12))
    np.testing.assert_allclose(housing.compliance, matrix, rtol=1e-15)
    bad = tmp_path / "bad.csv"
    bad.write_text("0,1e-9,x\n")
    with pytest.raises(CaseError, match=r"bad\.csv.*not a number"):
        Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(bad)}))


def test_missing_arrays_and_missing_file(tmp_path):
    path = tmp_path / "c.npz"
    np.savez(path, angles=ANGLES)
    with pytest.raises(CaseError, match=r"lacks the array\(s\) angle_deg, compliance_m_per_N"):
        Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(path)}))
    with pytest.raises(CaseError, match=r"cannot be read"):
        Housing.from_case(kamaz_case({"model": "compliance",
                                      "compliance_file": str(tmp_path / "absent.npz")}))


def _ring_kernel(angles_deg: np.ndarray, radius: float = 0.06, bending: float = 50.0,
                 axial: float = 5.0e7) -> np.ndarray:
    """Radial compliance [m/N] of a free thin ring at its nodes from its Fourier modes
    (inextensional bending w_n = q_n R⁴/(EI (n² − 1)²) for n ≥ 2, stretching w_0 = q_0 R²/EA;
    Timoshenko, Strength of Materials; nodal forces f_j give q_n = Σ f_j cos nθ_j/(πR)),
    without the translation terms n = 1: positive
    semi-definite, its eigenvalues of cos θ and sin θ zero to round-off."""
    theta = np.radians(angles_deg)
    difference = theta[:, None] - theta[None, :]
    kernel = np.full_like(difference, radius / (axial * 2.0 * np.pi))
    for n in range(2, len(theta) // 2 + 1):  # every mode the nodes resolve
        kernel += radius**3 / (bending * (n * n - 1) ** 2 * np.pi) * np.cos(n * difference)
    return kernel


def test_a_positive_semidefinite_compliance_is_accepted(tmp_path):
    """A ring kernel without its translation terms has two zero eigenvalues (round-off of
    either sign, about 1e-22 m/N against 6e-6 m/N; the old check refused it) and is
    accepted; it has no translation to correct, so the rigid-body correction leaves it
    unchanged."""
    angles = np.arange(0.0, 360.0, 5.0)
    kernel = _ring_kernel(angles)
    eigenvalues = np.linalg.eigvalsh(kernel)
    assert abs(eigenvalues[:2]).max() < 1e-12 * eigenvalues.max()  # semi-definite indeed
    path = tmp_path / "ring.npz"
    np.savez(path, angle_deg=angles, compliance_m_per_N=kernel)
    housing = Housing.from_case(kamaz_case({"model": "compliance", "compliance_file": str(path)},
                                           n_theta=72))
    np.testing.assert_allclose(housing.compliance, kernel, rtol=1e-12, atol=0.0)
    np.testing.assert_allclose(housing.corrected_compliance, kernel, rtol=0.0,
                               atol=1e-10 * kernel.max())
