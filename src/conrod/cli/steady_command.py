"""``conrod steady``: steady journal-bearing characteristics (Raimondi–Boyd conditions).

Two modes:

* dimensionless — ``--length-to-diameter 1 --eccentricity 0.8`` prints S, φ, (R/c)f,
  Q/(RcNL), Q_s/Q, P/p_max, θ_pmax, θ_p0 and the dimensionless stiffness and damping
  K̄ = Kc/W, C̄ = Ccω/W in the load frame (see :mod:`conrod.film.steady`);
* dimensional — ``--load 10000 --speed-rpm 3000 --viscosity 0.01 --diameter 0.05
  --width 0.05 --radial-clearance 5e-5`` finds ε and prints h_min, p_max, friction
  power, flows and the eight coefficients K_xx … C_yy (SI units) with K̄, C̄;
* load vector — the dimensional options with ``--load-angle``, ``--tilt-x/--tilt-y`` or a
  bore profile (``--preload``, ``--crush-relief-depth`` …, ``--profile-file``) find the
  journal position under the load on the Reynolds film and print the moments, the edge
  h_min and the 4 × 4 coefficients (:mod:`conrod.film.steady_axial`).
"""

from __future__ import annotations

import json
import math
import sys
from enum import StrEnum

import typer

from conrod.cli.app import EXIT_WRITE_FAILED, discard_stdout, exits_cleanly
from conrod.errors import CaseError
from conrod.io.interrupts import interrupts_stop_at_once


class Model(StrEnum):
    """Film models available to the steady calculator."""

    reynolds = "reynolds"
    mass_conserving = "mass_conserving"
    short = "short"


class Friction(StrEnum):
    """Friction conventions (see :mod:`conrod.film.characteristics`)."""

    full_film = "full_film"
    film_fraction = "film_fraction"


MODEL_OPTION = typer.Option(Model.reynolds, help="Film model")
FRICTION_OPTION = typer.Option(Friction.full_film, help="Friction convention")


def parse_grid(text: str | None) -> tuple[int, int] | None:
    """'144x32' → (144, 32) intervals; None stays None."""
    from conrod.cases.solver import MAX_GRID_NODES

    if text is None:
        return None
    try:
        n_theta, n_z = (int(part) for part in text.lower().split("x"))
    except ValueError:
        raise CaseError(f"grid = {text!r}: expected NTHETAxNZ, e.g. 144x32") from None
    if n_theta < 8 or n_z < 2 or n_theta % 2 or n_z % 2:
        raise CaseError(f"grid = {text!r}: out of range (allowed: even NTHETA >= 8, "
                        "even NZ >= 2)")
    if n_theta * (n_z + 1) > MAX_GRID_NODES:
        raise CaseError(f"grid = {text!r}: out of range (allowed: NTHETA * (NZ + 1) <= "
                        f"{MAX_GRID_NODES} nodes)")
    return n_theta, n_z


UNITS = {
    "eccentricity": "-", "attitude_angle_deg": "deg", "min_film_thickness": "m",
    "max_pressure": "Pa", "friction_torque": "N m", "friction_power": "W",
    "side_flow": "m^3/s", "inlet_flow": "m^3/s", "sommerfeld_number": "-",
    "length_to_diameter": "-", "friction_variable": "-", "flow_variable": "-",
    "side_flow_ratio": "-", "load_to_peak_pressure_ratio": "-",
    "peak_pressure_angle_deg": "deg", "film_end_angle_deg": "deg",
}
"""Unit of every number ``conrod steady`` prints (the linearised coefficients: see
:func:`unit_of`)."""


def unit_of(key: str) -> str:
    """Unit shown after a value in the text output, e.g. ' [m]' (SI; '' for a name such as
    the model)."""
    if "_bar_" in key:
        return " [-]"
    if key.startswith(("K_", "C_")):
        suffix = "s" if key.startswith("C_") else ""
        rows = ("N m" if key[2] == "g" else "N") + (f" {suffix}" if suffix else "")
        columns = "/rad" if key[-2] == "g" else "/m"
        return f" [{rows}{columns}]"
    if key.startswith("moment_") or key.startswith("M_"):
        return " [N m]"
    return f" [{UNITS[key]}]" if key in UNITS else ""


def with_units(values: dict) -> dict:
    """The JSON output: the values and, under ``units``, the unit of each number."""
    units = {key: unit_of(key).strip(" []") for key, value in values.items()
             if isinstance(value, int | float) and unit_of(key)}
    return {**values, "units": units}


def _print(values: dict, as_json: bool) -> None:
    """The results on stdout: here they are the command's result, so a stdout that fails
    (a closed pipe, a full disk) is results not written (exit 5)."""
    try:
        if as_json:
            typer.echo(json.dumps(with_units(values), indent=2))
        else:
            for key, value in values.items():
                shown = f"{value:.6g}" if isinstance(value, float) else str(value)
                typer.echo(f"{key:32s} {shown}{unit_of(key)}")
        sys.stdout.flush()
    except OSError as error:
        discard_stdout()
        reason = error.strerror or str(error) or type(error).__name__
        typer.echo(f"error: cannot write the results to standard output ({reason})", err=True)
        raise typer.Exit(code=EXIT_WRITE_FAILED) from None


def register(app: typer.Typer) -> None:
    """Add the ``steady`` command to ``app``."""

    @app.command("steady")
    @exits_cleanly
    def steady(
        length_to_diameter: float = typer.Option(None, help="L/D [-] (dimensionless mode)"),
        eccentricity: float = typer.Option(None, help="Eccentricity ratio ε [-]"),
        load: float = typer.Option(None, help="Bearing load W [N] (dimensional mode)"),
        speed_rpm: float = typer.Option(None, help="Journal speed [rpm]"),
        viscosity: float = typer.Option(None, help="Dynamic viscosity μ [Pa s]"),
        diameter: float = typer.Option(None, help="Journal diameter D [m]"),
        width: float = typer.Option(None, help="Bearing width L [m]"),
        radial_clearance: float = typer.Option(None, help="Radial clearance c [m]"),
        model: Model = MODEL_OPTION,
        grid: str = typer.Option(None, help="NTHETAxNZ intervals, e.g. 144x32"),
        friction: Friction = FRICTION_OPTION,
        as_json: bool = typer.Option(False, "--json", help="Print JSON"),
        load_angle: float = typer.Option(None, help="Direction of the load pressing the "
                                         "journal, film frame [deg] (load-vector mode)"),
        tilt_x: float = typer.Option(0.0, help="Journal tilt about the film's x axis [rad]"),
        tilt_y: float = typer.Option(0.0, help="Journal tilt about the film's y axis [rad]"),
        profile_file: str = typer.Option(None, help="Measured bore profile CSV (angle_deg, "
                                         "axial_position_m, offset_m)"),
        preload: float = typer.Option(0.0, help="Elliptical (lemon) bore preload m [-]"),
        lobe_angle: float = typer.Option(0.0, help="Axis of the lobes / halves [deg]"),
        offset_halves: float = typer.Option(0.0, help="Offset of the two halves [m]"),
        crush_relief_depth: float = typer.Option(0.0, help="Crush relief depth [m]"),
        crush_relief_extent: float = typer.Option(0.0, help="Crush relief extent [deg]"),
        end_relief_depth: float = typer.Option(0.0, help="End relief depth [m]"),
        end_relief_length: float = typer.Option(0.0, help="End relief axial length [m]"),
        taper: float = typer.Option(0.0, help="Axial taper (edge +L/2 minus -L/2) [m]"),
        crown: float = typer.Option(0.0, help="Crown (edges minus middle) [m]"),
) -> None:
        """Steady bearing characteristics under Raimondi & Boyd's full-bearing conditions;
        with a load angle, a tilt or a bore profile the journal position under a load vector
        on the Reynolds film (moments, edge h_min, the 4 x 4 coefficients)."""
        with interrupts_stop_at_once():  # starting: nothing computed yet
            from conrod.cases.bearing import MAX_RELATIVE_CLEARANCE
            from conrod.film.base import BearingGeometry
            from conrod.film.steady import raimondi_boyd_point, solve_for_load

        cells = parse_grid(grid)
        shape = {"preload": preload, "lobe_angle": math.radians(lobe_angle),
                 "offset_halves": offset_halves, "crush_relief_depth": crush_relief_depth,
                 "crush_relief_extent": math.radians(crush_relief_extent),
                 "end_relief_depth": end_relief_depth, "end_relief_length": end_relief_length,
                 "taper": taper, "crown": crown}
        profile = steady_profile(shape, profile_file)
        axial = load_angle is not None or tilt_x or tilt_y or profile is not None
        if axial and eccentricity is not None:
            raise CaseError("--eccentricity: Raimondi & Boyd's conditions are for an aligned "
                            "cylindrical bore (with --load-angle, --tilt-x/-y or a profile "
                            "give --load --speed-rpm --viscosity --diameter --width "
                            "--radial-clearance)")
        if eccentricity is not None:
            if length_to_diameter is None:
                raise CaseError("length_to_diameter: required with --eccentricity [-]")
            point = raimondi_boyd_point(length_to_diameter, eccentricity, model.value,
                                        cells, friction.value)
            _print(point.as_dict(), as_json)
            return
        needed = {"load": load, "speed_rpm": speed_rpm, "viscosity": viscosity,
                  "diameter": diameter, "width": width, "radial_clearance": radial_clearance}
        missing = [name for name, value in needed.items() if value is None]
        if missing:
            raise CaseError("give --length-to-diameter and --eccentricity, or all of "
                            "--load --speed-rpm --viscosity --diameter --width "
                            f"--radial-clearance (missing: {', '.join(missing)})")
        for name, value in needed.items():
            if not (math.isfinite(value) and value > 0.0):
                raise CaseError(f"{name} = {value!r}: out of range (allowed: finite, > 0)")
        if radial_clearance > MAX_RELATIVE_CLEARANCE * 0.5 * diameter:
            raise CaseError(f"radial_clearance = {radial_clearance!r}: out of range (allowed: "
                            f"<= {MAX_RELATIVE_CLEARANCE:g} x diameter/2 = "
                            f"{MAX_RELATIVE_CLEARANCE * 0.5 * diameter:g} m)")
        geometry = BearingGeometry(diameter=diameter, width=width,
                                   radial_clearance=radial_clearance, profile=profile)
        if axial:
            from conrod.film.steady_axial import solve_for_load_vector

            if model.value != "reynolds":
                raise CaseError(f"model = {model.value!r}: with a load angle, tilt or profile "
                                "allowed: reynolds")
            answer = solve_for_load_vector(
                load, math.radians(load_angle or 0.0), speed_rpm * math.pi / 30.0, viscosity,
                geometry, tilt=(tilt_x, tilt_y), grid=cells)
        else:
            answer = solve_for_load(load, speed_rpm * math.pi / 30.0, viscosity, geometry,
                                    model.value, cells, friction.value)
        _print(answer.as_dict(), as_json)


def steady_profile(shape: dict, profile_file: str | None):
    """The bore profile of the steady command's options (SI, angles in rad), None when all
    are zero and no file is given."""
    from conrod.film.profile import BoreProfile, ProfileTable

    table = ProfileTable.from_csv(profile_file, "--profile-file") if profile_file else None
    if table is None and not any(value for key, value in shape.items() if key != "lobe_angle"):
        return None
    return BoreProfile(**shape, table=table)
