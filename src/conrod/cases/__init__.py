"""Case files (TOML) validated with pydantic: one module per section."""

from conrod.cases.case import Case

__all__ = ["Case"]
