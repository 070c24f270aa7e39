"""``Sweep(study, out).run() -> pandas.DataFrame``: every variant on Dask distributed.

.. code-block:: python

    from conrod.sweep import Sweep
    table = Sweep("examples/studies/passenger_car_3x3.toml", "results/pc_sweep").run()
    table[["bearing.radial_clearance", "engine.speed", "h_min_m", "p_max_Pa"]]

Without a scheduler address a local cluster starts with one single-threaded worker
process per core (``workers`` to choose); with ``scheduler="tcp://HOST:PORT"`` the sweep
runs on an existing cluster whose workers have conrod installed and see ``out``.
Variants already finished under ``out/variants/`` are not run again. A worker that dies
has its variants rescheduled by Dask; a variant that fails is a row with its error.
"""

from __future__ import annotations

import contextlib
import json
import logging
import os
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pandas as pd

from conrod.errors import CaseError
from conrod.io.atomic import write_json
from conrod.io.result_folder import check_output_folder
from conrod.sweep.store import read_record, remove_stale
from conrod.sweep.study import Study
from conrod.sweep.table import record_row, rows_to_frame, write_parquet
from conrod.sweep.variant import Variant
from conrod.sweep.worker import STATUS_FAILED, run_variant

Progress = Callable[[int, int], None]
"""progress(done, total) after every finished (or cached) variant."""

TABLE_FILE = "sweep.parquet"
STUDY_FILE = "study.json"


class Sweep:
    """A study run into a results folder.

    study : Study or path of a study file (TOML).
    out : path  Results folder (``variants/``, ``sweep.parquet``, ``study.json``).
    scheduler : str or None  Address of a running Dask scheduler, e.g. ``tcp://host:8786``.
    workers : int or None  Worker processes of the local cluster (default: one per core).
    figures : bool  Write each variant's figures too (slower; off by default).
    """

    def __init__(self, study: Study | str | os.PathLike[str], out: str | os.PathLike[str],
                 *, scheduler: str | None = None, workers: int | None = None,
                 figures: bool = False):
        self.study = study if isinstance(study, Study) else Study.from_toml(study)
        self.out = Path(out)
        self._inputs = () if isinstance(study, Study) else (study,)
        if scheduler is not None and workers is not None:
            raise CaseError("--workers applies to the local cluster; with --scheduler the "
                            "cluster's own workers run the variants")
        if workers is not None and workers < 1:
            raise CaseError(f"--workers = {workers}: allowed >= 1")
        self.scheduler, self.workers, self.figures = scheduler, workers, figures
        self._variants: list[Variant] | None = None

    def variants(self) -> list[Variant]:
        """Every variant, resolved and validated (once)."""
        if self._variants is None:
            self._variants = self.study.variants()
        return self._variants

    def run(self, progress: Progress | None = None,
            on_record: Callable[[dict[str, Any]], None] | None = None) -> pd.DataFrame:
        """Run the unfinished variants; write and return the table (one row per variant)."""
        variants = self.variants()  # everything validated before anything runs
        check_output_folder(self.out, option="out", marker=STUDY_FILE, inputs=self._inputs)
        self.out.mkdir(parents=True, exist_ok=True)
        remove_stale(self.out)
        write_json(self.out / STUDY_FILE, self._description(variants))
        records = {v.key: r for v in variants if (r := read_record(self.out, v.key))}
        cached = set(records)
        todo = {v.key: v for v in variants if v.key not in records}
        done, total = len(records), len(records) + len(todo)
        if progress is not None:
            progress(done, total)
        if todo:
            for record in self._compute(list(todo.values())):
                records[record["hash"]] = record
                done += 1
                if on_record is not None:
                    on_record(record)
                if progress is not None:
                    progress(done, total)
            remove_stale(self.out)  # temporary folders of workers that died mid-variant
        rows = [record_row(v.index, v.axes, records[v.key], v.key in cached) for v in variants]
        frame = rows_to_frame(rows)
        write_parquet(frame, self.out / TABLE_FILE)
        return frame

    def _compute(self, variants: list[Variant]) -> Iterator[dict[str, Any]]:
        from distributed import as_completed

        with self._client() as client:
            futures = {}
            for v in variants:
                future = client.submit(run_variant, v.case_data, str(v.case_file.resolve()),
                                       v.key, v.axes, str(self.out.resolve()), self.figures,
                                       v.command, key=f"conrod-variant-{v.key}", pure=False)
                futures[future] = v
            for future in as_completed(futures):
                yield _result(future, futures[future])

    @contextlib.contextmanager
    def _client(self) -> Iterator[Any]:
        from distributed import Client

        if self.scheduler is not None:
            try:
                client = Client(self.scheduler, timeout="20s")
            except OSError as error:
                raise CaseError(f"--scheduler {self.scheduler!r}: cannot connect ({error})"
                                ) from None
            with client:
                yield client
            return
        with local_client(self.workers or os.cpu_count() or 1) as client:
            yield client

    def _description(self, variants: list[Variant]) -> dict[str, Any]:
        spec = self.study.spec
        return {"title": spec.title, "study_file": str(self.study.path or ""),
                "command": spec.command, "mode": spec.mode, "axes": [a.key for a in spec.axis],
                "override": spec.override, "variants": len(variants),
                "base_case": str(self.study.base_file(variants[0].axes).resolve())}


@contextlib.contextmanager
def local_client(workers: int) -> Iterator[Any]:
    """A Dask client of a local cluster: ``workers`` single-threaded worker processes, quiet
    logs, closed on exit. The scheduler's web server takes a free port (``:0``): with the
    default 8787 a second cluster on the machine fails to start."""
    from distributed import Client, LocalCluster

    with LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                      dashboard_address=":0", silence_logs=logging.ERROR) as cluster, \
            Client(cluster) as client:
        yield client


def _result(future: Any, variant: Variant) -> dict[str, Any]:
    """The record a future returned, or a failed record if its worker could not finish."""
    try:
        return future.result()
    except Exception as error:  # e.g. KilledWorker after repeated worker deaths
        return {"hash": variant.key, "axes": variant.axes, "status": STATUS_FAILED,
                "error": f"{type(error).__name__}: {error}", "summary": {},
                "wall_time_s": float("nan")}


def read_table(out: str | os.PathLike[str]) -> pd.DataFrame:
    """The table of a sweep folder."""
    path = Path(out) / TABLE_FILE
    if not path.is_file():
        raise CaseError(f"{str(path)!r}: no sweep table here (run 'conrod sweep' first)")
    return pd.read_parquet(path)


def read_description(out: str | os.PathLike[str]) -> dict[str, Any]:
    """``study.json`` of a sweep folder ({} if absent)."""
    try:
        return json.loads((Path(out) / STUDY_FILE).read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}
