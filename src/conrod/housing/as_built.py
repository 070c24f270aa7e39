"""The bearing geometry as built and warm: the clearance change of the warm journal and
housing (:mod:`conrod.housing.thermal`) and the housing's static bore shape — assembled
(:mod:`conrod.housing.assembly`) and thermally distorted — as a bore profile h₀(θ) on top
of which the running deformation acts."""

from __future__ import annotations

import dataclasses

import numpy as np

from conrod.errors import CaseError
from conrod.housing.thermal import WarmBore

SMALLEST_WARM_CLEARANCE = 0.1
"""Smallest warm radial clearance, share of the given (cold) one [-]."""


def film_start(case):
    """``case`` itself, or, when its ``[housing.thermal]`` takes its temperatures from the
    thermal film (none given), the case with journal and housing at the oil's supply
    temperature: the bore of the first orbit of the thermal iteration, and of anything
    asked before it (:mod:`conrod.simulation.warm_film_run`)."""
    section = case.housing.thermal
    if section is None or not section.from_film:
        return case
    supply = float(case.lubricant.supply_temperature)
    housing = case.housing.model_copy(update={"thermal": section.at_temperatures(
        supply, [0.0], [supply], supply)})
    return case.model_copy(update={"housing": housing})


def warm_bore(case, bore: np.ndarray | None = None, temperatures: tuple[float, float] | None
              = None, corner_temperature: np.ndarray | None = None) -> WarmBore | None:
    """The warm bore of ``[housing.thermal]`` (None without it, or at the reference
    temperature); ``bore``: the raw FE thermal bore displacement [m] with ``temperatures``,
    the housing's mean and the shell-side mean [degC] (default: the uniform
    ``housing_temperature``), and the conduction field at the mesh corners [degC]."""
    case = film_start(case)
    section = case.housing.thermal
    if section is None or not section.active:
        return None
    bearing = case.bearing
    shell = 0.5 * (case.housing.bore_diameter(bearing.diameter) - bearing.diameter)
    if temperatures is None:
        temperatures = (section.housing_temperature, section.housing_temperature)
    return WarmBore(section, 0.5 * bearing.diameter, 0.5 * bearing.diameter + shell, shell,
                    bore, *temperatures, corner_temperature)


def housing_bore_profile(housing) -> np.ndarray | None:
    """h₀(θ_j) [m] of the housing's static bore shape: the assembled bore and the thermal
    distortion's out-of-round part (None when there is neither)."""
    parts = [housing.assembled_profile()]
    if housing.warm is not None:
        parts.append(housing.warm.profile(housing.projector))
    parts = [part for part in parts if part is not None]
    return None if not parts else np.sum(parts, axis=0)


def carried_bore_shape(geometry, housing) -> np.ndarray | None:
    """The housing's static bore shape h₀(θ_j) [m] when the film of ``geometry`` carries it
    (its profile holds the as-built bore), else None."""
    profile = getattr(geometry, "profile", None)
    if profile is None or getattr(profile, "housing_bore", None) is None:
        return None
    return housing_bore_profile(housing)


def as_built_geometry(geometry, housing, warm: WarmBore | None, with_profile: bool):
    """``geometry`` (:class:`~conrod.film.base.BearingGeometry`) with the clearance change
    of ``warm`` and, when ``with_profile`` (a grid film on the elastic ``housing``), the
    housing's static bore shape as a bore profile beside its own."""
    if warm is not None:
        change = warm.clearance_change(None if housing is None else housing.projector)
        cold = geometry.radial_clearance
        if not cold + change > SMALLEST_WARM_CLEARANCE * cold:
            section = warm.section
            raise CaseError(
                f"housing.thermal: journal at {section.journal_temperature:g} degC, housing "
                f"at {warm.housing_temperature:g} degC change the radial clearance "
                f"{cold:.4g} m by {change:.4g} m (allowed: a warm clearance above "
                f"{SMALLEST_WARM_CLEARANCE:g} x the clearance; the journal seizes)")
        geometry = dataclasses.replace(geometry, radial_clearance=cold + change)
    profile = None if housing is None or not with_profile else housing_bore_profile(housing)
    if profile is None:
        return geometry
    from conrod.film.profile import BoreProfile, ProfileTable

    table = ProfileTable.from_arrays(housing.angles, np.zeros(1), profile[:, None],
                                     "as-built bore (housing.assembly, housing.thermal)")
    own = geometry.profile if geometry.profile is not None else BoreProfile()
    return dataclasses.replace(geometry, profile=dataclasses.replace(own, housing_bore=table))


def run_geometry(geometry, section, housing_of, case, grid_film: bool, fe_warm_of=None):
    """The run's geometry (:func:`as_built_geometry`): ``geometry`` itself without an active
    ``[housing.assembly]`` or ``[housing.thermal]`` (``section``: ``[housing]``), else as
    built and warm on the housing ``housing_of()`` (None for a rigid bore, whose clearance
    change is that of ``fe_warm_of()``, the FE housing's warm bore, for a housing that
    conducts from its shell side — the elastic run's — else a free ring's)."""
    if not any(part is not None and part.active for part in (section.assembly,
                                                             section.thermal)):
        return geometry
    housing = housing_of()
    warm = warm_bore(case) if housing is None else housing.warm
    if housing is None and section.thermal is not None and section.thermal.conducting:
        warm = fe_warm_of()
    return as_built_geometry(geometry, housing, warm, grid_film)


def as_built_summary(housing) -> dict:
    """What the run's bore carries as built and warm, for ``summary.json["elastic"]``
    (units in the key names; empty without an assembly or a warm bore)."""
    out: dict = {}
    if housing.assembly is not None:
        out["assembled_out_of_round_um"] = float(np.ptp(housing.assembled_profile()) * 1e6)
    if housing.warm is not None:
        out["thermal_clearance_change_um"] = float(
            housing.warm.clearance_change(housing.projector) * 1e6)
    profile = housing_bore_profile(housing)
    if profile is not None and out:
        out["housing_bore_profile_range_um"] = [float(profile.min() * 1e6),
                                                float(profile.max() * 1e6)]
    return out
