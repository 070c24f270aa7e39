"""Column names of a run's per-angle table, with their units: one naming for ``cycle.csv``
(:mod:`conrod.output.tables`) and :meth:`conrod.results.cycle_results.CycleResults.to_dataframe`."""

from __future__ import annotations

import numpy as np

CYCLE_COLUMNS = {
    "crank_angle_deg": ("crank_angle", np.degrees),
    "eccentricity_ratio_1": ("eccentricity_ratio", None),
    "eccentricity_x_m": ("eccentricity_x", None),
    "eccentricity_y_m": ("eccentricity_y", None),
    "velocity_x_m_s": ("velocity_x", None),
    "velocity_y_m_s": ("velocity_y", None),
    "attitude_angle_deg": ("attitude_angle", np.degrees),
    "h_min_m": ("h_min", None),
    "h_min_angle_shell_deg": ("h_min_angle_shell", np.degrees),
    "h_min_angle_journal_deg": ("h_min_angle_journal", np.degrees),
    "p_max_Pa": ("p_max", None),
    "p_max_angle_shell_deg": ("p_max_angle_shell", np.degrees),
    "friction_torque_N_m": ("friction_torque", None),
    "friction_power_W": ("friction_power", None),
    "side_flow_m3_s": ("side_flow", None),
    "supply_flow_m3_s": ("supply_flow", None),
    "load_x_N": ("load_x", None),
    "load_y_N": ("load_y", None),
    "journal_speed_rad_s": ("journal_speed", None),
    "shell_speed_rad_s": ("shell_speed", None),
    "contact_force_N": ("contact_force", None),
    "friction_force_N": ("friction_force", None),
    "contact_angle_deg": ("contact_angle", np.degrees),
    "journal_rotation_deg": ("journal_rotation", np.degrees),
    "sliding_speed_m_s": ("sliding_speed", None),
    "in_contact": ("in_contact", None),
}
"""cycle.csv column → (CycleResults field, conversion): the column names of ``cycle.csv``
and of :meth:`CycleResults.to_dataframe` alike. Every name ends in its unit (``_m``,
``_Pa``, ``_deg``, ``_m3_s``, ...; ``_1`` for a dimensionless ratio, ``eccentricity_ratio_1``)
but the flag ``in_contact`` (1 where the journal touches the shell)."""

AXIAL_COLUMNS = {
    "tilt_x_rad": ("tilt_x", None),
    "tilt_y_rad": ("tilt_y", None),
    "tilt_rate_x_rad_s": ("tilt_rate_x", None),
    "tilt_rate_y_rad_s": ("tilt_rate_y", None),
    "moment_x_N_m": ("moment_x", None),
    "moment_y_N_m": ("moment_y", None),
    "external_moment_x_N_m": ("external_moment_x", None),
    "external_moment_y_N_m": ("external_moment_y", None),
    "h_min_axial_position_m": ("h_min_axial_position", None),
    "h_min_at_edge": ("h_min_at_edge", None),
    "edge_h_min_m": ("edge_h_min", None),
}
"""cycle.csv columns of a tilted journal or a profiled bore → (key of ``CycleResults.axial``,
conversion) (:mod:`conrod.results.axial`); absent for an aligned cylindrical bearing."""


FEED_COLUMNS = {
    "journal_hole_flow_m3_s": ("journal_hole_flow", None),
    "journal_hole_angle_shell_deg": ("journal_hole_angle_shell", np.degrees),
    "journal_hole_pressure_Pa": ("journal_hole_pressure", None),
    "inlet_film_fraction": ("inlet_film_fraction", None),
}
"""cycle.csv columns of the crank-pin oil holes → (key of ``CycleResults.feed``,
conversion) (:mod:`conrod.results.feed`); absent without journal holes, the inlet film
fraction only with the mass-conserving film."""


def feed_table(feed: dict | None) -> dict[str, np.ndarray]:
    """The :data:`FEED_COLUMNS` of ``CycleResults.feed`` present in it; {} when None."""
    if feed is None:
        return {}
    return {column: (convert(np.asarray(feed[key])) if convert is not None
                     else np.asarray(feed[key]))
            for column, (key, convert) in FEED_COLUMNS.items() if key in feed}


def axial_table(axial: dict | None) -> dict[str, np.ndarray]:
    """The :data:`AXIAL_COLUMNS` of ``CycleResults.axial`` (bools as 0/1); {} when None."""
    if axial is None:
        return {}
    table = {}
    for column, (key, convert) in AXIAL_COLUMNS.items():
        values = np.asarray(axial[key])
        values = values.astype(int) if values.dtype == bool else values
        table[column] = convert(values) if convert is not None else values
    return table
