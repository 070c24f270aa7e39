"""Film stiffness and damping (rotordynamic coefficients) against independent answers."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np
import pytest

from conrod.film.base import BearingGeometry, FilmState
from conrod.film.linearised import linearise, linearise_by_differences
from conrod.film.reynolds.film import ReynoldsFilm
from conrod.film.short.film import ShortBearingFilm
from conrod.film.short.kernel import short_bearing_force

MU, D, C, OMEGA = 0.02, 0.05, 2.5e-5, 200.0
R = 0.5 * D


def geometry(length_to_diameter: float, **kwargs) -> BearingGeometry:
    return BearingGeometry(diameter=D, width=length_to_diameter * D, radial_clearance=C, **kwargs)


def state_at(eps_x: float, eps_y: float, vx: float = 0.0, vy: float = 0.0) -> FilmState:
    return FilmState(eccentricity_x=eps_x * C, eccentricity_y=eps_y * C, velocity_x=vx,
                     velocity_y=vy, journal_speed=OMEGA, viscosity=MU)


@pytest.mark.parametrize("state", [state_at(0.5, 0.2, 1e-3, -2e-3), state_at(-0.3, 0.6),
                                   state_at(0.8, 0.0, 0.0, 5e-4)])
def test_sensitivities_equal_central_differences(state):
    """Active-set derivatives = central differences of the force (1e-5 relative)."""
    film = ReynoldsFilm(geometry(0.5), n_theta=72, n_z=16, tolerance=1e-14)
    exact = film.sensitivities(state)
    differences = linearise_by_differences(film, state)
    assert exact.force == pytest.approx(differences.force, rel=1e-12)
    for name in ("stiffness", "damping"):
        a, b = getattr(exact, name), getattr(differences, name)
        assert np.abs(a - b).max() <= 1e-5 * np.abs(b).max()


def test_damping_is_symmetric_for_a_full_film():
    """Without cavitation the squeeze operator is self-adjoint: C_xy = C_yx."""
    film = ReynoldsFilm(geometry(0.5, cavitation_pressure=-1e30), n_theta=72, n_z=16,
                        tolerance=1e-13)
    damping = film.sensitivities(state_at(0.5, 0.3)).damping
    assert damping[0, 1] == pytest.approx(damping[1, 0], rel=1e-10)
    assert abs(damping[0, 1]) > 1e-3 * damping[0, 0]  # not trivially zero


def test_full_film_sommerfeld_stiffness_is_a_pure_rotation_at_small_eccentricity():
    """Full film, ε → 0: the force is linear, F = −k(ε)·R(90°−) e, so K_xx = K_yy and
    K_xy = −K_yx (a skew stiffness) and C = c_0 I (isotropic squeeze)."""
    film = ReynoldsFilm(geometry(1.0, cavitation_pressure=-1e30), n_theta=72, n_z=16,
                        tolerance=1e-13)
    lin = film.sensitivities(state_at(1e-3, 0.0))
    k, c = lin.stiffness, lin.damping
    assert k[0, 0] == pytest.approx(k[1, 1], abs=2e-3 * abs(k[0, 1]))
    assert k[0, 1] == pytest.approx(-k[1, 0], rel=1e-3)
    assert c[0, 0] == pytest.approx(c[1, 1], rel=1e-3)
    assert abs(c[0, 1]) < 1e-3 * c[0, 0]


def _short_coefficients(length: float, eps: float) -> tuple[np.ndarray, np.ndarray, float]:
    """Ocvirk K, C [N/m, N s/m] and W [N] in the load frame by Richardson-extrapolated
    central differences of the closed-form force (error ~1e-9)."""
    def force(x):
        return np.array(short_bearing_force(x[0], x[1], x[2], x[3], OMEGA, MU, R,
                                            length, C))
    base = np.array([eps * C, 0.0, 0.0, 0.0])
    jac = np.zeros((2, 4))
    for k in range(4):
        step = 1e-4 * (C if k < 2 else C * OMEGA)
        unit = np.zeros(4)
        unit[k] = 1.0

        def central(h, unit=unit):
            return (force(base + h * unit) - force(base - h * unit)) / (2.0 * h)

        jac[:, k] = (4.0 * central(step / 2) - central(step)) / 3.0
    f = force(base)
    w = float(np.hypot(*f))
    x_axis = -f / w
    rot = np.column_stack((x_axis, [-x_axis[1], x_axis[0]]))
    return rot.T @ -jac[:, :2] @ rot, rot.T @ -jac[:, 2:] @ rot, w


def test_short_bearing_limit_of_the_coefficients():
    """K̄, C̄ of the finite bearing → Ocvirk's closed form as L/D → 0 (error falls)."""
    eps = 0.5
    errors = []
    for ratio in (1 / 4, 1 / 8, 1 / 16):
        film = ReynoldsFilm(geometry(ratio), n_theta=144, n_z=16, tolerance=1e-12)
        lin = film.sensitivities(state_at(eps, 0.0)).in_load_frame()
        k_bar, c_bar = lin.dimensionless()
        k, c, w = _short_coefficients(ratio * D, eps)
        k_ref, c_ref = k * C / w, c * C * OMEGA / w
        errors.append(max(np.abs(k_bar - k_ref).max() / np.abs(k_ref).max(),
                          np.abs(c_bar - c_ref).max() / np.abs(c_ref).max()))
    assert errors[0] > errors[1] > errors[2]
    assert errors[2] < 0.02


def test_short_model_uses_differences_and_load_frame_is_aligned():
    """The closed-form model is linearised by differences; in the load frame the force
    is (W, 0) and a rotation of the state frame leaves the coefficients unchanged."""
    film = ShortBearingFilm(geometry(0.25))
    a = linearise(film, state_at(0.6, 0.0)).in_load_frame()
    b = linearise(film, state_at(0.6 * math.cos(1.0), 0.6 * math.sin(1.0))).in_load_frame()
    assert a.force[1] == pytest.approx(0.0, abs=1e-9 * a.load)
    assert a.force[0] == pytest.approx(-a.load)
    np.testing.assert_allclose(a.stiffness, b.stiffness, rtol=1e-6, atol=1e-6 * a.stiffness.max())
    np.testing.assert_allclose(a.damping, b.damping, rtol=1e-6, atol=1e-6 * a.damping.max())


def test_jacobian_and_flat_dictionary():
    film = ReynoldsFilm(geometry(0.5), n_theta=36, n_z=8)
    lin = film.sensitivities(replace(state_at(0.6, 0.0)))
    d_force_d_e, d_force_d_v = lin.force_jacobian
    np.testing.assert_array_equal(d_force_d_e, -lin.stiffness)
    np.testing.assert_array_equal(d_force_d_v, -lin.damping)
    values = lin.as_dict()
    assert set(values) == {f"{n}_{a}{b}" for n in ("K", "C", "K_bar", "C_bar")
                           for a in "xy" for b in "xy"}


def test_steady_command_prints_the_eight_coefficients():
    """`conrod steady --json`: K, C [N/m, N s/m] and K̄ = Kc/W, C̄ = Ccω/W in the load frame."""
    import json

    import typer
    from typer.testing import CliRunner

    from conrod.cli import steady_command

    app = typer.Typer()
    steady_command.register(app)

    @app.callback()
    def main() -> None:
        """conrod."""

    load, rpm = 2500.0, 1909.86
    result = CliRunner().invoke(app, ["steady", "--load", str(load), "--speed-rpm", str(rpm),
                                      "--viscosity", str(MU), "--diameter", str(D), "--width",
                                      str(0.5 * D), "--radial-clearance", str(C), "--json",
                                      "--grid", "72x16"])
    assert result.exit_code == 0, result.output
    values = json.loads(result.output)
    omega = rpm * math.pi / 30.0
    for a in "xy":
        for b in "xy":
            assert values[f"K_bar_{a}{b}"] == pytest.approx(values[f"K_{a}{b}"] * C / load,
                                                            rel=1e-6)
            assert values[f"C_bar_{a}{b}"] == pytest.approx(
                values[f"C_{a}{b}"] * C * omega / load, rel=1e-6)
    assert values["C_xy"] == pytest.approx(values["C_yx"], rel=1e-8)
    assert values["K_xx"] > 0.0 and values["C_xx"] > values["C_yy"] > 0.0
    text = CliRunner().invoke(app, ["steady", "--length-to-diameter", "0.5", "--eccentricity",
                                    "0.6", "--grid", "72x16"])
    assert "K_bar_xy" in text.output and "[-]" in text.output


@pytest.mark.parametrize("grid", [(72, 16), (144, 32)])
def test_adjoint_multigrid_equals_sparse_direct_solve(grid):
    """Two adjoint multigrid solves give the same K, C as one sparse LU (1e-9)."""
    from conrod.film.linearised import linearise_reynolds

    film = ReynoldsFilm(geometry(0.5, grooves=()), n_theta=grid[0], n_z=grid[1])
    state = state_at(0.5, 0.2, 1e-3, -2e-3)
    adjoint = linearise_reynolds(film, state, "adjoint")
    direct = linearise_reynolds(film, state, "direct")
    for name in ("stiffness", "damping"):
        a, b = getattr(adjoint, name), getattr(direct, name)
        assert np.abs(a - b).max() <= 1e-9 * np.abs(b).max()


def test_mass_conserving_differences_match_reynolds_adjoint_in_the_steady_calculator():
    """Steady Raimondi–Boyd point, L/D = 0.5, ε = 0.6: the JFO film (full-film history,
    inlet as a groove, central differences) and the Reynolds film (inlet line, adjoint)
    solve the same problem; their K̄, C̄ agree to 0.5 %."""
    from conrod.film.steady import raimondi_boyd_point

    reynolds = raimondi_boyd_point(0.5, 0.6, "reynolds", (72, 16)).coefficients
    jfo = raimondi_boyd_point(0.5, 0.6, "mass_conserving", (72, 16)).coefficients
    scale = max(abs(v) for v in reynolds.values())
    for key, value in reynolds.items():
        assert jfo[key] == pytest.approx(value, abs=5e-3 * scale)
