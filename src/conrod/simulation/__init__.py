"""The workflow floor: :class:`~conrod.simulation.simulation.Simulation` (one case, rigid or
elastic bore), the elastohydrodynamic run with its rigid companion, the rod-stress study and
running-in. Nothing below this package imports it; the sweep, the CLI, the report and the
package's public face do."""

from conrod.simulation.simulation import Simulation, default_film

__all__ = ["Simulation", "default_film"]
