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
