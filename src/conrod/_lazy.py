"""A package's public names imported when first used (PEP 562 module ``__getattr__``), so
that ``import conrod`` and reading a case file do not load the numerical stack."""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any


def lazy_getattr(package: str, public: dict[str, str], namespace: dict[str, Any]
                 ) -> Callable[[str], Any]:
    """The module ``__getattr__`` of ``package``: a name of ``public`` (name → the module
    that defines it) is imported on first use and kept in ``namespace`` (the package's
    ``globals()``); any other name is an AttributeError."""

    def module_getattr(name: str) -> Any:
        module = public.get(name)
        if module is None:
            raise AttributeError(f"module {package!r} has no attribute {name!r}")
        value = getattr(importlib.import_module(module), name)
        namespace[name] = value
        return value

    return module_getattr
