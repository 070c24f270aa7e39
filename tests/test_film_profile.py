"""Bore and shell profiles h₀(θ, z) in the grid films: shapes, tables, limits and the
elliptical (two-lobe) bearing against an independent solver."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.sparse.linalg import spsolve

from conrod.errors import CaseError
from conrod.film.base import BearingGeometry, FilmState
from conrod.film.mass_conserving.film import MassConservingFilm
from conrod.film.profile import BoreProfile, Harmonic, ProfileTable
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.film.table.mobility import MobilityFilm

MU, D, L, C, OMEGA = 0.01, 0.05, 0.025, 25e-6, 300.0


def geometry(profile=None, clearance=C) -> BearingGeometry:
    return BearingGeometry(diameter=D, width=L, radial_clearance=clearance, profile=profile)


def state(ex=0.4, ey=0.2, vx=0.0, vy=0.0) -> FilmState:
    return FilmState(eccentricity_x=ex * C, eccentricity_y=ey * C, velocity_x=vx,
                     velocity_y=vy, journal_speed=OMEGA, viscosity=MU)


def both(geo, **kwargs):
    return [ReynoldsFilm(geo, 48, 16, **kwargs), MassConservingFilm(geo, 48, 16, **kwargs)]


def test_zero_profile_is_the_cylindrical_bore_bit_for_bit():
    """A profile that is zero everywhere takes the cylindrical path: identical numbers."""
    for plain, zero in zip(both(geometry()), both(geometry(BoreProfile())), strict=True):
        a = plain.solve(state(), with_pressure=True)
        b = zero.solve(state(), with_pressure=True)
        assert np.array_equal(a.pressure, b.pressure)
        assert a.force_x == b.force_x and a.friction_torque_journal == b.friction_torque_journal


def test_uniform_offset_equals_a_larger_clearance():
    """A measured profile of uniform offset δ is the same film as clearance c + δ."""
    delta = 7e-6
    table = ProfileTable.from_arrays(np.radians([0.0, 180.0]), [0.0], [[delta], [delta]])
    for offset, larger in zip(both(geometry(BoreProfile(table=table)), tolerance=1e-13),
                              both(geometry(clearance=C + delta), tolerance=1e-13), strict=True):
        a, b = offset.solve(state()), larger.solve(state())
        assert a.force_x == pytest.approx(b.force_x, rel=1e-10)
        assert a.force_y == pytest.approx(b.force_y, rel=1e-10)
        assert a.min_film_thickness == pytest.approx(b.min_film_thickness, rel=1e-12)


def test_elliptical_profile_as_a_table_equals_the_parametric_one():
    """The lemon bore given as a table on the film's nodes gives the parametric film to
    round-off; a table on a 4x finer θ grid (linear interpolation) to O(Δθ²)."""
    lemon = BoreProfile(preload=0.4)
    reference = ReynoldsFilm(geometry(lemon), 48, 16)
    theta, z = reference.grid()
    for refine, tolerance in ((1, 1e-12), (4, 2e-3)):
        angles = np.linspace(0.0, 2.0 * math.pi, refine * theta.size, endpoint=False)
        offsets = lemon.field(angles, np.array([0.0]), C, L)
        table = BoreProfile(table=ProfileTable.from_arrays(angles, [0.0], offsets))
        a = ReynoldsFilm(geometry(table), 48, 16).solve(state())
        b = reference.solve(state())
        assert a.force_x == pytest.approx(b.force_x, rel=tolerance)
        assert a.force_y == pytest.approx(b.force_y, rel=tolerance)


def test_profile_shapes():
    """Each parametric shape at the points that define it [m]."""
    theta = np.radians([0.0, 45.0, 80.0, 90.0, 100.0, 180.0, 270.0])
    z = np.array([-0.5 * L, -0.25 * L, 0.0, 0.4 * L, 0.5 * L])
    crush = BoreProfile(crush_relief_depth=10e-6, crush_relief_extent=math.radians(20.0))
    field = crush.field(theta, z, C, L)
    assert field[:, 2] == pytest.approx([0, 0, 5e-6, 10e-6, 5e-6, 0, 10e-6], abs=1e-18)
    end = BoreProfile(end_relief_depth=4e-6, end_relief_length=0.2 * L).field(theta, z, C, L)
    assert end[0] == pytest.approx([4e-6, 0.0, 0.0, 2e-6, 4e-6], abs=1e-18)
    lemon = BoreProfile(preload=0.5).field(theta, z, C, L)[:, 0]
    assert lemon[[0, 5]] == pytest.approx(0.0, abs=1e-18)  # c on the lobe axis
    assert lemon[3] == pytest.approx(C, rel=1e-12)  # c_b = c/(1 − m) = 2c across it
    halves = BoreProfile(offset_halves=3e-6).field(theta, z, C, L)[:, 0]
    assert halves[[0, 5]] == pytest.approx(3e-6) and halves[4] == pytest.approx(
        3e-6 * (1 + math.sin(math.radians(100.0))))
    axial = BoreProfile(taper=2e-6, crown=1e-6).field(theta[:1], z, C, L)[0]
    assert axial == pytest.approx(2e-6 * z / L + 1e-6 * (2 * z / L) ** 2, abs=1e-18)
    oval = BoreProfile(out_of_round=(Harmonic(2, 1e-6, 0.5),)).field(theta, z[:1], C, L)[:, 0]
    assert oval == pytest.approx(1e-6 * np.cos(2 * (theta - 0.5)))


def test_profile_checks():
    with pytest.raises(CaseError, match="radial_clearance"):
        ReynoldsFilm(geometry(BoreProfile(crown=-1.2 * C)), 24, 8)
    with pytest.raises(CaseError, match="depth and extent"):
        BoreProfile(crush_relief_depth=1e-5)
    with pytest.raises(CaseError, match="cannot take a bore profile"):
        ShortBearingFilm(geometry(BoreProfile(preload=0.3)))
    with pytest.raises(CaseError, match="rotational symmetry"):
        MobilityFilm(geometry(BoreProfile(preload=0.3)), use_cache=False)
    short_table = ProfileTable.from_arrays([0.0, 1.0], [-0.4 * L, 0.4 * L], [[0, 0], [0, 0]])
    with pytest.raises(CaseError, match="span the width"):
        short_table.field(np.zeros(3), np.linspace(-0.5 * L, 0.5 * L, 3), L)


def test_profile_table_file(tmp_path):
    """A CSV table is read, checked and interpolated; bad files name file, line and value."""
    path = tmp_path / "profile.csv"
    rows = ["# measured shell, offset + = more clearance", "angle_deg,axial_position_m,offset_m"]
    for angle in (0.0, 90.0, 180.0, 270.0):
        for z in (-0.5 * L, 0.5 * L):
            rows.append(f"{angle},{z},{1e-6 * angle / 90.0 + 2e-6 * (z > 0)}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    table = ProfileTable.from_csv(path)
    field = table.field(np.radians([45.0, 315.0]), np.array([0.0]), L)
    assert field[:, 0] == pytest.approx([1.5e-6, 2.5e-6])
    path.write_text("\n".join(rows[:-1]) + "\n", encoding="utf-8")
    with pytest.raises(CaseError, match="tensor grid"):
        ProfileTable.from_csv(path)
    path.write_text("angle_deg,offset_m\n0,0\n1,0\n", encoding="utf-8")
    with pytest.raises(CaseError, match="axial_position_m"):
        ProfileTable.from_csv(path)


def test_symmetric_profile_keeps_the_mid_plane_symmetry_and_the_compiled_flight():
    """A crown (even in z) keeps the half-grid solve; the compiled force of the implicit
    orbit includes the profile and equals the film's; the massless squeeze loop, exact only
    on a circular bore, declines it."""
    film = ReynoldsFilm(geometry(BoreProfile(crown=4e-6, preload=0.2)), 48, 16)
    assert film.symmetric and film.compiled_kernel() is None
    at = state(vx=1e-3, vy=-2e-3)
    kernel = film.flight_kernel(None, 1e-12)
    fx, fy = kernel.force(at.eccentricity_x, at.eccentricity_y, at.velocity_x, at.velocity_y,
                          OMEGA, MU, kernel.params)
    result = film.solve(at)
    assert (fx, fy) == pytest.approx((result.force_x, result.force_y), rel=1e-12)
    tapered = ReynoldsFilm(geometry(BoreProfile(taper=4e-6)), 48, 16)
    assert not tapered.symmetric
    moment = tapered.solve(at).moment_y
    assert abs(moment) > 1e-4 * abs(result.force_x) * L  # an asymmetric bore tilts the load


# --------------------------------------------------------- independent Reynolds solver
def independent_reynolds(h: np.ndarray, h_rate: np.ndarray, radius: float, width: float,
                         speed: float, viscosity: float) -> np.ndarray:
    """Swift–Stieber Reynolds pressure [Pa] on a vertex grid (edges at 0 Pa), assembled from
    the face fluxes and solved by an active-set iteration with a sparse direct solve."""
    n, m = h.shape
    dx, dz = radius * 2.0 * math.pi / n, width / (m - 1)
    nodes = [(i, j) for i in range(n) for j in range(1, m - 1)]
    number = {node: k for k, node in enumerate(nodes)}
    matrix = sp.lil_matrix((len(nodes), len(nodes)))
    right = np.zeros(len(nodes))
    for (i, j), k in number.items():
        for (a, b, along) in ((i + 1, j, True), (i - 1, j, True), (i, j + 1, False),
                              (i, j - 1, False)):
            a %= n
            conductance = (0.5 * (h[i, j] + h[a, b])) ** 3 * (dz / dx if along else dx / dz)
            matrix[k, k] += conductance
            if (a, b) in number:
                matrix[k, number[(a, b)]] -= conductance
        wedge = 0.5 * speed * radius * (0.5 * (h[(i + 1) % n, j] - h[i - 1, j])) * dz
        right[k] = -12.0 * viscosity * (wedge + h_rate[i, j] * dx * dz)
    matrix = matrix.tocsr()
    active = np.ones(len(nodes), dtype=bool)
    p = np.zeros(len(nodes))
    for _ in range(100):
        p = np.zeros(len(nodes))
        p[active] = spsolve(matrix[active][:, active].tocsc(), right[active])
        excess = matrix @ p - right  # outflow beyond the source: ≥ 0 where p = 0
        new = (p > 0.0) | (~active & (excess < 0.0))
        if np.array_equal(new, active):
            break
        active = new
    pressure = np.zeros((n, m))
    for (i, j), k in number.items():
        pressure[i, j] = max(p[k], 0.0)
    return pressure


def independent_force(profile: np.ndarray, at: FilmState, theta, z) -> np.ndarray:
    h = (C - at.eccentricity_x * np.cos(theta) - at.eccentricity_y * np.sin(theta))[:, None] \
        + profile
    rate = np.broadcast_to((-at.velocity_x * np.cos(theta)
                            - at.velocity_y * np.sin(theta))[:, None], h.shape)
    p = independent_reynolds(h, rate, 0.5 * D, L, at.journal_speed, at.viscosity)
    width = np.full(z.size, z[1] - z[0])
    width[[0, -1]] *= 0.5
    arc = 0.5 * D * 2.0 * math.pi / theta.size
    return -arc * np.array([np.cos(theta) @ p @ width, np.sin(theta) @ p @ width])


@pytest.mark.slow
def test_two_lobe_bearing_coefficients_against_an_independent_solver():
    """Elliptical (two-lobe) bore, preload 0.5, L/D = 0.5: force and the dimensionless
    stiffness and damping in the load frame against central differences of an independent
    finite-volume Reynolds solver with the lobed film thickness. (Published tables of the
    two-lobe bearing were not found in the sources searched; this is the independent
    answer.) A centred journal carries no load but is held by a direct stiffness."""
    lemon = BoreProfile(preload=0.5)
    film = ReynoldsFilm(geometry(lemon), 36, 8, tolerance=1e-14)
    theta, z = film.grid()
    profile = lemon.field(theta, z, C, L)
    at = state(0.3, 0.25)
    lin = film.sensitivities(at)
    assert lin.force == pytest.approx(independent_force(profile, at, theta, z), rel=1e-9)
    step = 1e-5 * C
    columns = []
    for key, delta in (("eccentricity_x", step), ("eccentricity_y", step),
                       ("velocity_x", step * OMEGA), ("velocity_y", step * OMEGA)):
        plus = independent_force(profile, replace(at, **{key: getattr(at, key) + delta}),
                                 theta, z)
        minus = independent_force(profile, replace(at, **{key: getattr(at, key) - delta}),
                                  theta, z)
        columns.append((plus - minus) / (2 * delta))
    jacobian = np.column_stack(columns)
    load = math.hypot(*lin.force)
    k_bar, c_bar = lin.in_load_frame().dimensionless()
    assert np.abs(-jacobian[:, :2] - lin.stiffness).max() <= 1e-7 * np.abs(lin.stiffness).max()
    assert np.abs(-jacobian[:, 2:] - lin.damping).max() <= 1e-7 * np.abs(lin.damping).max()
    assert load > 0 and k_bar[0, 0] > 0 and c_bar[0, 0] > 0
    centred = film.sensitivities(state(0.0, 0.0))
    assert np.abs(centred.force).max() < 1e-9 * np.abs(centred.stiffness).max() * C
    assert centred.stiffness[0, 0] > 0.0  # the preload holds a centred journal


def test_steady_load_vector_on_profiled_and_tilted_bearings():
    """The steady calculator for a load vector: on a cylindrical bore turning the load turns
    the answer (rotation invariance); a lemon bore is stiffer along its lobe axis; a tilt
    puts h_min at an edge and gives moments; the CLI prints them."""
    import json

    import typer
    from typer.testing import CliRunner

    from conrod.cli import steady_command
    from conrod.film.steady_axial import solve_for_load_vector

    plain = geometry()
    a = solve_for_load_vector(2000.0, 0.0, OMEGA, MU, plain, grid=(48, 16))
    b = solve_for_load_vector(2000.0, 1.0, OMEGA, MU, plain, grid=(48, 16))
    turned = np.array([[math.cos(1.0), -math.sin(1.0)], [math.sin(1.0), math.cos(1.0)]]) @ [
        a.eccentricity_x, a.eccentricity_y]
    assert [b.eccentricity_x, b.eccentricity_y] == pytest.approx(turned, abs=2e-3 * C)
    assert a.min_film_axial_position == 0.0 and a.moment_x == pytest.approx(0.0, abs=1e-9)
    lemon = geometry(BoreProfile(preload=0.5))
    along = solve_for_load_vector(2000.0, 0.0, OMEGA, MU, lemon, grid=(48, 16))
    across = solve_for_load_vector(2000.0, 0.5 * math.pi, OMEGA, MU, lemon, grid=(48, 16))
    assert along.eccentricity < across.eccentricity  # c on the lobe axis, c/(1 − m) across
    tilted = solve_for_load_vector(2000.0, 0.0, OMEGA, MU, plain, grid=(48, 16),
                                   tilt=(0.0, 2.0e-4))
    assert abs(tilted.min_film_axial_position) == pytest.approx(0.5 * L)
    assert tilted.edge_min_film_thickness == tilted.min_film_thickness < a.min_film_thickness
    assert abs(tilted.moment_y) > 0.0 and "K_gygy" in tilted.as_dict()
    app = typer.Typer()
    app.callback()(lambda: None)
    steady_command.register(app)
    result = CliRunner().invoke(app, [
        "steady", "--load", "2000", "--speed-rpm", f"{OMEGA * 30 / math.pi}", "--viscosity",
        f"{MU}", "--diameter", f"{D}", "--width", f"{L}", "--radial-clearance", f"{C}",
        "--preload", "0.5", "--tilt-y", "2e-4", "--grid", "48x16", "--json"])
    assert result.exit_code == 0, result.output
    printed = json.loads(result.output)
    assert printed["moment_y"] != 0.0 and "C_gxgy" in printed
