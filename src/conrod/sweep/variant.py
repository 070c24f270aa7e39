"""One variant of a study: the base case with the axis values set, validated and hashed.

The hash identifies a variant's results folder: SHA-256 of the validated case content
(every key with defaults filled in, plus the bytes of the data files it names) and the
conrod version, so that a rerun finds what is already computed and a new conrod version
computes afresh.
"""

from __future__ import annotations

import copy
import functools
import hashlib
import json
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from conrod._version import __version__
from conrod.errors import CaseError

CASE_AXIS = "case"
"""Name of the axis whose values are whole case files [-]."""

HASH_LENGTH = 16
"""Hex digits of the variant hash used as folder name [-]."""


@dataclass(frozen=True)
class Variant:
    """A resolved, validated variant.

    index : int  Position in the study [-].
    axes : dict  Axis key → value (case-file axis: the file name).
    case_data : dict  The case as a TOML-like dict (base file + override + axis values).
    case_file : Path  The file the variant starts from (relative names resolve next to it).
    key : str  Hash of the resolved case, the command and the conrod version (folder name).
    command : str  ``"run"`` (orbit) or ``"mechanism"`` (clearance joints).
    """

    index: int
    axes: dict[str, Any]
    case_data: dict[str, Any] = field(repr=False)
    case_file: Path
    key: str
    command: str = "run"

    def case(self):
        """The validated :class:`conrod.cases.case.Case` of this variant."""
        from conrod.cases.case import Case

        return Case.from_dict(self.case_data, base_dir=self.case_file.resolve().parent,
                              path=self.case_file)

    def payload(self, out: Path, figures: bool = False) -> dict[str, Any]:
        """The keyword arguments of :func:`conrod.sweep.worker.run_variant` for this
        variant, stored into the sweep folder ``out`` (plain data: any worker runs it)."""
        return {"case_data": self.case_data, "case_file": str(self.case_file.resolve()),
                "key": self.key, "axes": self.axes, "out": str(Path(out).resolve()),
                "figures": figures, "command": self.command}


def _read_case_file(path: Path) -> dict[str, Any]:
    """The parsed case file (cached while its size and modification time stay the same)."""
    try:
        stat = path.stat()
    except OSError as error:
        raise CaseError(f"case file {str(path)!r}: cannot be read ({error.strerror})") from None
    return _parse_case_file(path, stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=64)
def _parse_case_file(path: Path, mtime_ns: int, size: int) -> dict[str, Any]:
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise CaseError(f"case file {str(path)!r}: cannot be read ({error.strerror})") from None
    except tomllib.TOMLDecodeError as error:
        raise CaseError(f"case file {str(path)!r}: not valid TOML ({error})") from None


def set_dotted(data: dict[str, Any], key: str, value: Any) -> None:
    """Set ``data[a][b][c] = value`` for ``key = "a.b.c"``, creating tables as needed."""
    parts = key.split(".")
    table = data
    for depth, part in enumerate(parts[:-1]):
        table = table.setdefault(part, {})
        if not isinstance(table, dict):
            raise CaseError(f"{'.'.join(parts[:depth + 1])} is a value, not a table")
    table[parts[-1]] = value


def _merge(target: dict[str, Any], extra: dict[str, Any]) -> None:
    for name, value in extra.items():
        if isinstance(value, dict) and isinstance(target.get(name), dict):
            _merge(target[name], value)
        else:
            target[name] = copy.deepcopy(value)


def resolve_variant(case_file: Path, axes: dict[str, Any], override: dict[str, Any],
                    index: int, command: str = "run") -> Variant:
    """Build and validate one variant; :class:`CaseError` names the axis, key and value.

    The merged case is validated once; only when that fails is it rebuilt step by step
    (the override, then one axis after the other) to name the step that makes it invalid.
    """
    base = _read_case_file(Path(case_file).resolve())
    data = copy.deepcopy(base)
    _merge(data, override)
    try:
        for key, value in axes.items():
            if key != CASE_AXIS:
                set_dotted(data, key, value)
        case = _validate(data, case_file, command)
    except CaseError:
        _raise_at_first_bad_step(base, case_file, axes, override, index, command)
        raise  # the steps all validate: the merged case itself is the problem
    shown = {k: (str(v) if k == CASE_AXIS else v) for k, v in axes.items()}
    return Variant(index, shown, data, Path(case_file), variant_hash(case, command), command)


def _raise_at_first_bad_step(base: dict[str, Any], case_file: Path, axes: dict[str, Any],
                             override: dict[str, Any], index: int, command: str) -> None:
    """Apply the override, then each axis, validating after each step; raise
    :class:`CaseError` naming the first step after which the case is invalid."""
    data = copy.deepcopy(base)
    try:
        _merge(data, override)
        _validate(data, case_file, command)
    except CaseError as error:
        raise CaseError(f"study override on {case_file.name}: {error}") from None
    for key, value in axes.items():
        if key == CASE_AXIS:
            continue
        try:
            set_dotted(data, key, value)
            _validate(data, case_file, command)
        except CaseError as error:
            raise CaseError(f"axis {key!r} = {value!r} (variant {index + 1}): {error}") from None


def _validate(data: dict[str, Any], case_file: Path, command: str):
    """The case of ``data`` checked as the command would (loads read, sections present)."""
    from conrod.cases.case import Case

    case = Case.from_dict(data, base_dir=Path(case_file).resolve().parent, path=case_file)
    if command == "mechanism":
        from conrod.mechanism.setup import mechanism_case

        mechanism_case(case)
    else:
        from conrod.simulation.simulation import Simulation

        Simulation(case)
    return case


def variant_hash(case, command: str = "run") -> str:
    """SHA-256 (first :data:`HASH_LENGTH` hex digits) of the case content, the command and
    the conrod version."""
    content = case.model_dump(mode="json")
    files = {name: _file_digest(case.resolve(name)) for name in _strings(content)
             if _is_data_file(case, name)}
    identity = {"case": content, "files": files, "conrod": __version__}
    if command != "run":
        identity["command"] = command
    text = json.dumps(identity, sort_keys=True, default=str)
    return hashlib.sha256(text.encode()).hexdigest()[:HASH_LENGTH]


def _strings(value: Any) -> list[str]:
    if isinstance(value, str):
        return [value]
    if isinstance(value, dict):
        return [s for item in value.values() for s in _strings(item)]
    if isinstance(value, list):
        return [s for item in value for s in _strings(item)]
    return []


def _is_data_file(case, name: str) -> bool:
    if not name or "\n" in name or len(name) > 4096:
        return False
    try:
        return case.resolve(name).is_file()
    except OSError:
        return False


def _file_digest(path: Path) -> str:
    stat = path.stat()
    return _digest(path, stat.st_mtime_ns, stat.st_size)


@functools.lru_cache(maxsize=256)
def _digest(path: Path, mtime_ns: int, size: int) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()
