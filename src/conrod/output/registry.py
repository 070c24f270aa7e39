"""The one registry of outputs and the one writer of a result folder.

Every result type says which tables and figures it has:

* ``tables(results)`` — :class:`TableSpec` s, registered next to the result types
  (:mod:`conrod.output.tables`);
* ``figures(results)`` — :class:`FigureSpec` s, registered in :mod:`conrod.plotting` (the
  only package that imports matplotlib; importing it registers the figures);
* ``result_kind(results)`` — the name of the kind of result ("run", "loads", ...).

:func:`write_results` is the one writer used by every CLI command, the sweep and the report:
it writes the tables and figures into a staging folder swapped in whole (a failing figure
writes nothing), the figures in two processes where a core is idle
(:func:`draw_figures`) — those a :class:`FigureDraft` drew ahead from the same inputs taken
as drawn — and writes last ``manifest.json``::

    {"conrod_version": str, "kind": str,
     "tables": [{"file", "title", "caption"}], "figures": [{"file", "title", "caption"}],
     "case": {"file", "source_name", "tables", "set"}}   # a run: the case as run

(``case``: :meth:`conrod.results.case_record.CaseRecord.manifest_item`; the case file and
its tables are among the tables.)

A new result type appears everywhere at once by registering its tables and figures.
"""

from __future__ import annotations

import dataclasses
import functools
import multiprocessing
import os
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from functools import singledispatch
from pathlib import Path
from typing import Any

from conrod.errors import CaseError
from conrod.io.atomic import atomic_path, write_csv, write_json, write_npz, write_text
from conrod.io.cores import spare_core
from conrod.io.result_folder import check_before_writing, staged_result_folder

MANIFEST = "manifest.json"
"""File name of the manifest, written last [-]."""

FIGURE_DPI = 130
"""Resolution of the written figures [dots per inch]."""


@dataclass(frozen=True)
class TableSpec:
    """One table file of a result.

    file : str  File name.
    title : str  Short title.
    caption : str  What the table holds, with units.
    build : callable  () → text or bytes (written as they are), or columns name → 1-D
        array (``.csv``), items (``.json``) or named arrays (``.npz``).
    """

    file: str
    title: str
    caption: str
    build: Callable[[], Any]


@dataclass(frozen=True)
class FigureSpec:
    """One figure file of a result.

    file : str  File name (format from the suffix, e.g. ``.png``).
    title : str  Short title.
    caption : str  What the figure shows, with units.
    build : callable  () → matplotlib Figure (built in :mod:`conrod.plotting`).
    """

    file: str
    title: str
    caption: str
    build: Callable[[], Any]


class UnregisteredResultError(CaseError, TypeError):
    """:func:`write_results` given an object of a type without registered tables."""


@singledispatch
def tables(results: Any) -> tuple[TableSpec, ...]:
    """Tables of ``results`` (registered per result type)."""
    raise TypeError(f"no tables registered for {type(results).__name__}")


@singledispatch
def figures(results: Any) -> tuple[FigureSpec, ...]:
    """Figures of ``results`` (registered per result type in :mod:`conrod.plotting`)."""
    raise LookupError(f"no figures registered for {type(results).__name__} "
                      "(import conrod.output to register them)")


@singledispatch
def result_kind(results: Any) -> str:
    """Kind of result written into the manifest ("run", "loads", "mechanism", ...)."""
    raise TypeError(f"no result kind registered for {type(results).__name__}")


def write_results(
    results: Any, out_dir: str | os.PathLike[str], *, figures: bool = True,
    draft: FigureDraft | None = None,
) -> list[Path]:
    """Write the tables (and figures) of ``results`` and ``manifest.json`` as one result set:
    into a staging folder that replaces ``out_dir`` whole
    (:func:`conrod.io.result_folder.staged_result_folder`, which adds each file's size and
    SHA-256 to the manifest); return the paths written (manifest last). The figures
    ``draft`` drew ahead are written as drawn where ``results`` draws them from the same
    inputs (:meth:`FigureDraft.drawn_for`). Arguments that are not a registered result, a
    usable folder or a bool raise :class:`CaseError`."""
    if tables.dispatch(type(results)) is tables.dispatch(object):
        name = type(results).__name__
        raise UnregisteredResultError(f"write_results: results = {name}: no tables registered "
                                      f"for {name} (allowed: what Simulation.run(), "
                                      "compute_engine_loads(), ... return)")
    if not isinstance(figures, bool):
        raise CaseError(f"write_results: figures = {figures!r}: True or False is required")
    check_before_writing(out_dir, "write_results: out_dir")
    table_specs = tables(results)
    figure_specs = _figure_specs(results) if figures else ()
    contents = [(spec, spec.build()) for spec in table_specs]
    drawn = draft.drawn_for(results) if draft is not None and figures else {}
    with staged_result_folder(out_dir) as stage:  # the whole set swapped in at once, or
        paths = [_write_table(stage / spec.file, content) for spec, content in contents]
        paths += draw_figures(figure_specs, stage, drawn)  # nothing where one fails
        paths.append(write_json(stage / MANIFEST, manifest(results, table_specs, figure_specs)))
    return [Path(out_dir) / path.relative_to(stage) for path in paths]


def manifest(results: Any, table_specs, figure_specs) -> dict[str, Any]:
    """The manifest items (see the module docstring)."""
    from conrod._version import __version__

    def entries(specs) -> list[dict[str, str]]:
        return [{"file": s.file, "title": s.title, "caption": s.caption} for s in specs]

    items = {"conrod_version": __version__, "kind": result_kind(results),
             "tables": entries(table_specs), "figures": entries(figure_specs)}
    record = getattr(results, "case_record", None)
    if record is not None:
        items["case"] = record.manifest_item()
    return items


def _figure_specs(results: Any) -> tuple[FigureSpec, ...]:
    return figures(results)


def _write_table(path: Path, content: Any) -> Path:
    if isinstance(content, str):
        return write_text(path, content)
    if isinstance(content, bytes):  # a copy of an input file, byte for byte
        return _write_bytes(path, content)
    if path.suffix == ".csv":
        return write_csv(path, content)
    if path.suffix == ".json":
        return write_json(path, content)
    if path.suffix == ".npz":
        return write_npz(path, content)
    return write_text(path, content)


def _write_bytes(path: Path, content: bytes) -> Path:
    with atomic_path(path) as tmp:
        tmp.write_bytes(content)
    return path


def _save(figure: Any, path: Path) -> Path:
    """Save a matplotlib Figure atomically: :func:`_rendered` 's bytes."""
    return _write_bytes(path, _figure_bytes(figure, path.suffix[1:]))


def _rendered(spec: FigureSpec) -> bytes:
    """The file ``spec`` saves, in memory (the bytes :func:`_save` writes)."""
    return _figure_bytes(spec.build(), Path(spec.file).suffix[1:])


def _figure_bytes(figure: Any, file_format: str) -> bytes:
    """``figure`` as a file of ``file_format`` at :data:`FIGURE_DPI`, cut to its tight box, a
    PNG drawn once (:func:`conrod.plotting.save.figure_bytes`; imported here, not at the top:
    this module never imports matplotlib)."""
    from conrod.plotting.save import figure_bytes

    return figure_bytes(figure, file_format, dpi=FIGURE_DPI)


def draw_figures(specs: tuple[FigureSpec, ...], folder: Path,
                 drawn: Mapping[str, bytes] | None = None) -> list[Path]:
    """Build and save the figures of ``specs`` into ``folder`` (paths in their order); a
    file ``drawn`` holds (drawn ahead from the same inputs) is written as it is. With at
    least :data:`TWO_PROCESSES_FROM` figures left and an idle core
    (:func:`conrod.io.cores.spare_core`) a forked process draws every second one meanwhile:
    the same code on the same data, the same bytes (README main job, 2-core machine: 14
    figures in 2.0 s against 3.2 s in one process, measured when every figure was drawn
    twice, before :func:`conrod.plotting.save.figure_bytes`). What that process does not deliver
    (it failed or ended) is drawn here, where a failure raises as it would have.
    ``CONROD_FIGURE_PROCESS=0`` turns it off."""
    drawn = drawn or {}
    for spec in specs:
        if spec.file in drawn:
            _write_bytes(folder / spec.file, drawn[spec.file])
    paths = [folder / spec.file for spec in specs]
    specs = tuple(spec for spec in specs if spec.file not in drawn)
    _draw_all(specs, folder)
    return paths


def _draw_all(specs: tuple[FigureSpec, ...], folder: Path) -> None:
    """The figures of ``specs``, in two processes where it pays (:func:`draw_figures`)."""
    here = [(spec, folder / spec.file) for spec in specs]
    if len(specs) < TWO_PROCESSES_FROM or os.environ.get(FIGURE_SWITCH, "1") == "0" \
            or not spare_core():
        _draw(here)
        return
    context = multiprocessing.get_context("fork")
    receiving, sending = context.Pipe(duplex=False)
    process = context.Process(target=_draw_there, args=(here[1::2], sending), daemon=True)
    process.start()
    sending.close()
    started = time.perf_counter()
    _draw(here[0::2])
    mine = time.perf_counter() - started
    try:  # its half takes about as long as this one: a process stuck much longer is ended
        delivered = receiving.recv() if receiving.poll(
            FIGURE_WAIT_SHARE * mine + FIGURE_WAIT_MIN) else False
    except (EOFError, OSError):  # the process ended without a word
        delivered = False
    if process.is_alive() and delivered is not True:
        process.kill()
    process.join()
    receiving.close()
    if delivered is not True:
        _draw(here[1::2])


TWO_PROCESSES_FROM = 3
"""Fewest figures drawn in two processes (below, the fork is not worth it) [-]."""
FIGURE_WAIT_SHARE, FIGURE_WAIT_MIN = 3.0, 10.0
"""The writer waits for the forked process at most this many times its own half's time
plus this many seconds [-, s], then draws the rest itself."""
FIGURE_SWITCH = "CONROD_FIGURE_PROCESS"
"""Environment variable: ``0`` draws every figure in the writing process."""


def _draw(pairs: list[tuple[FigureSpec, Path]]) -> list[Path]:
    """Build and save each figure of ``pairs`` (spec, path) in turn."""
    return [_save(spec.build(), path) for spec, path in pairs]


def _draw_there(pairs: list[tuple[FigureSpec, Path]], connection: Any) -> None:
    """The forked process: draw ``pairs`` and say whether all were saved."""
    try:
        _draw(pairs)
        connection.send(True)
    except BaseException:  # drawn again by the writing process, which raises
        connection.send(False)


class FigureDraft:
    """The figures of a run's provisional results drawn ahead by a forked process while the
    run computes what it still needs (``conrod run``: the coarser orbits of its grid-error
    estimate), then taken by :func:`write_results` (:meth:`drawn_for`) for the final results
    where these draw from the same inputs.

    ``fork(jobs, patience)`` starts the process on ``jobs`` ((file, () → the file's bytes) in
    order) and returns a handle whose ``take(file)`` gives the bytes, waiting for them, or
    something else where the process does not deliver them (not begun there, failed, or
    ended after ``patience`` seconds without a result), and whose ``stop()`` ends the
    process (:func:`conrod.simulation.side_runs.fork`, which shares the figures out between
    the process and the writer: the writer draws those the process has not begun once it
    needs them, and one that fails here raises as it would in the writer). The process uses
    whichever core the orbits leave free (the second process done, or the run waiting for
    it) instead of the figures being drawn after the last orbit.

    The final results of a run are its provisional ones with the summary's ``undrawn``
    fields set (the grid-error estimate, its warning), which no figure draws:
    every other field is the same object, so a figure drawn ahead is the figure of the
    final results, byte for byte (``tests/test_figure_process.py``,
    ``tests/test_outputs_elastic.py``).
    """

    def __init__(self, fork: Callable[..., Any]) -> None:
        self.fork = fork
        self.results: Any = None
        self.drawer: Any = None
        self.files: list[str] = []
        self.drawn: dict[str, bytes] = {}

    def provisional(self, results: Any) -> None:
        """Start drawing the figures of ``results`` (those drawn for earlier results are
        dropped)."""
        self.close()
        specs = _figure_specs(results)
        self.results, self.files, self.drawn = results, [spec.file for spec in specs], {}
        self.drawer = self.fork([(spec.file, functools.partial(_rendered, spec))
                                 for spec in specs], FIGURE_WAIT_MIN)

    def drawn_for(self, results: Any) -> dict[str, bytes]:
        """The figures drawn ahead that ``results`` draws alike (none when it draws from
        other inputs than the provisional results), the process's collected at the first
        call: a figure it has not begun by then, failed or did not deliver within
        :data:`FIGURE_WAIT_MIN` is left to the writer."""
        if self.results is None or not drawn_alike(self.results, results):
            return {}
        drawer, self.drawer = self.drawer, None
        if drawer is not None:
            try:
                self.drawn = {file: drawn for file in self.files
                              if isinstance(drawn := drawer.take(file), bytes)}
            finally:
                drawer.stop()
        return dict(self.drawn)

    def close(self) -> None:
        """End the drawing process, if one runs."""
        drawer, self.drawer = self.drawer, None
        if drawer is not None:
            drawer.stop()


def drawn_alike(before: Any, after: Any) -> bool:
    """True when every figure draws the same from ``after`` as from ``before``: results with
    the same fields, the same object in each of them and in the results within them, except
    the fields a result declares ``undrawn`` (a run summary's grid error and warnings) [-]."""
    if before is after:
        return True
    if not (dataclasses.is_dataclass(before) and dataclasses.is_dataclass(after)) \
            or dataclasses.fields(before) != dataclasses.fields(after):
        return False
    undrawn = getattr(before, "undrawn", ())
    for field in dataclasses.fields(before):
        if field.name in undrawn:
            continue
        old, new = getattr(before, field.name), getattr(after, field.name)
        if old is not new and not drawn_alike(old, new):
            return False
    return True
