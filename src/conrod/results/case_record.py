"""The case a result was computed from, as the result folder records it: the case file as
the user wrote it (its comments cite the sources of the numbers), copies of the tables it
reads (load table, pressure trace, housing mesh or compliance), and the values the run set on
top of the file (command-line options such as ``--film`` and ``--grid``, ``Case.with_``).

The files lie flat in the result folder (``case.toml``, ``case.<section>.<key><suffix>``)
and ``manifest.json["case"]`` lists them with the values set::

    "case": {"file": "case.toml", "source_name": "kamaz_740_truck_diesel.toml",
             "tables": {"load.table": "case.load.table.csv"},
             "set": {"solver.film": "reynolds", "solver.n_theta": 36}}

``Case.from_toml(folder / "case.toml").with_(load__table="case.load.table.csv",
solver__film="reynolds", ...)`` is the case as run (:func:`conrod.output.inputs.recorded_case`).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass, field
from typing import Any

CASE_FILE = "case.toml"
"""Name of the case file's copy in a result folder [-]."""


@dataclass(frozen=True)
class CaseRecord:
    """The case as run.

    source_name : str  Name of the case file it was read from ('' for a case built in
        Python, whose text is then written from its values).
    text : str  The case file as written by the user, or the generated TOML.
    tables : tuple  (dotted case key, file name in the result folder, content bytes) of
        every file the case reads.
    set_values : dict  Dotted case key → value the run set on top of ``text`` [SI units].
    """

    source_name: str
    text: str
    tables: tuple[tuple[str, str, bytes], ...] = ()
    set_values: dict[str, Any] = field(default_factory=dict)

    def manifest_item(self) -> dict[str, Any]:
        """``manifest.json["case"]``: the files and the values set on top of the file."""
        return {"file": CASE_FILE, "source_name": self.source_name,
                "tables": {key: name for key, name, _ in self.tables},
                "set": {key: _plain(value) for key, value in self.set_values.items()}}


def table_file_name(key: str, suffix: str) -> str:
    """Name in the result folder of the file a case key reads, e.g. ``load.table`` and
    ``.csv`` → ``case.load.table.csv``."""
    return f"case.{key}{suffix}"


def flatten(data: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested tables → dotted keys (lists, also of tables, are one value)."""
    flat: dict[str, Any] = {}
    for name, value in data.items():
        key = f"{prefix}.{name}" if prefix else name
        if isinstance(value, dict):
            flat.update(flatten(value, key))
        else:
            flat[key] = value
    return flat


def toml_text(data: dict[str, Any], header: str = "") -> str:
    """A TOML document of ``data`` (nested dicts of numbers, strings, booleans, lists and
    lists of tables; None values are left out), ``header`` as its opening comment."""
    lines = [f"# {line}" for line in header.splitlines()]
    lines += _table_lines(data, "")
    return "\n".join(lines).strip() + "\n"


def _table_lines(data: dict[str, Any], prefix: str) -> list[str]:
    lines = [f"{key} = {_value(value)}" for key, value in data.items()
             if value is not None and not isinstance(value, dict) and not _tables(value)]
    for key, value in data.items():
        name = f"{prefix}.{key}" if prefix else key
        if isinstance(value, dict):
            lines += ["", f"[{name}]", *_table_lines(value, name)]
        elif _tables(value):
            for item in value:
                lines += ["", f"[[{name}]]", *_table_lines(item, name)]
    return lines


def _tables(value: Any) -> bool:
    return isinstance(value, list) and bool(value) and all(isinstance(v, dict) for v in value)


def _value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        if isinstance(value, float) and not math.isfinite(value):
            raise ValueError(f"not finite: {value!r}")
        return repr(value)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_value(item) for item in value) + "]"
    return json.dumps(str(value), ensure_ascii=False)


def _plain(value: Any) -> Any:
    """A JSON-ready value (paths and other objects as text)."""
    if isinstance(value, bool | int | float | str) or value is None:
        return value
    if isinstance(value, list | tuple):
        return [_plain(item) for item in value]
    if isinstance(value, dict):
        return {key: _plain(item) for key, item in value.items()}
    return str(value)
