"""What a Dask worker does for one variant: run it, write its files, commit the folder.

Plain data in, plain data out (the record), so that any worker of any cluster with
conrod installed can run it. Failures are records too (status ``"failed"`` with the
error message); they are returned but not stored, so that a rerun tries them again.
"""

from __future__ import annotations

import shutil
import time
from pathlib import Path
from typing import Any

from conrod._version import __version__

STATUS_OK = "ok"
STATUS_FAILED = "failed"


def write_variant_results(results, out_dir: Path, *, figures: bool) -> None:
    """Write one variant's files with the one writer every command uses (and its manifest)."""
    from conrod.output.registry import write_results

    write_results(results, out_dir, figures=figures)


def compute_into(case, command: str, out_dir: Path, figures: bool) -> None:
    """Run the command's computation on ``case`` and write its files into ``out_dir``."""
    if command == "mechanism":
        from conrod.mechanism.results import MechanismRun
        from conrod.mechanism.setup import mechanism_case
        from conrod.mechanism.simulation import simulate
        from conrod.results.plausibility import check_mechanism

        base = mechanism_case(case)
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
        run = MechanismRun(results, base.speed_rpm, base.load_scale,
                           tuple(check_mechanism(results, base.mechanism)))
        write_variant_results(run, out_dir, figures=figures)
        return
    from conrod.simulation.simulation import Simulation

    write_variant_results(Simulation(case).run(), out_dir, figures=figures)


def run_variant(case_data: dict[str, Any], case_file: str, key: str, axes: dict[str, Any],
                out: str, figures: bool = False, command: str = "run") -> dict[str, Any]:
    """Compute one variant and store it under ``out/variants/<key>/``; return its record."""
    from conrod.cases.case import Case
    from conrod.sweep.store import commit_variant, new_variant_folder

    start = time.perf_counter()
    record: dict[str, Any] = {"hash": key, "axes": axes, "case_file": case_file,
                              "command": command, "conrod_version": __version__,
                              "case": case_data}
    tmp = None
    try:
        case = Case.from_dict(case_data, base_dir=Path(case_file).resolve().parent,
                              path=Path(case_file))
        tmp = new_variant_folder(Path(out), key)
        compute_into(case, command, tmp, figures)
        record.update(status=STATUS_OK, error="", summary=_summary(tmp))
        record["wall_time_s"] = time.perf_counter() - start
        commit_variant(tmp, record)
    except Exception as error:  # a failed variant is a row of the table, not a crash
        if tmp is not None:
            shutil.rmtree(tmp, ignore_errors=True)
        record.update(status=STATUS_FAILED, error=_one_line(error), summary={},
                      wall_time_s=time.perf_counter() - start)
    return record


def _summary(folder: Path) -> dict[str, Any]:
    """The variant's summary.json as written (what ``conrod run`` would have written)."""
    import json

    return json.loads((folder / "summary.json").read_text(encoding="utf-8"))


def _one_line(error: BaseException) -> str:
    text = " ".join(str(error).split()) or type(error).__name__
    return text if error.__class__.__module__.startswith("conrod") else (
        f"{type(error).__name__}: {text}")
