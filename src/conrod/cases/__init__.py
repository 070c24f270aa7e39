"""Case files (TOML) validated with pydantic: one module per section."""

from __future__ import annotations

from typing import TYPE_CHECKING

from conrod._lazy import lazy_getattr

if TYPE_CHECKING:  # pragma: no cover
    from conrod.cases.case import Case

_PUBLIC = {
    "Case": "conrod.cases.case",
}
"""Public name → the module that defines it (imported when the name is first used)."""


__getattr__ = lazy_getattr(__name__, _PUBLIC, globals())


__all__ = ["Case"]
