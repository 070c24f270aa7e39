"""The build backend (build_backend/conrod_build.py): a wheel rewritten with files added
keeps every file and a RECORD that matches them; the computation's outcome decides what is
added; editable installs and the switch leave setuptools' build alone. The computation is
replaced here by a stand-in ``conrod.simulation.precompile`` inside the wheel (the real one
compiles for a minute; docs/install.md has its measurement)."""

from __future__ import annotations

import base64
import csv
import hashlib
import importlib.util
import io
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def backend():
    spec = importlib.util.spec_from_file_location(
        "conrod_build", ROOT / "build_backend" / "conrod_build.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


STAND_IN = {
    "compiles": "import pathlib\n"
                "folder = pathlib.Path('conrod/film/__pycache__')\n"
                "folder.mkdir(parents=True)\n"
                "(folder / 'kernel.f-3.py311.nbi').write_bytes(b'index')\n"
                "(folder / 'kernel.f-3.py311.1.nbc').write_bytes(b'code')\n"
                "(folder / 'kernel.cpython-311.pyc').write_bytes(b'not numba')\n"
                "print('compiled')\n",
    "fails": "raise SystemExit('conrod: case file missing')\n",
}


def _wheel(folder: Path, precompile: str) -> Path:
    """A wheel of a package ``conrod`` with a stand-in precompile module and its RECORD."""
    files = {"conrod/__init__.py": b"", "conrod/simulation/__init__.py": b"",
             "conrod/film/__init__.py": b"", "conrod/data/table.csv": b"a,b\n1,2\n",
             "conrod/simulation/precompile.py": precompile.encode()}
    rows = "".join(f"{name},,\n" for name in files) + "conrod-0.1.dist-info/RECORD,,\n"
    wheel = folder / "conrod-0.1-py3-none-any.whl"
    with zipfile.ZipFile(wheel, "w") as archive:
        for name, content in files.items():
            archive.writestr(name, content)
        archive.writestr("conrod-0.1.dist-info/RECORD", rows)
    return wheel


def _record(wheel: Path) -> dict[str, tuple[str, str]]:
    with zipfile.ZipFile(wheel) as archive:
        text = archive.read("conrod-0.1.dist-info/RECORD").decode()
        names = set(archive.namelist())
        contents = {name: archive.read(name) for name in names}
    rows = {row[0]: (row[1], row[2]) for row in csv.reader(io.StringIO(text))}
    assert set(rows) == names  # every file listed, nothing else
    for name, (digest, size) in rows.items():
        if name.endswith("RECORD"):
            assert (digest, size) == ("", "")
            continue
        content = contents[name]
        expected = base64.urlsafe_b64encode(hashlib.sha256(content).digest()).rstrip(b"=")
        assert digest == f"sha256={expected.decode()}" and int(size) == len(content), name
    return rows


def test_the_compiled_kernels_are_added_to_the_wheel_with_a_matching_record(
        backend, tmp_path, capsys):
    wheel = _wheel(tmp_path, STAND_IN["compiles"])
    before = zipfile.ZipFile(wheel).read("conrod/data/table.csv")
    assert backend.with_compiled_kernels(wheel, case=tmp_path / "case.toml") == 2
    rows = _record(wheel)
    assert {"conrod/film/__pycache__/kernel.f-3.py311.nbi",
            "conrod/film/__pycache__/kernel.f-3.py311.1.nbc"} <= set(rows)
    assert "conrod/film/__pycache__/kernel.cpython-311.pyc" not in rows  # numba's files only
    with zipfile.ZipFile(wheel) as archive:
        assert archive.read("conrod/data/table.csv") == before
        assert archive.read("conrod/film/__pycache__/kernel.f-3.py311.nbi") == b"index"
    assert "compiled (2 files in the wheel)" in capsys.readouterr().err


def test_a_failing_computation_leaves_the_wheel_as_setuptools_built_it(
        backend, tmp_path, capsys):
    wheel = _wheel(tmp_path, STAND_IN["fails"])
    before = wheel.read_bytes()
    assert backend.with_compiled_kernels(wheel, case=tmp_path / "case.toml") == 0
    assert wheel.read_bytes() == before
    assert capsys.readouterr().err.strip() == (
        "conrod: kernels not compiled at install (conrod: case file missing); the first run "
        "compiles them")


def test_only_the_wheel_asks_for_the_computations_packages_and_the_switch_drops_them(
        backend, monkeypatch):
    import types

    setuptools = types.SimpleNamespace(get_requires_for_build_wheel=lambda settings=None: ["wheel"],
                                       get_requires_for_build_editable=lambda settings=None: [])
    monkeypatch.setattr(backend, "_setuptools", lambda: setuptools)
    requirements = backend.kernel_requirements()
    assert sorted(backend._name(spec) for spec in requirements) == sorted(
        backend.KERNEL_IMPORTS)
    assert "numba>=0.59" in requirements  # pyproject.toml's own specifier
    monkeypatch.delenv(backend.SWITCH, raising=False)
    assert backend.get_requires_for_build_wheel() == ["wheel", *requirements]
    assert backend.get_requires_for_build_editable() == []  # setuptools' own
    for off in ({"precompile": "0"}, {"precompile": "false"}):
        assert backend.get_requires_for_build_wheel(off) == ["wheel"]
    monkeypatch.setenv(backend.SWITCH, "0")
    assert not backend.wanted() and backend.wanted({"precompile": "1"})
    assert backend.get_requires_for_build_wheel() == ["wheel"]
    with pytest.raises(AttributeError):
        backend.build_something_else  # noqa: B018


def test_the_backend_is_the_one_pyproject_names():
    import tomllib

    system = tomllib.loads((ROOT / "pyproject.toml").read_text())["build-system"]
    assert (system["build-backend"], system["backend-path"]) == ("conrod_build",
                                                                 ["build_backend"])
    assert sys.version_info >= (3, 11)  # tomllib in the backend
