"""Unit conversions used at the input/output edges only (SI inside).

Each constant converts *from* the named engineering unit *to* SI by multiplication.
"""

from __future__ import annotations

import math

RPM_TO_RAD_S = 2.0 * math.pi / 60.0
"""[rad/s per rpm]"""
DEG_TO_RAD = math.pi / 180.0
"""[rad per deg]"""
MM_TO_M = 1.0e-3
"""[m per mm]"""
UM_TO_M = 1.0e-6
"""[m per µm]"""
MPA_TO_PA = 1.0e6
"""[Pa per MPa]"""
KGF_TO_N = 9.80665
"""[N per kgf]"""
KGF_CM2_TO_PA = 9.80665e4
"""[Pa per kgf/cm²]"""
ZERO_CELSIUS_K = 273.15
"""[K]"""


def rpm_to_rad_s(speed_rpm: float) -> float:
    """Convert a rotational speed [rpm] to an angular velocity [rad/s]."""
    return speed_rpm * RPM_TO_RAD_S


def crank_angle_to_time(crank_angle_deg: float, speed_rpm: float) -> float:
    """Time [s] for the crank to turn ``crank_angle_deg`` [deg] at ``speed_rpm`` [rpm].

    ``dt = dφ / (6 n)`` with φ in degrees and n in rpm (seed 000, eq. 3.1.3).
    """
    return crank_angle_deg / (6.0 * speed_rpm)
