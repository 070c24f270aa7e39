"""Layering and the output registry: one writer, one manifest, plotting only where it
belongs, no concrete-type questions in the orbit stage, no internal labels in user text."""

from __future__ import annotations

import ast
import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PACKAGE = ROOT / "src" / "conrod"
PLOTTING_ALLOWED = ("plotting", "cli", "report", "sweep")
"""The figures themselves, and the output layers that write them (commands, report, sweep
variants with ``--figures``)."""


def _imports(path: Path) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


def test_only_plotting_and_the_user_layers_import_plotting_or_matplotlib():
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        part = path.relative_to(PACKAGE).parts[0]
        if part in PLOTTING_ALLOWED:
            continue
        bad = {n for n in _imports(path)
               if n.startswith(("conrod.plotting", "matplotlib"))}
        if bad:
            offenders.append(f"{path.relative_to(PACKAGE)}: {sorted(bad)}")
    assert offenders == []


def test_the_orbit_stage_asks_capabilities_not_types():
    pattern = re.compile(r"type\(.*\) is|film_grid|\.tables\[")
    hits = [f"{p.name}:{n}" for p in (PACKAGE / "orbit").glob("*.py")
            for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
            if pattern.search(line)]
    assert hits == []


def test_the_case_schema_and_the_factory_read_one_registry_of_names():
    from typing import get_args

    from conrod.cases.solver import SolverSection
    from conrod.registry import FILM_MODELS, INTEGRATORS, film_class, integrator

    fields = SolverSection.model_fields
    assert set(get_args(fields["film"].annotation)) == set(FILM_MODELS)
    assert set(get_args(fields["integrator"].annotation)) == set(INTEGRATORS)
    for name in FILM_MODELS:
        assert callable(film_class(name).from_settings)
    for name in INTEGRATORS:
        assert integrator(name).name == name


def test_every_result_file_is_in_the_manifest(tmp_path):
    """The one writer writes each registered table and figure and lists them, with
    titles and captions, in manifest.json (written last)."""
    import conrod.plotting  # noqa: F401
    from conrod import __version__
    from conrod.cases.case import Case
    from conrod.loads.engine_loads import compute_engine_loads
    from conrod.output.registry import figures, tables, write_results

    case = Case.from_toml(ROOT / "examples" / "passenger_car_diesel_2000rpm.toml")
    loads = compute_engine_loads(case, step_deg=2.0)
    paths = write_results(loads, tmp_path)
    manifest = json.loads((tmp_path / "manifest.json").read_text(encoding="utf-8"))
    assert paths[-1].name == "manifest.json"
    assert manifest["conrod_version"] == __version__ and manifest["kind"] == "loads"
    listed = [e["file"] for e in manifest["tables"] + manifest["figures"]]
    assert listed == [s.file for s in tables(loads) + figures(loads)]
    assert sorted(listed + ["manifest.json"]) == sorted(p.name for p in tmp_path.iterdir())
    for entry in manifest["tables"] + manifest["figures"]:
        assert entry["title"] and "[" in entry["caption"]  # captions carry units


def test_a_result_type_without_registered_outputs_is_refused(tmp_path):
    from conrod.output.registry import write_results

    with pytest.raises(TypeError, match="no tables registered"):
        write_results(object(), tmp_path)
    assert not any(tmp_path.iterdir())


def test_no_internal_process_labels_in_user_text():
    """Sources are cited (docs/references.md), never internal issue or spec labels."""
    label = re.compile(r"\b[Ii]ssue \d|\bSPEC\b|\b[Ss]eed[ -]?00\d")
    roots = [PACKAGE, ROOT / "docs", ROOT / "examples", ROOT / "README.md"]
    paths = [p for root in roots for p in ([root] if root.is_file() else root.rglob("*"))
             if p.suffix in (".py", ".md", ".toml")]
    hits = [f"{p.relative_to(ROOT)}:{n}" for p in paths
            for n, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
            if label.search(line)]
    assert hits == []
