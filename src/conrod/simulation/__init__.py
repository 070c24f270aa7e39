"""The workflow floor: :class:`~conrod.simulation.simulation.Simulation` (one case, rigid or
elastic bore), the elastohydrodynamic run with its rigid companion, the rod-stress study and
running-in. Nothing below this package imports it; the sweep, the CLI, the report and the
package's public face do."""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.simulation.simulation import Simulation, default_film

_PUBLIC = {
    **dict.fromkeys(("Simulation", "default_film"), "conrod.simulation.simulation"),
}
"""Public name → the module that defines it (imported when the name is first used)."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["Simulation", "default_film"]
