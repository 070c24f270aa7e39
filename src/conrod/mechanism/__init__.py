"""Slider-crank with clearances in both rod bearings: worn shells, impacts ([D3]).

.. code-block:: python

    from conrod.mechanism import mechanism_case, simulate

    run = mechanism_case(Case.from_toml("examples/kulayev_worn_rod_bearings.toml"))
    results = simulate(run.mechanism, run.scaled_gas_table(), run.settings)
    results.summary()["max_impact_velocity_big_end_m_s"]     # [m/s]

Layers: :mod:`geometry` (ellipse contact law) and :mod:`kernel` (right-hand side) are
numba kernels; :mod:`integrator` integrates them; :mod:`model` holds the components;
:mod:`simulation` and :mod:`setup` run one operating mode; :mod:`results` and :mod:`regimes`
type them (the sweep over many modes is :func:`conrod.sweep.mechanism.run_sweep`).

The names below are imported when first used (the kernels compile with numba).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.mechanism.model import ClearanceJoint, CrankTrain, Mechanism
    from conrod.mechanism.regimes import SweepResults
    from conrod.mechanism.results import Impacts, MechanismResults
    from conrod.mechanism.setup import MechanismCase, mechanism_case
    from conrod.mechanism.simulation import RunSettings, simulate

_PUBLIC = {
    **dict.fromkeys(("ClearanceJoint", "CrankTrain", "Mechanism"), "conrod.mechanism.model"),
    "SweepResults": "conrod.mechanism.regimes",
    **dict.fromkeys(("Impacts", "MechanismResults"), "conrod.mechanism.results"),
    **dict.fromkeys(("MechanismCase", "mechanism_case"), "conrod.mechanism.setup"),
    **dict.fromkeys(("RunSettings", "simulate"), "conrod.mechanism.simulation"),
}
"""Public name → the module that defines it."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = [
    "ClearanceJoint", "CrankTrain", "Impacts", "Mechanism", "MechanismCase", "MechanismResults",
    "RunSettings", "SweepResults", "mechanism_case", "simulate",
]
