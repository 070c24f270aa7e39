"""Command-line options that take an optional value (``conrod run --fields [STRIDE_DEG]``):
the parser takes a value after every option, so a bare option gets its default inserted
before parsing."""

from __future__ import annotations

FIELDS_DEFAULT_DEG = 1.0
"""Stride of ``--fields`` given without a value [deg of crank angle]."""


def optional_fields_stride(argv: list[str]) -> list[str]:
    """``argv`` with the default stride after a bare ``--fields`` of ``conrod run`` (last,
    or followed by another option): ``--fields [STRIDE_DEG]`` takes an optional value."""
    out = list(argv)
    for i, token in enumerate(out):
        if token == "--fields" and (i + 1 == len(out) or out[i + 1].startswith("--")):
            out.insert(i + 1, f"{FIELDS_DEFAULT_DEG:g}")
            break
    return out
