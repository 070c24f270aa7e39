"""Unit conversions used at the input/output edges only (SI inside).

Each constant converts *from* the named engineering unit *to* SI by multiplication.
"""

from __future__ import annotations

import math

RPM_TO_RAD_S = 2.0 * math.pi / 60.0
"""[rad/s per rpm]"""
MM_TO_M = 1.0e-3
"""[m per mm]"""
UM_TO_M = 1.0e-6
"""[m per µm]"""
KGF_TO_N = 9.80665
"""[N per kgf]"""


def rpm_to_rad_s(speed_rpm: float) -> float:
    """Convert a rotational speed [rpm] to an angular velocity [rad/s]."""
    return speed_rpm * RPM_TO_RAD_S

