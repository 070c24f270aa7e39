"""Start-up stays light: ``import conrod``, ``conrod --version`` and the help pages load no
part of the numerical stack (each checked in a fresh process, by what is in sys.modules)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

SRC = Path(__file__).resolve().parents[1] / "src"
HEAVY = ("numba", "scipy", "pandas", "dask", "distributed", "matplotlib", "numpy", "skfem")
"""Packages that only a computation (or a figure, a sweep) needs."""

LOADED_AFTER = """
import json, sys
{statement}
print(json.dumps(sorted(name for name in {heavy!r} if name in sys.modules)))
"""

CLI = """
from conrod.cli.app import main
try:
    main()
except SystemExit:
    pass
"""


def _heavy_loaded(statement: str, *args: str, heavy: tuple[str, ...] = HEAVY) -> list[str]:
    code = LOADED_AFTER.format(statement=statement, heavy=heavy)
    env = {**os.environ, "PYTHONPATH": str(SRC)}
    done = subprocess.run([sys.executable, "-c", code, *args], capture_output=True, text=True,
                          env=env, check=False, timeout=120)
    assert done.returncode == 0, done.stderr[-2000:]
    return json.loads(done.stdout.strip().splitlines()[-1])


@pytest.mark.parametrize("statement", [
    "import conrod", "import conrod.film", "import conrod.mechanism", "import conrod.sweep",
    "import conrod.io.result_folder", "from conrod import __version__, ConrodError",
])
def test_importing_the_package_loads_no_numerical_stack(statement):
    assert _heavy_loaded(statement) == []


@pytest.mark.parametrize("args", [("--version",), ("--help",), ("run", "--help"),
                                  ("loads", "--help"), ("mechanism", "--help"),
                                  ("steady", "--help")])
def test_version_and_help_load_no_numerical_stack(args):
    assert _heavy_loaded(CLI, *args) == []


@pytest.mark.parametrize("args", [("--help",), ("run", "--help"), ("sweep", "--help")])
def test_help_pages_are_plain_text_without_rich_or_markdown(args):
    """The help pages are click's plain text: rich and markdown-it (0.17 s of imports and
    0.1 s of layout per page on a 2-core machine) are not loaded to print them."""
    assert _heavy_loaded(CLI, *args, heavy=("rich", "markdown_it")) == []


def test_a_lazy_name_is_the_defining_module_s_object():
    import conrod
    import conrod.film
    from conrod.film.base import BearingGeometry

    assert conrod.film.BearingGeometry is BearingGeometry is conrod.BearingGeometry
    with pytest.raises(AttributeError, match="no attribute 'Bearing'"):
        conrod.film.Bearing  # noqa: B018


def test_the_implicit_and_elastic_orbits_do_not_load_scipys_integrators():
    """The implicit step (also of the elastic bore) imports the adaptive integrator's module
    for its helpers only; SciPy's integrators (0.2-0.5 s to import, in each process of a
    run) are loaded where ``solve_ivp`` integrates, and only there."""
    statement = ("import conrod.orbit.implicit, conrod.orbit.implicit_step, "
                 "conrod.orbit.system_steps, conrod.ehd.film")
    assert _heavy_loaded(statement, heavy=("scipy.integrate",)) == []
