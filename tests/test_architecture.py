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
PLOTTING_WITHIN_FUNCTIONS = ("output",)
"""The result writer: it may import :mod:`conrod.plotting` inside a function, when it draws
a figure (so that writing tables never loads matplotlib), never at the top of a module and
never matplotlib itself."""


def _imports(path: Path, *, top_only: bool = False) -> set[str]:
    """The modules ``path`` imports (``top_only``: those imported when the module is, not
    inside a function)."""
    names: set[str] = set()
    for node in _nodes(ast.parse(path.read_text(encoding="utf-8")), top_only):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.add(node.module)
            names.update(f"{node.module}.{alias.name}" for alias in node.names)
    return names


def _nodes(tree: ast.AST, top_only: bool):
    """Every node of ``tree`` (``top_only``: but those inside functions)."""
    stack = [tree]
    while stack:
        node = stack.pop()
        yield node
        stack.extend(child for child in ast.iter_child_nodes(node) if not (
            top_only and isinstance(child, ast.FunctionDef | ast.AsyncFunctionDef)))


def test_only_plotting_and_the_user_layers_import_plotting_or_matplotlib():
    offenders = []
    for path in PACKAGE.rglob("*.py"):
        part = path.relative_to(PACKAGE).parts[0]
        if part in PLOTTING_ALLOWED:
            continue
        lazy = part in PLOTTING_WITHIN_FUNCTIONS
        bad = {n for n in _imports(path) if n.startswith("matplotlib")} | {
            n for n in _imports(path, top_only=lazy) if n.startswith("conrod.plotting")}
        if bad:
            offenders.append(f"{path.relative_to(PACKAGE)}: {sorted(bad)}")
    assert offenders == []


def _module_graph() -> dict[str, set[str]]:
    """conrod module → the conrod modules it imports (module- and function-level imports,
    ``if TYPE_CHECKING`` blocks included), read from the AST."""
    modules = {}
    for path in PACKAGE.rglob("*.py"):
        rel = path.relative_to(PACKAGE.parent).with_suffix("")
        parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
        modules[".".join(parts)] = path
    graph: dict[str, set[str]] = {name: set() for name in modules}
    for name, path in modules.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module and not node.level:
                targets = [f"{node.module}.{alias.name}" for alias in node.names]
            else:
                continue
            for target in targets:
                while target and target not in modules:
                    target = target.rpartition(".")[0]
                if target and target != name and not name.startswith(target + "."):
                    graph[name].add(target)
    return graph


def test_no_import_cycles():
    """No module reaches itself through the imports of others (Tarjan's strongly connected
    components of the import graph)."""
    graph, index, low, stack, on, cycles = _module_graph(), {}, {}, [], set(), []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        on.add(node)
        for other in graph[node]:
            if other not in index:
                visit(other)
                low[node] = min(low[node], low[other])
            elif other in on:
                low[node] = min(low[node], index[other])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                on.discard(member)
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                cycles.append(sorted(component))

    for node in sorted(graph):
        if node not in index:
            visit(node)
    assert cycles == []


def test_the_layer_contract_holds():
    """import-linter's layers contract of pyproject.toml (cli > report > sweep > simulation |
    output > orbit | plotting > ehd | results > housing | mechanism > contact | loads > cases
    > film > registry | io > errors | units | oil | _version), function-level imports
    included."""
    importlinter = pytest.importorskip("importlinter.cli")
    assert importlinter.lint_imports(config_filename=str(ROOT / "pyproject.toml"),
                                     no_cache=True, no_logo=True) == 0


def test_no_concrete_film_type_outside_its_own_module():
    """Consumers ask for declared capabilities (film/capabilities.py), never for a film
    class: no ``isinstance(x, <a film class>)`` outside the module that defines it."""
    film_classes = {}
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.ClassDef) and node.name.endswith("Film"):
                film_classes[node.name] = path
    hits = []
    for path in PACKAGE.rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if (isinstance(node, ast.Call) and getattr(node.func, "id", None) == "isinstance"
                    and len(node.args) == 2):
                second = node.args[1]
                names = second.elts if isinstance(second, ast.Tuple) else [second]
                for name in names:
                    label = getattr(name, "id", getattr(name, "attr", None))
                    if label in film_classes and film_classes[label] != path:
                        hits.append(f"{path.relative_to(PACKAGE)}:{node.lineno} {label}")
    assert hits == []


def test_no_private_name_used_across_files():
    """No ``from m import _x``, and no ``obj._x`` whose ``_x`` is not defined in the same
    file (a module's own private helpers and attributes stay its own)."""
    hits = []
    for path in PACKAGE.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        own = _defined_names(tree)
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                hits += [f"{path.relative_to(PACKAGE)}:{node.lineno} import {alias.name}"
                         for alias in node.names if _private(alias.name)]
            elif (isinstance(node, ast.Attribute) and _private(node.attr)
                  and node.attr not in own
                  and not (isinstance(node.value, ast.Name) and node.value.id == "os")):
                hits.append(f"{path.relative_to(PACKAGE)}:{node.lineno} {ast.unparse(node)}")
    assert hits == []


def _defined_names(tree: ast.AST) -> set[str]:
    """Names a file defines itself: functions, classes, class attributes and attributes
    assigned on any object (``self._x = ...``)."""
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.Attribute) and isinstance(node.ctx, ast.Store):
            names.add(node.attr)
        elif isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
            names.add(node.target.id)
        elif isinstance(node, ast.Assign):
            names.update(t.id for t in node.targets if isinstance(t, ast.Name))
    return names


def _private(name: str) -> bool:
    return name.startswith("_") and not name.startswith("__")


def test_sizes_stay_readable():
    """No module over 450 lines, no folder over 30 modules, median function under 15
    lines."""
    lengths, big, crowded = [], [], []
    for folder in [PACKAGE, *(p for p in PACKAGE.iterdir() if p.is_dir())]:
        if len(list(folder.glob("*.py"))) > 30:
            crowded.append(folder.name)
    for path in PACKAGE.rglob("*.py"):
        text = path.read_text(encoding="utf-8")
        if len(text.splitlines()) > 450:
            big.append(f"{path.relative_to(PACKAGE)} ({len(text.splitlines())})")
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
                lengths.append(node.end_lineno - node.lineno + 1)
    assert big == [] and crowded == []
    assert sorted(lengths)[len(lengths) // 2] < 15


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
    import conrod.output  # noqa: F401  (registers the tables and figures)
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
