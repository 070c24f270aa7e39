"""conrod's build backend: setuptools' own, and a wheel that carries numba's compiled kernels
of the README's main job.

``pip install .`` builds the wheel on the machine it installs on. After setuptools has built
it, :func:`build_wheel` unpacks it, runs ``python -m conrod.simulation.precompile`` on the
README's example there (numba writes each kernel into the ``__pycache__`` folder beside its
module, keyed on this machine's CPU and on the content of conrod's modules) and packs the
wheel again with those files in its ``RECORD``. The installed package loads them: the first
``conrod run`` compiles nothing (docs/install.md). The computation needs NumPy, SciPy,
numba, pydantic, scikit-fem and threadpoolctl in pip's build environment:
:func:`get_requires_for_build_wheel` asks for them with the specifiers of
``pyproject.toml``'s dependencies. An editable install (``pip install -e .``) and an sdist
are setuptools' alone.

``CONROD_PRECOMPILE=0`` (or ``--config-settings precompile=0``) builds the plain wheel; a
computation that fails or runs past :data:`TIME_LIMIT` leaves the plain wheel too, with one
line on standard error: the first run then compiles what it needs, as without this backend.
"""

from __future__ import annotations

import base64
import csv
import hashlib
import io
import os
import subprocess
import sys
import tempfile
import tomllib
import zipfile
from pathlib import Path
from types import ModuleType
from typing import Any

ROOT = Path(__file__).resolve().parents[1]
CASE = ROOT / "examples" / "kamaz_740_truck_diesel.toml"
"""The README main job's case file, computed at build time."""
KERNEL_IMPORTS = ("numpy", "scipy", "numba", "pydantic", "scikit-fem", "threadpoolctl")
"""The distributions the main job's computation imports (no plotting, no output) [-]."""
SWITCH = "CONROD_PRECOMPILE"
"""Environment variable (or config setting ``precompile``): ``0`` builds the plain wheel."""
TIME_LIMIT = 1800.0
"""Longest the computation may take at build time [s] (2-core machine: 30-60 s)."""
CACHE_SUFFIXES = (".nbi", ".nbc")
"""numba's index and data files of a compiled kernel."""


SETUPTOOLS_HOOKS = ("build_editable", "build_sdist", "get_requires_for_build_editable",
                    "get_requires_for_build_sdist", "prepare_metadata_for_build_editable",
                    "prepare_metadata_for_build_wheel")
"""The rest of the PEP 517 interface: setuptools' own."""


def _setuptools() -> ModuleType:
    from setuptools import build_meta  # in pip's build environment; imported when built

    return build_meta


def __getattr__(name: str) -> Any:
    if name in SETUPTOOLS_HOOKS:
        return getattr(_setuptools(), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def wanted(config_settings: dict | None = None) -> bool:
    """Whether the wheel is built with compiled kernels."""
    setting = (config_settings or {}).get("precompile", os.environ.get(SWITCH, "1"))
    return str(setting).strip().lower() not in ("0", "false", "no", "off")


def kernel_requirements(pyproject: Path = ROOT / "pyproject.toml") -> list[str]:
    """``pyproject.toml``'s dependency specifiers of :data:`KERNEL_IMPORTS`."""
    dependencies = tomllib.loads(pyproject.read_text(encoding="utf-8"))["project"][
        "dependencies"]
    chosen = [spec for spec in dependencies if _name(spec) in KERNEL_IMPORTS]
    missing = set(KERNEL_IMPORTS) - {_name(spec) for spec in chosen}
    if missing:
        raise RuntimeError(f"pyproject.toml: no dependency {sorted(missing)} (build_backend)")
    return chosen


def _name(specifier: str) -> str:
    from packaging.requirements import Requirement  # in pip's build environment (pyproject)
    from packaging.utils import canonicalize_name

    return canonicalize_name(Requirement(specifier).name)


def get_requires_for_build_wheel(config_settings: dict | None = None) -> list[str]:
    """setuptools' requirements, and those of the computation when it is wanted."""
    own = list(_setuptools().get_requires_for_build_wheel(config_settings))
    return own + kernel_requirements() if wanted(config_settings) and CASE.is_file() else own


def build_wheel(wheel_directory: str, config_settings: dict | None = None,
                metadata_directory: str | None = None) -> str:
    """setuptools' wheel, with the main job's compiled kernels where wanted and possible."""
    name = _setuptools().build_wheel(wheel_directory, config_settings, metadata_directory)
    if wanted(config_settings) and CASE.is_file():
        with_compiled_kernels(Path(wheel_directory) / name)
    return name


def with_compiled_kernels(wheel: Path, case: Path = CASE, timeout: float = TIME_LIMIT) -> int:
    """Add the kernels compiled by the main job's computation to ``wheel`` (in place);
    the number of files added (0 where the computation failed: the wheel is unchanged)."""
    with tempfile.TemporaryDirectory(prefix="conrod-kernels-") as folder:
        unpacked = Path(folder)
        with zipfile.ZipFile(wheel) as archive:
            archive.extractall(unpacked)
        env = {key: value for key, value in os.environ.items() if key != "NUMBA_CACHE_DIR"}
        env["PYTHONPATH"] = os.pathsep.join(filter(None, (str(unpacked),
                                                          env.get("PYTHONPATH"))))
        env["PYTHONDONTWRITEBYTECODE"] = "1"
        command = [sys.executable, "-m", "conrod.simulation.precompile", str(case)]
        try:
            done = subprocess.run(command, cwd=unpacked, env=env, capture_output=True,
                                  text=True, timeout=timeout, check=False)
        except subprocess.TimeoutExpired:
            return _not_compiled(f"not done in {timeout:.0f} s")
        if done.returncode != 0:
            last = (done.stderr.strip().splitlines() or [f"exit {done.returncode}"])[-1]
            return _not_compiled(last)
        compiled = sorted(path for path in unpacked.rglob("*") if path.suffix in
                          CACHE_SUFFIXES and path.parent.name == "__pycache__")
        add_files(wheel, {path.relative_to(unpacked).as_posix(): path.read_bytes()
                          for path in compiled})
        print(done.stdout.strip(), f"({len(compiled)} files in the wheel)", file=sys.stderr)
        return len(compiled)


def _not_compiled(why: str) -> int:
    print(f"conrod: kernels not compiled at install ({why}); the first run compiles them",
          file=sys.stderr)
    return 0


def add_files(wheel: Path, files: dict[str, bytes]) -> None:
    """Rewrite ``wheel`` with ``files`` (archive name → content) added and its ``RECORD``
    (sha256, size of every file) written anew; atomic (a temporary file replaces it)."""
    with zipfile.ZipFile(wheel) as archive:
        record = next(info for info in archive.infolist()
                      if info.filename.endswith(".dist-info/RECORD"))
        kept = [(info, archive.read(info)) for info in archive.infolist() if info is not record]
    added = []
    for name, content in files.items():
        info = zipfile.ZipInfo(name, date_time=record.date_time)
        info.external_attr, info.compress_type = 0o644 << 16, zipfile.ZIP_DEFLATED
        added.append((info, content))
    rows = io.StringIO()
    writer = csv.writer(rows, lineterminator="\n")
    for info, content in (*kept, *added):
        digest = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=")
        writer.writerow((info.filename, f"sha256={digest.decode()}", len(content)))
    writer.writerow((record.filename, "", ""))
    partial = wheel.with_name(wheel.name + ".partial")
    with zipfile.ZipFile(partial, "w", compression=zipfile.ZIP_DEFLATED) as archive:
        for info, content in (*kept, *added):
            archive.writestr(info, content)
        archive.writestr(record, rows.getvalue())
    partial.replace(wheel)
