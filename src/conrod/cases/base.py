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
    """A case-file section in strict mode: unknown keys are errors, numbers must be numbers
    (no ``true`` for 1, no ``"0.02"`` for 0.02), integers integers, NaN and infinity are
    refused; values are validated on assignment."""

    model_config = ConfigDict(
        extra="forbid", frozen=True, validate_default=True, strict=True, allow_inf_nan=False
    )


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


_TYPE_HINTS = {
    "float_type": "a number is required (not text, not true/false)",
    "int_type": "a whole number is required (not text, not true/false, no decimals)",
    "string_type": "text in quotes is required",
    "bool_type": "true or false is required",
    "list_type": "a list [ ... ] is required",
    "model_type": "a section (table) is required",
    "dict_type": "a section (table) is required",
    "finite_number": "a finite number is required (not nan or inf)",
    "string_too_short": "must not be empty",
}
"""Plain wording of pydantic's type errors (what the case file must hold instead)."""


def _shown(value: Any) -> str:
    """The offending value as written, shortened to keep the message on one line."""
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _dotted(prefix: str, loc: tuple[Any, ...]) -> str:
    """'bearing.grooves[0].width' from a pydantic location."""
    text = prefix
    for part in loc:
        if isinstance(part, int):
            text += f"[{part}]"
        else:
            text += ("." if text else "") + str(part)
    return text


def _location(error: Any) -> tuple[Any, ...]:
    return tuple(p for p in error["loc"] if not str(p).startswith(("function-", "lax-")))


def _closest_key(root: type[BaseModel], loc: tuple[Any, ...]) -> str | None:
    """The valid key closest to the unknown key at ``loc`` (difflib), if any is close."""
    model, name = _resolve_model(root, tuple(p for p in loc if not isinstance(p, int)))
    hint = difflib.get_close_matches(name, sorted(model.model_fields), n=1, cutoff=0.5)
    return hint[0] if hint else None


def _explained_by_a_misspelling(root: type[BaseModel], errors: list[Any]) -> set[int]:
    """Indices of "required field is missing" errors whose field is the suggestion for an
    unknown key beside it ('sped' for 'speed'): the misspelling says it all."""
    suggested = set()
    for error in errors:
        loc = _location(error)
        if error["type"] == "extra_forbidden" and loc:
            key = _closest_key(root, loc)
            if key is not None:
                suggested.add((*loc[:-1], key))
    return {i for i, error in enumerate(errors)
            if error["type"] == "missing" and _location(error) in suggested}


RANGE_ERRORS = ("greater_than", "greater_than_equal", "less_than", "less_than_equal")
"""pydantic error types of a value outside a field's range."""
_BOUNDS = (("gt", lambda v, b: v > b), ("ge", lambda v, b: v >= b),
           ("lt", lambda v, b: v < b), ("le", lambda v, b: v <= b))


def unit_slips(*slips: tuple[float, str]) -> dict[str, Any]:
    """``json_schema_extra`` of a field whose value is often typed in another unit: (factor
    to the field's unit, that unit) pairs, e.g. ``unit_slips((1e-3, "mm"))`` for a length in
    metres typed in millimetres. A value out of the field's range whose conversion is in
    range gets "did you mean ...?" in its message."""
    return {"unit_slips": [list(slip) for slip in slips]}


def in_field_range(model: type[BaseModel], name: str, value: float) -> bool:
    """True when ``value`` satisfies the ``ge/gt/le/lt`` bounds of ``model.name``."""
    info = model.model_fields.get(name)
    if info is None:
        return False
    return all(check(value, getattr(item, attr)) for item in info.metadata
               for attr, check in _BOUNDS if getattr(item, attr, None) is not None)


def slip_hint(value: float, unit: str, slips: Any, plausible: Any) -> str:
    """'; did you mean 4e-05 m = 40 µm?' for the first (factor, written unit) of ``slips``
    that turns ``value`` (as written, in that unit) into a ``plausible`` value in ``unit``;
    '' when none does."""
    for factor, written in slips or ():
        candidate = value * factor
        if plausible(candidate):
            return f"; did you mean {candidate:.4g} {unit} = {value:.4g} {written}?"
    return ""


def _field_slip(model: type[BaseModel], name: str, value: Any, unit: str) -> str:
    info = model.model_fields.get(name)
    extra = info.json_schema_extra if info is not None else None
    if not isinstance(extra, dict) or not isinstance(value, int | float):
        return ""
    return slip_hint(float(value), unit, extra.get("unit_slips"),
                     lambda v: in_field_range(model, name, v))


def _describe(root: type[BaseModel], error: Any, prefix: str) -> str:
    loc = _location(error)
    dotted = _dotted(prefix, loc)
    value = error.get("input")
    kind = error["type"]
    model, name = _resolve_model(root, tuple(p for p in loc if not isinstance(p, int)))
    if kind == "extra_forbidden":
        valid = sorted(model.model_fields)
        hint = _closest_key(root, loc)
        suggestion = f"; did you mean '{hint}'?" if hint else ""
        return (
            f"{dotted}: unknown key '{name}'{suggestion} "
            f"(valid keys here: {', '.join(valid)})"
)
    if kind == "missing":
        unit = field_unit(model, name)
        return f"{dotted}: required field is missing" + (f" [{unit}]" if unit else "")
    text = str(error["msg"]).removeprefix("Value error, ")
    if kind == "value_error" and isinstance(value, dict):  # a cross-field check: says it all
        return text
    text = _TYPE_HINTS.get(kind, text)
    unit = field_unit(model, name)
    allowed = field_range(model, name)
    message = f"{dotted or 'case'} = {_shown(value)}: {text}"
    if allowed:
        message += f" (allowed: {allowed}" + (f" {unit}" if unit else "") + ")"
    elif unit:
        message += f" [{unit}]"
    if kind in RANGE_ERRORS:
        message += _field_slip(model, name, value, unit)
    return message


def format_validation_error(
    error: ValidationError, root: type[BaseModel], prefix: str = ""
) -> str:
    """One readable message (one line per problem) for a pydantic ``ValidationError``; a
    missing field is not listed beside the misspelt key that suggests it."""
    errors = error.errors()
    explained = _explained_by_a_misspelling(root, errors)
    return "\n".join(_describe(root, item, prefix) for i, item in enumerate(errors)
                     if i not in explained)


def validate_section(model: type[BaseModel], data: Any, prefix: str = "") -> Any:
    """Build ``model`` from ``data``; raise :class:`CaseError` with a readable message."""
    try:
        return model.model_validate(data)
    except ValidationError as error:
        raise CaseError(format_validation_error(error, model, prefix)) from None


def range_error(field: str, value: Any, allowed: str, unit: str = "", hint: str = ""
                ) -> CaseError:
    """A :class:`CaseError` for a cross-field check, in the same wording as field errors;
    ``hint`` (from :func:`slip_hint`) is appended."""
    unit_text = f" {unit}" if unit else ""
    return CaseError(f"{field} = {value!r}: out of range (allowed: {allowed}{unit_text})"
                     f"{hint}")
