"""Effective film temperature from a global heat balance ([D2] Table 1 column t*).

All friction power is carried away by the oil that flows through the bearing:

.. math:: \\bar N = ρ\\, c_p\\, \\bar Q\\, (T_{eff} − T_{supply}),

with N̄ the cycle-mean friction power of the film plus the dry friction of hard contact
μ_dry P_c |V_slide| [W] and Q̄ the cycle-mean side flow [m³/s] (in a
periodic orbit it equals the mean supply flow). With a Vogel law μ(T) the orbit is
recomputed with μ(T_eff) and T_eff updated, under-relaxed, until it changes by less than
``[solver] thermal_tolerance`` [K].
"""

from __future__ import annotations

RELAXATION = 0.5
"""Under-relaxation of the temperature update [-]."""


def effective_temperature(
    mean_friction_power: float, mean_flow: float, supply_temperature: float,
    density: float, specific_heat: float,
) -> float | None:
    """T_eff = T_supply + N̄/(ρ c_p Q̄) [°C]; None when there is no flow to carry the heat."""
    if mean_flow <= 0.0:
        return None
    return supply_temperature + mean_friction_power / (density * specific_heat * mean_flow)


def relaxed_update(current: float, target: float) -> float:
    """Next temperature guess T + r (T_target − T) [°C]."""
    return current + RELAXATION * (target - current)
