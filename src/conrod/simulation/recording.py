"""What a result folder records of its case (:class:`conrod.results.case_record.CaseRecord`):
the case file as the user wrote it, the tables it reads and the values the run set on top."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from pydantic import BaseModel

from conrod.cases.case import Case
from conrod.errors import ConrodError
from conrod.results.case_record import CaseRecord, flatten, table_file_name, toml_text


def record_case(case: Case, solver: Any) -> CaseRecord:
    """The record of ``case`` run with the resolved ``[solver]`` section ``solver``: the
    case file's text when the case was read from one (with the values the run changed, e.g.
    by ``--film`` or ``Case.with_``), else the case written out as TOML; a copy of every
    file the case reads."""
    run_case = case.model_copy(update={"solver": solver})
    run_values = flatten(run_case.model_dump(mode="json"))
    source = _source_file(case)
    if source is None:
        data = run_case.model_dump(mode="json", exclude_none=True)
        text = toml_text(data, "The case as run (built in Python, not read from a file).")
        name, file_values = "", run_values
    else:
        name, text, file_values = source
    tables = tuple(_table(case, key, path) for key, path in file_keys(run_case))
    copied = {key for key, _, _ in tables}
    set_values = {key: value for key, value in run_values.items()
                  if key not in copied and file_values.get(key, _MISSING) != value}
    return CaseRecord(name, text, tables, set_values)


_MISSING = object()


def _source_file(case: Case) -> tuple[str, str, dict[str, Any]] | None:
    """(file name, text, its values flattened) of the file ``case`` was read from, None
    when there is none or it no longer reads as a valid case."""
    path = case.path
    if path is None:
        return None
    try:
        text = Path(path).read_bytes().decode("utf-8")  # line ends as written
        values = flatten(Case.from_toml(path).model_dump(mode="json"))
    except (OSError, UnicodeError, ConrodError):
        return None
    return Path(path).name, text, values


def file_keys(case: Case) -> list[tuple[str, Path]]:
    """(dotted key, path as written) of every file the case reads (pressure trace, load
    table, housing mesh, compliance and inertia files)."""
    found = []
    for section_name in type(case).model_fields:
        section = getattr(case, section_name)
        if not isinstance(section, BaseModel):
            continue
        for key in type(section).model_fields:
            value = getattr(section, key)
            if isinstance(value, Path):
                found.append((f"{section_name}.{key}", value))
    return found


def _table(case: Case, key: str, path: Path) -> tuple[str, str, bytes]:
    resolved = case.resolve(path)
    return key, table_file_name(key, resolved.suffix), resolved.read_bytes()
