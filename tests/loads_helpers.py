"""Helpers shared by the loads tests: small engine cases written to a temporary folder."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from conrod.cases.case import Case

ENGINE = {
    "bore": 0.1,
    "stroke": 0.1,
    "rod_length": 0.18,
    "speed": 3000.0,
    "piston_mass": 1.2,
    "rod_mass": 1.5,
    "rod_cg_from_big_end": 0.05,
}
BEARING = {"diameter": 0.06, "width": 0.025, "radial_clearance": 3.0e-5}


def write_trace(path: Path, angles_deg, pressures_pa) -> Path:
    """Write a pressure-trace CSV (crank_angle_deg, pressure_Pa) with a provenance comment."""
    lines = ["# synthetic trace for tests", "crank_angle_deg,pressure_Pa"]
    lines += [f"{float(a)!r},{float(p)!r}" for a, p in zip(angles_deg, pressures_pa, strict=True)]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def trace_case(folder: Path, pressure=None, **engine) -> Case:
    """Case with a trace over 0..719 deg (constant ambient 1e5 Pa unless given)."""
    angles = np.arange(0.0, 720.0, 1.0)
    values = np.full(angles.shape, 1.0e5) if pressure is None else pressure(angles)
    write_trace(folder / "trace.csv", angles, values)
    data = {
        "engine": {**ENGINE, **engine, "pressure_trace": "trace.csv"},
        "bearing": dict(BEARING),
    }
    return Case.from_dict(data, base_dir=folder)


def loads_cli():
    """A typer app with only ``conrod loads`` registered (isolated from other commands)."""
    import typer

    from conrod.cli import loads_command

    app = typer.Typer()

    @app.callback()
    def _group() -> None:
        """conrod (test instance)."""

    loads_command.register(app)
    return app


def case_text(engine_lines: str, bearing: bool = True) -> str:
    """TOML text of a case with the given ``[engine]`` body and a parametric pressure."""
    text = "[engine]\n" + engine_lines + "\n"
    text += (
        "[engine.pressure_model]\ncompression_ratio = 17.0\nintake_pressure = 0.09e6\n"
        "max_pressure = 9.0e6\nexhaust_pressure = 0.11e6\nmax_pressure_duration = 15.0\n"
        "compression_index = 1.35\nexpansion_index = 1.25\n"
    )
    if bearing:
        text += "[bearing]\ndiameter = 0.06\nwidth = 0.025\n"
    return text
