"""Tables of every result type, registered in :func:`conrod.output.registry.tables`.

Column names carry their unit as a suffix (``_m``, ``_Pa``, ``_deg``, ...); the captions
say what each table holds. The figures are registered in :mod:`conrod.plotting`.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from conrod.contact.analysis import ContactResults
from conrod.loads.cycle import LoadCycle
from conrod.loads.engine_loads import EngineLoads
from conrod.mechanism.regimes import SweepRun
from conrod.mechanism.results import JOINT_NAMES, MechanismResults, MechanismRun
from conrod.output.registry import TableSpec, result_kind, tables
from conrod.output.signoff_tables import signoff_tables
from conrod.output.thermal_tables import thermal_outputs
from conrod.results.axial import axial_summary_items
from conrod.results.case_record import CASE_FILE
from conrod.results.columns import CYCLE_COLUMNS, axial_table, feed_table
from conrod.results.cycle_results import RunResults
from conrod.results.feed import feed_summary_items

LOADS_COLUMNS = (
    ("crank_angle_deg", lambda r: r.crank_angle_deg),
    ("cylinder_pressure_Pa", lambda r: r.cylinder_pressure),
    ("gas_force_N", lambda r: r.gas_force),
    ("reciprocating_inertia_force_N", lambda r: r.reciprocating_inertia_force),
    ("rod_force_N", lambda r: r.rod_force),
    ("radial_force_N", lambda r: r.radial_force),
    ("tangential_force_N", lambda r: r.tangential_force),
    ("load_magnitude_N", lambda r: r.load_magnitude),
    ("load_rod_x_N", lambda r: r.load_rod_x),
    ("load_rod_y_N", lambda r: r.load_rod_y),
    ("load_crank_x_N", lambda r: r.load_crank_x),
    ("load_crank_y_N", lambda r: r.load_crank_y),
    ("load_engine_x_N", lambda r: r.load_engine_x),
    ("load_engine_y_N", lambda r: r.load_engine_y),
    ("rod_angle_deg", lambda r: np.degrees(r.rod_angle)),
    ("rod_angular_velocity_rad_s", lambda r: r.rod_angular_velocity),
    ("journal_speed_rad_s", lambda r: r.journal_speed),
    ("shell_speed_rad_s", lambda r: r.shell_speed),
)
"""Columns of ``loads.csv``: name (unit in the suffix) and how to get it from EngineLoads."""


# ----------------------------------------------------------------------- orbit run
def cycle_table(results: RunResults) -> dict[str, np.ndarray]:
    """cycle.csv columns (engineering names with units), refined by the contact analysis."""
    table = {}
    for column, (name, convert) in CYCLE_COLUMNS.items():
        values = np.asarray(getattr(results.cycle, name))
        if values.dtype == bool:
            values = values.astype(int)
        table[column] = convert(values) if convert is not None else values
    if results.contact is not None:
        table.update(results.contact.cycle_columns())
    table.update(axial_table(results.cycle.axial))  # tilt, moments, edge h_min (if any)
    table.update(feed_table(results.cycle.feed))  # crank-pin oil holes (if any)
    return table


def summary_items(results: RunResults) -> dict:
    """summary.json content: the headline, conrod version, case hash and resolved solver
    settings first, then the summary and the contact post-processing items."""
    from conrod._version import __version__
    from conrod.results.summary import headline

    items: dict[str, Any] = {"headline": headline(results), "conrod_version": __version__,
             "case_hash_sha256": results.case_hash, "converged": results.summary.periodic,
             "solver_settings": results.settings}
    items.update(results.summary.as_json_items())
    if results.cycle.axial is not None:  # edge h_min and moments of a tilt or a profile
        items.update(axial_summary_items(results.cycle.crank_angle, results.cycle.axial))
    items.update(feed_summary_items(results.cycle.feed))  # crank-pin oil holes (if any)
    if results.contact is not None:
        items.update(results.contact.summary_items())
    if getattr(results, "thermal_film", None) is not None:  # the film's temperature field
        items.update(results.thermal_film.summary_items())
    if getattr(results, "thermal_maps", None) is not None:  # maps at chosen crank angles
        items.setdefault("thermal_film", {})["maps"] = results.thermal_maps.summary_items()
    if results.signoff is not None:
        items.update(results.signoff.flat_items())  # scalars: the sweep table's columns
        items["signoff"] = results.signoff.as_json_items()
    return items


def contact_tables(results) -> tuple[TableSpec, ...]:
    """The contact and wear tables of a run, only where the journal touches the shell or
    the asperities carry load (a run without contact writes none)."""
    contact = results.contact
    if contact is None or not contact.has_contact:
        return ()
    return tables(contact)


def case_tables(results) -> tuple[TableSpec, ...]:
    """The case as run (:class:`conrod.results.case_record.CaseRecord`): the case file as
    written and a copy of every table it reads; ``manifest.json["case"]`` names them with
    the values the run set on top of the file."""
    record = getattr(results, "case_record", None)
    if record is None:
        return ()
    source = f" ({record.source_name})" if record.source_name else ""
    specs = [TableSpec(CASE_FILE, "Case file",
                       f"The case file as given{source}, with the sources in its comments; "
                       "the values the run set on top of it (command-line options) are in "
                       "manifest.json 'case'.", lambda: record.text.encode("utf-8"))]
    for key, name, content in record.tables:
        specs.append(TableSpec(name, f"Case input {key}",
                               f"Copy of the file the case reads as {key}.",
                               lambda content=content: content))
    return tuple(specs)


@tables.register
def _run_tables(results: RunResults) -> tuple[TableSpec, ...]:
    own = (
        TableSpec("cycle.csv", "Bearing characteristics over the cycle",
                  "Journal-centre orbit, film characteristics, loads and contact at each "
                  "output crank angle (units in the column names: m, Pa, W, m^3/s, N, deg).",
                  lambda: cycle_table(results)),
        TableSpec("summary.json", "Cycle summary",
                  "The headline; smallest film h_min [m] and largest p_max [Pa] with their "
                  "crank angles [deg], cycle means, heat balance, grid-error estimate and "
                  "run diagnostics.",
                  lambda: summary_items(results)),
)
    return (own + contact_tables(results) + signoff_tables(results) + case_tables(results)
            + thermal_outputs(results, tables))


@result_kind.register
def _run_kind(results: RunResults) -> str:
    return "run"


# ------------------------------------------------------------------------ contact
@tables.register
def _contact_tables(contact: ContactResults) -> tuple[TableSpec, ...]:
    wear = contact.wear
    angle = np.degrees(wear.element_angle)
    return (
        TableSpec("wear_journal.csv", "Journal wear per element",
                  "Friction work [J] and wear depth [m] per journal surface element after one "
                  "cycle, by element angle [deg].",
                  lambda: {"angle_deg": angle, "friction_work_J": wear.journal_work,
                           "wear_m": wear.journal_wear}),
        TableSpec("wear_shell.csv", "Shell wear per element",
                  "Friction work [J] and wear depth [m] per shell surface element after one "
                  "cycle, by element angle [deg].",
                  lambda: {"angle_deg": angle, "friction_work_J": wear.shell_work,
                           "wear_m": wear.shell_wear}),
)


@result_kind.register
def _contact_kind(contact: ContactResults) -> str:
    return "contact"


# -------------------------------------------------------------------------- loads
def loads_table(loads: EngineLoads) -> dict[str, np.ndarray]:
    """The ``loads.csv`` columns as a dict name → array."""
    # "+ 0.0" turns -0.0 into 0.0 so that the table does not show "-0"
    return {name: np.asarray(get(loads), dtype=float) + 0.0 for name, get in LOADS_COLUMNS}


@tables.register
def _loads_tables(loads: EngineLoads) -> tuple[TableSpec, ...]:
    return (
        TableSpec("loads.csv", "Engine loads on the big-end bearing",
                  "Cylinder pressure [Pa], gas, inertia, rod and bearing forces [N] in the "
                  "rod, crank and engine frames, rod angle [deg] and surface speeds [rad/s] "
                  "at each crank angle [deg].",
                  lambda: loads_table(loads)),
        TableSpec("loads_summary.json", "Load summary",
                  "Peak and mean bearing load [N] with crank angles [deg], oil-hole angle "
                  "[deg] and the inertia forces [N].",
                  loads.summary),
)


@result_kind.register
def _loads_kind(loads: EngineLoads) -> str:
    return "loads"


# ---------------------------------------------------------------------- mechanism
def mechanism_table(results: MechanismResults) -> dict[str, np.ndarray]:
    """Columns of ``mechanism.csv`` over the last cycle (crank angle 0…720°)."""
    mask = results.last_cycle()
    start = (results.cycles - 1) * results.cycle_length
    table = {
        "crank_angle_deg": np.degrees(results.crank_angle[mask] - start),
        "piston_position_m": results.piston_position[mask],
        "piston_position_rigid_m": results.piston_position_rigid[mask],
        "rod_obliquity_deg": np.degrees(results.rod_obliquity[mask]),
        "gas_force_N": results.gas_force[mask],
    }
    for index, name in enumerate(JOINT_NAMES):
        table[f"{name}_gap_m"] = results.gap[index, mask]
        table[f"{name}_journal_along_rod_m"] = results.journal_offset[index, 0, mask]
        table[f"{name}_journal_across_rod_m"] = results.journal_offset[index, 1, mask]
        table[f"{name}_force_N"] = results.contact_force[index, mask]
        table[f"{name}_friction_N"] = results.friction_force[index, mask]
    table["energy_residual_J"] = results.energy_residual[mask]
    return table


def impacts_text(results: MechanismResults) -> str:
    """``impacts.csv``: every impact of the settled cycles (all but the first), crank angle
    within its cycle [deg], joint by name, impact velocity [m/s], cycle number from 1."""
    impacts = results.settled_impacts()
    cycle = np.floor(impacts.crank_angle / results.cycle_length)
    angles = np.degrees(impacts.crank_angle - cycle * results.cycle_length)
    lines = ["crank_angle_deg,joint,impact_velocity_m_s,cycle"]
    for angle, joint, speed, number in zip(angles, impacts.joint, impacts.velocity,
                                           cycle.astype(int) + 1, strict=True):
        lines.append(f"{angle:.6f},{JOINT_NAMES[int(joint)]},{speed:.9g},{number}")
    return "\n".join(lines) + "\n"


@tables.register
def _mechanism_tables(run: MechanismRun) -> tuple[TableSpec, ...]:
    return (
        TableSpec("mechanism.csv", "Slider-crank with clearances, last cycle",
                  "Piston position [m], rod obliquity [deg], gas force [N], gap [m], journal "
                  "offset [m], contact and friction force [N] of both rod bearings and the "
                  "energy residual [J] over the last cycle.",
                  lambda: mechanism_table(run.results)),
        TableSpec("impacts.csv", "Impacts of the settled cycles",
                  "Crank angle within the cycle [deg], joint, impact velocity [m/s] and cycle "
                  "number of every impact after the start-up cycle.",
                  lambda: impacts_text(run.results)),
        TableSpec("summary.json", "Mechanism summary",
                  "Operating point, impacts per cycle, impact velocities [m/s], contact forces "
                  "[N], energy residual [J] and integrator statistics.",
                  run.summary),
)


@result_kind.register
def _mechanism_kind(run: MechanismRun) -> str:
    return "mechanism"


@tables.register
def _sweep_tables(run: SweepRun) -> tuple[TableSpec, ...]:
    return (
        TableSpec("sweep.csv", "Impact statistics over the operating modes",
                  "Per crank speed [rpm] and load scale [-]: largest and mean impact velocity "
                  "[m/s] and impacts per cycle of both joints, and their velocity ratio [-].",
                  run.sweep.columns),
        TableSpec("sweep.json", "Most informative regime",
                  "Operating mode with the largest impact-velocity ratio of the worn joint, "
                  "number of runs and wall time [s].",
                  run.summary),
)


@result_kind.register
def _sweep_kind(run: SweepRun) -> str:
    return "mechanism_sweep"


# ------------------------------------------------------------------ load table
def table_load_columns(loads: LoadCycle) -> dict[str, np.ndarray]:
    """loads.csv of a load-table case: the load in the bearing (film) frame."""
    return {"crank_angle_deg": np.degrees(loads.crank_angle), "load_x_N": loads.load_x,
            "load_y_N": loads.load_y, "load_N": np.hypot(loads.load_x, loads.load_y),
            "journal_speed_rad_s": loads.journal_speed, "shell_speed_rad_s": loads.shell_speed}


def table_load_summary(loads: LoadCycle) -> dict:
    """Peak and mean load [N] of a load table, the peak's crank angle [deg]."""
    magnitude = np.hypot(loads.load_x, loads.load_y)
    i = int(np.argmax(magnitude))
    return {"peak_load_N": float(magnitude[i]),
            "peak_load_crank_angle_deg": float(np.degrees(loads.crank_angle[i])),
            "mean_load_N": float(magnitude.mean()), "cycle_deg": float(np.degrees(loads.cycle)),
            "frame": "bearing (film) frame, as given in the load table"}


@tables.register
def _table_load_tables(loads: LoadCycle) -> tuple[TableSpec, ...]:
    return (
        TableSpec("loads.csv", "Bearing load from the load table",
                  "Load components in the bearing frame and magnitude [N], surface speeds "
                  "[rad/s] against crank angle [deg].", lambda: table_load_columns(loads)),
        TableSpec("loads_summary.json", "Load summary",
                  "Peak load [N] and its crank angle [deg], mean load [N].",
                  lambda: table_load_summary(loads)),
    )


@result_kind.register
def _table_load_kind(loads: LoadCycle) -> str:
    return "loads"
