"""Atomic result files: a crash never leaves a half-written file.

The names below are imported when first used: the CLI imports :mod:`conrod.io.interrupts`
at start-up, and that must not load NumPy (the CSV writer's).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.io.atomic import atomic_path, write_csv, write_json, write_text

_PUBLIC = dict.fromkeys(("atomic_path", "write_csv", "write_json", "write_text"),
                        "conrod.io.atomic")
"""Public name → the module that defines it."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["atomic_path", "write_csv", "write_json", "write_text"]
