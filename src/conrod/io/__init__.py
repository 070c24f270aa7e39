"""Atomic result files: a crash never leaves a half-written file.

The names below are imported when first used: the CLI imports :mod:`conrod.io.interrupts`
at start-up, and that must not load NumPy (the CSV writer's).
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # pragma: no cover
    from conrod.io.atomic import atomic_path, write_csv, write_json, write_text

_PUBLIC = dict.fromkeys(("atomic_path", "write_csv", "write_json", "write_text"),
                        "conrod.io.atomic")
"""Public name → the module that defines it."""


def __getattr__(name: str) -> Any:
    if name not in _PUBLIC:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = getattr(importlib.import_module(_PUBLIC[name]), name)
    globals()[name] = value
    return value


__all__ = ["atomic_path", "write_csv", "write_json", "write_text"]
