"""What a worker does for one variant: run it, write its files, commit the folder.

Plain data in, plain data out (the record), so that any worker of any cluster with
conrod installed can run it; :func:`run_batch` runs several cheap variants as one task.
Failures are records too (status ``"failed"`` with the error message); they are returned
but not stored, so that a rerun tries them again.
"""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

from conrod._version import __version__
from conrod.sweep.status import STATUS_FAILED, variant_status

RETURNED_ITEMS = ("hash", "axes", "status", "error", "summary", "wall_time_s",
                  "compute_time_s")
"""Items of a record sent back to the sweep (the case stays in ``variant.json``) [-]."""


def write_variant_results(results, out_dir: Path, *, figures: bool) -> None:
    """Write one variant's files with the one writer every command uses (and its manifest)."""
    from conrod.output.registry import write_results

    write_results(results, out_dir, figures=figures)


def compute(case, command: str):
    """The result object of the command's computation on ``case`` (what it writes)."""
    if command == "mechanism":
        from conrod.mechanism.results import MechanismRun
        from conrod.mechanism.setup import mechanism_case
        from conrod.mechanism.simulation import simulate
        from conrod.results.plausibility import check_mechanism

        base = mechanism_case(case)
        results = simulate(base.mechanism, base.scaled_gas_table(), base.settings)
        return MechanismRun(results, base.speed_rpm, base.load_scale,
                            tuple(check_mechanism(results, base.mechanism)))
    from conrod.simulation.simulation import Simulation

    return Simulation(case).run()


def compute_into(case, command: str, out_dir: Path, figures: bool) -> None:
    """Run the command's computation on ``case`` and write its files into ``out_dir``."""
    write_variant_results(compute(case, command), out_dir, figures=figures)


def preload(command: str = "run") -> None:
    """Import what a variant of ``command`` runs and writes, and set up numba's compiler, so
    that worker processes forked afterwards start with it loaded."""
    import conrod.output  # noqa: F401  (registers the tables)
    from conrod.output import registry  # noqa: F401

    if command == "mechanism":
        import conrod.mechanism.simulation  # noqa: F401
    else:
        import conrod.simulation.simulation  # noqa: F401
    from numba.core.registry import cpu_target

    cpu_target.typing_context.refresh()
    cpu_target.target_context.refresh()


def run_variant(case_data: dict[str, Any], case_file: str, key: str, axes: dict[str, Any],
                out: str, figures: bool = False, command: str = "run") -> dict[str, Any]:
    """Compute one variant and store it under ``out/variants/<key>/``; return its record."""
    from conrod.cases.case import Case
    from conrod.sweep.store import commit_variant, discard_unfinished, variant_folder

    start = time.perf_counter()
    folder = variant_folder(Path(out), key)
    record: dict[str, Any] = {"hash": key, "axes": axes, "case_file": case_file,
                              "command": command, "conrod_version": __version__,
                              "case": case_data}
    try:
        case = Case.from_dict(case_data, base_dir=Path(case_file).resolve().parent,
                              path=Path(case_file))
        results = compute(case, command)
        record["compute_time_s"] = time.perf_counter() - start
        write_variant_results(results, folder, figures=figures)
        summary = _summary(folder)
        record.update(status=variant_status(summary), error="", summary=summary)
        record["wall_time_s"] = time.perf_counter() - start
        commit_variant(folder, record)
    except Exception as error:  # a failed variant is a row of the table, not a crash
        discard_unfinished(folder)
        record.update(status=STATUS_FAILED, error=_one_line(error), summary={},
                      wall_time_s=time.perf_counter() - start)
        record.setdefault("compute_time_s", float("nan"))
    return record


def run_payload(payload: dict[str, Any]) -> dict[str, Any]:
    """:func:`run_variant` of one payload (:meth:`conrod.sweep.variant.Variant.payload`),
    its record without the case (which stays in ``variant.json``)."""
    record = run_variant(**payload)
    return {name: record[name] for name in RETURNED_ITEMS if name in record}


def run_batch(payloads: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """:func:`run_payload` of every payload, in order: one task of several cheap variants."""
    return [run_payload(payload) for payload in payloads]


def _summary(folder: Path) -> dict[str, Any]:
    """The variant's summary.json as written (what ``conrod run`` would have written)."""
    import json

    return json.loads((folder / "summary.json").read_text(encoding="utf-8"))


def _one_line(error: BaseException) -> str:
    text = " ".join(str(error).split()) or type(error).__name__
    return text if error.__class__.__module__.startswith("conrod") else (
        f"{type(error).__name__}: {text}")
