"""The case's inputs for the report: every key with its value, unit and source.

Units come from the case-file schema (the brackets in each field's description); sources
from the comment on the key's line in the case file, which the shipped cases use to cite
where each number comes from.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

from pydantic import BaseModel

from conrod.cases.base import field_unit
from conrod.cases.case import Case
from conrod.sweep.columns import model_in

_SECTION = re.compile(r"^\s*\[\[?\s*([A-Za-z0-9_.\-\" ]+?)\s*\]\]?")
_KEY = re.compile(r"^\s*([A-Za-z0-9_\-]+)\s*=")


def line_comments(text: str) -> dict[str, str]:
    """Dotted key → the comment on its line (``key = value  # comment``)."""
    comments: dict[str, str] = {}
    section = ""
    for line in text.splitlines():
        header = _SECTION.match(line)
        if header:
            section = header.group(1).replace('"', "").replace(" ", "")
            continue
        key = _KEY.match(line)
        if key and "#" in line:
            dotted = f"{section}.{key.group(1)}" if section else key.group(1)
            comments[dotted] = re.sub(r"^\[[^\]]*\]\s*", "", _comment_of(line))
    return comments


def _comment_of(line: str) -> str:
    """Text after the first ``#`` outside a string."""
    quote = None
    for i, char in enumerate(line):
        if char in "\"'" and quote in (None, char):
            quote = None if quote == char else char
        elif char == "#" and quote is None:
            return line[i + 1:].strip()
    return ""


def header_notes(text: str) -> list[str]:
    """The comment lines that open the case file (its description and general sources)."""
    notes = []
    for line in text.splitlines():
        if not line.strip().startswith("#"):
            break
        notes.append(line.strip().lstrip("#").strip())
    return [n for n in notes if n]


def unit_of(dotted: str) -> str:
    """Unit of a dotted case key from the schema ('' when dimensionless or unknown)."""
    model: type[BaseModel] = Case
    parts = dotted.split(".")
    for part in parts[:-1]:
        info = model.model_fields.get(part)
        nested = model_in(getattr(info, "annotation", None)) if info else None
        if nested is None:
            return ""
        model = nested
    return field_unit(model, parts[-1])



def flatten(data: dict[str, Any], prefix: str = "") -> dict[str, Any]:
    """Nested tables → dotted keys (lists of tables are kept as one value)."""
    flat: dict[str, Any] = {}
    for name, value in data.items():
        key = f"{prefix}.{name}" if prefix else name
        if isinstance(value, dict):
            flat.update(flatten(value, key))
        else:
            flat[key] = value
    return flat


def input_rows(case_file: Path | None, data: dict[str, Any] | None = None,
               swept: tuple[str, ...] = (), set_keys: tuple[str, ...] = ()
               ) -> list[dict[str, str]]:
    """Rows (key, value, unit, source) of the case; ``data`` overrides the file's values;
    ``swept`` keys are marked as swept, ``set_keys`` as set for the run on top of the file."""
    text = case_file.read_text(encoding="utf-8") if case_file and case_file.is_file() else ""
    if data is None:
        data = tomllib.loads(text) if text else {}
    comments = line_comments(text)
    rows = []
    for key, value in flatten(data).items():
        if key in ("title", "source"):
            continue
        source = ("swept (see the variant table)" if key in swept else
                  "set for this run (command line)" if key in set_keys else
                  comments.get(key, ""))
        rows.append({"key": key, "value": _show(value), "unit": unit_of(key), "source": source})
    return rows


def _show(value: Any) -> str:
    if isinstance(value, float):
        return f"{value:.6g}"
    return str(value)
