"""Base of every case-file section: strict pydantic models with engineer-readable errors.

Every field declares its unit in brackets in ``description`` and its range with
``ge``/``gt``/``le``/``lt``. :func:`format_validation_error` turns pydantic's error
list into one message that names the field, the value, the allowed range and the
unit, and suggests the closest valid key for a misspelt one ("did you mean ...?").
"""

from __future__ import annotations

import difflib
import re
from typing import Any

from pydantic import BaseModel, ConfigDict, ValidationError

from conrod.errors import CaseError


class Section(BaseModel):
    """A case-file section: unknown keys are errors, values are validated on assignment."""

    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=True)


_UNIT = re.compile(r"\[([^\]]*)\]")


def field_unit(model: type[BaseModel], name: str) -> str:
    """Unit of ``model.name`` read from the brackets in its description ('' if none)."""
    info = model.model_fields.get(name)
    if info is None or not info.description:
        return ""
    match = _UNIT.search(info.description)
    unit = match.group(1) if match else ""
    return "" if unit == "-" else unit


def field_range(model: type[BaseModel], name: str) -> str:
    """Allowed range of ``model.name`` from its ``ge/gt/le/lt`` metadata, e.g. '> 0 and <= 2'."""
    info = model.model_fields.get(name)
    if info is None:
        return ""
    parts = []
    for item in info.metadata:
        for attr, symbol in (("gt", ">"), ("ge", ">="), ("lt", "<"), ("le", "<=")):
            value = getattr(item, attr, None)
            if value is not None:
                parts.append(f"{symbol} {value:g}")
    return " and ".join(parts)


def _resolve_model(root: type[BaseModel], loc: tuple[Any, ...]) -> tuple[type[BaseModel], str]:
    """Walk ``loc`` through nested models; return the owning model and the last field name."""
    model: type[BaseModel] = root
    for part in loc[:-1]:
        info = model.model_fields.get(str(part))
        annotation = getattr(info, "annotation", None) if info else None
        nested = _first_model(annotation)
        if nested is None:
            break
        model = nested
    return model, str(loc[-1]) if loc else ""


def _first_model(annotation: Any) -> type[BaseModel] | None:
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for arg in getattr(annotation, "__args__", ()) or ():
        found = _first_model(arg)
        if found is not None:
            return found
    return None


def _describe(root: type[BaseModel], error: Any, prefix: str) -> str:
    loc = tuple(p for p in error["loc"] if not isinstance(p, int) or True)
    dotted = ".".join(str(p) for p in (prefix, *loc) if p != "")
    value = error.get("input")
    kind = error["type"]
    model, name = _resolve_model(root, loc)
    if kind == "extra_forbidden":
        valid = sorted(model.model_fields)
        hint = difflib.get_close_matches(name, valid, n=1, cutoff=0.5)
        suggestion = f"; did you mean '{hint[0]}'?" if hint else ""
        return (
            f"{dotted}: unknown key '{name}'{suggestion} "
            f"(valid keys here: {', '.join(valid)})"
)
    if kind == "missing":
        unit = field_unit(model, name)
        return f"{dotted}: required field is missing" + (f" [{unit}]" if unit else "")
    text = str(error["msg"]).removeprefix("Value error, ")
    if isinstance(value, dict):  # a section-level (cross-field) check: its text says it all
        return text
    unit = field_unit(model, name)
    allowed = field_range(model, name)
    message = f"{dotted} = {value!r}: {text}"
    if allowed:
        message += f" (allowed: {allowed}" + (f" {unit}" if unit else "") + ")"
    elif unit:
        message += f" [{unit}]"
    return message


def format_validation_error(
    error: ValidationError, root: type[BaseModel], prefix: str = ""
) -> str:
    """One readable message (one line per problem) for a pydantic ``ValidationError``."""
    return "\n".join(_describe(root, item, prefix) for item in error.errors())


def validate_section(model: type[BaseModel], data: Any, prefix: str = "") -> Any:
    """Build ``model`` from ``data``; raise :class:`CaseError` with a readable message."""
    try:
        return model.model_validate(data)
    except ValidationError as error:
        raise CaseError(format_validation_error(error, model, prefix)) from None


def range_error(field: str, value: Any, allowed: str, unit: str = "") -> CaseError:
    """A :class:`CaseError` for a cross-field check, in the same wording as field errors."""
    unit_text = f" {unit}" if unit else ""
    return CaseError(f"{field} = {value!r}: out of range (allowed: {allowed}{unit_text})")
