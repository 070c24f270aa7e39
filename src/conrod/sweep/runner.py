"""``Sweep(study, out).run() -> pandas.DataFrame``: every variant, in parallel.

.. code-block:: python

    from conrod.sweep import Sweep
    table = Sweep("examples/studies/passenger_car_3x3.toml", "results/pc_sweep").run()
    table[["bearing.radial_clearance_m", "engine.speed_rpm", "status", "h_min_m"]]

Without a scheduler address the variants run in worker processes on this machine, one
per core (``workers`` to choose; :mod:`conrod.sweep.pool`); with
``scheduler="tcp://HOST:PORT"`` they run on an existing Dask cluster whose workers have
conrod installed and see ``out`` (:mod:`conrod.sweep.cluster`). Variants already finished
under ``out/variants/`` are not run again. A worker that dies has its variants computed by
the others; a variant that fails is a row with its error.
"""

from __future__ import annotations

import contextlib
import json
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.errors import CaseError
from conrod.io.atomic import write_json
from conrod.io.result_folder import check_output_folder
from conrod.sweep.columns import axis_column
from conrod.sweep.status import STATUS_FAILED
from conrod.sweep.store import read_record, remove_stale
from conrod.sweep.study import Study
from conrod.sweep.table import record_row, rows_to_frame, write_parquet
from conrod.sweep.variant import Variant

Progress = Callable[[int, int], None]
"""progress(done, total) after every finished (or cached) variant."""

TABLE_FILE = "sweep.parquet"
STUDY_FILE = "study.json"
MOST_WORKERS = 4096
"""Largest ``workers`` accepted for a local run [-]."""


class Sweep:
    """A study run into a results folder.

    study : Study or path of a study file (TOML).
    out : path  Results folder (``variants/``, ``sweep.parquet``, ``study.json``).
    scheduler : str or None  Address of a running Dask scheduler, e.g. ``tcp://host:8786``.
    workers : int or None  Worker processes on this machine (default: one per core).
    figures : bool  Write each variant's figures too (slower; off by default).
    """

    def __init__(self, study: Study | str | os.PathLike[str], out: str | os.PathLike[str],
                 *, scheduler: str | None = None, workers: int | None = None,
                 figures: bool = False):
        _check_arguments(study, out, scheduler, workers, figures)
        self.study = study if isinstance(study, Study) else Study.from_toml(study)
        self.out = Path(out)
        self._inputs = () if isinstance(study, Study) else (study,)
        self.scheduler, self.workers, self.figures = scheduler, workers, figures
        self._variants: list[Variant] | None = None

    def variants(self) -> list[Variant]:
        """Every variant, resolved and validated (once)."""
        if self._variants is None:
            self._variants = self.study.variants()
        return self._variants

    def run(self, progress: Progress | None = None,
            on_record: Callable[[dict[str, Any]], None] | None = None) -> pd.DataFrame:
        """Run the unfinished variants; write and return the table (one row per variant).

        progress : callable(done, total) or None  Called after every finished variant.
        on_record : callable(record) or None  Receives each computed variant's record.
        """
        for name, value in (("progress", progress), ("on_record", on_record)):
            if value is not None and not callable(value):
                raise CaseError(f"{name} = {value!r}: not callable (allowed: None or a "
                                "function)")
        variants = self.variants()  # everything validated before anything runs
        check_output_folder(self.out, option="out", marker=STUDY_FILE, inputs=self._inputs)
        self.out.mkdir(parents=True, exist_ok=True)
        remove_stale(self.out)
        write_json(self.out / STUDY_FILE, self._description(variants))
        records = {v.key: r for v in variants if (r := read_record(self.out, v.key))}
        cached = set(records)
        todo = list({v.key: v for v in variants if v.key not in records}.values())
        done, total = len(records), len(records) + len(todo)
        if progress is not None:
            progress(done, total)
        try:
            with contextlib.closing(self._compute(todo)) as computed:  # workers end here
                for record in computed:
                    records[record["hash"]] = record
                    done += 1
                    if on_record is not None:
                        on_record(record)
                    if progress is not None:
                        progress(done, total)
        finally:
            if todo:
                remove_stale(self.out)  # what workers left when they were stopped or died
        rows = [record_row(v.index, v.axes, records[v.key], v.key in cached) for v in variants]
        frame = rows_to_frame(rows)
        write_parquet(frame, self.out / TABLE_FILE)
        return frame

    def _compute(self, variants: list[Variant]) -> Iterator[dict[str, Any]]:
        if not variants:
            return
        payloads = [v.payload(self.out, self.figures) for v in variants]
        if self.scheduler is not None:
            from conrod.sweep.cluster import connect, run_on_cluster

            with connect(self.scheduler) as client:
                for _, record in run_on_cluster(client, payloads):
                    yield record
            return
        yield from _run_locally(payloads, self.workers or available_cores(),
                                self.study.spec.command)

    def _description(self, variants: list[Variant]) -> dict[str, Any]:
        spec = self.study.spec
        return {"title": spec.title, "study_file": str(self.study.path or ""),
                "command": spec.command, "mode": spec.mode, "axes": [a.key for a in spec.axis],
                "axis_columns": {a.key: axis_column(a.key) for a in spec.axis},
                "override": spec.override, "variants": len(variants),
                "base_case": str(self.study.base_file(variants[0].axes).resolve())}


def _run_locally(payloads: list[dict[str, Any]], workers: int, command: str
                 ) -> Iterator[dict[str, Any]]:
    from conrod.sweep.pool import DONE, LocalPool
    from conrod.sweep.worker import preload, run_payload

    preload(command)  # imported once here, inherited by every worker
    with LocalPool(run_payload, workers) as pool:
        for index, kind, value in pool.imap([(payload,) for payload in payloads]):
            if kind == DONE:
                yield value
                continue
            text = value if isinstance(value, str) else f"{type(value).__name__}: {value}"
            payload = payloads[index]
            yield {"hash": payload["key"], "axes": payload["axes"], "status": STATUS_FAILED,
                   "error": text, "summary": {}, "wall_time_s": float("nan")}


def available_cores() -> int:
    """Cores this process may run on (its CPU affinity where the system tells) [-]."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:
        return os.cpu_count() or 1


def _check_arguments(study: Any, out: Any, scheduler: Any, workers: Any, figures: Any) -> None:
    """:class:`CaseError` naming the first argument of :class:`Sweep` that is not usable."""
    if not isinstance(study, Study | str | os.PathLike):
        raise CaseError(f"study = {study!r}: not a study (allowed: a conrod.sweep.Study or "
                        "the path of a study file)")
    if not isinstance(out, str | os.PathLike) or not str(out):
        raise CaseError(f"out = {out!r}: not a folder path (allowed: a path, e.g. "
                        "'results/sweep')")
    if scheduler is not None and (not isinstance(scheduler, str) or "://" not in scheduler):
        raise CaseError(f"--scheduler {scheduler!r}: not a scheduler address (allowed: "
                        "PROTOCOL://HOST:PORT of a running Dask scheduler, e.g. "
                        "tcp://10.0.0.5:8786)")
    if scheduler is not None and workers is not None:
        raise CaseError("--workers applies to the worker processes on this machine; with "
                        "--scheduler the cluster's own workers run the variants")
    if workers is not None and (not isinstance(workers, int) or isinstance(workers, bool)
                                or not 1 <= workers <= MOST_WORKERS):
        raise CaseError(f"--workers = {workers!r}: out of range (allowed: an integer >= 1 "
                        f"and <= {MOST_WORKERS})")
    if not isinstance(figures, bool):
        raise CaseError(f"figures = {figures!r}: not a boolean (allowed: True or False)")


def read_table(out: str | os.PathLike[str]) -> pd.DataFrame:
    """The table of a sweep folder."""
    if not isinstance(out, str | os.PathLike):
        raise CaseError(f"out = {out!r}: not a folder path (allowed: a sweep folder)")
    path = Path(out) / TABLE_FILE
    if not path.is_file():
        raise CaseError(f"{str(path)!r}: no sweep table here (run 'conrod sweep' first)")
    return pd.read_parquet(path)


def read_description(out: str | os.PathLike[str]) -> dict[str, Any]:
    """``study.json`` of a sweep folder ({} if absent)."""
    try:
        return json.loads((Path(out) / STUDY_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError, TypeError):
        return {}
