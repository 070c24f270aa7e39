"""numba's kernels of the README's main job compiled ahead of its first run.

``pip install .`` builds conrod's wheel on the machine it installs on; while it does, the
build runs :func:`precompile` on the unpacked wheel (``build_backend/conrod_build.py``), so
numba writes the compiled kernels into the wheel's ``__pycache__`` folders and the installed
package loads them: the first ``conrod run`` compiles nothing (docs/install.md). The
computation is the main job's own (``conrod run examples/kamaz_740_truck_diesel.toml
--film reynolds --grid 144x16``: the elastic orbit, its rigid companion on the second core,
the grid-error orbits), with nothing written but the compiled kernels; a kernel compiled
for one argument type is cached for that type only, so a smaller stand-in computation would
leave the run to compile what it calls differently.

.. code-block:: bash

    python -m conrod.simulation.precompile examples/kamaz_740_truck_diesel.toml
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

MAIN_JOB = {"film": "reynolds", "n_theta": 144, "n_z": 16}
"""The README main job's options (``--film reynolds --grid 144x16``) [-]."""


def precompile(case_file: str | Path, **options: object) -> float:
    """Compute ``case_file`` as ``conrod run`` does with :data:`MAIN_JOB` (``options``
    replace its entries) and return the wall time [s]; writes no results."""
    from conrod.cases.case import Case
    from conrod.simulation.grid_error import coarse_jobs, with_grid_error
    from conrod.simulation.side_runs import beside
    from conrod.simulation.simulation import Simulation

    start = time.perf_counter()
    simulation = Simulation(Case.from_toml(Path(case_file)), **{**MAIN_JOB, **options})
    with beside(simulation, coarse_jobs(simulation)):
        with_grid_error(simulation.run(), simulation)
    return time.perf_counter() - start


def main(argv: list[str] | None = None) -> int:
    """``python -m conrod.simulation.precompile CASE``: one line on standard output."""
    args = sys.argv[1:] if argv is None else argv
    if len(args) != 1:
        print("usage: python -m conrod.simulation.precompile CASE_FILE", file=sys.stderr)
        return 2
    seconds = precompile(args[0])
    print(f"conrod: kernels of the main job compiled in {seconds:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
